// Wave kinematics interpolated from a space-time grid, at a cost per evaluation that does
// not depend on the number of wave components (issue 21; docs/model-format.md 4.2,
// docs/verification.md "Grid wave kinematics").
// - The exact field (wave_field.hpp) is a sum over N Airy components at every point and time.
//   For a long-crested sea (all components travel along one direction b) it depends on
//   s = x cos b + y sin b, z and t only. The grid holds, at stations s_m = m ds (every
//   integer m, filled when first needed), levels z_j in [-d, 0] and times t_n = n dt, the
//   exact sums (without the ramp) of eta(s, t) and of the Airy velocity, local acceleration
//   and dynamic pressure at z_j. A column (s_m, t_n) costs N complex products when first
//   asked for (its elevation: the phase w t_n - k s_m + phase is the product of a time
//   phasor e^{i (w t_n + phase)}, N complex products per time sample from the previous
//   sample's, N sines and cosines at every 64th (kAnchor), and a station
//   phasor e^{-i k s_m}, N once per station), and 4 N multiply-adds per level for the
//   velocity and acceleration (N more for the pressure, only when a caller asks for it: a
//   beam's Morison load does not), filled by blocks of kBlock levels as points need them;
//   each once per run. The cost per
//   evaluation (16 columns x 4 levels x 5 values) does not depend on N; the filling grows
//   with N times the grid nodes the line visits (one new time sample per dt).
// - Depth truncation: the components are kept sorted by wave number, and level z_j sums only
//   the first n_j of them, those whose dropped tail is provably negligible: for each of the
//   five values q (weights w_q = w, w^2, w, w^2, 1 of a_i), the dropped terms' bound
//   sum_{i >= n_j} |a_i| w_q(w_i) |f_q,i(z_j)| is at most kTruncation = 1e-14 times the
//   value's largest possible size at the surface, sum_i |a_i| w_q(w_i) (|cos| <= 1). Short
//   waves die out with depth (e^{k z}), so deep levels sum a fraction of the components
//   (storm: all above about -30 m, a quarter at the seabed of 290 m); the error is far below
//   the interpolation's and below the 1e-12 to which the grid equals the sum at its nodes.
//   The velocity and acceleration of a block of kBlock levels are summed together, over the
//   components of its top level (the deeper levels' further terms are inside their bound:
//   summing them is as exact), as row sums (math/row_sums.hpp); the pressure level by level.
// - Levels: z_0 = 0, z_{j+1} = z_j - (dz + dz_growth |z_j|), the last one at -d (deep
//   water: at -21 / k_min, where e^{k_min z} < 1e-9; below it the exact sum is used): fine
//   at the surface where the shortest components live, coarse at depth where only the long
//   ones remain.
// - A point is evaluated as the exact field does, with every sum replaced by 4-point
//   Lagrange interpolation (cubic) in s, in t and (on the unequal levels) in z: eta(s, t)
//   first; above it the point is dry; below, Wheeler stretching maps z to
//   z_s = d (z - eta) / (d + eta) (deep: z - eta; without stretching z_s = min(z, 0)) and the
//   Airy values are interpolated at (s, z_s, t). Stretching thus costs nothing extra and its
//   error is that of eta times dU/dz.
// - Error of cubic Lagrange interpolation of cos(k x) with spacing h on the middle interval:
//   at most (9/16)/4! (k h)^4 = 0.0234 (k h)^4 of the amplitude (e.g. Davis 1975,
//   "Interpolation and Approximation", thm. 3.1.1); for a component of frequency w, each
//   direction adds 0.0234 (k ds)^4, 0.0234 (w dt)^4 and 0.0234 (k h_z)^4 e^{k z} of its
//   amplitude. With the defaults (ds 0.25 m, dz 0.25 m, dz_growth 0.1, dt 0.1 s) the
//   shortest component of the default band (5 wp) of a Tp = 10 s sea (w = 3.14 rad/s,
//   k = 1.0 rad/m) is within 2.2e-4 (time) + 9e-5 (s) + 9e-5 (z) of its own amplitude; the
//   whole JONSWAP sea (Hs 6 m, Tp 10 s, 200 components) within 1e-4 of the RMS velocity,
//   RMS elevation and rho g RMS elevation, 2e-4 of the RMS acceleration, measured at 1800
//   points between the nodes, with and without stretching (tests/unit/test_wave_grid.cpp).
// Time slices: all the points of one time (every Newton iteration of a step asks at the
// same t) share the time interpolation. Each thread keeps, for the t it last asked at, the
// columns of each station it visited contracted in time, S_m(j) = sum_b w_b(t) C(m, n0 + b)(j)
// (filled by blocks of levels as the columns are); a point then costs 4 stations x 4 levels x
// 5 values instead of 16 columns x 4 levels x 5, and no lock. The sums are the same tensor
// product as before, in another order (round-off only).
// Columns live in a ring of 64 time slots (memory ~ 64 x stations visited x (5 N + 5 J)
// doubles, a few MB for a riser; a slot's columns are kept as spares for the next time,
// at most 64 of them); evaluations more than 60 dt apart recompute columns (a time
// loop's are not). Memory is capped at spec.max_bytes (256 MB): a point whose columns would
// exceed it (a line kilometres long across the waves at a fine ds) gets the exact sum, so the
// grid never makes a run fail or swap, only slower. Thread-safe: columns are read under a
// shared lock and created and filled under an exclusive one; their values do not depend on the
// order or the thread that fills them, so the results are identical for any number of threads
// (below the cap).
#pragma once

#include <array>
#include <cstdint>
#include <mutex>
#include <shared_mutex>
#include <unordered_map>
#include <vector>

#include "seaflex/hydro/wave_field.hpp"

namespace seaflex::hydro {

/// Grid spacings (docs/model-format.md 4.2, `grid`).
struct WaveGridSpec {
  double ds = 0.25;        ///< (m) station spacing along the wave direction, > 0
  double dz = 0.25;        ///< (m) level spacing at the mean surface, > 0
  double dz_growth = 0.1;  ///< (-) the spacing grows by this times the depth, >= 0
  double dt = 0.1;         ///< (s) time sample spacing, > 0
  /// (bytes) the most memory the stored columns may take; a point whose columns would
  /// exceed it gets the exact sum instead (correct, only slower). Not an input key.
  double max_bytes = 256e6;
};

class WaveGrid {
 public:
  /// The most levels the grid accepts, and the most depth factors (components x levels):
  /// guards against a resource blow-up.
  static constexpr int kMaxLevels = 20000;
  static constexpr double kMaxFactors = 2e7;

  /// field: the exact sea, long-crested (all components with one direction), without a
  /// grid of its own. Throws std::invalid_argument naming the field: "ds must be > 0, got
  /// 0" (same for dz, dt), "dz_growth must be >= 0, got -1", "dz: 25000 levels over the
  /// depth of 1000 m, more than 20000: increase dz or dz_growth", "100000 components x 51
  /// levels is more than 2e7 depth factors: use fewer components or larger dz, dz_growth",
  /// "the components travel in more than one direction: grid kinematics need a long-crested
  /// sea".
  WaveGrid(WaveField field, WaveGridSpec spec);

  /// As WaveField::elevation, interpolated.
  double elevation(double x, double y, double t) const;
  /// As WaveField::kinematics, interpolated (exact below the grid's deepest level). With
  /// pressure = false the dynamic pressure is neither filled nor interpolated (NaN).
  FluidKinematics kinematics(const Vec3& p, double t, bool pressure = true) const;

  /// The levels z_j (m), from 0 down.
  const std::vector<double>& levels() const { return z_; }
  const WaveGridSpec& spec() const { return spec_; }
  /// Work done so far: columns started (N sines and cosines each) and blocks of kBlock levels
  /// filled (N kBlock 4 multiply-adds each, 5 with the pressure).
  std::int64_t columns_started() const;
  /// Columns stored now, and the most that may be (spec().max_bytes).
  std::int64_t columns_stored() const;
  std::int64_t max_columns() const { return max_columns_; }
  std::int64_t blocks_filled() const;

  /// Levels per lazily filled block of a column.
  static constexpr int kBlock = 4;
  /// The dropped terms' bound at each level, relative to the surface's (file header).
  static constexpr double kTruncation = 1e-14;
  /// The number of components (the longest waves first) level j needs (its depth
  /// truncation); its velocity and acceleration sum those of its block's top level.
  std::size_t components_at_level(std::size_t j) const { return keep_[j]; }

 private:
  // one station and time: eta, the components' coefficients, and the Airy values
  // [uh(J), uz(J), ah(J), az(J), p/(rho g)(J)], filled by blocks of levels
  struct Column {
    double eta = 0.0;
    // [q N + i]: w a cos, -w^2 a sin, -w a sin, -w^2 a cos, a cos (of theta_i), the factors
    // of f_h, f_h, f_v, f_v, f_p in u_h, du_h/dt, u_z, du_z/dt, p/(rho g)
    std::vector<double> coef;
    std::vector<double> values;
    std::vector<char> filled;    // per block: the velocity and acceleration
    std::vector<char> filled_p;  // per block: the pressure (only when asked for)
  };
  struct Slot {
    std::int64_t n = INT64_MIN;
    std::unordered_map<std::int64_t, Column> columns;
    // the time phasors of t_n: [2 i] = cos(w_i t_n + phase_i), [2 i + 1] = sin(...), made
    // from the anchor's by turning (column())
    std::vector<double> phasors;
  };
  // the station phasors of s_m: [2 i] = cos(k_i s_m), [2 i + 1] = sin(k_i s_m); caller holds
  // mutex_. Kept for at most max_station_phasors_ stations (then all are dropped and made
  // again): 4096, or fewer so that they take at most an eighth of spec.max_bytes.
  const std::vector<double>& station_phasors(std::int64_t m) const;
  static constexpr int kSlots = 64;
  // the time samples whose phasors are sines and cosines; the others are turned from them
  static constexpr std::int64_t kAnchor = 64;
  // columns of recycled slots, kept to be filled again without allocating or zeroing their
  // coefficients (at most kSpareColumns; emptied with the slots when over the memory cap)
  static constexpr std::size_t kSpareColumns = 64;
  // empties a slot whose time is over, keeping its columns as spares; caller holds mutex_
  void recycle(Slot& slot) const;

  // the column (m, n), with its elevation and coefficients; caller holds mutex_
  Column& column(std::int64_t m, std::int64_t n) const;
  // fills the blocks of levels j0 .. j1 of col (the pressure too when asked); caller holds
  // mutex_
  void fill_levels(Column& col, std::size_t j0, std::size_t j1, bool pressure) const;
  // the 16 columns (m0 + a, n0 + b) at [4 b + a], or nullptr when storing the missing ones
  // would exceed max_columns_; caller holds mutex_ exclusively. Remembered per thread.
  const std::array<Column*, 16>* stencil(std::int64_t m0, std::int64_t n0) const;
  // this thread's remembered stencil if it is (m0, n0) and still valid, else nullptr; caller
  // holds mutex_ (shared is enough)
  const std::array<Column*, 16>* cached_stencil(std::int64_t m0, std::int64_t n0) const;
  // the last stencil of each thread (a Morison point asks 7 times at nearly one place)
  struct StencilCache {
    std::uint64_t grid = 0, generation = 0;
    std::int64_t m0 = 0, n0 = 0;
    std::array<Column*, 16> cols{};
  };
  static thread_local StencilCache t_cache_;
  enum class Outcome { kDone, kFill, kExact };
  // one station's columns contracted in time at one t (see the file header)
  struct Slice {
    double eta = 0.0;
    std::vector<double> values;  // [q J + j], as Column::values
    std::vector<char> filled;    // per block of levels: the velocity and acceleration
    std::vector<char> filled_p;  // per block of levels: the pressure
  };
  // this thread's slices at the time t of the grid `grid`, by station
  struct SliceCache {
    std::uint64_t grid = 0;
    double t = 0.0;
    bool valid = false;
    std::size_t bytes = 0;
    std::unordered_map<std::int64_t, Slice> stations;
    // the last four stations asked for (consecutive points of a line share them; map nodes
    // do not move until the map is cleared)
    std::int64_t last_m0 = 0;
    std::array<Slice*, 4> last{};
  };
  // the four slices m0 .. m0+3 of this thread's cache if all are there; caller has cache
  bool find_slices(SliceCache& cache, std::int64_t m0, std::array<Slice*, 4>& sl) const;
  static thread_local SliceCache t_slices_;
  // this thread's slice cache, emptied when it holds another time, grid or too much memory
  SliceCache& slices_at(double t) const;
  // the slices of the stations m0 .. m0+3 from the stencil's columns (elevation only, their
  // levels are filled by fill_slices); caller holds mutex_ exclusively
  void make_slices(const std::array<Column*, 16>& cols, const std::array<double, 4>& wt,
                   std::int64_t m0, SliceCache& cache, std::array<Slice*, 4>& out) const;
  // the blocks of levels j0 .. j0+3 of the four slices (the pressure too when asked), filling
  // the columns' first; caller holds mutex_ exclusively
  void fill_slices(const std::array<Column*, 16>& cols, const std::array<double, 4>& wt,
                   const std::array<Slice*, 4>& sl, std::size_t j0, bool pressure) const;
  // the point p from the four slices (its pressure when asked, else NaN): kDone (out set),
  // kExact (below the grid), kFill (a level block is missing: j0 set to the first of the 4
  // levels it needs)
  Outcome evaluate_slices(const std::array<Slice*, 4>& sl, const std::array<double, 4>& ws,
                          const Vec3& p, double ramp, bool pressure, FluidKinematics& out,
                          std::size_t& j0) const;
  Slot& slot_of(std::int64_t n) const {
    return slots_[static_cast<std::size_t>(((n % kSlots) + kSlots) % kSlots)];
  }

  WaveField field_;
  // field_'s components sorted by wave number (depth truncation); the grid uses these
  std::vector<WaveComponent> comps_;
  std::vector<std::size_t> keep_;  // components summed at each level
  std::vector<double> turn_;       // [2 i], [2 i + 1]: cos, sin of w_i dt (sorted components)
  WaveGridSpec spec_;
  double cos_b_ = 1.0, sin_b_ = 0.0;
  std::vector<double> z_;
  // 1 / prod_{b != a} (z_{j0+a} - z_{j0+b}): the Lagrange denominators of the 4 levels from j0
  std::vector<std::array<double, 4>> z_den_;
  // depth factors f_h, f_v, f_p of (sorted) component i at level j: [j * N + i]
  std::vector<double> fh_, fv_, fp_;
  mutable std::shared_mutex mutex_;
  mutable std::vector<Slot> slots_;
  mutable std::unordered_map<std::int64_t, std::vector<double>> station_phasors_;
  mutable std::int64_t started_ = 0, blocks_ = 0, stored_ = 0;
  mutable std::vector<Column> spare_;  // recycled columns (caller holds mutex_)
  std::int64_t max_columns_ = 0;
  std::size_t max_station_phasors_ = 4096;
  mutable std::uint64_t generation_ = 0;  // counts slot clearings (they free columns)
  std::uint64_t id_;                      // this grid, for the threads' stencil caches
};

}  // namespace seaflex::hydro
