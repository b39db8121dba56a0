#include "mode_output.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <stdexcept>

#include "seaflex/core/output_file.hpp"
#include "seaflex/io/output_selection.hpp"
#include "seaflex/io/vtk_recorder.hpp"

namespace seaflex::cli {

std::vector<Index> position_coordinates(const io::Model& model) {
  std::vector<Index> out;
  for (const auto& b : model.system->bodies()) {
    if (const auto* beam = dynamic_cast<const AncfBeam*>(b.get())) {
      for (int k = 0; k < beam->num_nodes(); ++k) out.push_back(beam->node_index(k));
    } else if (const auto* plate = dynamic_cast<const AncfPlate*>(b.get())) {
      for (int i = 0; i <= plate->nx(); ++i)
        for (int j = 0; j <= plate->ny(); ++j) out.push_back(plate->node_index(i, j));
    } else if (dynamic_cast<const RigidBody*>(b.get())) {
      out.push_back(b->offset());  // the centre of mass: the first three coordinates
    }
  }
  return out;
}

void clear_mode_shapes(const std::filesystem::path& dir) {
  std::error_code ec;
  std::vector<std::filesystem::path> stale;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    const bool animation = name.starts_with("mode") && name.ends_with(".pvd") && name.size() > 8 &&
                           name.find_first_not_of("0123456789", 4) == name.size() - 4;
    if (animation) stale.push_back(entry.path());
  }
  for (const auto& p : stale) {
    std::filesystem::remove(p, ec);
    std::filesystem::remove_all(dir / "vtk" / p.stem(), ec);
  }
  std::filesystem::remove(dir / "mode_shapes.csv", ec);
}

void write_mode_shapes(const io::Model& model, const State& state, const ModalResult& modes,
                       const std::filesystem::path& dir, bool vtk) {
  const System& sys = *model.system;
  const std::filesystem::path path = dir / "mode_shapes.csv";
  std::string text = "coordinate";
  for (Index k = 0; k < modes.shapes.cols(); ++k)
    fmt::format_to(std::back_inserter(text), ",mode{}", k + 1);
  text += '\n';
  for (Index i = 0; i < modes.shapes.rows(); ++i) {
    text += sys.coordinate_name(i);
    for (Index k = 0; k < modes.shapes.cols(); ++k)
      fmt::format_to(std::back_inserter(text), ",{:.17g}", modes.shapes(i, k));
    text += '\n';
  }
  write_file_atomically(path, text);  // complete or absent, never through a planted link
  if (!vtk) return;
  const std::vector<Index> positions = position_coordinates(model);
  Eigen::AlignedBox<double, 3> box;
  for (Index i : positions) box.extend(Vec3(state.q.segment<3>(i)));
  const double extent = box.isEmpty() ? 1.0 : std::max(1.0, box.sizes().maxCoeff());
  for (Index k = 0; k < modes.shapes.cols(); ++k) {
    const VecX phi = modes.shapes.col(k);
    double largest = 0.0;
    for (Index i : positions) largest = std::max(largest, phi.segment<3>(i).norm());
    const double a = largest > 0.0 ? 0.05 * extent / largest : 0.0;
    const double T = modes.frequency_hz[k] > 0.0 ? 1.0 / modes.frequency_hz[k] : 1.0;
    std::vector<post::BeamResults> beams;
    for (const AncfBeam* b : io::output_beams(model))
      beams.emplace_back(*b, io::pipe_pressure(model, *b), model.output.beam_gauss_points);
    io::VtkRecorder rec(dir, fmt::format("mode{}", k + 1), std::move(beams),
                        io::output_plates(model), io::output_rigid_bodies(model), std::nullopt);
    rec.begin({});
    State s = state;
    for (int j = 0; j <= kModeFrames; ++j) {
      s.t = T * j / kModeFrames;
      s.q = state.q + a * std::sin(2.0 * std::numbers::pi * j / kModeFrames) * phi;
      rec.record(s, {});
    }
    rec.flush();
  }
}

}  // namespace seaflex::cli
