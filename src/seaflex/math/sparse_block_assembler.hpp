// Assembly of dense element blocks into one sparse matrix whose pattern is fixed once.
//
// Build phase: every contributor declares the (row, column) index lists of the dense
// blocks it will add and keeps the returned BlockId. finalize() builds the compressed
// column pattern and, for each block, the positions of its entries in the value array.
// Evaluation phase: set_zero() then add(id, block, scale) writes straight into the
// value array: no search, no allocation, cost linear in the number of entries.
// Product mode (begin_product(x, y) ... end_product()): add() stores nothing and adds
// block * x[cols] into y[rows] instead, so y gains (the sum of the blocks) * x without the
// matrix being formed: an implicit integrator's M(q) a when M(q) changes with the state
// (issue 21). The same parallel rule holds: blocks added concurrently must not share rows.
#pragma once

#include <span>
#include <vector>

#include "seaflex/core/types.hpp"

namespace seaflex::math {

using BlockId = int;

class SparseBlockAssembler {
 public:
  SparseBlockAssembler() = default;
  explicit SparseBlockAssembler(Index rows, Index cols) { resize(rows, cols); }

  /// Starts a new pattern of the given size, forgetting every block.
  void resize(Index rows, Index cols);

  /// Declares a dense block; rows and cols are global indices. Build phase only.
  BlockId declare_block(std::span<const Index> rows, std::span<const Index> cols);

  /// Fixes the pattern. After this, declare_block throws.
  void finalize();
  bool finalized() const { return finalized_; }

  void set_zero();
  /// matrix(rows[i], cols[j]) += scale * block(i, j) for the declared block id.
  void add(BlockId id, const Eigen::Ref<const MatX>& block, double scale = 1.0);
  /// matrix(cols[j], rows[i]) += scale * block(i, j): adds the transpose into the
  /// mirrored position (the block must have been declared with rows/cols swapped).
  void add_transposed(BlockId mirrored_id, const Eigen::Ref<const MatX>& block, double scale = 1.0);

  /// Product mode: until end_product(), add(id, block, s) does y[rows] += s block x[cols]
  /// and add_transposed likewise with the block transposed; the matrix is left as it was.
  /// x has cols() entries, y rows(); both must outlive the product.
  void begin_product(const VecX& x, VecX& y);
  void end_product();
  bool in_product() const { return product_x_ != nullptr; }
  /// In product mode, the vector multiplied and the one added into: an element that knows
  /// the structure of its block may add its product itself (same rows rule as add()).
  const VecX& product_x() const { return *product_x_; }
  VecX& product_y() { return *product_y_; }

  const SpMat& matrix() const { return matrix_; }
  SpMat& matrix() { return matrix_; }

  Index block_rows(BlockId id) const { return blocks_[id].rows; }
  Index block_cols(BlockId id) const { return blocks_[id].cols; }

 private:
  struct Block {
    Index rows = 0;
    Index cols = 0;
    std::size_t row_off = 0;  // offset into row_index_
    std::size_t col_off = 0;  // offset into col_index_
    std::size_t first = 0;    // offset into value_pos_
  };
  Index rows_ = 0;
  Index cols_ = 0;
  bool finalized_ = false;
  std::vector<Block> blocks_;
  std::vector<Index> row_index_;  // per block: its row list
  std::vector<Index> col_index_;  // per block: its column list
  std::vector<int> value_pos_;    // per block entry (column-major): position in valuePtr
  SpMat matrix_;
  // product mode: y[rows[i]] += scale entry(i, j) x[cols[j]] over the block's lists
  template <class Entry>
  void add_product(const Block& blk, double scale, Entry entry) {
    const Index* rows = row_index_.data() + blk.row_off;
    const Index* cols = col_index_.data() + blk.col_off;
    for (Index j = 0; j < blk.cols; ++j) {
      const double xj = scale * (*product_x_)[cols[j]];
      for (Index i = 0; i < blk.rows; ++i) (*product_y_)[rows[i]] += entry(i, j) * xj;
    }
  }

  const VecX* product_x_ = nullptr;  // product mode (begin_product)
  VecX* product_y_ = nullptr;
};

}  // namespace seaflex::math
