// math::row_sums and row_sums_pair against a plain long double sum (an independent order and
// precision): every row count of a group of four and its remainder, lengths that are and are
// not multiples of four, and an empty sum.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "seaflex/math/row_sums.hpp"

namespace {

// sum_i a_r,i x_i in long double, and the bound of a double sum's round-off: n eps sum |a x|
// (Higham, "Accuracy and Stability of Numerical Algorithms", 2002, eq. (3.5): |error| <=
// gamma_n sum |a_i x_i| for any order of summation; with FMA the bound holds as well)
struct Reference {
  double value, bound;
};
Reference reference(const double* a, const double* x, std::size_t n) {
  long double s = 0.0L, m = 0.0L;
  for (std::size_t i = 0; i < n; ++i) {
    s += static_cast<long double>(a[i]) * x[i];
    m += std::abs(static_cast<long double>(a[i]) * x[i]);
  }
  const double eps = std::numeric_limits<double>::epsilon();
  return {static_cast<double>(s), static_cast<double>(n + 1) * eps * static_cast<double>(m)};
}

TEST(RowSums, EqualTheSumsToRoundOffForAnyRowCountAndLength) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const std::size_t rows : {1u, 2u, 3u, 4u, 5u, 7u, 18u})
    for (const std::size_t n : {0u, 1u, 3u, 4u, 5u, 8u, 37u, 400u}) {
      const std::size_t stride = n + 3;  // rows need not be packed
      std::vector<double> a(rows * stride), x(n), out(rows, -99.0);
      for (double& v : a) v = u(gen);
      for (double& v : x) v = u(gen);
      seaflex::math::row_sums(a.data(), stride, rows, x.data(), n, out.data());
      for (std::size_t r = 0; r < rows; ++r) {
        const Reference ref = reference(a.data() + r * stride, x.data(), n);
        EXPECT_NEAR(out[r], ref.value, ref.bound) << "rows " << rows << " n " << n << " r " << r;
      }
    }
}

TEST(RowSums, PairEqualsTwoSumsAndTakesOneToFourRows) {
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int rows = 1; rows <= 4; ++rows)
    for (const std::size_t n : {0u, 2u, 4u, 9u, 200u}) {
      const std::size_t stride = n + 1;
      std::vector<double> a(static_cast<std::size_t>(rows) * stride), x0(n), x1(n);
      std::vector<double> out0(4, -99.0), out1(4, -99.0);
      for (double& v : a) v = u(gen);
      for (double& v : x0) v = u(gen);
      for (double& v : x1) v = u(gen);
      seaflex::math::row_sums_pair(a.data(), stride, rows, x0.data(), x1.data(), n, out0.data(),
                                   out1.data());
      for (int r = 0; r < rows; ++r) {
        const double* row = a.data() + static_cast<std::size_t>(r) * stride;
        const Reference r0 = reference(row, x0.data(), n), r1 = reference(row, x1.data(), n);
        EXPECT_NEAR(out0[static_cast<std::size_t>(r)], r0.value, r0.bound);
        EXPECT_NEAR(out1[static_cast<std::size_t>(r)], r1.value, r1.bound);
      }
      for (int r = rows; r < 4; ++r) {  // the rows beyond are not written
        EXPECT_EQ(out0[static_cast<std::size_t>(r)], -99.0);
        EXPECT_EQ(out1[static_cast<std::size_t>(r)], -99.0);
      }
    }
  double v = 0.0;
  EXPECT_THROW(seaflex::math::row_sums_pair(&v, 1, 0, &v, &v, 1, &v, &v), std::invalid_argument);
  EXPECT_THROW(seaflex::math::row_sums_pair(&v, 1, 5, &v, &v, 1, &v, &v), std::invalid_argument);
}

}  // namespace
