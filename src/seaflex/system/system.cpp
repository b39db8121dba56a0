#include "seaflex/system/system.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace seaflex {

Body& System::add_body(std::unique_ptr<Body> body) {
  if (finalized_) throw std::logic_error("System: add_body after finalize");
  if (find_body(body->name()))
    throw std::invalid_argument("System: duplicate body " + body->name());
  body_index_.emplace(body->name(), body.get());
  bodies_.push_back(std::move(body));
  for (auto& c : bodies_.back()->internal_constraints()) constraints_.push_back(std::move(c));
  return *bodies_.back();
}

void System::add_force(std::unique_ptr<Force> force) {
  if (finalized_) throw std::logic_error("System: add_force after finalize");
  forces_.push_back(std::move(force));
}

void System::add_constraint(std::unique_ptr<Constraint> constraint) {
  if (finalized_) throw std::logic_error("System: add_constraint after finalize");
  constraints_.push_back(std::move(constraint));
}

const Body* System::find_body(std::string_view name) const {
  const auto it = body_index_.find(std::string(name));
  return it != body_index_.end() ? it->second : nullptr;
}

void System::finalize() {
  if (finalized_) throw std::logic_error("System: finalize twice");
  n_ = 0;
  for (auto& b : bodies_) {
    b->set_offset(n_);
    n_ += b->num_coordinates();
  }
  m_ = 0;
  for (auto& c : constraints_) {
    row_offset_.push_back(m_);
    m_ += c->num_rows();
  }
  pattern_.resize(n_ + m_, n_ + m_);
  cq_pattern_.resize(m_, n_);
  for (auto& b : bodies_) b->declare_blocks(pattern_);
  for (auto& f : forces_) f->declare_blocks(pattern_);
  for (std::size_t k = 0; k < constraints_.size(); ++k) {
    const Constraint& c = *constraints_[k];
    constraint_dofs_.push_back(c.coordinates());
    const auto& dofs = constraint_dofs_.back();
    std::vector<Index> rows(c.num_rows());
    for (Index r = 0; r < c.num_rows(); ++r) rows[r] = n_ + row_offset_[k] + r;
    cq_block_.push_back(pattern_.declare_block(rows, dofs));
    cqt_block_.push_back(pattern_.declare_block(dofs, rows));
    hess_block_.push_back(c.is_linear() ? -1 : pattern_.declare_block(dofs, dofs));
    for (Index r = 0; r < c.num_rows(); ++r) rows[r] = row_offset_[k] + r;
    cq_only_block_.push_back(cq_pattern_.declare_block(rows, dofs));
  }
  pattern_.finalize();
  cq_pattern_.finalize();
  // the rows that hold a body by themselves (Dae::reaction_only_rows): of the constraints
  // whose coordinates all lie in one body, as many rows as that body has coordinates
  std::vector<Index> held_rows(bodies_.size(), 0);
  std::vector<std::size_t> owner(constraints_.size(), bodies_.size());
  for (std::size_t k = 0; k < constraints_.size(); ++k) {
    const auto& dofs = constraint_dofs_[k];
    if (dofs.empty()) continue;
    const auto [lo, hi] = std::minmax_element(dofs.begin(), dofs.end());
    const std::size_t b = body_index(*lo);
    if (b < bodies_.size() && *hi < bodies_[b]->offset() + bodies_[b]->num_coordinates()) {
      owner[k] = b;
      held_rows[b] += constraints_[k]->num_rows();
    }
  }
  for (std::size_t k = 0; k < constraints_.size(); ++k)
    if (owner[k] < bodies_.size() && held_rows[owner[k]] == bodies_[owner[k]]->num_coordinates())
      for (Index r = 0; r < constraints_[k]->num_rows(); ++r)
        reaction_only_rows_.push_back(row_offset_[k] + r);
  finalized_ = true;
}

State System::initial_state() const {
  if (!finalized_) throw std::logic_error("System: initial_state before finalize");
  State s;
  s.q = VecX::Zero(n_);
  s.v = VecX::Zero(n_);
  s.lambda = VecX::Zero(m_);
  for (const auto& b : bodies_) b->write_initial_state(s.q, s.v);
  return s;
}

DaeEval System::make_eval() const {
  if (!finalized_) throw std::logic_error("System: make_eval before finalize");
  DaeEval e;
  e.Q = VecX::Zero(n_);
  e.C = VecX::Zero(m_);
  e.Cdot = VecX::Zero(m_);
  e.gamma = VecX::Zero(m_);
  e.CqT_lambda = VecX::Zero(n_);
  e.product = VecX::Zero(n_ + m_);
  e.product_x = VecX::Zero(n_ + m_);
  e.kkt = pattern_;
  e.Cq = cq_pattern_;
  for (std::size_t k = 0; k < constraints_.size(); ++k) {
    const Index rows = constraints_[k]->num_rows();
    const Index cols = static_cast<Index>(constraint_dofs_[k].size());
    ConstraintEval ce{VecX::Zero(rows), MatX::Zero(rows, cols), VecX::Zero(rows), VecX::Zero(rows)};
    e.constraint_buffers.push_back(std::move(ce));
    e.hessian_buffers.push_back(constraints_[k]->is_linear() ? MatX() : MatX::Zero(cols, cols));
  }
  return e;
}

void System::evaluate(const State& state, const DaeRequest& request, DaeEval& out) const {
  AssemblyTarget target;
  target.scales = request.scales;
  target.acceleration = request.acceleration;
  if (request.forces) {
    out.Q.setZero();
    target.forces = &out.Q;
  }
  const bool product = request.matrix && request.product_with != nullptr;
  if (product) {
    out.product_x.head(n_) = *request.product_with;
    out.product.setZero();
    target.matrix = &out.kkt;
  } else if (request.matrix) {
    out.kkt.set_zero();
    target.matrix = &out.kkt;
  }
  if (target.forces || (target.matrix && request.scales.any())) {
    // product mode ends however the assembly ends (an element may throw)
    struct ProductMode {
      math::SparseBlockAssembler* kkt;
      ~ProductMode() {
        if (kkt) kkt->end_product();
      }
    } mode{product ? &out.kkt : nullptr};
    if (product) out.kkt.begin_product(out.product_x, out.product);
    for (const auto& b : bodies_) b->assemble(state, target);
    for (const auto& f : forces_) f->assemble(state, request.load_factor, target);
  }
  if (!request.constraints && !request.matrix && !request.reaction_forces &&
      !request.constraint_jacobian)
    return;
  if (request.reaction_forces) out.CqT_lambda.setZero();
  if (request.constraint_jacobian) out.Cq.set_zero();
  for (std::size_t k = 0; k < constraints_.size(); ++k) {
    const Constraint& c = *constraints_[k];
    ConstraintEval& ce = out.constraint_buffers[k];
    c.evaluate(state, ce);
    const auto& dofs = constraint_dofs_[k];
    const Index r0 = row_offset_[k];
    if (request.constraints) {
      out.C.segment(r0, c.num_rows()) = ce.C;
      out.gamma.segment(r0, c.num_rows()) = ce.gamma;
      // Cdot = C_q v + C_t, gathering v without a temporary (no allocation per step)
      for (Index r = 0; r < c.num_rows(); ++r) {
        double cdot = ce.Ct[r];
        for (std::size_t i = 0; i < dofs.size(); ++i) cdot += ce.Cq(r, i) * state.v[dofs[i]];
        out.Cdot[r0 + r] = cdot;
      }
    }
    if (request.reaction_forces)
      for (std::size_t i = 0; i < dofs.size(); ++i)
        for (Index r = 0; r < c.num_rows(); ++r)
          out.CqT_lambda[dofs[i]] += ce.Cq(r, i) * state.lambda[r0 + r];
    if (request.constraint_jacobian) out.Cq.add(cq_only_block_[k], ce.Cq);
    if (request.matrix && !product) {
      out.kkt.add(cq_block_[k], ce.Cq);
      out.kkt.add_transposed(cqt_block_[k], ce.Cq);
      if (request.multiplier_hessian && request.scales.kq != 0.0 && hess_block_[k] >= 0) {
        MatX& H = out.hessian_buffers[k];
        H.setZero();
        c.add_multiplier_hessian(state, state.lambda.segment(r0, c.num_rows()), H);
        out.kkt.add(hess_block_[k], H, request.scales.kq);
      }
    }
  }
}

bool System::constant_mass() const {
  for (const auto& b : bodies_)
    if (!b->constant_mass()) return false;
  for (const auto& f : forces_)
    if (!f->constant_mass()) return false;
  return true;
}

bool System::constant_mass_kkt() const {
  if (!constant_mass()) return false;
  for (const auto& c : constraints_)
    if (!c->is_linear()) return false;
  return true;
}

void System::start(const State& state) {
  for (auto& f : forces_) f->start(state);
}

void System::accept_step(const State& state) {
  for (auto& f : forces_) f->accept_step(state);
}

// the body that owns a coordinate: bodies are numbered in order, so the last one that starts
// at or before i (binary search); bodies_.size() when none holds it
std::size_t System::body_index(Index i) const {
  const auto it = std::upper_bound(bodies_.begin(), bodies_.end(), i,
                                   [](Index c, const auto& b) { return c < b->offset(); });
  if (it == bodies_.begin()) return bodies_.size();
  const Body& b = **std::prev(it);
  return i < b.offset() + b.num_coordinates()
             ? static_cast<std::size_t>(std::prev(it) - bodies_.begin())
             : bodies_.size();
}

std::string System::coordinate_name(Index i) const {
  const std::size_t k = body_index(i);
  if (k < bodies_.size()) return bodies_[k]->coordinate_name(i - bodies_[k]->offset());
  return fmt::format("q[{}]", i);
}

double System::step_scale(const State& state, const VecX& dq) const {
  double scale = 1.0;
  for (const auto& b : bodies_) scale = std::min(scale, b->step_scale(state, dq));
  return scale;
}

double System::length_scale() const {
  double length = std::numeric_limits<double>::infinity();
  for (const auto& b : bodies_) length = std::min(length, b->length_scale());
  return length;
}

// the constraint that owns a row: the last one that starts at or before it (binary search)
std::size_t System::constraint_index(Index row) const {
  const auto it = std::upper_bound(row_offset_.begin(), row_offset_.end(), row);
  if (it == row_offset_.begin()) return constraints_.size();
  const auto k = static_cast<std::size_t>(std::prev(it) - row_offset_.begin());
  return k < constraints_.size() && row < row_offset_[k] + constraints_[k]->num_rows()
             ? k
             : constraints_.size();
}

const Constraint* System::constraint_at_row(Index row) const {
  const std::size_t k = constraint_index(row);
  return k < constraints_.size() ? constraints_[k].get() : nullptr;
}

std::string System::constraint_name(Index row) const {
  const std::size_t k = constraint_index(row);
  if (k < constraints_.size()) return constraints_[k]->row_name(row - row_offset_[k]);
  return fmt::format("constraint row {}", row);
}

Energies System::energies(const State& state) const {
  Energies e;
  for (const auto& b : bodies_) {
    e.kinetic += b->kinetic_energy(state);
    e.strain += b->strain_energy(state);
  }
  for (const auto& f : forces_) e.potential += f->potential_energy(state);
  return e;
}

ChannelList System::channels() const {
  ChannelList list;
  for (const auto& b : bodies_) b->add_channels(list);
  for (const auto& f : forces_) f->add_channels(list);
  for (std::size_t k = 0; k < constraints_.size(); ++k)
    constraints_[k]->add_channels(list, row_offset_[k]);
  return list;
}

}  // namespace seaflex
