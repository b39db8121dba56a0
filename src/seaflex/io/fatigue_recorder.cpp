#include "seaflex/io/fatigue_recorder.hpp"

#include <fmt/format.h>

#include <exception>
#include <limits>

#include "seaflex/elements/ancf_cable.hpp"

namespace seaflex::io {

namespace {

constexpr double kYear = 365.25 * 86400.0;  // s

// the unit tangent r'/|r'| of the beam at a station
Vec3 tangent(const AncfBeam& beam, const State& state, const post::BeamStation& st) {
  const ancf_cable::Vec12 e = beam.element_coordinates(state.q, st.element);
  const double l = beam.element_length(st.element);
  return (ancf_cable::relative_nodes(e) * ancf_cable::shape_dx(st.xi, l)).normalized();
}

}  // namespace

std::vector<std::filesystem::path> FatigueRecorder::files(const std::filesystem::path& dir,
                                                          const std::string& prefix,
                                                          const std::string& beam) {
  return {dir / fmt::format("{}{}.fatigue.csv", prefix, beam),
          dir / fmt::format("{}{}.fatigue_stress.csv", prefix, beam)};
}

FatigueRecorder::FatigueRecorder(const std::filesystem::path& dir, const std::string& prefix,
                                 std::vector<post::BeamResults> beams,
                                 const FatigueSettings& settings)
    : settings_(settings) {
  for (auto& r : beams) {
    // the thinnest wall of the beam's sections
    double wall = settings_.thickness;
    if (!(wall > 0.0)) {
      wall = std::numeric_limits<double>::infinity();
      for (const BeamSection& sec : r.beam().sections())
        wall = std::min(wall, 0.5 * (sec.outer_diameter - sec.inner_diameter));
    }
    // DNV-RP-C203 (2016) eq. (2.4.3): ranges of the hot-spot stress (SCF included in the
    // stresses, record()) are scaled by (t/t_ref)^k
    const double factor = post::thickness_factor(wall, settings_.curve.t_ref, settings_.curve.k);
    const int histories = static_cast<int>(r.num_stations()) * settings_.points;
    const auto paths = files(dir, prefix, r.beam().name());
    beams_.push_back({std::move(r),
                      post::FatigueDamage(histories, settings_.curve, factor),
                      {},
                      paths[0],
                      paths[1],
                      {}});
    if (settings_.write_stresses) beams_.back().stresses = RowFile(paths[1]);
  }
}

void FatigueRecorder::begin(const std::vector<std::string>&) {
  for (auto& b : beams_) {
    if (!b.stresses.is_open()) continue;
    line_ = "time,station,s";
    for (int j = 0; j < settings_.points; ++j) fmt::format_to(std::back_inserter(line_), ",p{}", j);
    line_ += '\n';
    b.stresses.append(line_);
  }
}

void FatigueRecorder::record(const State& state, std::span<const double>) {
  if (state.t < settings_.start - 1e-9) return;
  if (rows_ == 0) t_first_ = state.t;
  t_last_ = state.t;
  ++rows_;
  const int points = settings_.points;
  for (auto& b : beams_) {
    b.results.compute(state, table_);
    const AncfBeam& beam = b.results.beam();
    const auto& stations = b.results.stations();
    buffer_.resize(stations.size() * static_cast<std::size_t>(points));
    if (b.reference.empty())
      for (const auto& st : stations)
        b.reference.push_back(post::circumference_reference(tangent(beam, state, st)));
    line_.clear();
    for (std::size_t i = 0; i < stations.size(); ++i) {
      const auto row = table_.row(static_cast<Index>(i));
      const Vec3 M(row(static_cast<int>(post::BeamQuantity::kMomentX)),
                   row(static_cast<int>(post::BeamQuantity::kMomentY)),
                   row(static_cast<int>(post::BeamQuantity::kMomentZ)));
      const double T_wall = row(static_cast<int>(post::BeamQuantity::kTensionWall));
      const BeamSection& sec = beam.section(stations[i].element);
      std::span<double> out(buffer_.data() + i * static_cast<std::size_t>(points),
                            static_cast<std::size_t>(points));
      post::pipe_fibre_stresses(T_wall, M, tangent(beam, state, stations[i]), b.reference[i],
                                sec.area, sec.second_moment, 0.5 * sec.outer_diameter, out);
      for (double& s : out) s *= settings_.scf;  // hot-spot stress
      if (b.stresses.is_open()) {
        fmt::format_to(std::back_inserter(line_), "{:.17g},{},{:.17g}", state.t, i, stations[i].s);
        for (double s : out) fmt::format_to(std::back_inserter(line_), ",{:.17g}", s);
        line_ += '\n';
      }
    }
    if (b.stresses.is_open()) b.stresses.append(line_);  // one write: whole rows only
    b.damage.add(buffer_);
  }
}

void FatigueRecorder::flush() {
  if (rows_ == 0) return;
  const double exposure = settings_.exposure > 0.0 ? settings_.exposure : t_last_ - t_first_;
  const int points = settings_.points;
  summary_.reset();
  std::exception_ptr failure;  // every file is attempted; the first failure is thrown after
  for (auto& b : beams_) {
    post::FatigueDamage done = b.damage;  // the residue counted on a copy: the run goes on
    done.finish();
    line_ = "station,s,worst_point,worst_angle_deg,damage,damage_per_year,life_years,exposure_s";
    for (int j = 0; j < points; ++j) fmt::format_to(std::back_inserter(line_), ",damage_p{}", j);
    line_ += '\n';
    const auto& stations = b.results.stations();
    for (std::size_t i = 0; i < stations.size(); ++i) {
      int worst = 0;
      for (int j = 1; j < points; ++j)
        if (done.damage(static_cast<int>(i) * points + j) >
            done.damage(static_cast<int>(i) * points + worst))
          worst = j;
      const double d = done.damage(static_cast<int>(i) * points + worst);
      const double per_year = exposure > 0.0 ? d * kYear / exposure : 0.0;
      const double life = per_year > 0.0 ? 1.0 / per_year : INFINITY;
      fmt::format_to(std::back_inserter(line_),
                     "{},{:.17g},{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}", i, stations[i].s,
                     worst, 360.0 * worst / points, d, per_year, life, exposure);
      for (int j = 0; j < points; ++j)
        fmt::format_to(std::back_inserter(line_), ",{:.17g}",
                       done.damage(static_cast<int>(i) * points + j));
      line_ += '\n';
      if (!summary_ || d > summary_->damage)
        summary_ = FatigueSummary{b.results.beam().name(), stations[i].s, worst, d, life, exposure};
    }
    try {
      write_file_atomically(b.path, line_);  // complete or absent
    } catch (const OutputError&) {
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace seaflex::io
