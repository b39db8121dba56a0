// Displaced volume and centre of buoyancy of hull pieces below z = 0 against closed forms
// (hydro/displaced_volume.hpp), and the hull's restoring moment against the wall-sided
// formula GZ = sin(phi) (GM + BM tan^2(phi) / 2) (e.g. Biran, Ship Hydrostatics and
// Stability, 2003, sec. 6.4).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "seaflex/elements/rigid_body.hpp"
#include "seaflex/forces/hull_hydrostatics.hpp"
#include "seaflex/hydro/displaced_volume.hpp"
#include "seaflex/math/rotation.hpp"
#include "seaflex/system/system.hpp"

using namespace seaflex;
using hydro::ConvexPolyhedron;

namespace {
constexpr double kPi = std::numbers::pi;

TEST(HullHydrostatics, BoxVolumeAndCentroidUpright) {
  // a 110 x 46 x 7.5 m box with its centre 0.3 m above the surface: draft 3.45 m.
  // Exact by construction (a polyhedron integrated exactly): 1e-12 relative round-off.
  const auto box = ConvexPolyhedron::box(Vec3::Zero(), Vec3(110, 46, 7.5), Mat3::Identity());
  EXPECT_NEAR(box.volume(), 110 * 46 * 7.5, 1e-12 * 110 * 46 * 7.5);
  const auto d = hydro::submerged_part(box, Vec3(5, -2, 0.3), Mat3::Identity());
  const double draft = 3.75 - 0.3;
  EXPECT_NEAR(d.volume, 110 * 46 * draft, 1e-9);
  EXPECT_NEAR(d.centroid.x(), 5.0, 1e-9);
  EXPECT_NEAR(d.centroid.y(), -2.0, 1e-9);
  EXPECT_NEAR(d.centroid.z(), -draft / 2, 1e-9);
  EXPECT_NEAR(d.waterplane_area, 110 * 46, 1e-8);
  // wholly dry and wholly wet
  EXPECT_EQ(hydro::submerged_part(box, Vec3(0, 0, 10), Mat3::Identity()).volume, 0.0);
  const auto wet = hydro::submerged_part(box, Vec3(1, 2, -10), Mat3::Identity());
  EXPECT_NEAR(wet.volume, 110 * 46 * 7.5, 1e-8);
  EXPECT_NEAR((wet.centroid - Vec3(1, 2, -10)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(wet.waterplane_area, 0.0, 1e-9);
}

TEST(HullHydrostatics, HeeledBoxFollowsWallSidedFormula) {
  // box B = 46, T = 3.75 (draft), heeled by phi about the x axis through the waterline
  // centre; as long as deck and bottom stay out of / under water the displaced volume is
  // unchanged and the centre of buoyancy moves to the immersed side (-y for a positive
  // roll, which lifts +y), y = -(B^2 / (12 T)) tan(phi),
  // z = -T/2 + (B^2 / (24 T)) tan^2(phi) in heeled axes. Exact (polyhedra): 1e-9.
  const double B = 46, T = 3.75, H = 10.0;
  const auto box = ConvexPolyhedron::box(Vec3(0, 0, H / 2 - T), Vec3(110, B, H), Mat3::Identity());
  for (double deg : {2.0, 5.0, 8.0}) {
    const double phi = deg * kPi / 180;
    const Mat3 R = math::rotation_from_roll_pitch_yaw(phi, 0, 0);
    const auto d = hydro::submerged_part(box, Vec3::Zero(), R);
    EXPECT_NEAR(d.volume, 110 * B * T, 1e-8 * 110 * B * T) << deg;
    const Vec3 b_body = R.transpose() * d.centroid;
    const double t = std::tan(phi);
    EXPECT_NEAR(b_body.y(), -B * B / (12 * T) * t, 1e-9) << deg;
    EXPECT_NEAR(b_body.z(), -T / 2 + B * B / (24 * T) * t * t, 1e-9) << deg;
  }
}

TEST(HullHydrostatics, CylinderVolumesAndWaterplane) {
  const double D = 10, L = 20;
  // upright, half its length under water: pi R^2 L/2 exactly (area-matched polygon)
  const auto col = ConvexPolyhedron::cylinder(Vec3(0, 0, -L / 2), Vec3(0, 0, L / 2), D);
  const auto up = hydro::submerged_part(col, Vec3::Zero(), Mat3::Identity());
  EXPECT_NEAR(up.volume, kPi * 25 * L / 2, 1e-9 * kPi * 25 * L);
  EXPECT_NEAR(up.waterplane_area, kPi * 25, 1e-9);
  EXPECT_NEAR(up.centroid.z(), -L / 4, 1e-9);
  // horizontal with its axis on the surface: half the volume (the polygon has an even
  // number of sides and the cut runs through two opposite vertices or edges)
  const auto pont = ConvexPolyhedron::cylinder(Vec3(-L / 2, 0, 0), Vec3(L / 2, 0, 0), D);
  const auto half = hydro::submerged_part(pont, Vec3::Zero(), Mat3::Identity());
  EXPECT_NEAR(half.volume, kPi * 25 * L / 2, 1e-9 * kPi * 25 * L);
  // centroid of a half disc at 4R/(3 pi) below the axis: the 64-gon is within 2e-4
  EXPECT_NEAR(half.centroid.z(), -4 * 5 / (3 * kPi), 2e-4 * 5);
}

TEST(HullHydrostatics, RestoringMomentOfHeeledBarge) {
  // the thesis's barge (110 x 46 x 7.5 m, draft 3.75 m), CG at the waterline; the
  // righting moment rho g V GZ with GZ = sin(phi) (GM + BM tan^2(phi)/2), GM = KB + BM - KG.
  // The hull is exact, so the moment agrees to round-off (1e-9 relative).
  const double L = 110, B = 46, T = 3.75, rho = 1025, g = 9.81;
  System sys;
  auto& body = static_cast<RigidBody&>(sys.add_body(std::make_unique<RigidBody>(
      "barge", rho * L * B * T, Mat3::Identity() * 1e9, RigidBodyInitial{})));
  std::vector<ConvexPolyhedron> pieces{
      ConvexPolyhedron::box(Vec3(0, 0, 3.75 - T), Vec3(L, B, 7.5), Mat3::Identity())};
  auto owned = std::make_unique<HullHydrostatics>("hs", body, pieces, rho, g);
  const HullHydrostatics& hs = *owned;
  sys.add_force(std::move(owned));
  sys.finalize();
  for (double deg : {1.0, 4.0, 8.0}) {
    const double phi = deg * kPi / 180;
    State s = sys.initial_state();
    s.q.segment<4>(3) =
        math::euler_parameters_from_rotation(math::rotation_from_roll_pitch_yaw(phi, 0, 0));
    const Wrench W = hs.wrench_at(s);
    const double V = L * B * T, BM = B * B / (12 * T), GM = -T / 2 + BM;
    const double GZ = std::sin(phi) * (GM + 0.5 * BM * std::tan(phi) * std::tan(phi));
    EXPECT_NEAR(W.force.z(), rho * g * V, 1e-9 * rho * g * V) << deg;
    EXPECT_NEAR(W.moment.x(), -rho * g * V * GZ, 1e-9 * rho * g * V * GZ) << deg;
    EXPECT_NEAR(W.moment.y(), 0.0, 1e-6 * rho * g * V);
  }
}

}  // namespace
