// KktSolver with each backend (SparseLU, KLU, UMFPACK): a hand-made KKT system with a
// known solution, the Newton KKT matrices of examples/cantilever.yaml and
// examples/riser_in_current.yaml (unsymmetric: Morison drag), refactorization with new
// values on the same pattern, singular matrices, statics with each backend, and the
// backend names.
// The residual is measured as the normwise backward error
//   |A x - b|_inf / (|A|_inf |x|_inf + |b|_inf),
// which a backward-stable LU keeps near machine epsilon whatever the conditioning; the
// KKT matrices mix stiffness of order 1e7 with constraint entries of order 1.
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "seaflex/io/model_loader.hpp"
#include "seaflex/solvers/kkt_solver.hpp"
#include "seaflex/solvers/statics.hpp"

using namespace seaflex;

namespace {

constexpr std::array<LinearSolverKind, 3> kKinds{
    LinearSolverKind::kSparseLU, LinearSolverKind::kKlu, LinearSolverKind::kUmfpack};

double inf_norm(const SpMat& A) {
  VecX row_sums = VecX::Zero(A.rows());
  for (int k = 0; k < A.outerSize(); ++k) {
    for (SpMat::InnerIterator it(A, k); it; ++it) row_sums[it.row()] += std::abs(it.value());
  }
  return row_sums.maxCoeff();
}

double backward_error(const SpMat& A, const VecX& x, const VecX& b) {
  const VecX r = A * x - b;
  return r.lpNorm<Eigen::Infinity>() /
         (inf_norm(A) * x.lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>());
}

SpMat from_dense(const MatX& D) {
  SpMat A = D.sparseView();
  A.makeCompressed();
  return A;
}

// Two point masses (2 kg, 3 kg) on x, a spring k = 5 N/m between them and a third
// coordinate z (mass 1 kg), with one constraint x0 + z = 0: H = M + K, C_q = [1 0 1].
MatX small_kkt() {
  MatX A = MatX::Zero(4, 4);
  A.topLeftCorner(3, 3) << 2.0 + 5.0, -5.0, 0.0,  //
      -5.0, 3.0 + 5.0, 0.0,                       //
      0.0, 0.0, 1.0;
  A(3, 0) = A(0, 3) = 1.0;
  A(3, 2) = A(2, 3) = 1.0;
  return A;
}

// how each backend's messages begin
std::string label(LinearSolverKind kind) {
  switch (kind) {
    case LinearSolverKind::kSparseLU:
      return "SparseLU: ";
    case LinearSolverKind::kKlu:
      return "KLU: ";
    case LinearSolverKind::kUmfpack:
      return "UMFPACK: ";
  }
  return "";
}

struct KktSystem {
  SpMat A;
  VecX b;
};

// The scaled Newton KKT matrix of a model file at its initial state (a slightly bent one
// when bend is set) and the right-hand side [Q; -C].
KktSystem model_kkt(const std::string& file, double kq, double kv, double bend = 0.0) {
  const io::Model model = io::load_model_file(std::string(SEAFLEX_SOURCE_DIR) + "/" + file);
  const System& system = *model.system;
  State state = system.initial_state();
  for (Index i = 0; i < state.q.size(); ++i) state.q[i] += bend * std::sin(0.7 * i);
  state.v.setConstant(0.1);
  DaeEval eval = system.make_eval();
  DaeRequest request;
  request.matrix = true;
  request.scales = {1.0, kq, kv};
  system.evaluate(state, request, eval);
  KktSystem kkt{eval.kkt.matrix(), VecX::Zero(eval.kkt.matrix().rows())};
  kkt.b.head(system.num_coordinates()) = eval.Q;
  kkt.b.tail(system.num_constraints()) = -eval.C;
  return kkt;
}

TEST(KktSolver, DefaultIsKlu) {
  const KktSolver solver;
  EXPECT_EQ(solver.kind(), LinearSolverKind::kKlu);
  EXPECT_FALSE(solver.factorized());
  EXPECT_EQ(solver.factorizations(), 0);
}

TEST(KktSolver, SmallSystemHasItsExactSolution) {
  const SpMat A = from_dense(small_kkt());
  const VecX x_exact = (VecX(4) << 0.5, -1.0, -0.5, 2.0).finished();
  const VecX b = small_kkt() * x_exact;  // [1.5, -10.5, 1.5, 0]
  for (const LinearSolverKind kind : kKinds) {
    SCOPED_TRACE(std::string(KktSolver::to_string(kind)));
    KktSolver solver(kind);
    ASSERT_TRUE(solver.factorize(A)) << solver.message();
    EXPECT_TRUE(solver.message().empty());
    EXPECT_EQ(solver.factorizations(), 1);
    VecX x;
    solver.solve(b, x);
    ASSERT_EQ(x.size(), 4);
    EXPECT_LT((x - x_exact).lpNorm<Eigen::Infinity>(), 1e-14);
    EXPECT_LT(backward_error(A, x, b), 1e-15);
  }
}

// Newton matrices (km = 1, kq = 1e-4, kv = 1e-2): the cantilever's H is symmetric, the
// riser's is not (Morison drag gives an unsymmetric dQ/dv). All backends agree to 1e-10
// relative.
class KktModelTest : public ::testing::TestWithParam<const char*> {};

TEST_P(KktModelTest, BackendsSolveAndAgree) {
  const KktSystem kkt = model_kkt(GetParam(), 1e-4, 1e-2);
  ASSERT_GT(kkt.A.rows(), 60);
  VecX reference;
  for (const LinearSolverKind kind : kKinds) {
    SCOPED_TRACE(std::string(KktSolver::to_string(kind)));
    KktSolver solver(kind);
    ASSERT_TRUE(solver.factorize(kkt.A)) << solver.message();
    VecX x;
    solver.solve(kkt.b, x);
    EXPECT_LT(backward_error(kkt.A, x, kkt.b), 1e-12);
    if (reference.size() == 0) {
      reference = x;
    } else {
      EXPECT_LT((x - reference).norm() / reference.norm(), 1e-10);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Examples, KktModelTest,
                         ::testing::Values("examples/cantilever.yaml",
                                           "examples/riser_in_current.yaml"));

TEST(KktSolver, RiserMatrixIsUnsymmetric) {
  const KktSystem kkt = model_kkt("examples/riser_in_current.yaml", 1e-4, 1e-2);
  const SpMat At = kkt.A.transpose();
  // |A - A^T| is about 10 (kv times the drag coefficients) against |A| = 1e8 (kq times
  // EA/l): small, but eight orders above round-off, so H is genuinely unsymmetric
  EXPECT_GT((kkt.A - At).norm(), 1e-9 * kkt.A.norm());
  EXPECT_GT((kkt.A - At).norm(), 1.0);
}

// The same pattern with new values (another state and other scales) is factored again
// without a new analysis and solved as accurately.
TEST(KktSolver, RefactorizesWithNewValues) {
  const KktSystem first = model_kkt("examples/riser_in_current.yaml", 1e-4, 1e-2);
  const KktSystem second = model_kkt("examples/riser_in_current.yaml", 1e-3, 1e-1, 1e-3);
  ASSERT_EQ(first.A.nonZeros(), second.A.nonZeros());
  ASSERT_GT((first.A - second.A).norm(), 1e-3 * first.A.norm());
  for (const LinearSolverKind kind : kKinds) {
    SCOPED_TRACE(std::string(KktSolver::to_string(kind)));
    KktSolver solver(kind);
    solver.set_reuse_pivots(true);
    VecX x1, x2;
    ASSERT_TRUE(solver.factorize(first.A)) << solver.message();
    solver.solve(first.b, x1);
    ASSERT_TRUE(solver.factorize(second.A)) << solver.message();
    solver.solve(second.b, x2);
    EXPECT_EQ(solver.factorizations(), 2);
    // KLU: the second reuses the first's pivot order (klu_refactor)
    EXPECT_EQ(solver.reused_pivots(), kind == LinearSolverKind::kKlu ? 1 : 0);
    EXPECT_LT(backward_error(first.A, x1, first.b), 1e-12);
    EXPECT_LT(backward_error(second.A, x2, second.b), 1e-12);
    EXPECT_GT((x2 - x1).norm(), 1e-6 * x1.norm());
  }
}

// KLU's solves run on its factors copied by rows without their exact zeros, block by block
// (kkt_solver.cpp, KluBackend). The storm's Newton matrix has 5 BTF blocks (the hull, the
// ring and the tensioner's rows apart from the riser) with entries above them, and the riser
// bends in one plane, so the matrix stores exact zeros (its out-of-plane couplings) that the
// factors keep. Its solution agrees with SparseLU's and UMFPACK's; then, through
// klu_refactor, a planar matrix with other values (the rows kept, new values gathered into
// them) and a matrix of the same pattern bent out of the plane (the dropped zeros now
// nonzero: the rows built again), the same.
TEST(KktSolver, KluSolvesByBlocksWithoutTheFactorsZeros) {
  const KktSystem planar = model_kkt("bench/storm/storm_n100.yaml", 1e-4, 1e-2);
  const KktSystem planar2 = model_kkt("bench/storm/storm_n100.yaml", 2e-4, 3e-2);
  const KktSystem bent = model_kkt("bench/storm/storm_n100.yaml", 1e-4, 1e-2, 1e-3);
  ASSERT_GT((planar2.A - planar.A).norm(), 1e-3 * planar.A.norm());
  ASSERT_EQ(planar.A.nonZeros(), bent.A.nonZeros());
  Index zeros_planar = 0, zeros_bent = 0;
  for (Index e = 0; e < planar.A.nonZeros(); ++e) {
    zeros_planar += planar.A.valuePtr()[e] == 0.0;
    zeros_bent += bent.A.valuePtr()[e] == 0.0;
  }
  EXPECT_GT(zeros_planar, planar.A.nonZeros() / 10);  // stored exact zeros
  EXPECT_LT(zeros_bent, zeros_planar / 2);
  std::array<VecX, 3> reference;
  for (const LinearSolverKind kind : kKinds) {
    SCOPED_TRACE(std::string(KktSolver::to_string(kind)));
    KktSolver solver(kind);
    solver.set_reuse_pivots(true);
    int k = 0;
    for (const KktSystem* kkt : {&planar, &planar2, &bent}) {
      SCOPED_TRACE(k);
      VecX x;
      ASSERT_TRUE(solver.factorize(kkt->A)) << solver.message();
      solver.solve(kkt->b, x);
      EXPECT_LT(backward_error(kkt->A, x, kkt->b), 1e-12);
      if (reference[k].size() == 0) reference[k] = x;
      EXPECT_LT((x - reference[k]).norm() / reference[k].norm(), 1e-10);
      ++k;
    }
    EXPECT_EQ(solver.reused_pivots(), kind == LinearSolverKind::kKlu ? 2 : 0);
  }
}

// KLU reuses a pivot order only while it stays sound: on the same pattern, values that make
// the old pivot tiny (1e-14 against 1 in its column) are pivoted again, and a pattern of the
// same size and number of entries but other positions is factored afresh; both are solved to
// round-off. Without the checks, the reused (diagonal) order would give an error of 8e-4 in x
// here (elimination without pivoting in numpy: the pivot 1e-14 amplifies round-off).
TEST(KktSolver, KluPivotsAgainWhenTheOldOrderFails) {
  KktSolver solver(LinearSolverKind::kKlu);
  solver.set_reuse_pivots(true);
  MatX A = MatX::Zero(3, 3);
  A << 1.0, 1.0, 0.0,        //
      1.0, 1.0 + 1e-3, 2.0,  //
      0.0, 2.0, 1.0;
  const VecX x_exact = (VecX(3) << 1.0, -2.0, 3.0).finished();
  VecX x;
  ASSERT_TRUE(solver.factorize(from_dense(A))) << solver.message();
  solver.solve(A * x_exact, x);
  EXPECT_LT((x - x_exact).lpNorm<Eigen::Infinity>(), 1e-11);
  // new values, sound pivots: reused
  MatX B = A;
  B(0, 0) = 1.5;
  ASSERT_TRUE(solver.factorize(from_dense(B))) << solver.message();
  solver.solve(B * x_exact, x);
  EXPECT_LT((x - x_exact).lpNorm<Eigen::Infinity>(), 1e-11);
  EXPECT_EQ(solver.reused_pivots(), 1);
  // the first pivot 1e-14: pivoted again
  MatX C = A;
  C(0, 0) = 1e-14;
  ASSERT_TRUE(solver.factorize(from_dense(C))) << solver.message();
  solver.solve(C * x_exact, x);
  EXPECT_LT((x - x_exact).lpNorm<Eigen::Infinity>(), 1e-11);
  EXPECT_EQ(solver.reused_pivots(), 1);
  EXPECT_EQ(solver.factorizations(), 3);
  // same size and number of entries, other positions
  MatX D = MatX::Zero(3, 3);
  D << 2.0, 0.0, 1.0,  //
      1.0, 3.0, 0.5,   //
      0.0, 1.0, 4.0;
  SpMat Ds = from_dense(D);
  ASSERT_EQ(Ds.nonZeros(), from_dense(C).nonZeros());
  ASSERT_TRUE(solver.factorize(Ds)) << solver.message();
  solver.solve(D * x_exact, x);
  EXPECT_LT((x - x_exact).lpNorm<Eigen::Infinity>(), 1e-13);
  EXPECT_EQ(solver.reused_pivots(), 1);
  // a matrix in uncompressed storage is read through a compressed copy: the same solution
  Ds.uncompress();
  ASSERT_FALSE(Ds.isCompressed());
  KktSolver fresh(LinearSolverKind::kKlu);
  ASSERT_TRUE(fresh.factorize(Ds)) << fresh.message();
  fresh.solve(D * x_exact, x);
  EXPECT_LT((x - x_exact).lpNorm<Eigen::Infinity>(), 1e-13);
}

// A new pattern (here: another size) is analyzed again.
TEST(KktSolver, NewPatternIsAnalyzedAgain) {
  const KktSystem riser = model_kkt("examples/riser_in_current.yaml", 1e-4, 1e-2);
  const SpMat small = from_dense(small_kkt());
  const VecX x_exact = (VecX(4) << 0.5, -1.0, -0.5, 2.0).finished();
  for (const LinearSolverKind kind : kKinds) {
    SCOPED_TRACE(std::string(KktSolver::to_string(kind)));
    KktSolver solver(kind);
    VecX x;
    ASSERT_TRUE(solver.factorize(riser.A)) << solver.message();
    ASSERT_TRUE(solver.factorize(small)) << solver.message();
    solver.solve(small_kkt() * x_exact, x);
    EXPECT_LT((x - x_exact).lpNorm<Eigen::Infinity>(), 1e-14);
  }
}

// A new pattern of the same size and number of entries is analyzed again too: an upper
// bidiagonal matrix (block triangular: three 1 x 1 blocks to KLU) and then a lower one, whose
// entries below the diagonal the first analysis would leave outside its blocks.
TEST(KktSolver, SameSizeOtherPositionsIsAnalyzedAgain) {
  MatX U = MatX::Zero(3, 3), L = MatX::Zero(3, 3);
  U << 2.0, 1.0, 0.0,  //
      0.0, 3.0, 1.0,   //
      0.0, 0.0, 4.0;
  L << 2.0, 0.0, 0.0,  //
      1.0, 3.0, 0.0,   //
      0.0, 1.0, 4.0;
  const SpMat Us = from_dense(U), Ls = from_dense(L);
  ASSERT_EQ(Us.nonZeros(), Ls.nonZeros());
  const VecX x_exact = (VecX(3) << 1.0, -2.0, 3.0).finished();
  for (const LinearSolverKind kind : kKinds) {
    SCOPED_TRACE(std::string(KktSolver::to_string(kind)));
    for (const bool reuse : {false, true}) {
      KktSolver solver(kind);
      solver.set_reuse_pivots(reuse);
      VecX x;
      ASSERT_TRUE(solver.factorize(Us)) << solver.message();
      solver.solve(U * x_exact, x);
      EXPECT_LT((x - x_exact).lpNorm<Eigen::Infinity>(), 1e-14);
      ASSERT_TRUE(solver.factorize(Ls)) << solver.message();
      solver.solve(L * x_exact, x);
      EXPECT_LT((x - x_exact).lpNorm<Eigen::Infinity>(), 1e-14);
    }
  }
}

// Redundant constraints (two equal rows of C_q) and a coordinate without mass or
// stiffness (an empty column): factorize returns false with a message, and the solver
// recovers on a regular matrix of the same pattern.
TEST(KktSolver, SingularMatrixIsReported) {
  MatX redundant = MatX::Zero(4, 4);
  redundant.topLeftCorner(2, 2) << 2.0, 0.0, 0.0, 3.0;
  redundant(2, 0) = redundant(0, 2) = 1.0;
  redundant(3, 0) = redundant(0, 3) = 1.0;
  MatX massless = small_kkt();
  massless.row(1).setZero();
  massless.col(1).setZero();
  for (const MatX& dense : {redundant, massless}) {
    for (const LinearSolverKind kind : kKinds) {
      SCOPED_TRACE(std::string(KktSolver::to_string(kind)));
      KktSolver solver(kind);
      EXPECT_FALSE(solver.factorize(from_dense(dense)));
      EXPECT_FALSE(solver.factorized());
      EXPECT_FALSE(solver.message().empty());
      EXPECT_EQ(solver.message().rfind(label(kind), 0), 0u) << solver.message();
    }
  }
  // recovery: the redundant pattern with a regularized value in the constraint block
  MatX regular = redundant;
  regular(3, 3) = -1.0;
  for (const LinearSolverKind kind : kKinds) {
    SCOPED_TRACE(std::string(KktSolver::to_string(kind)));
    KktSolver solver(kind);
    SpMat A = from_dense(regular);
    SpMat S = A;
    S.coeffRef(3, 3) = 0.0;  // same stored pattern, singular values
    EXPECT_FALSE(solver.factorize(S));
    EXPECT_FALSE(solver.message().empty());
    ASSERT_TRUE(solver.factorize(A)) << solver.message();
    EXPECT_TRUE(solver.message().empty());
    const VecX x_exact = (VecX(4) << 1.0, 2.0, 3.0, 4.0).finished();
    VecX x;
    solver.solve(regular * x_exact, x);
    EXPECT_LT((x - x_exact).lpNorm<Eigen::Infinity>(), 1e-13);
  }
}

// StaticsSettings::linear_solver: Newton statics of the cantilever (tip deflection 0.5490 m,
// docs/verification.md) gives the same equilibrium with every backend.
TEST(KktSolver, StaticsAgreesAcrossBackends) {
  const io::Model model =
      io::load_model_file(std::string(SEAFLEX_SOURCE_DIR) + "/examples/cantilever.yaml");
  EXPECT_EQ(model.statics.linear_solver, kDefaultLinearSolver);
  VecX reference;
  for (const LinearSolverKind kind : kKinds) {
    SCOPED_TRACE(std::string(KktSolver::to_string(kind)));
    StaticsSettings settings = model.statics;
    settings.linear_solver = kind;
    State state = model.system->initial_state();
    const StaticsReport report = solve_statics(*model.system, state, settings);
    EXPECT_LT(report.residual, 1e-8);
    EXPECT_NEAR(state.q[6 * 10 + 2], -0.5490, 1e-4);  // tip z, 10 elements
    if (reference.size() == 0) {
      reference = state.q;
    } else {
      EXPECT_LT((state.q - reference).lpNorm<Eigen::Infinity>(), 1e-10);
    }
  }
}

TEST(KktSolver, NamesRoundTrip) {
  for (const LinearSolverKind kind : kKinds) {
    const std::optional<LinearSolverKind> parsed = KktSolver::parse(KktSolver::to_string(kind));
    ASSERT_TRUE(parsed.has_value());
    EXPECT_EQ(*parsed, kind);
    EXPECT_EQ(KktSolver(kind).kind(), kind);
  }
  EXPECT_EQ(KktSolver::to_string(LinearSolverKind::kSparseLU), "sparselu");
  EXPECT_EQ(KktSolver::to_string(LinearSolverKind::kKlu), "klu");
  EXPECT_EQ(KktSolver::to_string(LinearSolverKind::kUmfpack), "umfpack");
  EXPECT_EQ(KktSolver::names(), "sparselu, klu, umfpack");
  EXPECT_FALSE(KktSolver::parse("cholmod").has_value());
  EXPECT_FALSE(KktSolver::parse("KLU").has_value());
  EXPECT_FALSE(KktSolver::parse("").has_value());
}

}  // namespace
