#include "seaflex/forces/rope.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "seaflex/core/errors.hpp"

namespace seaflex {

Rope::Rope(std::string name, std::vector<MarkerPair> segments, std::vector<int> parts,
           double free_length, double axial_stiffness, double damping)
    : Force(std::move(name)),
      segments_(std::move(segments)),
      parts_(std::move(parts)),
      free_length_(free_length),
      axial_stiffness_(axial_stiffness),
      damping_(damping) {
  if (segments_.empty() || segments_.size() != parts_.size())
    throw std::invalid_argument("Rope: one part count per segment, at least one segment");
  if (!(free_length_ > 0.0)) throw std::invalid_argument("Rope: the free length must be > 0");
}

void Rope::declare_blocks(math::SparseBlockAssembler& matrix) {
  dofs_.clear();
  cols_.assign(segments_.size(), {});
  for (std::size_t s = 0; s < segments_.size(); ++s)
    for (Index i : segments_[s].bind()) {
      auto it = std::find(dofs_.begin(), dofs_.end(), i);
      if (it == dofs_.end()) it = dofs_.insert(dofs_.end(), i);
      cols_[s].push_back(static_cast<Index>(it - dofs_.begin()));
    }
  block_ = dofs_.empty() ? -1 : matrix.declare_block(dofs_, dofs_);
}

double Rope::length(const State& state) const {
  double L = 0.0;
  for (std::size_t s = 0; s < segments_.size(); ++s)
    L += parts_[s] * (segments_[s].b().position(state) - segments_[s].a().position(state)).norm();
  return L;
}

int Rope::first_vanishing_segment(const State& state) const {
  for (std::size_t s = 0; s < segments_.size(); ++s)
    if (!((segments_[s].b().position(state) - segments_[s].a().position(state)).norm() > 0.0))
      return static_cast<int>(s);
  return -1;
}

double Rope::free_length(const State& state) const {
  return winch_ ? free_length_ + winch_->change(state.t) : free_length_;
}

double Rope::tension(const State& state) const {
  double L = 0.0, Ld = 0.0;
  PairVectorEval d;
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    segments_[s].evaluate(MarkerVector::kPoint, -1.0, 1.0, state, d);
    const double l = d.value.norm();
    L += parts_[s] * l;
    if (l > 0.0) Ld += parts_[s] * d.value.dot(d.rate) / l;
  }
  const double L0 = free_length(state), L0d = winch_ ? winch_->rate(state.t) : 0.0;
  if (L <= L0) return 0.0;
  return std::max(0.0, axial_stiffness_ * (L - L0) / L0 + damping_ * (Ld - L0d));
}

void Rope::assemble(const State& state, double, AssemblyTarget& target) const {
  if (dofs_.empty()) return;
  const std::size_t ns = segments_.size();
  std::vector<PairVectorEval> d(ns);
  double L = 0.0, Ld = 0.0;
  for (std::size_t s = 0; s < ns; ++s) {
    segments_[s].evaluate(MarkerVector::kPoint, -1.0, 1.0, state, d[s]);
    const double l = d[s].value.norm();
    if (!(l > 0.0))
      throw SolverError(fmt::format("t = {:.6g} s: points {} and {} of rope {} met, so the "
                                    "direction of its segment is undefined",
                                    state.t, s, s + 1, name()),
                        state.t);
    L += parts_[s] * l;
    Ld += parts_[s] * d[s].value.dot(d[s].rate) / l;
  }
  const double L0 = free_length(state), L0d = winch_ ? winch_->rate(state.t) : 0.0;
  if (!(L0 > 0.0))
    throw SolverError(fmt::format("t = {:.6g} s: the winch of rope {} has hauled in its whole "
                                  "length (free length {:.6g} m)",
                                  state.t, name(), L0),
                      state.t);
  if (L <= L0) return;  // slack
  const double k = axial_stiffness_ / L0;
  const double T = k * (L - L0) + damping_ * (Ld - L0d);
  if (T <= 0.0) return;  // a rope cannot push, even while it shortens fast

  const Index m = static_cast<Index>(dofs_.size());
  VecX g = VecX::Zero(m), h = VecX::Zero(m);  // dL/dq, dL'/dq on the union
  const bool matrix = target.matrix && target.scales.kq != 0.0;
  MatX dQ = matrix ? MatX::Zero(m, m) : MatX();
  for (std::size_t s = 0; s < ns; ++s) {
    const PairVectorEval& e = d[s];
    const double l = e.value.norm();
    const Vec3 u = e.value / l;
    const double n = parts_[s];
    const Mat3 P = Mat3::Identity() - u * u.transpose();
    const std::vector<Index>& cols = cols_[s];
    const Index ms = static_cast<Index>(cols.size());
    for (Index i = 0; i < ms; ++i) {
      g[cols[i]] += n * e.J.col(i).dot(u);
      h[cols[i]] += n * (e.J.col(i).dot(P * e.rate) / l + e.Jv.col(i).dot(u));
    }
    if (!matrix) continue;
    // -T d2L/dq2 of this segment: transverse stiffness and the markers' Hessians
    PairSquare local = -(n * T / l) * (e.J.transpose() * P * e.J);
    segments_[s].add_hessian(MarkerVector::kPoint, -1.0, 1.0, state, -n * T * u, local);
    for (Index i = 0; i < ms; ++i)
      for (Index j = 0; j < ms; ++j) dQ(cols[i], cols[j]) += local(i, j);
  }
  if (target.forces)
    for (Index i = 0; i < m; ++i) (*target.forces)[dofs_[i]] -= T * g[i];
  if (!target.matrix) return;
  const MatrixScales& sc = target.scales;
  MatX A = MatX::Zero(m, m);
  if (matrix) {
    dQ -= g * (k * g + damping_ * h).transpose();
    A -= sc.kq * dQ;
  }
  if (sc.kv != 0.0 && damping_ != 0.0) A += sc.kv * damping_ * g * g.transpose();  // -kv dQ/dv
  target.matrix->add(block_, A);
}

double Rope::potential_energy(const State& state) const {
  const double L0 = free_length(state);
  const double x = length(state) - L0;
  return x > 0.0 ? 0.5 * axial_stiffness_ / L0 * x * x : 0.0;
}

void Rope::add_channels(ChannelList& channels) const {
  channels.push_back(
      {fmt::format("{}.tension", name()), [this](const State& s) { return tension(s); }});
  channels.push_back(
      {fmt::format("{}.length", name()), [this](const State& s) { return length(s); }});
  if (winch_)
    channels.push_back(
        {fmt::format("{}.free_length", name()), [this](const State& s) { return free_length(s); }});
}

}  // namespace seaflex
