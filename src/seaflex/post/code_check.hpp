// Riser code checks at one section: DNV-ST-F201 (2018; formerly DNV-OS-F201, 2010) LRFD
// combined loading, and API RP 2RD (1998, reaffirmed) von Mises stress against the
// allowable. The formulas of DNV-ST-F201 are those of DNV-OS-F201 (2010) Sec.5 D100-D200
// (section 5.4 of the 2018 standard):
//   design load effects       M_d  = gamma_F M_F + gamma_E M_E,  T_ed = gamma_F T_F + gamma_E T_E
//   burst resistance          p_b(t) = 2/sqrt(3) 2t/(D - t) min(f_y, f_u / 1.15)
//   plastic capacities        M_k = f_y alpha_c (D - t2)^2 t2,  T_k = f_y alpha_c pi (D - t2) t2
//                             alpha_c = (1 - beta) + beta f_u / f_y
//                             beta = (0.4 + q_h)                  D/t2 < 15
//                                    (0.4 + q_h)(60 - D/t2) / 45   15 <= D/t2 <= 60
//                                    0                             D/t2 > 60
//                             q_h = (p_ld - p_e) / p_b(t2) 2/sqrt(3)  (p_ld > p_e, else 0)
//   net internal overpressure (p_ld >= p_e):
//     u = gamma_SC gamma_m { |M_d|/M_k sqrt(1 - ((p_ld - p_e)/p_b(t1))^2) + (T_ed/T_k)^2 }
//         + ((p_ld - p_e)/p_b(t1))^2
//   net external overpressure (p_e > p_ld):
//     u = (gamma_SC gamma_m)^2 { |M_d|/M_k + (T_ed/T_k)^2 }^2
//         + (gamma_SC gamma_m (p_e - p_ld)/p_c(t2))^2
//   collapse pressure p_c:    (p_c - p_el)(p_c^2 - p_p^2) = p_c p_el p_p f_0 D/t
//                             p_el = 2 E (t/D)^3 / (1 - nu^2),  p_p = 2 f_y alpha_fab t/D
// with t1 = t - t_fab - t_corr (burst) and t2 = t - t_corr (the other terms), f_y = SMYS
// and f_u = SMTS (derated by the user for temperature). u <= 1 passes. The condition
// factor gamma_C multiplies the design load effects M_d and T_ed here (as DNV-ST-F101
// does; 1.0 by default). Where the inputs come from in DNV-OS-F201 (2010): the load
// effect factors Table 5-2, f_y and f_u Table 5-5, t1 and t2 Sec.5 C203, the condition
// factor Table 5-11, the ovality f_0 Sec.5 G201. The equation numbers are not cited: the
// standard's text was not at hand; the formulas above are those of its combined-loading
// criteria (Sec.5 D, DNV-ST-F201 (2018) section 5.4).
// API RP 2RD section 4.2 (working stress): sigma_vm <= C_f sigma_a, sigma_a = 2/3 SMYS,
// C_f = 1.0 operating (1.2 extreme, 1.5 survival and test): u = sigma_vm / (C_f 2/3 SMYS),
// sigma_vm the von Mises stress of the outer fibre (post/beam_results.hpp).
// Units: SI (N, N m, Pa, m).
#pragma once

namespace seaflex::post {

/// A pipe's section and material for DNV-ST-F201.
struct DnvPipe {
  double outer_diameter = 0.0;      ///< D (m)
  double wall = 0.0;                ///< nominal wall thickness t (m)
  double corrosion = 0.0;           ///< t_corr (m)
  double fabrication = 0.0;         ///< t_fab, negative fabrication tolerance (m)
  double smys = 0.0;                ///< f_y (Pa)
  double smts = 0.0;                ///< f_u (Pa)
  double youngs_modulus = 2.07e11;  ///< E (Pa), for the collapse pressure
  double poisson = 0.3;             ///< nu
  double ovality = 0.005;           ///< f_0 (at least 0.005 in the standard)
  double alpha_fab = 1.0;           ///< fabrication factor of p_p (1.0 seamless)
};

/// Partial safety factors of DNV-ST-F201 (defaults: ULS load effect factors of
/// combination a, normal safety class, ULS material factor).
struct DnvFactors {
  double gamma_F = 1.1;    ///< functional load effect factor
  double gamma_E = 1.3;    ///< environmental load effect factor
  double gamma_C = 1.0;    ///< condition factor (on the design load effects here)
  double gamma_SC = 1.14;  ///< safety class factor (low 1.04, normal 1.14, high 1.26)
  double gamma_m = 1.15;   ///< material resistance factor (ULS, ALS)
};

/// The load effects at a section: functional and environmental parts of the bending moment
/// (magnitudes of the vector sums are taken by the caller) and of the effective tension.
struct DnvLoadEffects {
  double moment_functional = 0.0;  ///< M_F (N m)
  double moment_environmental =
      0.0;  ///< M_E (N m) (the design moment is |gamma_F M_F + gamma_E M_E|)
  double tension_functional = 0.0;     ///< T_eF (N)
  double tension_environmental = 0.0;  ///< T_eE (N)
  double internal_pressure = 0.0;      ///< p_ld (Pa)
  double external_pressure = 0.0;      ///< p_e (Pa)
};

/// Burst resistance p_b(t) (Pa).
double dnv_burst_pressure(const DnvPipe& pipe, double t);
/// Plastic bending moment M_k (N m) and tension T_k (N) for net pressure p_ld - p_e.
double dnv_plastic_moment(const DnvPipe& pipe, double p_ld, double p_e);
double dnv_plastic_tension(const DnvPipe& pipe, double p_ld, double p_e);
/// Collapse pressure p_c(t) (Pa), the root of the cubic below min(p_el, p_p).
double dnv_collapse_pressure(const DnvPipe& pipe, double t);
/// The combined-loading utilisation u (pass: u <= 1). m_d, t_ed: the design moment
/// magnitude |gamma_F M_F + gamma_E M_E| (N m) and design effective tension (N) already
/// factored (gamma_C included).
double dnv_combined_utilisation(const DnvPipe& pipe, const DnvFactors& f, double m_d, double t_ed,
                                double p_ld, double p_e);

/// API RP 2RD: sigma_vm / (C_f 2/3 SMYS).
double api_rp_2rd_utilisation(double von_mises, double smys, double c_f);

}  // namespace seaflex::post
