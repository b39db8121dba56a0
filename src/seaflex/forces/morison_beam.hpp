// Morison loads on an ANCF beam (thesis eq. 176, applied through the shape functions as
// in eq. 177: Q = int S^T f dx, Gauss-integrated along each element's wet part). Per
// unit reference length, at a point r = S e with axis t = r'/|r'|:
//   drag          f_d = 1/2 rho Cd D |u_n| u_n,     u = fluid velocity - r_dot (relative)
//   axial drag    f_a = 1/2 rho Cd_ax pi D |u_a| u_a t,   u_a = t . u
//   fluid inertia f_i = rho Cm A a_n                 (a_n normal part of the fluid
//                                                     acceleration; A = pi D^2/4)
//   axial inertia f_ia = rho Cm_ax A (t . a) t       (Froude-Krylov, Cm_ax = 1 + Ca_ax:
//                                                     the axial part of the pressure
//                                                     gradient -rho a, applied as a
//                                                     distributed load like buoyancy, the
//                                                     hydrostatic one, for the effective
//                                                     tension; OrcaFlex's axial terms)
//   added mass    -rho A (Ca (I - t t^T) + Ca_ax t t^T) r_ddot   (in the mass matrix:
//                                                     int S^T rho A (...) S dx)
//   buoyancy      rho g A e_z on the submerged part  (external pressure resultant; the
//                                                     tension reported is the effective
//                                                     tension)
//   internal fluid: weight -rho_i g A_i e_z and mass rho_i A_i on the whole beam.
// Partially submerged elements are integrated over the part below the instantaneous
// surface (the crossing found by false position); an element whose two ends are both
// under water is taken as wholly wet.
// Tangents: dQ/dv exact; dQ/dq exact in the axis t, and by central differences of the
// fluid field in the position; the motion of the wet end and the state dependence of the
// added mass matrix are left out of the tangent (they matter only to implicit solvers'
// convergence rate, never to the solution).
// Fluid reuse (fluid_reuse = delta > 0, issue 21): the fluid velocity, acceleration and
// pressure found at a Gauss point are kept with the time and place they were found at, and
// used again while the time is the same and the point has moved by at most delta (max
// norm): an implicit step's Newton iterations (all at one t, the point moving by the
// updates, micrometres once the predictor is close) evaluate the sea once per step instead
// of once per iteration. The load is then that of the fluid at most delta away, an error of
// at most delta |grad u| in the velocity (|grad u| <= sum_i k_i w_i a_i for Airy waves,
// dU/dz for a current profile): 1e-3 m in a Hs 6 m, Tp 10 s sea (|grad u| about 0.3 1/s)
// is 3e-4 m/s. With reuse the field is constant near each point within an iteration, so
// the position tangent's central differences of the fluid are left out (the fluid's
// gradient changes only the convergence rate: it is about |grad u| h of the drag's
// velocity tangent, 3 % at h = 0.1 s). 0 (the default) evaluates at every call.
// The kept values belong to one element each (the element loop gives an element to one
// thread at a time), so results are the same for any number of threads.
#pragma once

#include <limits>
#include <memory>
#include <vector>

#include "seaflex/elements/ancf_beam.hpp"
#include "seaflex/hydro/ocean.hpp"
#include "seaflex/math/gauss_legendre.hpp"
#include "seaflex/model/force.hpp"

namespace seaflex {

struct MorisonBeamCoefficients {
  double diameter = 0.0;           ///< hydrodynamic diameter D (m)
  double cd = 0.0;                 ///< normal drag coefficient
  double cd_axial = 0.0;           ///< axial drag coefficient (on the perimeter pi D)
  double ca = 0.0;                 ///< normal added mass coefficient
  double cm = 0.0;                 ///< inertia coefficient on the fluid acceleration
  double ca_axial = 0.0;           ///< axial added mass coefficient
  double cm_axial = 0.0;           ///< axial inertia coefficient (Froude-Krylov + Ca_ax)
  bool buoyancy = true;            ///< buoyancy of the submerged part
  double internal_density = 0.0;   ///< rho_i of the contents (kg/m^3), 0 = empty
  double internal_diameter = 0.0;  ///< D_i of the contents (m)
  int gauss_points = 5;            ///< per element (wet part)
  double fluid_reuse = 0.0;        ///< (m) reuse distance of the fluid kinematics, 0 = off
};

class MorisonBeam : public Force {
 public:
  MorisonBeam(std::string name, const AncfBeam& beam, MorisonBeamCoefficients coefficients,
              std::shared_ptr<const hydro::Ocean> ocean);
  /// A line made of sections: coefficients[i] applies to the elements of the beam's section
  /// i (one entry per beam.sections(); gauss_points is taken from the first).
  MorisonBeam(std::string name, const AncfBeam& beam,
              std::vector<MorisonBeamCoefficients> coefficients,
              std::shared_ptr<const hydro::Ocean> ocean);

  void declare_blocks(math::SparseBlockAssembler& matrix) override;
  void assemble(const State& state, double load_factor, AssemblyTarget& target) const override;
  double potential_energy(const State&) const override { return 0.0; }
  bool constant_mass() const override;

  /// The coefficients of the beam's section i (beam().section_index(element)).
  const MorisonBeamCoefficients& coefficients(int section = 0) const {
    return coefficients_[section];
  }
  const AncfBeam& beam() const { return beam_; }
  /// Wet part [xi0, xi1] of element k; xi1 <= xi0 when dry.
  std::pair<double, double> wet_interval(const State& state, int k) const;

 private:
  /// Load per unit reference length at one point, and its derivatives.
  struct PointLoad {
    Vec3 f = Vec3::Zero();
    Vec3 t;       // the unit tangent r' / |r'|
    Mat3 df_dv;   // d f / d r_dot (set only when the derivatives are asked for)
    Mat3 df_drp;  // d f / d r'
  };
  /// A section's coefficients times the water's density (thesis eq. 176), made once.
  struct PointConstants {
    double drag = 0.0;           // 1/2 rho Cd D
    double drag_axial = 0.0;     // 1/2 rho Cd_ax pi D
    double inertia = 0.0;        // rho Cm A
    double inertia_axial = 0.0;  // rho Cm_ax A
    double buoyancy = 0.0;       // rho g A, or 0 without buoyancy
  };
  PointLoad point_load(const PointConstants& c, const hydro::FluidPoint& fl, const Vec3& rp,
                       const Vec3& rdot, double load_factor, bool derivatives,
                       bool with_buoyancy = true) const;
  /// The fluid at Gauss point g of element k at r, time t: kept and reused (fluid_reuse);
  /// `fresh`: found again at r (and kept), whatever is kept. An evaluation that forms the
  /// Newton matrix asks fresh: a restart forms that matrix again from the iterate alone
  /// (GeneralizedAlpha::restore), which must give the same matrix, bit for bit.
  hydro::FluidPoint fluid_at(int k, std::size_t g, const Vec3& r, double t, bool fresh) const;

  struct KeptFluid {
    double t = std::numeric_limits<double>::quiet_NaN();
    Vec3 r = Vec3::Zero();
    hydro::FluidPoint fluid;
  };

  const AncfBeam& beam_;
  std::vector<MorisonBeamCoefficients> coefficients_;  // per beam section
  std::vector<PointConstants> constants_;              // per beam section
  std::shared_ptr<const hydro::Ocean> ocean_;
  math::QuadratureRule rule_;
  // the shape functions and their slopes at the Gauss points of a wholly wet element k:
  // [k * gauss points + g] (the common case, computed once)
  std::vector<ancf_cable::Vec4> wet_shape_, wet_shape_dx_;
  std::vector<math::BlockId> blocks_;
  double reuse_ = 0.0;                   // fluid_reuse (m)
  mutable std::vector<KeptFluid> kept_;  // [k * gauss points + g]
};

}  // namespace seaflex
