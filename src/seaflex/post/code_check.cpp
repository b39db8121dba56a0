#include "seaflex/post/code_check.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace seaflex::post {

namespace {
const double kSqrt3 = std::sqrt(3.0);
}

double dnv_burst_pressure(const DnvPipe& pipe, double t) {
  const double D = pipe.outer_diameter;
  return 2.0 / kSqrt3 * 2.0 * t / (D - t) * std::min(pipe.smys, pipe.smts / 1.15);
}

namespace {
double alpha_c(const DnvPipe& pipe, double p_ld, double p_e) {
  const double t2 = pipe.wall - pipe.corrosion;
  const double D = pipe.outer_diameter;
  const double q_h = p_ld > p_e ? (p_ld - p_e) / dnv_burst_pressure(pipe, t2) * 2.0 / kSqrt3 : 0.0;
  const double dt = D / t2;
  const double beta = dt < 15.0 ? 0.4 + q_h : dt <= 60.0 ? (0.4 + q_h) * (60.0 - dt) / 45.0 : 0.0;
  return (1.0 - beta) + beta * pipe.smts / pipe.smys;
}
}  // namespace

double dnv_plastic_moment(const DnvPipe& pipe, double p_ld, double p_e) {
  const double t2 = pipe.wall - pipe.corrosion;
  const double D = pipe.outer_diameter;
  return pipe.smys * alpha_c(pipe, p_ld, p_e) * (D - t2) * (D - t2) * t2;
}

double dnv_plastic_tension(const DnvPipe& pipe, double p_ld, double p_e) {
  const double t2 = pipe.wall - pipe.corrosion;
  const double D = pipe.outer_diameter;
  return pipe.smys * alpha_c(pipe, p_ld, p_e) * std::numbers::pi * (D - t2) * t2;
}

double dnv_collapse_pressure(const DnvPipe& pipe, double t) {
  const double D = pipe.outer_diameter, nu = pipe.poisson;
  const double p_el = 2.0 * pipe.youngs_modulus * std::pow(t / D, 3) / (1.0 - nu * nu);
  const double p_p = 2.0 * pipe.smys * pipe.alpha_fab * t / D;
  // f(p) = (p - p_el)(p^2 - p_p^2) - p p_el p_p f_0 D/t: f(0) > 0, f(min(p_el, p_p)) <= 0
  const auto f = [&](double p) {
    return (p - p_el) * (p * p - p_p * p_p) - p * p_el * p_p * pipe.ovality * D / t;
  };
  double lo = 0.0, hi = std::min(p_el, p_p);
  for (int i = 0; i < 200 && hi - lo > 1e-14 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double dnv_combined_utilisation(const DnvPipe& pipe, const DnvFactors& f, double m_d, double t_ed,
                                double p_ld, double p_e) {
  const double t1 = pipe.wall - pipe.fabrication - pipe.corrosion;
  const double t2 = pipe.wall - pipe.corrosion;
  const double Mk = dnv_plastic_moment(pipe, p_ld, p_e);
  const double Tk = dnv_plastic_tension(pipe, p_ld, p_e);
  const double g = f.gamma_SC * f.gamma_m;
  const double tension = t_ed / Tk;
  if (p_ld >= p_e) {  // net internal overpressure
    const double q = (p_ld - p_e) / dnv_burst_pressure(pipe, t1);
    return g * (std::abs(m_d) / Mk * std::sqrt(std::max(0.0, 1.0 - q * q)) + tension * tension) +
           q * q;
  }
  // net external overpressure
  const double bend = std::abs(m_d) / Mk + tension * tension;
  const double pc = g * (p_e - p_ld) / dnv_collapse_pressure(pipe, t2);
  return g * g * bend * bend + pc * pc;
}

double api_rp_2rd_utilisation(double von_mises, double smys, double c_f) {
  return von_mises / (c_f * 2.0 / 3.0 * smys);  // API RP 2RD section 4.2: sigma_a = 2/3 SMYS
}

}  // namespace seaflex::post
