#include "seaflex/hydro/wave_grid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "seaflex/math/row_sums.hpp"

namespace seaflex::hydro {

namespace {

// the stencil on an equal lattice of spacing h: first index and weights (nodes i0 .. i0+3,
// x between nodes i0+1 and i0+2)
std::int64_t lattice_stencil(double x, double h, std::array<double, 4>& w) {
  const double u = x / h;
  const double fl = std::floor(u);
  const double f = u - fl;
  // nodes at -1, 0, 1, 2 relative to fl
  const double a = f + 1.0, b = f, c = f - 1.0, d = f - 2.0;
  w[0] = -b * c * d / 6.0;
  w[1] = a * c * d / 2.0;
  w[2] = -a * b * d / 2.0;
  w[3] = a * b * c / 6.0;
  return static_cast<std::int64_t>(fl) - 1;
}

// a process-wide number for each grid (never 0), so a thread's cache never mistakes a new grid
// at the address of a destroyed one for it
std::uint64_t next_id() {
  static std::atomic<std::uint64_t> counter{0};
  return ++counter;
}

}  // namespace

WaveGrid::WaveGrid(WaveField field, WaveGridSpec spec)
    : field_(std::move(field)), spec_(spec), slots_(kSlots), id_(next_id()) {
  field_.set_grid(nullptr);  // the fallback below the grid is the exact sum
  if (!(spec.ds > 0.0) || !std::isfinite(spec.ds))
    throw std::invalid_argument(fmt::format("ds must be > 0, got {}", spec.ds));
  if (!(spec.dz > 0.0) || !std::isfinite(spec.dz))
    throw std::invalid_argument(fmt::format("dz must be > 0, got {}", spec.dz));
  if (!(spec.dz_growth >= 0.0) || !std::isfinite(spec.dz_growth))
    throw std::invalid_argument(fmt::format("dz_growth must be >= 0, got {}", spec.dz_growth));
  if (!(spec.dt > 0.0) || !std::isfinite(spec.dt))
    throw std::invalid_argument(fmt::format("dt must be > 0, got {}", spec.dt));
  comps_ = field_.components();
  std::stable_sort(comps_.begin(), comps_.end(),
                   [](const WaveComponent& a, const WaveComponent& b) { return a.k < b.k; });
  const auto& comps = comps_;
  turn_.resize(2 * comps.size());  // e^{i w dt}, the time phasors' step
  for (std::size_t i = 0; i < comps.size(); ++i) {
    turn_[2 * i] = std::cos(comps[i].omega * spec.dt);
    turn_[2 * i + 1] = std::sin(comps[i].omega * spec.dt);
  }
  if (!comps.empty()) {
    for (const auto& c : comps)
      if (c.direction != comps.front().direction)
        throw std::invalid_argument(
            "the components travel in more than one direction: grid kinematics need a "
            "long-crested sea");
    cos_b_ = std::cos(comps.front().direction);
    sin_b_ = std::sin(comps.front().direction);
  }
  // the deepest level: the seabed, or in deep water where e^{k_min z} < 1e-9
  const double depth = field_.depth();
  const bool deep = std::isinf(depth);
  double bottom = depth;
  if (deep) {
    double kmin = std::numeric_limits<double>::infinity();
    for (const auto& c : comps)
      if (c.amplitude != 0.0 && c.k > 0.0) kmin = std::min(kmin, c.k);
    bottom = std::isfinite(kmin) ? 21.0 / kmin : 1.0;
  }
  z_.push_back(0.0);
  while (z_.back() > -bottom) {
    const double next = z_.back() - (spec.dz + spec.dz_growth * (-z_.back()));
    z_.push_back(std::max(next, -bottom));
    if (static_cast<int>(z_.size()) > kMaxLevels)
      throw std::invalid_argument(
          fmt::format("dz: more than {} levels over the depth of {:g} m: increase dz or dz_growth",
                      kMaxLevels, bottom));
  }
  if (z_.size() < 4) z_ = {0.0, -bottom / 3.0, -2.0 * bottom / 3.0, -bottom};  // a cubic: 4
  if (!deep)
    for (double& z : z_) z = std::max(z, -depth);
  z_den_.resize(z_.size() - 3);
  for (std::size_t j0 = 0; j0 + 3 < z_.size(); ++j0)
    for (std::size_t a = 0; a < 4; ++a) {
      double den = 1.0;
      for (std::size_t b = 0; b < 4; ++b)
        if (b != a) den *= z_[j0 + a] - z_[j0 + b];
      z_den_[j0][a] = 1.0 / den;
    }
  if (static_cast<double>(comps.size()) * static_cast<double>(z_.size()) > kMaxFactors)
    throw std::invalid_argument(fmt::format(
        "{} components x {} levels is more than {:g} depth factors: use fewer components or "
        "larger dz, dz_growth",
        comps.size(), z_.size(), kMaxFactors));
  const double column_bytes =
      8.0 * (1.0 + 5.0 * static_cast<double>(comps.size()) + 5.0 * static_cast<double>(z_.size())) +
      128.0;  // the map node, the vectors' headers
  max_columns_ =
      static_cast<std::int64_t>(std::max(64.0, std::min(spec.max_bytes / column_bytes, 1e12)));
  max_station_phasors_ = static_cast<std::size_t>(std::clamp(
      spec.max_bytes / 8.0 / (16.0 * static_cast<double>(std::max<std::size_t>(comps.size(), 1))),
      1.0, 4096.0));
  // depth factors at every level (the same expressions as WaveField::airy)
  const std::size_t J = z_.size(), N = comps.size();
  fh_.assign(comps.size() * J, 0.0);
  fv_.assign(comps.size() * J, 0.0);
  fp_.assign(comps.size() * J, 0.0);
  for (std::size_t i = 0; i < comps.size(); ++i) {
    const double k = comps[i].k;
    if (comps[i].amplitude == 0.0 || comps[i].omega == 0.0) continue;  // as WaveField::airy
    for (std::size_t j = 0; j < J; ++j) {
      const double z = z_[j];
      const double ekz = std::exp(k * z);
      if (deep) {
        fh_[j * N + i] = fv_[j * N + i] = fp_[j * N + i] = ekz;
      } else {
        const double e_image = std::exp(-k * (z + 2.0 * depth));
        const double e2 = std::exp(-2.0 * k * depth);
        const double one_minus = -std::expm1(-2.0 * k * depth);
        fh_[j * N + i] = (ekz + e_image) / one_minus;
        fv_[j * N + i] = (ekz - e_image) / one_minus;
        fp_[j * N + i] = (ekz + e_image) / (1.0 + e2);
      }
    }
  }
  // depth truncation (file header): at each level the shortest components whose summed
  // bound is below kTruncation of the surface's, for each of the five values
  keep_.assign(J, N);
  std::array<double, 3> surface{};  // sum |a| w, sum |a| w^2, sum |a|
  auto weights = [&](std::size_t i) {
    const double a = std::abs(comps[i].amplitude), w = std::abs(comps[i].omega);
    return std::array<double, 3>{a * w, a * w * w, a};
  };
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t q = 0; q < 3; ++q) surface[q] += weights(i)[q];
  for (std::size_t j = 0; j < J; ++j) {
    std::array<double, 3> tail{};  // of u and du/dt (both factors), and of p
    std::size_t n = N;
    while (n > 0) {
      const std::size_t i = n - 1;
      const auto wq = weights(i);
      const double fhv = std::max(std::abs(fh_[j * N + i]), std::abs(fv_[j * N + i]));
      const std::array<double, 3> next{tail[0] + wq[0] * fhv, tail[1] + wq[1] * fhv,
                                       tail[2] + wq[2] * std::abs(fp_[j * N + i])};
      bool small = true;
      for (std::size_t q = 0; q < 3; ++q) small = small && next[q] <= kTruncation * surface[q];
      if (!small) break;
      tail = next;
      --n;
    }
    keep_[j] = n;
  }
}

std::int64_t WaveGrid::columns_started() const {
  const std::lock_guard<std::shared_mutex> lock(mutex_);
  return started_;
}

std::int64_t WaveGrid::blocks_filled() const {
  const std::lock_guard<std::shared_mutex> lock(mutex_);
  return blocks_;
}

std::int64_t WaveGrid::columns_stored() const {
  const std::lock_guard<std::shared_mutex> lock(mutex_);
  return stored_;
}

const std::vector<double>& WaveGrid::station_phasors(std::int64_t m) const {
  if (station_phasors_.size() >= max_station_phasors_ && !station_phasors_.count(m))
    station_phasors_.clear();  // bounded memory (a line sweeping across many stations)
  auto [it, inserted] = station_phasors_.try_emplace(m);
  if (inserted) {
    const auto& comps = comps_;
    const double s = static_cast<double>(m) * spec_.ds;
    it->second.resize(2 * comps.size());
    for (std::size_t i = 0; i < comps.size(); ++i) {
      const double ks = comps[i].k * s;
      it->second[2 * i] = std::cos(ks);
      it->second[2 * i + 1] = std::sin(ks);
    }
  }
  return it->second;
}

void WaveGrid::recycle(Slot& slot) const {
  stored_ -= static_cast<std::int64_t>(slot.columns.size());
  for (auto& kv : slot.columns) {
    if (spare_.size() >= kSpareColumns) break;
    spare_.push_back(std::move(kv.second));
  }
  slot.columns.clear();
}

WaveGrid::Column& WaveGrid::column(std::int64_t m, std::int64_t n) const {
  Slot& slot = slot_of(n);
  const auto& comps = comps_;
  const std::size_t N = comps.size();
  if (slot.n != n) {
    recycle(slot);
    slot.n = n;
    ++generation_;
    // the time phasors of t_n, shared by its stations: N sines and cosines at an anchor
    // (every kAnchor-th sample), the samples after it by turning the previous one's by
    // e^{i w dt}: each sample's phasors are the same chain of products from its anchor
    // whichever order the samples are made in (from sample n - 1 when its slot holds it,
    // else from the anchor), so the values do not depend on the evaluation order (a restart,
    // the thread); the chain's round-off grows to a few kAnchor ulps at most
    const std::int64_t anchor = n - ((n % kAnchor) + kAnchor) % kAnchor;
    const Slot& before = slot_of(n - 1);
    std::int64_t from = anchor;
    slot.phasors.resize(2 * N);
    if (n != anchor && before.n == n - 1 && before.phasors.size() == 2 * N) {
      slot.phasors = before.phasors;
      from = n - 1;
    } else {
      const double t = static_cast<double>(anchor) * spec_.dt;
      for (std::size_t i = 0; i < N; ++i) {
        const double wt = comps[i].omega * t + comps[i].phase;
        slot.phasors[2 * i] = std::cos(wt);
        slot.phasors[2 * i + 1] = std::sin(wt);
      }
    }
    for (std::int64_t k = from; k < n; ++k)
      for (std::size_t i = 0; i < N; ++i) {
        const double c = slot.phasors[2 * i], sn = slot.phasors[2 * i + 1];
        const double rc = turn_[2 * i], rs = turn_[2 * i + 1];
        slot.phasors[2 * i] = c * rc - sn * rs;
        slot.phasors[2 * i + 1] = sn * rc + c * rs;
      }
  }
  auto [it, inserted] = slot.columns.try_emplace(m);
  Column& col = it->second;
  if (!inserted) return col;
  if (!spare_.empty()) {  // its vectors keep their sizes: resize and assign below are cheap
    col = std::move(spare_.back());
    spare_.pop_back();
    col.eta = 0.0;
  }
  // the elevation and the coefficients at (s_m, t_n): theta = (w t_n + phase) - k s_m, so
  // cos theta = cos A cos B + sin A sin B, sin theta = sin A cos B - cos A sin B with
  // A = w t_n + phase (the slot's phasors) and B = k s_m (the station's)
  const std::vector<double>& st = station_phasors(m);
  const std::vector<double>& tp = slot.phasors;
  const std::size_t J = z_.size();
  col.coef.resize(5 * N);
  for (std::size_t i = 0; i < N; ++i) {
    const auto& c = comps[i];
    const double cA = tp[2 * i], sA = tp[2 * i + 1], cB = st[2 * i], sB = st[2 * i + 1];
    const double ac = c.amplitude * (cA * cB + sA * sB), as = c.amplitude * (sA * cB - cA * sB);
    col.eta += ac;
    const double w = c.omega, ww = c.omega * c.omega;
    col.coef[i] = w * ac;            // u_h
    col.coef[N + i] = -ww * as;      // du_h/dt
    col.coef[2 * N + i] = -w * as;   // u_z
    col.coef[3 * N + i] = -ww * ac;  // du_z/dt
    col.coef[4 * N + i] = ac;        // p / (rho g)
  }
  col.values.assign(5 * J, 0.0);
  col.filled.assign((J + kBlock - 1) / kBlock, 0);
  col.filled_p.assign(col.filled.size(), 0);
  ++started_;
  ++stored_;
  return col;
}

void WaveGrid::fill_levels(Column& col, std::size_t j0, std::size_t j1, bool pressure) const {
  const std::size_t J = z_.size();
  const auto N = static_cast<Eigen::Index>(comps_.size());
  for (std::size_t blk = j0 / kBlock; blk <= j1 / kBlock; ++blk) {
    const bool kin = !col.filled[blk], pre = pressure && !col.filled_p[blk];
    if (!kin && !pre) continue;
    if (kin) ++blocks_;
    col.filled[blk] = 1;
    if (pressure) col.filled_p[blk] = 1;
    // the exact sums at the block's levels, without the ramp (WaveField::airy), over the
    // components the block's top level keeps (depth truncation: the deeper levels keep
    // fewer, and their further terms, each below the truncation's bound, are added too):
    // the four kinematics values of the block's levels as sums of the levels' depth factors
    // (rows) times the column's coefficients (math/row_sums.hpp, each row read once for two
    // of them); the pressure, when asked, a dot product per level over the level's own
    // components
    const std::size_t lo = blk * kBlock, hi = std::min(J, lo + kBlock);
    using CMap = Eigen::Map<const Eigen::VectorXd>;
    if (kin) {
      const int rows = static_cast<int>(hi - lo);
      const std::size_t n = keep_[lo], NN = static_cast<std::size_t>(N);
      const std::size_t row = lo * NN;
      double* v = col.values.data();
      const double* c = col.coef.data();
      math::row_sums_pair(fh_.data() + row, NN, rows, c, c + NN, n, v + lo,
                          v + 2 * J + lo);  // uh, ah
      math::row_sums_pair(fv_.data() + row, NN, rows, c + 2 * NN, c + 3 * NN, n, v + J + lo,
                          v + 3 * J + lo);  // uz, az
    }
    if (!pre) continue;
    for (std::size_t j = lo; j < hi; ++j) {
      const auto n = static_cast<Eigen::Index>(keep_[j]);
      const CMap c_p(col.coef.data() + 4 * N, n),
          fp(fp_.data() + j * static_cast<std::size_t>(N), n);
      col.values[4 * J + j] = fp.dot(c_p);
    }
  }
}

thread_local WaveGrid::StencilCache WaveGrid::t_cache_;

const std::array<WaveGrid::Column*, 16>* WaveGrid::cached_stencil(std::int64_t m0,
                                                                  std::int64_t n0) const {
  const StencilCache& c = t_cache_;
  if (c.grid == id_ && c.generation == generation_ && c.m0 == m0 && c.n0 == n0) return &c.cols;
  return nullptr;
}

const std::array<WaveGrid::Column*, 16>* WaveGrid::stencil(std::int64_t m0, std::int64_t n0) const {
  if (const auto* hit = cached_stencil(m0, n0)) return hit;
  // the memory cap: the columns this stencil would add, less those a cleared slot frees
  const auto stored_after = [&] {
    std::int64_t after = stored_;
    for (int b = 0; b < 4; ++b) {
      const Slot& slot = slot_of(n0 + b);
      if (slot.n != n0 + b) {
        after += 4 - static_cast<std::int64_t>(slot.columns.size());
        continue;
      }
      for (int a = 0; a < 4; ++a) after += slot.columns.count(m0 + a) ? 0 : 1;
    }
    return after;
  };
  if (stored_after() > max_columns_) {
    // over the cap: first drop the times other than the stencil's and the next few
    for (Slot& slot : slots_)
      if (!slot.columns.empty() && (slot.n < n0 || slot.n > n0 + 7)) {
        stored_ -= static_cast<std::int64_t>(slot.columns.size());
        slot.columns.clear();
        slot.n = INT64_MIN;
        ++generation_;
      }
    spare_.clear();
    spare_.shrink_to_fit();
    if (stored_after() > max_columns_) return nullptr;
  }
  StencilCache& cache = t_cache_;
  for (int b = 0; b < 4; ++b)
    for (int a = 0; a < 4; ++a)
      cache.cols[static_cast<std::size_t>(4 * b + a)] = &column(m0 + a, n0 + b);
  // column() may have cleared a slot: the generation after the 16 lookups (they never clear
  // one another's slots: 4 consecutive times use 4 different slots)
  cache.grid = id_;
  cache.generation = generation_;
  cache.m0 = m0;
  cache.n0 = n0;
  return &cache.cols;
}

thread_local WaveGrid::SliceCache WaveGrid::t_slices_;

WaveGrid::SliceCache& WaveGrid::slices_at(double t) const {
  SliceCache& c = t_slices_;
  // a slice is (5 J + 1) doubles and its flags: at most a quarter of the columns' budget
  if (!c.valid || c.grid != id_ || c.t != t || static_cast<double>(c.bytes) > spec_.max_bytes / 4) {
    c.stations.clear();
    c.last = {};
    c.bytes = 0;
    c.grid = id_;
    c.t = t;
    c.valid = true;
  }
  return c;
}

bool WaveGrid::find_slices(SliceCache& cache, std::int64_t m0, std::array<Slice*, 4>& sl) const {
  if (cache.last[0] && cache.last_m0 == m0) {
    sl = cache.last;
    return true;
  }
  for (std::size_t a = 0; a < 4; ++a) {
    const auto it = cache.stations.find(m0 + static_cast<std::int64_t>(a));
    if (it == cache.stations.end()) return false;
    sl[a] = &it->second;
  }
  cache.last_m0 = m0;
  cache.last = sl;
  return true;
}

void WaveGrid::make_slices(const std::array<Column*, 16>& cols, const std::array<double, 4>& wt,
                           std::int64_t m0, SliceCache& cache, std::array<Slice*, 4>& out) const {
  const std::size_t J = z_.size();
  for (int a = 0; a < 4; ++a) {
    auto [it, inserted] = cache.stations.try_emplace(m0 + a);
    Slice& sl = it->second;
    out[static_cast<std::size_t>(a)] = &sl;
    if (!inserted) continue;
    for (int b = 0; b < 4; ++b)
      sl.eta += wt[static_cast<std::size_t>(b)] * cols[static_cast<std::size_t>(4 * b + a)]->eta;
    sl.values.assign(5 * J, 0.0);
    sl.filled.assign((J + kBlock - 1) / kBlock, 0);
    sl.filled_p.assign(sl.filled.size(), 0);
    cache.bytes += 8 * (5 * J + 1) + 2 * sl.filled.size() + 64;
  }
}

void WaveGrid::fill_slices(const std::array<Column*, 16>& cols, const std::array<double, 4>& wt,
                           const std::array<Slice*, 4>& sl, std::size_t j0, bool pressure) const {
  const std::size_t J = z_.size();
  for (int a = 0; a < 4; ++a) {
    Slice& s = *sl[static_cast<std::size_t>(a)];
    for (std::size_t blk = j0 / kBlock; blk <= (j0 + 3) / kBlock; ++blk) {
      // the four kinematics values [0, 4) and the pressure [4, 5), each once
      const std::size_t q0 = s.filled[blk] ? 4 : 0, q1 = pressure && !s.filled_p[blk] ? 5 : 4;
      if (q0 >= q1) continue;
      const std::size_t lo = blk * kBlock, hi = std::min(J, lo + kBlock);
      for (int b = 0; b < 4; ++b) {
        Column& c = *cols[static_cast<std::size_t>(4 * b + a)];
        fill_levels(c, lo, hi - 1, pressure);
        const double w = wt[static_cast<std::size_t>(b)];
        for (std::size_t q = q0; q < q1; ++q)
          for (std::size_t j = lo; j < hi; ++j) s.values[q * J + j] += w * c.values[q * J + j];
      }
      s.filled[blk] = 1;
      if (pressure) s.filled_p[blk] = 1;
    }
  }
}

WaveGrid::Outcome WaveGrid::evaluate_slices(const std::array<Slice*, 4>& sl,
                                            const std::array<double, 4>& ws, const Vec3& p,
                                            double ramp, bool pressure, FluidKinematics& out,
                                            std::size_t& j0) const {
  const std::size_t J = z_.size();
  double eta = 0.0;
  for (std::size_t a = 0; a < 4; ++a) eta += ws[a] * sl[a]->eta;
  eta *= ramp;
  if (p.z() > eta) {
    out = FluidKinematics{};
    return Outcome::kDone;
  }
  const double depth = field_.depth();
  const bool deep = std::isinf(depth);
  double z = p.z();
  if (!deep && z < -depth) z = -depth;
  double z_eval;
  if (field_.wheeler_stretching()) {
    // Wheeler (1970), as WaveField::kinematics
    z_eval = deep ? z - eta : depth * (z - eta) / (depth + eta);
  } else {
    z_eval = std::min(z, 0.0);
  }
  if (z_eval < z_.back()) return Outcome::kExact;  // deep water below the grid
  z_eval = std::min(z_eval, 0.0);
  // the level interval z_j >= z_eval >= z_{j+1} (levels descend), then 4 levels around it
  const auto it = std::lower_bound(z_.begin(), z_.end(), z_eval, std::greater<double>());
  const std::ptrdiff_t j = std::max<std::ptrdiff_t>(0, (it - z_.begin()) - 1);
  j0 = static_cast<std::size_t>(
      std::clamp<std::ptrdiff_t>(j - 1, 0, static_cast<std::ptrdiff_t>(J) - 4));
  for (const Slice* s : sl)
    if (!s->filled[j0 / kBlock] || !s->filled[(j0 + 3) / kBlock] ||
        (pressure && (!s->filled_p[j0 / kBlock] || !s->filled_p[(j0 + 3) / kBlock])))
      return Outcome::kFill;
  // 4-point Lagrange weights in z with the stored denominators
  const double* zn = z_.data() + j0;
  const double d0 = z_eval - zn[0], d1 = z_eval - zn[1], d2 = z_eval - zn[2], d3 = z_eval - zn[3];
  const std::array<double, 4>& den = z_den_[j0];
  const std::array<double, 4> wz{d1 * d2 * d3 * den[0], d0 * d2 * d3 * den[1],
                                 d0 * d1 * d3 * den[2], d0 * d1 * d2 * den[3]};
  std::array<double, 5> v{};
  const std::size_t values = pressure ? 5 : 4;
  for (std::size_t a = 0; a < 4; ++a) {
    const double* col = sl[a]->values.data() + j0;
    for (std::size_t q = 0; q < values; ++q) {
      const double* cq = col + q * J;
      v[q] += ws[a] * (wz[0] * cq[0] + wz[1] * cq[1] + wz[2] * cq[2] + wz[3] * cq[3]);
    }
  }
  out.velocity = ramp * Vec3(v[0] * cos_b_, v[0] * sin_b_, v[1]);
  out.acceleration = ramp * Vec3(v[2] * cos_b_, v[2] * sin_b_, v[3]);
  out.dynamic_pressure =
      pressure ? ramp * field_.rho() * field_.g() * v[4] : std::numeric_limits<double>::quiet_NaN();
  out.wet = true;
  return Outcome::kDone;
}

double WaveGrid::elevation(double x, double y, double t) const {
  const double ramp = field_.ramp_factor(t);
  if (ramp == 0.0) return 0.0;
  std::array<double, 4> ws{}, wt{};
  const std::int64_t m0 = lattice_stencil(x * cos_b_ + y * sin_b_, spec_.ds, ws);
  SliceCache& cache = slices_at(t);
  std::array<Slice*, 4> sl{};
  const bool have = find_slices(cache, m0, sl);
  if (!have) {
    const std::int64_t n0 = lattice_stencil(t, spec_.dt, wt);
    const std::unique_lock<std::shared_mutex> lock(mutex_);
    const auto* cols = stencil(m0, n0);
    if (!cols) return field_.elevation(x, y, t);  // over the memory cap: exact
    make_slices(*cols, wt, m0, cache, sl);
  }
  double eta = 0.0;
  for (std::size_t a = 0; a < 4; ++a) eta += ws[a] * sl[a]->eta;
  return ramp * eta;
}

FluidKinematics WaveGrid::kinematics(const Vec3& p, double t, bool pressure) const {
  const double ramp = field_.ramp_factor(t);
  if (ramp == 0.0) {
    FluidKinematics calm;
    calm.wet = p.z() <= 0.0;
    return calm;
  }
  std::array<double, 4> ws{}, wt{};
  const std::int64_t m0 = lattice_stencil(p.x() * cos_b_ + p.y() * sin_b_, spec_.ds, ws);
  SliceCache& cache = slices_at(t);
  std::array<Slice*, 4> sl{};
  const bool have = find_slices(cache, m0, sl);
  FluidKinematics out;
  std::size_t j0 = 0;
  // the common case: this thread's slices at t hold the point's stations and levels
  Outcome outcome = have ? evaluate_slices(sl, ws, p, ramp, pressure, out, j0) : Outcome::kFill;
  if (outcome == Outcome::kFill) {
    const std::int64_t n0 = lattice_stencil(t, spec_.dt, wt);
    const std::unique_lock<std::shared_mutex> lock(mutex_);
    const auto* cols = stencil(m0, n0);
    if (!cols) return field_.kinematics(p, t);  // over the memory cap: exact
    if (!have) make_slices(*cols, wt, m0, cache, sl);
    outcome = evaluate_slices(sl, ws, p, ramp, pressure, out, j0);
    if (outcome == Outcome::kFill) {
      fill_slices(*cols, wt, sl, j0, pressure);
      outcome = evaluate_slices(sl, ws, p, ramp, pressure, out, j0);
    }
  }
  // below the grid in deep water: the exact sum
  return outcome == Outcome::kExact ? field_.kinematics(p, t) : out;
}

}  // namespace seaflex::hydro
