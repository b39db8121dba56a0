#include "seaflex/math/sparse_block_assembler.hpp"

#include <algorithm>
#include <stdexcept>

namespace seaflex::math {

void SparseBlockAssembler::resize(Index rows, Index cols) {
  rows_ = rows;
  cols_ = cols;
  finalized_ = false;
  blocks_.clear();
  row_index_.clear();
  col_index_.clear();
  value_pos_.clear();
  matrix_.resize(rows, cols);
}

BlockId SparseBlockAssembler::declare_block(std::span<const Index> rows,
                                            std::span<const Index> cols) {
  if (finalized_) throw std::logic_error("SparseBlockAssembler: declare_block after finalize");
  for (Index r : rows)
    if (r < 0 || r >= rows_) throw std::out_of_range("SparseBlockAssembler: row out of range");
  for (Index c : cols)
    if (c < 0 || c >= cols_) throw std::out_of_range("SparseBlockAssembler: column out of range");
  Block b;
  b.rows = static_cast<Index>(rows.size());
  b.cols = static_cast<Index>(cols.size());
  b.first = value_pos_.size();
  b.row_off = row_index_.size();
  b.col_off = col_index_.size();
  row_index_.insert(row_index_.end(), rows.begin(), rows.end());
  col_index_.insert(col_index_.end(), cols.begin(), cols.end());
  value_pos_.resize(value_pos_.size() + rows.size() * cols.size(), -1);
  blocks_.push_back(b);
  return static_cast<BlockId>(blocks_.size() - 1);
}

void SparseBlockAssembler::finalize() {
  // pattern from all declared entries (duplicates merge)
  std::vector<Eigen::Triplet<double, int>> triplets;
  triplets.reserve(value_pos_.size());
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    const Block& blk = blocks_[b];
    for (Index j = 0; j < blk.cols; ++j)
      for (Index i = 0; i < blk.rows; ++i)
        triplets.emplace_back(static_cast<int>(row_index_[blk.row_off + i]),
                              static_cast<int>(col_index_[blk.col_off + j]), 0.0);
  }
  matrix_.resize(rows_, cols_);
  matrix_.setFromTriplets(triplets.begin(), triplets.end());
  matrix_.makeCompressed();
  // map every block entry to its slot in the value array
  const int* outer = matrix_.outerIndexPtr();
  const int* inner = matrix_.innerIndexPtr();
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    const Block& blk = blocks_[b];
    for (Index j = 0; j < blk.cols; ++j) {
      const Index c = col_index_[blk.col_off + j];
      for (Index i = 0; i < blk.rows; ++i) {
        const Index r = row_index_[blk.row_off + i];
        int lo = outer[c], hi = outer[c + 1];
        // binary search of row r in column c
        while (lo < hi) {
          const int mid = (lo + hi) / 2;
          if (inner[mid] < r)
            lo = mid + 1;
          else
            hi = mid;
        }
        value_pos_[blk.first + static_cast<std::size_t>(j * blk.rows + i)] = lo;
      }
    }
  }
  finalized_ = true;
}

void SparseBlockAssembler::set_zero() {
  std::fill(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros(), 0.0);
}

void SparseBlockAssembler::begin_product(const VecX& x, VecX& y) {
  if (x.size() != cols_ || y.size() != rows_)
    throw std::invalid_argument("SparseBlockAssembler: product vectors of the wrong size");
  product_x_ = &x;
  product_y_ = &y;
}

void SparseBlockAssembler::end_product() {
  product_x_ = nullptr;
  product_y_ = nullptr;
}

void SparseBlockAssembler::add(BlockId id, const Eigen::Ref<const MatX>& block, double scale) {
  const Block& blk = blocks_[id];
  if (product_x_) {
    add_product(blk, scale, [&](Index i, Index j) { return block(i, j); });
    return;
  }
  double* values = matrix_.valuePtr();
  const int* pos = value_pos_.data() + blk.first;
  for (Index j = 0; j < blk.cols; ++j)
    for (Index i = 0; i < blk.rows; ++i) values[*pos++] += scale * block(i, j);
}

void SparseBlockAssembler::add_transposed(BlockId mirrored_id, const Eigen::Ref<const MatX>& block,
                                          double scale) {
  const Block& blk = blocks_[mirrored_id];  // blk.rows == block.cols()
  if (product_x_) {  // y[rows_m[i]] += block(j, i) x[cols_m[j]] with the mirrored lists
    add_product(blk, scale, [&](Index i, Index j) { return block(j, i); });
    return;
  }
  double* values = matrix_.valuePtr();
  const int* pos = value_pos_.data() + blk.first;
  for (Index j = 0; j < blk.cols; ++j)
    for (Index i = 0; i < blk.rows; ++i) values[*pos++] += scale * block(j, i);
}

}  // namespace seaflex::math
