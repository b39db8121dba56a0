// Cost of one ANCF cable element's elastic force evaluation for each axial (exact, L1,
// L2) and bending (exact, T1, T2) model of CableElasticity, with the tangent stiffness
// (K non-null, "force_and_tangent") and without it (K = nullptr, "force"). Element:
// 1 m, EA = 2.1e9 N, EI = 1.75e6 N m^2, 5 Gauss points (the default), straight along x
// with a deterministic perturbation of about 1e-3 in every coordinate, so that strain
// and curvature are non-zero.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "seaflex/elements/ancf_cable.hpp"
#include "seaflex/elements/ancf_cable_elastic.hpp"

namespace {

using seaflex::Vec3;
using seaflex::ancf_cable::AxialModel;
using seaflex::ancf_cable::BendingModel;
using seaflex::ancf_cable::CableElasticity;
using seaflex::ancf_cable::Mat12;
using seaflex::ancf_cable::Vec12;

constexpr double kLength = 1.0;  // m
constexpr double kEA = 2.1e9;    // N
constexpr double kEI = 1.75e6;   // N m^2

Vec12 deformed_element() {
  Vec12 e = seaflex::ancf_cable::straight(Vec3::Zero(), Vec3::UnitX(), kLength);
  for (int i = 0; i < 12; ++i) e[i] += 1e-3 * std::sin(1.0 + 0.7 * i);
  return e;
}

using Kernel = double (CableElasticity::*)(const Vec12&, Vec12&, Mat12*) const;

void BM_Elastic(benchmark::State& st, Kernel kernel, bool with_tangent) {
  // The models chosen here only matter to add_forces; every add_* member can be called.
  const CableElasticity el(kLength, kEA, kEI, AxialModel::kExact, BendingModel::kExact);
  Vec12 e = deformed_element();
  Vec12 Q;
  Mat12 K;
  Mat12* K_ptr = with_tangent ? &K : nullptr;
  for (auto _ : st) {
    Q.setZero();
    if (K_ptr) K.setZero();
    benchmark::DoNotOptimize(e.data());
    double U = (el.*kernel)(e, Q, K_ptr);
    benchmark::DoNotOptimize(U);
    benchmark::DoNotOptimize(Q.data());
    benchmark::DoNotOptimize(K.data());
    benchmark::ClobberMemory();
  }
}

struct ElasticCase {
  const char* label;
  Kernel kernel;
};

const bool kRegistered = [] {
  const ElasticCase cases[] = {
      {"axial_exact", &CableElasticity::add_axial_exact},
      {"axial_L1", &CableElasticity::add_axial_l1},
      {"axial_L2", &CableElasticity::add_axial_l2},
      {"bending_exact", &CableElasticity::add_bending_exact},
      {"bending_T1", &CableElasticity::add_bending_t1},
      {"bending_T2", &CableElasticity::add_bending_t2},
  };
  for (const ElasticCase& c : cases) {
    const std::string base = std::string("BM_Elastic/") + c.label;
    benchmark::RegisterBenchmark((base + "/force").c_str(), BM_Elastic, c.kernel, false);
    benchmark::RegisterBenchmark((base + "/force_and_tangent").c_str(), BM_Elastic, c.kernel, true);
  }
  return true;
}();

}  // namespace
