#include "seaflex/math/sparse_block_assembler.hpp"

#include <gtest/gtest.h>

#include <tuple>

using namespace seaflex;

namespace {
// a 5 x 5 pattern: two overlapping 3 x 3 blocks (rows 0-2, 2-4), a 1 x 2 block at (4; 0, 1)
// and its mirror at (0, 1; 4)
struct FourBlocks {
  math::SparseBlockAssembler a{5, 5};
  math::BlockId b1, b2, b3, b3t;
  FourBlocks() {
    const std::vector<Index> d1{0, 1, 2}, d2{2, 3, 4}, rows{4}, cols{0, 1};
    b1 = a.declare_block(d1, d1);
    b2 = a.declare_block(d2, d2);
    b3 = a.declare_block(rows, cols);
    b3t = a.declare_block(cols, rows);
    a.finalize();
  }
};
}  // namespace

// two overlapping blocks assemble to the same matrix as a dense reference
TEST(SparseBlockAssembler, OverlappingBlocksSum) {
  FourBlocks f;
  auto& a = f.a;
  const auto [b1, b2, b3, b3t] = std::tuple{f.b1, f.b2, f.b3, f.b3t};
  MatX m1 = MatX::Random(3, 3), m2 = MatX::Random(3, 3), m3 = MatX::Random(1, 2);
  a.set_zero();
  a.add(b1, m1);
  a.add(b2, m2, 2.0);
  a.add(b3, m3);
  a.add_transposed(b3t, m3);
  MatX ref = MatX::Zero(5, 5);
  ref.block(0, 0, 3, 3) += m1;
  ref.block(2, 2, 3, 3) += 2.0 * m2;
  ref.block(4, 0, 1, 2) += m3;
  ref.block(0, 4, 2, 1) += m3.transpose();
  EXPECT_LT((MatX(a.matrix()) - ref).norm(), 1e-15);
  // set_zero keeps the pattern and clears values
  a.set_zero();
  EXPECT_EQ(MatX(a.matrix()).norm(), 0.0);
  EXPECT_EQ(a.matrix().nonZeros(), 9 + 9 - 1 + 2 + 2);
}

TEST(SparseBlockAssembler, RejectsOutOfRangeAndLateDeclarations) {
  math::SparseBlockAssembler a(2, 2);
  const std::vector<Index> bad{2};
  EXPECT_THROW(a.declare_block(bad, bad), std::out_of_range);
  a.finalize();
  const std::vector<Index> ok{0};
  EXPECT_THROW(a.declare_block(ok, ok), std::logic_error);
}

// product mode: the same add() calls give (sum of the blocks) x without touching the
// matrix; checked against the assembled matrix times x (round-off: 1e-14 of |A||x|)
TEST(SparseBlockAssembler, ProductModeEqualsTheAssembledMatrixTimesAVector) {
  FourBlocks f;
  auto& a = f.a;
  const auto [b1, b2, b3, b3t] = std::tuple{f.b1, f.b2, f.b3, f.b3t};
  const MatX m1 = MatX::Random(3, 3), m2 = MatX::Random(3, 3), m3 = MatX::Random(1, 2);
  auto add_all = [&] {
    a.add(b1, m1);
    a.add(b2, m2, 2.0);
    a.add(b3, m3, -0.5);
    a.add_transposed(b3t, m3, 3.0);
  };
  a.set_zero();
  add_all();
  const MatX assembled = MatX(a.matrix());
  const VecX x = VecX::Random(5);
  VecX y = VecX::Zero(5);
  a.begin_product(x, y);
  EXPECT_TRUE(a.in_product());
  add_all();
  a.end_product();
  EXPECT_FALSE(a.in_product());
  const VecX ref = assembled * x;
  EXPECT_LT((y - ref).norm(), 1e-14 * assembled.norm() * x.norm());
  EXPECT_GT(ref.norm(), 0.1);
  // the matrix was left as it was
  EXPECT_EQ((MatX(a.matrix()) - assembled).norm(), 0.0);
  VecX wrong = VecX::Zero(4);
  EXPECT_THROW(a.begin_product(x, wrong), std::invalid_argument);
}
