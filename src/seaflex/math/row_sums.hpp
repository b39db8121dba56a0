// Sums of matrix rows times vectors, out_r = sum_i a_r,i x_i, for the few long sums the storm
// spends its time in (issue 21): the grid wave kinematics' depth sums (hydro/wave_grid.cpp)
// and the RAO motion's sum over the wave components (hydro/rao_motion.cpp). Each sum is kept
// as four partial sums (i mod 4), added in a fixed order at the end, so the loops run four
// components at a time in vector registers without reassociating anything. The kernels are
// compiled also for AVX2 and FMA, picked when the program loads (math/vector_clones.hpp);
// the FMA version's results differ from the other's at round-off.
#pragma once

#include <cstddef>

namespace seaflex::math {

/// out[r] = sum_{i < n} a[r * stride + i] x[i] for r < rows.
void row_sums(const double* a, std::size_t stride, std::size_t rows, const double* x, std::size_t n,
              double* out);

/// The same for two vectors over at most four rows, each row read once for both:
/// out0[r] = sum_i a_r,i x0_i, out1[r] = sum_i a_r,i x1_i for r < rows <= 4.
void row_sums_pair(const double* a, std::size_t stride, int rows, const double* x0,
                   const double* x1, std::size_t n, double* out0, double* out1);

}  // namespace seaflex::math
