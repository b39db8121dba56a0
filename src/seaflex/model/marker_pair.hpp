// Shared plumbing of joints and force elements between two markers: the union of their
// coordinates and the evaluation of a difference x_b - x_a of marker vectors (or of one
// of them) on that union, with the Hessian contraction d(J^T F)/dq.
#pragma once

#include <memory>

#include "seaflex/model/marker.hpp"

namespace seaflex {

inline constexpr int kMaxPairCoordinates = 2 * kMaxMarkerCoordinates;
using PairJacobian =
    Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::ColMajor, 3, kMaxPairCoordinates>;
using PairSquare = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor,
                                 kMaxPairCoordinates, kMaxPairCoordinates>;
using PairVector =
    Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxPairCoordinates, 1>;

struct PairVectorEval {
  Vec3 value = Vec3::Zero();
  Vec3 rate = Vec3::Zero();
  Vec3 bias = Vec3::Zero();  ///< J' v (+ x_tt of moving markers)
  Vec3 dt = Vec3::Zero();    ///< explicit time derivative x_t (moving markers)
  PairJacobian J;            ///< d value / dq on the union
  PairJacobian Jv;           ///< d rate / dq on the union
};

class MarkerPair {
 public:
  MarkerPair(std::unique_ptr<Marker> a, std::unique_ptr<Marker> b);

  const Marker& a() const { return *a_; }
  const Marker& b() const { return *b_; }
  /// Union of the two markers' coordinates; call after numbering.
  const std::vector<Index>& bind();
  const std::vector<Index>& dofs() const { return dofs_; }

  /// sign_a x_a(which) + sign_b x_b(which) on the union (a sign 0 leaves a marker out).
  void evaluate(MarkerVector which, double sign_a, double sign_b, const State& state,
                PairVectorEval& out) const;
  /// H += d(J^T F)/dq of the same combination.
  void add_hessian(MarkerVector which, double sign_a, double sign_b, const State& state,
                   const Vec3& F, Eigen::Ref<MatX> H) const;

 private:
  std::unique_ptr<Marker> a_, b_;
  std::vector<Index> dofs_;
  std::vector<Index> a_cols_, b_cols_;
};

}  // namespace seaflex
