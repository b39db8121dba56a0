// Convergence of the simply supported plate of thesis 3.1.2 for every force model, on
// 2 x 2 to 16 x 16 meshes: the tables of docs/verification.md. Label `slow` (about a
// minute and a quarter in release); run with  ctest --test-dir build -L slow --verbose
//
// The L1 midplane model has a singular tangent (docs/theory/ancf_plate.md), so its rows
// were sought by dynamic relaxation instead of Newton statics: RK4 from the flat plate under
// the load with a mass-proportional damping force Q_d = -c M v, c = 2 omega_1, until the
// motion has died out. The harness reproduces Newton statics on the default model; for L1
// it finds no equilibrium (the L1 equations are unstable), which is what is asserted.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "plate_models.hpp"
#include "seaflex/integrators/rk4_augmented.hpp"

using namespace seaflex;
using namespace seaflex::plate_models;

namespace {
constexpr int kMeshes[] = {2, 4, 8, 16};

/// The system with a damping force Q_d = -c M v added to Q (test only; the loader returns
/// a finalized system, to which no Force can be added, so the force is added here, to what
/// the integrator sees). M is the system's constant mass matrix. Only what RK4 asks is
/// supported: Q, constraints and the matrix with km (no damping tangent, kv = 0).
class MassProportionalDamping final : public Dae {
 public:
  MassProportionalDamping(const System& system, double c) : sys_(system), c_(c) {
    DaeEval e = sys_.make_eval();
    DaeRequest r;
    r.forces = false;
    r.constraints = false;
    r.matrix = true;
    r.scales.km = 1.0;
    sys_.evaluate(sys_.initial_state(), r, e);
    const Index n = sys_.num_coordinates();
    M_ = e.kkt.matrix().topLeftCorner(n, n);
  }
  const SpMat& mass() const { return M_; }

  Index num_coordinates() const override { return sys_.num_coordinates(); }
  Index num_constraints() const override { return sys_.num_constraints(); }
  DaeEval make_eval() const override { return sys_.make_eval(); }
  void evaluate(const State& state, const DaeRequest& request, DaeEval& out) const override {
    if (request.matrix && request.scales.kv != 0.0)
      throw std::logic_error("MassProportionalDamping: no damping tangent");
    sys_.evaluate(state, request, out);
    if (request.forces) out.Q.noalias() -= c_ * (M_ * state.v);
  }
  bool constant_mass_kkt() const override { return sys_.constant_mass_kkt(); }
  std::string coordinate_name(Index i) const override { return sys_.coordinate_name(i); }
  std::string constraint_name(Index row) const override { return sys_.constraint_name(row); }

 private:
  const System& sys_;
  double c_;
  SpMat M_;
};

/// Largest omega of the unconstrained K x = omega^2 M x at the flat plate (K the tangent
/// -dQ/dq) by power iteration: an upper bound of the constrained system's, for the RK4 step.
double highest_frequency(const System& sys, const SpMat& M) {
  DaeEval e = sys.make_eval();
  DaeRequest r;
  r.forces = false;
  r.constraints = false;
  r.matrix = true;
  r.scales.kq = 1.0;
  const State s = sys.initial_state();
  sys.evaluate(s, r, e);
  const Index n = sys.num_coordinates();
  const SpMat K = e.kkt.matrix().topLeftCorner(n, n);
  Eigen::SimplicialLDLT<SpMat> ldlt(M);
  VecX x = VecX::Ones(n) + 0.1 * VecX::LinSpaced(n, 0.0, 1.0);
  double lambda = 0.0;
  for (int it = 0; it < 300; ++it) {
    VecX y = ldlt.solve(K * x);
    lambda = y.norm() / x.norm();
    x = y / y.norm();
  }
  return std::sqrt(lambda);
}

struct Relaxed {
  double w = 0.0;               ///< centre deflection (m, down)
  double t = 0.0;               ///< simulated time (s)
  int steps = 0;                ///< RK4 steps
  double h = 0.0;               ///< step (s)
  bool converged = false;       ///< both tolerances met
  bool diverged = false;        ///< a coordinate grew beyond 1e3 (or the centre beyond 1 m)
  double v_max = 0.0;           ///< max |v_i| at the end (m/s, 1/s for slopes)
  double dw = 0.0;              ///< change of w over the last period (m)
  double in_plane_slope = 0.0;  ///< max change of an in-plane component of a nodal slope
  double seconds = 0.0;         ///< wall time
};

// tolerances: over one period of the first mode the centre moves less than kDw and no
// velocity component exceeds kVmax
constexpr double kDw = 1e-10, kVmax = 1e-8;

/// Dynamic relaxation of a plate case from the flat, resting plate.
/// step_divisor divides the RK4 step (to show that a divergence does not depend on it).
Relaxed relax(const PlateCase& c, double t_max = 3.0, double step_divisor = 1.0) {
  const auto t0 = std::chrono::steady_clock::now();
  io::Model model = load(c);
  const System& sys = *model.system;
  const auto& plate = dynamic_cast<const AncfPlate&>(*sys.find_body("plate"));
  const double omega1 = 2.0 * std::numbers::pi * std::numbers::pi / (kSide * kSide) *
                        std::sqrt(flexural_rigidity() / (kRho * kH));
  MassProportionalDamping dae(sys, 2.0 * omega1);
  const double period = 2.0 * std::numbers::pi / omega1;
  // RK4 is stable up to h omega = 2.8 on the imaginary axis; 2.0 leaves room for the
  // stiffening under load
  const int per_period =
      static_cast<int>(std::ceil(step_divisor * period * highest_frequency(sys, dae.mass()) / 2.0));
  Relaxed out;
  out.h = period / per_period;
  State s = sys.initial_state();
  const State flat = s;
  const Index centre = plate.node_index(c.n / 2, c.n / 2) + 2;
  Rk4Augmented rk4;
  dae.start(s);
  double w_prev = 0.0;
  for (int k = 1; s.t < t_max; ++k) {
    const StepReport rep = rk4.step(dae, s, out.h);
    EXPECT_TRUE(rep.ok) << rep.message;
    if (!rep.ok || !std::isfinite(s.q[centre]) || std::abs(s.q[centre]) > 1.0 ||
        !(s.q.lpNorm<Eigen::Infinity>() < 1e3)) {
      out.diverged = true;
      out.w = -s.q[centre];
      break;
    }
    s.t = k * out.h;
    dae.accept_step(s);
    out.steps = k;
    if (k % per_period != 0) continue;
    out.w = -s.q[centre];
    out.dw = std::abs(out.w - w_prev);
    out.v_max = s.v.lpNorm<Eigen::Infinity>();
    w_prev = out.w;
    if (out.dw < kDw && out.v_max < kVmax) {
      out.converged = true;
      break;
    }
  }
  out.t = s.t;
  for (int i = 0; i <= c.n; ++i)
    for (int j = 0; j <= c.n; ++j) {
      const Index k = plate.node_index(i, j);
      for (Index off : {3, 6, 9})  // r_p1, r_p2, r_p1p2: their x and y components
        for (Index d : {0, 1})
          out.in_plane_slope =
              std::max(out.in_plane_slope, std::abs(s.q[k + off + d] - flat.q[k + off + d]));
    }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

void print_relaxed(const Relaxed& r, double ref) {
  std::printf(
      "    w = %.7f m (%+.3f%% of Navier)  t = %.2f s, %d steps of %.3g s, |dw| = %.1e m,"
      " max|v| = %.1e, in-plane slopes moved %.2e, %s, %.1f s\n",
      r.w, 100.0 * (r.w / ref - 1.0), r.t, r.steps, r.h, r.dw, r.v_max, r.in_plane_slope,
      r.converged ? "converged" : (r.diverged ? "DIVERGED" : "NOT converged"), r.seconds);
}
}  // namespace

// Full self-weight, edges free in the plane; each model within 1 % of Navier from 8 x 8
// on, and within 0.1 % between 8 x 8 and 16 x 16 (converged in the mesh: what remains is
// the geometric nonlinearity, -0.50 %)
TEST(PlateConvergence, SelfWeightEveryModel) {
  const double ref = navier_reference();
  std::printf(
      "\n  centre deflection (m), simply supported, in_plane: free, q = 7798.95 Pa;"
      " Navier %.6f m\n  %-12s",
      ref, "model");
  for (int n : kMeshes) std::printf(" %18dx%-2d", n, n);
  std::printf("\n");
  for (const auto& [m, t] : kSolvableModels) {
    std::printf("  %-5s/%-6s", m, t);
    double w8 = 0.0;
    for (int n : kMeshes) {
      const double w = centre_deflection({n, "simply_supported", m, t, 1.0, "free"});
      std::printf("  %.6f (%+.2f%%)", w, 100.0 * (w / ref - 1.0));
      if (n >= 8) {
        EXPECT_NEAR(w / ref, 1.0, 0.01) << m << "/" << t << " " << n;
      }
      if (n == 8) w8 = w;
      if (n == 16) {
        EXPECT_NEAR(w / w8, 1.0, 1e-3) << m << "/" << t;
      }
    }
    std::printf("\n");
  }
}

// Linear range (1 % of the load, scaled by 100) of the default model for each support
// variant: the mesh convergence to Navier itself (16 x 16 within 0.01 %)
TEST(PlateConvergence, LinearRangeDefaultModel) {
  const double ref = navier_reference();
  std::printf("\n  linear range (load / 100, deflection x 100), default model\n");
  for (const char* ip : {"fixed", "sliding", "free"}) {
    std::printf("  in_plane %-8s", ip);
    for (int n : kMeshes) {
      const double w =
          100.0 * centre_deflection({n, "simply_supported", "exact", "exact", 0.01, ip});
      std::printf("  %.7f (%+.3f%%)", w, 100.0 * (w / ref - 1.0));
      if (n == 16) {
        EXPECT_NEAR(w / ref, 1.0, 1e-4) << ip;
      }
    }
    std::printf("\n");
  }
}

// the three in-plane conditions at the full load (geometric nonlinearity)
TEST(PlateConvergence, InPlaneConditionsAtFullLoad) {
  const double ref = navier_reference();
  std::printf("\n  full load, default model, by in-plane edge condition\n");
  for (const char* ip : {"fixed", "sliding", "free"}) {
    std::printf("  in_plane %-8s", ip);
    for (int n : kMeshes) {
      const double w = centre_deflection({n, "simply_supported", "exact", "exact", 1.0, ip});
      std::printf("  %.6f (%+.2f%%)", w, 100.0 * (w / ref - 1.0));
    }
    std::printf("\n");
  }
  SUCCEED();
}

/// Fastest exponential growth rate (1/s) of small motions about q: max Re sqrt(-mu) over the
/// eigenvalues mu of M^-1 K restricted to the null space of the constraints (K = -dQ/dq);
/// zero when every mu is real and positive (stable oscillations).
double growth_rate(const System& sys, const VecX& q) {
  DaeEval e = sys.make_eval();
  DaeRequest r;
  r.forces = false;
  r.matrix = true;
  r.scales.kq = 1.0;
  State s = sys.initial_state();
  s.q = q;
  sys.evaluate(s, r, e);
  const Index n = sys.num_coordinates(), m = sys.num_constraints();
  const MatX A = MatX(e.kkt.matrix());
  const MatX Z = Eigen::FullPivLU<MatX>(A.bottomLeftCorner(m, n)).kernel();
  const MatX Kr = Z.transpose() * A.topLeftCorner(n, n) * Z;
  r.scales.kq = 0.0;
  r.scales.km = 1.0;
  sys.evaluate(s, r, e);
  const MatX Mr = Z.transpose() * MatX(e.kkt.matrix()).topLeftCorner(n, n) * Z;
  Eigen::EigenSolver<MatX> es(Mr.ldlt().solve(Kr), false);
  double growth = 0.0;
  for (Index i = 0; i < es.eigenvalues().size(); ++i)
    growth = std::max(growth, std::sqrt(-es.eigenvalues()[i]).real());
  return growth;
}

// The dynamic-relaxation harness against Newton statics on the default model (full load,
// in_plane free): the same discrete equilibrium, to 1e-4 relative
TEST(PlateConvergence, DynamicRelaxationMatchesStatics) {
  const double ref = navier_reference();
  std::printf("\n  dynamic relaxation vs Newton statics, exact/exact, in_plane free\n");
  for (int n : {2, 4}) {
    const PlateCase c{n, "simply_supported", "exact", "exact", 1.0, "free"};
    const double newton = centre_deflection(c);
    const Relaxed r = relax(c);
    std::printf("  %2dx%-2d Newton %.7f m, relaxed %.7f m, difference %.1e relative\n", n, n,
                newton, r.w, r.w / newton - 1.0);
    print_relaxed(r, ref);
    EXPECT_TRUE(r.converged) << n;
    EXPECT_NEAR(r.w / newton, 1.0, 1e-4) << n;
  }
}

// L1 with each transverse model: there is no equilibrium for dynamic relaxation to find.
// Its tangent is not symmetric, and small motions about the flat, unstressed plate grow
// exponentially from 4 x 4 on (complex eigenvalues of M^-1 K: flutter), at a rate that
// does not depend on the time step; on 2 x 2 the flat plate is stable but the deflected
// plate is not (negative eigenvalues at the exact/exact equilibrium), and the relaxation
// wanders. docs/verification.md section 9.
TEST(PlateConvergence, L1HasNoRelaxedEquilibrium) {
  std::printf(
      "\n  L1 midplane, in_plane free, full load, dynamic relaxation from the flat plate\n");
  for (const char* t : {"T2", "T3", "exact"}) {
    for (int n : {2, 4, 8}) {
      const PlateCase c{n, "simply_supported", "L1", t, 1.0, "free"};
      io::Model model = load(c);
      const double g_flat = growth_rate(*model.system, model.system->initial_state().q);
      double g_loaded = 0.0;
      if (n <= 4) {
        io::Model mex = load({n, "simply_supported", "exact", "exact", 1.0, "free"});
        State sex = mex.system->initial_state();
        solve_statics(*mex.system, sex, mex.statics);
        g_loaded = growth_rate(*model.system, sex.q);
      }
      std::printf("  L1/%-5s %dx%d: growth rate about the flat plate %.4g 1/s", t, n, n, g_flat);
      if (n <= 4) std::printf(", about the exact/exact equilibrium %.4g 1/s", g_loaded);
      std::printf("\n");
      for (double divisor : {1.0, 4.0}) {
        if (n == 8 && divisor > 1.0) continue;
        const Relaxed r = relax(c, n == 2 ? 3.0 : 0.5, divisor);
        print_relaxed(r, navier_reference());
        EXPECT_FALSE(r.converged) << t << " " << n;
      }
      if (n == 2) {
        EXPECT_LT(g_flat, 1e-2) << t;
        EXPECT_GT(g_loaded, 10.0) << t;
      } else {
        EXPECT_GT(g_flat, 1e3) << t << " " << n;
      }
    }
  }
}
