#include "seaflex/math/row_sums.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>

#include "seaflex/math/vector_clones.hpp"

namespace seaflex::math {

namespace {
// four doubles (GCC's vector extension: two SSE2 registers or one AVX2 register)
using V4 = double __attribute__((vector_size(4 * sizeof(double))));

// rows r0 .. r0+3 (the missing ones repeat the last row; their sums are dropped)
SEAFLEX_VECTOR_CLONES
void four_rows(const double* a, std::size_t stride, std::size_t rows, const double* x,
               std::size_t n, double* out) {
  std::array<const double*, 4> row{};
  for (std::size_t r = 0; r < 4; ++r) row[r] = a + std::min(r, rows - 1) * stride;
  V4 acc[4] = {};
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    V4 xv;
    std::memcpy(&xv, x + i, sizeof xv);
    for (std::size_t r = 0; r < 4; ++r) {
      V4 ar;
      std::memcpy(&ar, row[r] + i, sizeof ar);
      acc[r] += ar * xv;
    }
  }
  for (std::size_t r = 0; r < rows; ++r) {
    double s = (acc[r][0] + acc[r][1]) + (acc[r][2] + acc[r][3]);
    for (std::size_t k = i; k < n; ++k) s += row[r][k] * x[k];
    out[r] = s;
  }
}
}  // namespace

void row_sums(const double* a, std::size_t stride, std::size_t rows, const double* x, std::size_t n,
              double* out) {
  for (std::size_t r0 = 0; r0 < rows; r0 += 4)
    four_rows(a + r0 * stride, stride, std::min<std::size_t>(4, rows - r0), x, n, out + r0);
}

SEAFLEX_VECTOR_CLONES
void row_sums_pair(const double* a, std::size_t stride, int rows, const double* x0,
                   const double* x1, std::size_t n, double* out0, double* out1) {
  if (rows < 1 || rows > 4) throw std::invalid_argument("row_sums_pair: 1 to 4 rows");
  std::array<const double*, 4> row{};
  for (int r = 0; r < 4; ++r) row[r] = a + static_cast<std::size_t>(std::min(r, rows - 1)) * stride;
  V4 a0[4] = {}, a1[4] = {};
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    V4 v0, v1;
    std::memcpy(&v0, x0 + i, sizeof v0);
    std::memcpy(&v1, x1 + i, sizeof v1);
    for (int r = 0; r < 4; ++r) {
      V4 ar;
      std::memcpy(&ar, row[r] + i, sizeof ar);
      a0[r] += ar * v0;
      a1[r] += ar * v1;
    }
  }
  for (int r = 0; r < rows; ++r) {
    double s0 = (a0[r][0] + a0[r][1]) + (a0[r][2] + a0[r][3]);
    double s1 = (a1[r][0] + a1[r][1]) + (a1[r][2] + a1[r][3]);
    for (std::size_t k = i; k < n; ++k) {
      s0 += row[r][k] * x0[k];
      s1 += row[r][k] * x1[k];
    }
    out0[r] = s0;
    out1[r] = s1;
  }
}

}  // namespace seaflex::math
