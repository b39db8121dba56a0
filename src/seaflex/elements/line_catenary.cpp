#include "seaflex/elements/line_catenary.hpp"

#include <algorithm>
#include <cmath>

namespace seaflex {

namespace {

// a breakpoint from the lower end: a node (node >= 0) or a point weight (load != 0)
struct Event {
  double sigma = 0.0;
  int node = -1;
  double load = 0.0;
};

struct Shot {
  bool ok = false;
  double x = 0.0, z = 0.0;     // of the upper end, from the lower end
  std::vector<double> nx, nz;  // per node from the lower end (index = node from P)
  std::vector<double> tx, tz;  // unit tangents
};

class Chain {
 public:
  Chain(std::vector<Event> events, std::vector<double> piece_w, int nodes, bool seabed)
      : events_(std::move(events)), w_(std::move(piece_w)), nodes_(nodes), seabed_(seabed) {}

  // events_[i] .. events_[i + 1] is piece i of weight w_[i] (N/m)
  Shot shoot(double H, double V0) const {
    Shot s;
    s.nx.assign(nodes_, 0.0);
    s.nz.assign(nodes_, 0.0);
    s.tx.assign(nodes_, 1.0);
    s.tz.assign(nodes_, 0.0);
    double x = 0.0, z = 0.0, V = V0;
    bool laid = seabed_ && V0 < 0.0;
    auto record = [&](int node) {
      if (node < 0) return;
      s.nx[node] = x;
      s.nz[node] = z;
      const double T = std::hypot(H, laid ? 0.0 : V);
      s.tx[node] = H / T;
      s.tz[node] = laid ? 0.0 : V / T;
    };
    for (std::size_t i = 0; i < events_.size(); ++i) {
      const Event& e = events_[i];
      V += e.load;
      if (laid && V >= 0.0) laid = false;  // touchdown at a point weight
      record(e.node);
      if (i + 1 == events_.size()) break;
      double a = e.sigma;
      const double b = events_[i + 1].sigma;
      const double w = w_[i];
      if (laid) {
        // on the seabed until V reaches 0 (touchdown) inside the piece
        const double td = w > 0.0 ? a + (-V) / w : b + 1.0;
        if (td >= b) {
          x += b - a;
          V += w * (b - a);
          continue;
        }
        x += td - a;
        a = td;
        V = 0.0;
        laid = false;
      }
      const double Vb = V + w * (b - a);
      if (std::abs(w * (b - a)) < 1e-9 * std::max(H, std::abs(V))) {
        const double Vm = 0.5 * (V + Vb), T = std::hypot(H, Vm);
        x += (b - a) * H / T;
        z += (b - a) * Vm / T;
      } else {
        x += H / w * (std::asinh(Vb / H) - std::asinh(V / H));
        z += (std::hypot(H, Vb) - std::hypot(H, V)) / w;
      }
      V = Vb;
    }
    if (laid) return s;  // the whole line on the seabed
    s.ok = std::isfinite(x) && std::isfinite(z);
    s.x = x;
    s.z = z;
    return s;
  }

 private:
  std::vector<Event> events_;
  std::vector<double> w_;
  int nodes_;
  bool seabed_;
};

}  // namespace

std::optional<BeamGeometry> weighted_catenary(const Vec3& start, const Vec3& end,
                                              const std::vector<double>& element_lengths,
                                              const LineWeights& weights, bool seabed,
                                              const BeamGeometry& guess,
                                              const CatenaryShape& shape) {
  const int n = static_cast<int>(element_lengths.size());
  if (n < 1 || weights.per_length.size() != element_lengths.size()) return std::nullopt;
  const bool reversed = end.z() < start.z();
  const Vec3 P = reversed ? end : start, U = reversed ? start : end;
  Vec3 e(U.x() - P.x(), U.y() - P.y(), 0.0);
  const double X = e.norm(), h = U.z() - P.z();
  if (!(X > 0.0)) return std::nullopt;
  e /= X;
  std::vector<double> arc(n + 1, 0.0);
  for (int k = 0; k < n; ++k) arc[k + 1] = arc[k] + element_lengths[k];
  const double L = arc[n];
  // events from the lower end: node k of the beam at sigma = arc[k] (or L - arc[k])
  std::vector<Event> events;
  for (int k = 0; k <= n; ++k) {
    const int j = reversed ? n - k : k;  // node index counted from P
    events.push_back({reversed ? L - arc[k] : arc[k], j, 0.0});
  }
  for (const auto& [s, load] : weights.points) events.push_back({reversed ? L - s : s, -1, load});
  std::stable_sort(events.begin(), events.end(),
                   [](const Event& a, const Event& b) { return a.sigma < b.sigma; });
  std::vector<double> piece_w;
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < events.size(); ++i) {
    const double mid = 0.5 * (events[i].sigma + events[i + 1].sigma);
    const double s = reversed ? L - mid : mid;
    const int k = static_cast<int>(std::upper_bound(arc.begin(), arc.end(), s) - arc.begin()) - 1;
    const double w = weights.per_length[std::clamp(k, 0, n - 1)];
    piece_w.push_back(w);
    total += w * (events[i + 1].sigma - events[i].sigma);
  }
  for (const auto& p : weights.points) total += p.second;
  if (!(total > 0.0)) return std::nullopt;  // lighter than water in all: it floats
  const Chain chain(events, piece_w, n + 1, seabed);

  // start: the uniform catenary of the same length and mean weight (H = a w_mean, and
  // V_P from its laid length or its slope at P)
  const double w_mean = total / L;
  const Vec3 tP = reversed ? Vec3(-guess.slopes.back()) : guess.slopes.front();
  const double th = std::max(1e-6, std::hypot(tP.x(), tP.y()));
  const double H = std::max(shape.a * w_mean, 1e-9 * total);
  const double V0 = shape.touchdown ? -w_mean * shape.laid_length : H * tP.z() / th;
  auto residual = [&](double lnH, double v0, Eigen::Vector2d* r) {
    const Shot s = chain.shoot(std::exp(lnH), v0);
    if (!s.ok) return false;
    *r = Eigen::Vector2d(s.x - X, s.z - h);
    return true;
  };
  double p0 = std::log(H), p1 = V0;
  Eigen::Vector2d r;
  if (!residual(p0, p1, &r)) {
    p1 = std::max(p1, 0.0);
    if (!residual(p0, p1, &r)) return std::nullopt;
  }
  const double tol = 1e-9 * (X + std::abs(h) + L);
  for (int it = 0; it < 200 && r.norm() > tol; ++it) {
    Eigen::Matrix2d J;
    const double d0 = 1e-7, d1 = 1e-7 * std::max(total, std::abs(p1));
    Eigen::Vector2d rp;
    if (!residual(p0 + d0, p1, &rp)) return std::nullopt;
    J.col(0) = (rp - r) / d0;
    if (!residual(p0, p1 + d1, &rp)) return std::nullopt;
    J.col(1) = (rp - r) / d1;
    const Eigen::Vector2d step = J.fullPivLu().solve(-r);
    if (!step.allFinite()) return std::nullopt;
    double t = 1.0;
    Eigen::Vector2d rt;
    // backtracking: no step of ln H above 2 (a factor e^2)
    if (std::abs(step[0]) > 2.0) t = 2.0 / std::abs(step[0]);
    while (t > 1e-8 &&
           (!residual(p0 + t * step[0], p1 + t * step[1], &rt) || rt.norm() >= r.norm()))
      t *= 0.5;
    if (!(t > 1e-8)) return std::nullopt;
    p0 += t * step[0];
    p1 += t * step[1];
    r = rt;
  }
  if (!(r.norm() <= tol)) return std::nullopt;
  const Shot s = chain.shoot(std::exp(p0), p1);
  BeamGeometry g;
  g.element_lengths = element_lengths;
  g.positions.resize(n + 1);
  g.slopes.resize(n + 1);
  const Vec3 ez(0.0, 0.0, 1.0);
  for (int k = 0; k <= n; ++k) {
    const int j = reversed ? n - k : k;
    Vec3 p = P + s.nx[j] * e;
    p.z() = P.z() + s.nz[j];
    const Vec3 t = s.tx[j] * e + s.tz[j] * ez;
    g.positions[k] = p;
    g.slopes[k] = reversed ? Vec3(-t) : t;
  }
  g.positions.front() = start;
  g.positions.back() = end;
  return g;
}

}  // namespace seaflex
