#include "seaflex/io/code_check_recorder.hpp"

#include <fmt/format.h>

#include <exception>
#include <stdexcept>

#include "seaflex/core/output_file.hpp"
#include "seaflex/post/code_check.hpp"

namespace seaflex::io {

std::filesystem::path CodeCheckRecorder::file(const std::filesystem::path& dir,
                                              const std::string& prefix, const std::string& beam) {
  return dir / fmt::format("{}{}.code_check.csv", prefix, beam);
}

CodeCheckRecorder::CodeCheckRecorder(const std::filesystem::path& dir, const std::string& prefix,
                                     std::vector<post::BeamResults> beams,
                                     const CodeCheckSettings& settings)
    : settings_(settings) {
  for (auto& r : beams) {
    std::vector<post::DnvPipe> pipes;
    for (const BeamSection& sec : r.beam().sections()) {
      post::DnvPipe pipe;
      pipe.outer_diameter = sec.outer_diameter;
      pipe.wall = 0.5 * (sec.outer_diameter - sec.inner_diameter);
      pipe.corrosion = settings_.corrosion;
      pipe.fabrication = settings_.fabrication;
      pipe.smys = settings_.smys;
      pipe.smts = settings_.smts;
      pipe.youngs_modulus = sec.youngs_modulus;
      pipes.push_back(pipe);
    }
    const std::size_t n = static_cast<std::size_t>(r.num_stations());
    const auto path = file(dir, prefix, r.beam().name());
    beams_.push_back({std::move(r),
                      std::move(pipes),
                      {},
                      {},
                      std::vector<double>(n, -1.0),
                      std::vector<double>(n, 0.0),
                      std::vector<double>(n, -1.0),
                      std::vector<double>(n, 0.0),
                      path});
  }
}

void CodeCheckRecorder::begin(const std::vector<std::string>&) {}

void CodeCheckRecorder::record(const State& state, std::span<const double>) {
  if (state.t < settings_.start - 1e-9) return;
  any_ = true;
  const post::DnvFactors& f = settings_.factors;
  for (auto& b : beams_) {
    b.results.compute(state, table_);
    const Index n = table_.rows();
    const auto q = [&](Index i, post::BeamQuantity k) { return table_(i, static_cast<int>(k)); };
    if (b.moment_f.empty())
      for (Index i = 0; i < n; ++i) {
        b.moment_f.emplace_back(q(i, post::BeamQuantity::kMomentX),
                                q(i, post::BeamQuantity::kMomentY),
                                q(i, post::BeamQuantity::kMomentZ));
        b.tension_f.push_back(q(i, post::BeamQuantity::kTensionEffective));
      }
    for (Index i = 0; i < n; ++i) {
      const std::size_t k = static_cast<std::size_t>(i);
      const Vec3 M(q(i, post::BeamQuantity::kMomentX), q(i, post::BeamQuantity::kMomentY),
                   q(i, post::BeamQuantity::kMomentZ));
      const double T = q(i, post::BeamQuantity::kTensionEffective);
      // design load effects (post/code_check.hpp), gamma_C on the load effects
      const double m_d =
          f.gamma_C * (f.gamma_F * b.moment_f[k] + f.gamma_E * (M - b.moment_f[k])).norm();
      const double t_ed =
          f.gamma_C * (f.gamma_F * b.tension_f[k] + f.gamma_E * (T - b.tension_f[k]));
      const double u_dnv = post::dnv_combined_utilisation(
          b.pipes[b.results.beam().section_index(b.results.stations()[k].element)], f, m_d, t_ed,
          q(i, post::BeamQuantity::kPressureInternal), q(i, post::BeamQuantity::kPressureExternal));
      const double u_api = post::api_rp_2rd_utilisation(q(i, post::BeamQuantity::kStressVonMises),
                                                        settings_.smys, settings_.design_factor);
      if (u_dnv > b.dnv[k]) {
        b.dnv[k] = u_dnv;
        b.dnv_t[k] = state.t;
      }
      if (u_api > b.api[k]) {
        b.api[k] = u_api;
        b.api_t[k] = state.t;
      }
    }
  }
}

void CodeCheckRecorder::flush() {
  if (!any_) return;
  summary_ = {{"DNV-ST-F201", "", 0, -1, 0}, {"API RP 2RD", "", 0, -1, 0}};
  std::exception_ptr failure;  // every file is attempted; the first failure is thrown after
  for (auto& b : beams_) {
    std::string text = "station,s,dnv_utilisation,dnv_time,api_utilisation,api_time\n";
    const auto& stations = b.results.stations();
    for (std::size_t i = 0; i < stations.size(); ++i) {
      fmt::format_to(std::back_inserter(text), "{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", i,
                     stations[i].s, b.dnv[i], b.dnv_t[i], b.api[i], b.api_t[i]);
      const std::string& name = b.results.beam().name();
      if (b.dnv[i] > summary_[0].utilisation)
        summary_[0] = {"DNV-ST-F201", name, stations[i].s, b.dnv[i], b.dnv_t[i]};
      if (b.api[i] > summary_[1].utilisation)
        summary_[1] = {"API RP 2RD", name, stations[i].s, b.api[i], b.api_t[i]};
    }
    try {
      write_file_atomically(b.path, text);  // complete or absent
    } catch (const OutputError&) {
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

namespace {
VecX to_vec(const std::vector<double>& v) {
  return Eigen::Map<const VecX>(v.data(), static_cast<Index>(v.size()));
}
std::vector<double> from_vec(const VecX& v) {
  return {v.data(), v.data() + v.size()};
}
}  // namespace

bool CodeCheckRecorder::save(CheckpointWriter& out, const std::string& prefix) const {
  out.put(prefix + ".any", static_cast<long>(any_));
  for (std::size_t k = 0; k < beams_.size(); ++k) {
    const Beam& b = beams_[k];
    const std::string p = fmt::format("{}.beam{}", prefix, k);
    out.put(p + ".functional", static_cast<long>(!b.moment_f.empty()));
    if (!b.moment_f.empty()) {
      MatX m(static_cast<Index>(b.moment_f.size()), 3);
      for (std::size_t i = 0; i < b.moment_f.size(); ++i)
        m.row(static_cast<Index>(i)) = b.moment_f[i];
      out.put(p + ".moment_f", m);
      out.put(p + ".tension_f", to_vec(b.tension_f));
    }
    out.put(p + ".dnv", to_vec(b.dnv));
    out.put(p + ".dnv_t", to_vec(b.dnv_t));
    out.put(p + ".api", to_vec(b.api));
    out.put(p + ".api_t", to_vec(b.api_t));
  }
  return true;
}

void CodeCheckRecorder::restore(const CheckpointReader& in, const std::string& prefix) {
  any_ = in.integer(prefix + ".any", 0, 1) != 0;
  for (std::size_t k = 0; k < beams_.size(); ++k) {
    Beam& b = beams_[k];
    const std::string p = fmt::format("{}.beam{}", prefix, k);
    // every table has one entry per result station of this model's beam
    const auto n = static_cast<Index>(b.results.stations().size());
    b.moment_f.clear();
    if (in.integer(p + ".functional", 0, 1) != 0) {
      const MatX m = in.matrix(p + ".moment_f", n, 3);
      for (Index i = 0; i < m.rows(); ++i) b.moment_f.emplace_back(m.row(i).transpose());
      b.tension_f = from_vec(in.vector(p + ".tension_f", n));
    }
    b.dnv = from_vec(in.vector(p + ".dnv", n));
    b.dnv_t = from_vec(in.vector(p + ".dnv_t", n));
    b.api = from_vec(in.vector(p + ".api", n));
    b.api_t = from_vec(in.vector(p + ".api_t", n));
  }
}

}  // namespace seaflex::io
