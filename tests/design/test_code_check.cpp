// Code checks (post/code_check.hpp): DNV-ST-F201 capacities and utilisation against hand
// calculations of the standard's formulas, and API RP 2RD.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "seaflex/post/code_check.hpp"

namespace seaflex::post {
namespace {

// A 10.75" x 0.75" riser pipe (D = 0.27305 m, t = 0.01905 m), X65 (SMYS 448 MPa,
// SMTS 531 MPa), no corrosion or fabrication tolerance: D/t = 14.333 < 15, so
// beta = 0.4 + q_h.
DnvPipe riser() {
  DnvPipe p;
  p.outer_diameter = 0.27305;
  p.wall = 0.01905;
  p.smys = 448e6;
  p.smts = 531e6;
  return p;
}

TEST(DnvF201, CapacitiesByHand) {
  const DnvPipe p = riser();
  const double D = p.outer_diameter, t = p.wall;
  // p_b = 2/sqrt(3) * 2t/(D-t) * min(448, 531/1.15 = 461.7) MPa
  const double pb = 2 / std::sqrt(3.0) * 2 * t / (D - t) * 448e6;
  EXPECT_NEAR(dnv_burst_pressure(p, t), pb, 1e-9 * pb);
  // no net pressure: q_h = 0, beta = 0.4, alpha_c = 0.6 + 0.4 * 531/448
  const double ac = 0.6 + 0.4 * 531.0 / 448.0;
  EXPECT_NEAR(dnv_plastic_moment(p, 0, 0), 448e6 * ac * (D - t) * (D - t) * t, 1e-3);
  EXPECT_NEAR(dnv_plastic_tension(p, 0, 0), 448e6 * ac * std::numbers::pi * (D - t) * t, 1e-3);
  // net internal 20 MPa: q_h = 20e6/pb * 2/sqrt(3), beta = 0.4 + q_h
  const double qh = 20e6 / pb * 2 / std::sqrt(3.0);
  const double ac2 = (1 - (0.4 + qh)) + (0.4 + qh) * 531.0 / 448.0;
  EXPECT_NEAR(dnv_plastic_moment(p, 25e6, 5e6), 448e6 * ac2 * (D - t) * (D - t) * t, 1e-3);
}

TEST(DnvF201, UtilisationInternalAndExternalOverpressure) {
  const DnvPipe p = riser();
  const DnvFactors f;  // 1.1, 1.3, 1.0, 1.14, 1.15
  const double Md = 1.1 * 2e5, Ted = 1.1 * 1.5e6;
  // internal overpressure 10 MPa
  const double Mk = dnv_plastic_moment(p, 15e6, 5e6), Tk = dnv_plastic_tension(p, 15e6, 5e6);
  const double q = 10e6 / dnv_burst_pressure(p, p.wall);
  const double u_int =
      1.14 * 1.15 * (Md / Mk * std::sqrt(1 - q * q) + (Ted / Tk) * (Ted / Tk)) + q * q;
  EXPECT_NEAR(dnv_combined_utilisation(p, f, Md, Ted, 15e6, 5e6), u_int, 1e-12);
  // external overpressure 8 MPa: collapse pressure root of the cubic
  const double pc = dnv_collapse_pressure(p, p.wall);
  const double D = p.outer_diameter, t = p.wall;
  const double pel = 2 * 2.07e11 * std::pow(t / D, 3) / (1 - 0.09), pp = 2 * 448e6 * t / D;
  EXPECT_NEAR((pc - pel) * (pc * pc - pp * pp), pc * pel * pp * 0.005 * D / t,
              1e-9 * pc * pel * pp);
  EXPECT_LT(pc, std::min(pel, pp));
  const double Mk0 = dnv_plastic_moment(p, 0, 8e6), Tk0 = dnv_plastic_tension(p, 0, 8e6);
  const double g = 1.14 * 1.15, b = Md / Mk0 + (Ted / Tk0) * (Ted / Tk0);
  const double u_ext = g * g * b * b + (g * 8e6 / pc) * (g * 8e6 / pc);
  EXPECT_NEAR(dnv_combined_utilisation(p, f, Md, Ted, 0, 8e6), u_ext, 1e-12);
}

TEST(ApiRp2rd, AllowableIsTwoThirdsSmys) {
  EXPECT_NEAR(api_rp_2rd_utilisation(200e6, 448e6, 1.2), 200e6 / (1.2 * 2.0 / 3.0 * 448e6), 1e-15);
}

}  // namespace
}  // namespace seaflex::post
