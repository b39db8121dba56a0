#include "seaflex/model/marker_pair.hpp"

#include <algorithm>
#include <stdexcept>

namespace seaflex {

MarkerPair::MarkerPair(std::unique_ptr<Marker> a, std::unique_ptr<Marker> b)
    : a_(std::move(a)), b_(std::move(b)) {}

const std::vector<Index>& MarkerPair::bind() {
  dofs_.clear();
  auto place = [&](const Marker& m, std::vector<Index>& cols) {
    cols.clear();
    for (Index i : m.coordinates()) {
      auto it = std::find(dofs_.begin(), dofs_.end(), i);
      if (it == dofs_.end()) it = dofs_.insert(dofs_.end(), i);
      cols.push_back(static_cast<Index>(it - dofs_.begin()));
    }
  };
  place(*a_, a_cols_);
  place(*b_, b_cols_);
  if (static_cast<int>(dofs_.size()) > kMaxPairCoordinates)
    throw std::logic_error("MarkerPair: markers depend on too many coordinates");
  return dofs_;
}

void MarkerPair::evaluate(MarkerVector which, double sign_a, double sign_b, const State& state,
                          PairVectorEval& out) const {
  const Index n = static_cast<Index>(dofs_.size());
  out.value.setZero();
  out.rate.setZero();
  out.bias.setZero();
  out.dt.setZero();
  out.J.setZero(3, n);
  out.Jv.setZero(3, n);
  MarkerVectorEval e;
  auto add = [&](const Marker& m, const std::vector<Index>& cols, double sign) {
    if (sign == 0.0) return;
    e.dt.setZero();  // markers fixed on bodies leave it alone
    m.evaluate(which, state, e);
    out.value += sign * e.value;
    out.dt += sign * e.dt;
    out.rate += sign * e.rate;
    out.bias += sign * e.bias;
    for (std::size_t c = 0; c < cols.size(); ++c) {
      out.J.col(cols[c]) += sign * e.J.col(c);
      out.Jv.col(cols[c]) += sign * e.Jv.col(c);
    }
  };
  add(*a_, a_cols_, sign_a);
  add(*b_, b_cols_, sign_b);
}

void MarkerPair::add_hessian(MarkerVector which, double sign_a, double sign_b, const State& state,
                             const Vec3& F, Eigen::Ref<MatX> H) const {
  MarkerSquare local;
  auto add = [&](const Marker& m, const std::vector<Index>& cols, double sign) {
    if (sign == 0.0 || m.linear()) return;
    const Index n = static_cast<Index>(cols.size());
    local.setZero(n, n);
    m.add_hessian(which, state, sign * F, local);
    for (Index i = 0; i < n; ++i)
      for (Index j = 0; j < n; ++j) H(cols[i], cols[j]) += local(i, j);
  };
  add(*a_, a_cols_, sign_a);
  add(*b_, b_cols_, sign_b);
}

}  // namespace seaflex
