// Convergence of the simply supported plate of thesis 3.1.2 for every force model, on
// 2 x 2 to 16 x 16 meshes: the tables of docs/verification.md. Label `slow` (about a
// minute in release); run with  ctest --test-dir build -L slow --verbose
#include <gtest/gtest.h>

#include <cstdio>

#include "plate_models.hpp"

using namespace seaflex;
using namespace seaflex::plate_models;

namespace {
constexpr int kMeshes[] = {2, 4, 8, 16};
}

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
