#include "seaflex/constraints/joint.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <tuple>

namespace seaflex {

namespace {
bool has_frame(const Marker& m) {
  return m.has(MarkerVector::kAxisX) && m.has(MarkerVector::kAxisY) && m.has(MarkerVector::kAxisZ);
}

// the frame side must have x and y axes: a beam given first goes behind the other marker
bool swap_needed(JointType type, const Marker& from, const Marker& to) {
  return type != JointType::kBall && !has_frame(from) && has_frame(to);
}
}  // namespace

std::string_view joint_type_name(JointType type) {
  switch (type) {
    case JointType::kBall:
      return "ball";
    case JointType::kUniversal:
      return "universal";
    case JointType::kRevolute:
      return "revolute";
    case JointType::kCylindrical:
      return "cylindrical";
    case JointType::kPrismatic:
      return "prismatic";
    case JointType::kFixed:
      return "fixed";
  }
  return "?";
}

Joint::Joint(std::string name, JointType type, std::unique_ptr<Marker> from,
             std::unique_ptr<Marker> to)
    : Constraint(std::move(name)),
      type_(type),
      swapped_(swap_needed(type, *from, *to)),
      pair_(swapped_ ? std::move(to) : std::move(from),
            swapped_ ? std::move(from) : std::move(to)) {
  const Marker& a = pair_.a();
  const Marker& b = pair_.b();
  const std::string_view tn = joint_type_name(type);
  const bool beam_beam = !has_frame(a);
  if (type != JointType::kBall && beam_beam && type != JointType::kFixed)
    throw std::invalid_argument(fmt::format(
        "a {} joint needs x and y axes on one side, but {} and {} are beam markers, which "
        "have only the slope axis (the cable element carries no torsion); beam to beam "
        "takes ball or fixed",
        tn, a.describe(), b.describe()));
  const bool to_frame = has_frame(b);
  if ((type == JointType::kUniversal || type == JointType::kPrismatic) && !to_frame)
    throw std::invalid_argument(fmt::format(
        "a {} joint needs the y axis of both markers, but {} is a beam marker, which has "
        "only the slope axis (the cable element carries no torsion)",
        tn, b.describe()));

  if (type == JointType::kBall || type == JointType::kUniversal || type == JointType::kRevolute ||
      type == JointType::kFixed) {
    add_row(Factor::kUnitX, Factor::kSeparation, "x");
    add_row(Factor::kUnitY, Factor::kSeparation, "y");
    add_row(Factor::kUnitZ, Factor::kSeparation, "z");
  }
  switch (type) {
    case JointType::kBall:
      break;
    case JointType::kUniversal:
      add_row(Factor::kFromX, Factor::kToY, "cross x.y");
      break;
    case JointType::kRevolute:
      add_row(Factor::kFromX, Factor::kToZ, "axis x.z");
      add_row(Factor::kFromY, Factor::kToZ, "axis y.z");
      break;
    case JointType::kCylindrical:
    case JointType::kPrismatic:
      add_row(Factor::kFromX, Factor::kToZ, "axis x.z");
      add_row(Factor::kFromY, Factor::kToZ, "axis y.z");
      add_row(Factor::kFromX, Factor::kSeparation, "offset x");
      add_row(Factor::kFromY, Factor::kSeparation, "offset y");
      if (type == JointType::kPrismatic) add_row(Factor::kFromX, Factor::kToY, "twist x.y");
      break;
    case JointType::kFixed:
      if (beam_beam) {  // slope continuity, thesis eq. (154-155)
        add_row(Factor::kUnitX, Factor::kSlopeDifference, "slope x");
        add_row(Factor::kUnitY, Factor::kSlopeDifference, "slope y");
        add_row(Factor::kUnitZ, Factor::kSlopeDifference, "slope z");
      } else if (!to_frame) {  // beam slope along the body's z axis, thesis eq. (160-171)
        add_row(Factor::kFromX, Factor::kToZ, "slope x");
        add_row(Factor::kFromY, Factor::kToZ, "slope y");
      } else {  // thesis eq. (147-149)
        add_row(Factor::kFromZ, Factor::kToX, "angle z.x");
        add_row(Factor::kFromZ, Factor::kToY, "angle z.y");
        add_row(Factor::kFromX, Factor::kToY, "angle x.y");
      }
      break;
  }

  // a factor of a moving marker is not constant: it turns C_q with time
  auto constant = [&](Factor f) {
    const FactorDef d = define(f);
    return (d.sign_from == 0.0 || (a.body() == nullptr && !a.moving())) &&
           (d.sign_to == 0.0 || (b.body() == nullptr && !b.moving()));
  };
  linear_ = a.linear() && b.linear() && std::all_of(rows_.begin(), rows_.end(), [&](const Row& r) {
              return constant(r.u) || constant(r.w);
            });
}

void Joint::add_row(Factor u, Factor w, std::string label) {
  rows_.push_back({u, w, std::move(label)});
}

Joint::FactorDef Joint::define(Factor f) {
  switch (f) {
    case Factor::kUnitX:
    case Factor::kUnitY:
    case Factor::kUnitZ:
      return {MarkerVector::kPoint, 0.0, 0.0};
    case Factor::kFromX:
      return {MarkerVector::kAxisX, 1.0, 0.0};
    case Factor::kFromY:
      return {MarkerVector::kAxisY, 1.0, 0.0};
    case Factor::kFromZ:
      return {MarkerVector::kAxisZ, 1.0, 0.0};
    case Factor::kToX:
      return {MarkerVector::kAxisX, 0.0, 1.0};
    case Factor::kToY:
      return {MarkerVector::kAxisY, 0.0, 1.0};
    case Factor::kToZ:
      return {MarkerVector::kAxisZ, 0.0, 1.0};
    case Factor::kSeparation:
      return {MarkerVector::kPoint, -1.0, 1.0};
    case Factor::kSlopeDifference:
      return {MarkerVector::kAxisZ, -1.0, 1.0};
  }
  return {MarkerVector::kPoint, 0.0, 0.0};
}

std::string Joint::row_name(Index row) const {
  return fmt::format("{}: {}", name(), rows_.at(row).label);
}

std::vector<Index> Joint::coordinates() const {
  return pair_.bind();
}

void Joint::factor(Factor f, const State& state, PairVectorEval& out) const {
  const FactorDef d = define(f);
  pair_.evaluate(d.vector, d.sign_from, d.sign_to, state, out);
  if (f <= Factor::kUnitZ) out.value = Vec3::Unit(static_cast<int>(f));
}

void Joint::evaluate(const State& state, ConstraintEval& out) const {
  // each factor once, however many rows share it (a prismatic joint's 5 rows use 4 factors
  // twice or more); the rows' values are the same products as before
  std::array<PairVectorEval, kFactorCount> factors;
  std::array<bool, kFactorCount> have{};
  auto get = [&](Factor f) -> const PairVectorEval& {
    const auto i = static_cast<std::size_t>(f);
    if (!have[i]) factor(f, state, factors[i]);
    have[i] = true;
    return factors[i];
  };
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    const PairVectorEval& u = get(rows_[r].u);
    const PairVectorEval& w = get(rows_[r].w);
    // C = u . w;  C_q = u^T J_w + w^T J_u;  C_t = u . w_t + w . u_t (moving markers);
    // eq. (133): gamma = -(u . w_bias + w . u_bias + 2 u' . w'), with x'' = J q'' + bias
    // for each factor (bias holds x_tt and rate holds x_t of a moving marker, so the
    // terms 2 C_qt q' + C_tt of eq. (133) are included)
    out.C[r] = u.value.dot(w.value);
    out.Cq.row(r) = u.value.transpose() * w.J + w.value.transpose() * u.J;
    out.Ct[r] = u.value.dot(w.dt) + w.value.dot(u.dt);
    out.gamma[r] = -(u.value.dot(w.bias) + w.value.dot(u.bias) + 2.0 * u.rate.dot(w.rate));
  }
}

void Joint::add_multiplier_hessian(const State& state, const Eigen::Ref<const VecX>& mu,
                                   Eigen::Ref<MatX> H) const {
  PairVectorEval u, w;
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    if (mu[r] == 0.0) continue;
    factor(rows_[r].u, state, u);
    factor(rows_[r].w, state, w);
    // d(C_q^T mu)/dq = mu (J_u^T J_w + J_w^T J_u) + d(J_u^T (mu w))/dq + d(J_w^T (mu u))/dq
    const PairSquare cross = u.J.transpose() * w.J;
    H += mu[r] * (cross + cross.transpose());
    const FactorDef du = define(rows_[r].u), dw = define(rows_[r].w);
    pair_.add_hessian(du.vector, du.sign_from, du.sign_to, state, mu[r] * w.value, H);
    pair_.add_hessian(dw.vector, dw.sign_from, dw.sign_to, state, mu[r] * u.value, H);
  }
}

std::pair<Vec3, Vec3> Joint::reaction(const State& state, const Eigen::Ref<const VecX>& mu) const {
  Vec3 F = Vec3::Zero(), M = Vec3::Zero();
  PairVectorEval u, w;
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    factor(rows_[r].u, state, u);
    const Factor wf = rows_[r].w;
    if (!swapped_) {
      if (wf == Factor::kSeparation) {
        F -= mu[r] * u.value;
      } else {
        // w holds the "to" axis a (kToX..kToZ, or the slope difference): moment mu u x a
        pair_.evaluate(define(wf).vector, 0.0, 1.0, state, w);
        M += mu[r] * u.value.cross(w.value);
      }
    } else {
      // the body named "to" is internally "from": w = d holds -p_from, giving the force
      // mu u at its point; u = an axis a of it gives the moment mu w x a (exact also
      // where the joint is violated, unlike the opposite of the other body's reaction)
      factor(wf, state, w);
      if (wf == Factor::kSeparation) F += mu[r] * u.value;
      if (rows_[r].u >= Factor::kFromX && rows_[r].u <= Factor::kFromZ)
        M += mu[r] * w.value.cross(u.value);
    }
  }
  if (extra_moment_) M += extra_moment_(state);
  return {F, M};
}

void Joint::add_channels(ChannelList& channels, Index row_offset) const {
  const Index rows = num_rows();
  static const char* names[] = {"fx", "fy", "fz", "mx", "my", "mz"};
  // the six components from one reaction per output row (ChannelRow): each evaluates the
  // joint's factors again otherwise
  struct Memo {
    std::mutex mutex;  // a model's channels read from two threads at once stay correct
    long row = 0;
    Vec3 F, M;
  };
  const auto memo = std::make_shared<Memo>();
  for (int i = 0; i < 6; ++i) {
    channels.push_back(
        {fmt::format("{}.{}", name(), names[i]), [this, i, row_offset, rows, memo](const State& s) {
           if (s.lambda.size() < row_offset + rows)
             throw std::logic_error("Joint: state without multipliers");
           const long row = ChannelRow::current();
           const std::lock_guard<std::mutex> lock(memo->mutex);
           if (row == 0 || memo->row != row) {
             std::tie(memo->F, memo->M) = reaction(s, s.lambda.segment(row_offset, rows));
             memo->row = row;
           }
           return i < 3 ? memo->F[i] : memo->M[i - 3];
         }});
  }
}

}  // namespace seaflex
