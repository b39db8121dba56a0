// A ParaView animation: per output row, one VTK XML PolyData file (.vtp, ASCII) per body
// and one for the sea surface in DIR/vtk/, and the collection DIR/<stem>.pvd listing them
// by time (one part per body), kept valid after every row. Beams are polylines through
// their result stations (post/beam_results.hpp) carrying every beam result and their
// diameter as point data; plates are quads through their nodes; rigid bodies are the box
// of uniform density with their mass and principal moments of inertia (sides
// a_k = sqrt(6 (I_j + I_l - I_k) / m)), on their principal axes; the sea surface is a grid
// over the model's horizontal extent with the wave elevation as z and as point data.
// Written only when asked (output.vtk, --vtk): the cost of a row is linear in the model.
#pragma once

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "seaflex/elements/ancf_plate.hpp"
#include "seaflex/elements/rigid_body.hpp"
#include "seaflex/hydro/ocean.hpp"
#include "seaflex/post/beam_results.hpp"
#include "seaflex/simulation/recorder.hpp"

namespace seaflex::io {

/// The sea surface drawn: a grid of n x n points over [x0, x1] x [y0, y1].
struct VtkSea {
  std::shared_ptr<const hydro::Ocean> ocean;
  double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0;
  int n = 41;
};

class VtkRecorder : public Recorder {
 public:
  /// Creates DIR/vtk and opens DIR/<stem>.pvd; throws std::runtime_error when it cannot.
  VtkRecorder(const std::filesystem::path& dir, const std::string& stem,
              std::vector<post::BeamResults> beams, std::vector<const AncfPlate*> plates,
              std::vector<const RigidBody*> bodies, std::optional<VtkSea> sea);
  ~VtkRecorder() override;
  VtkRecorder(const VtkRecorder&) = delete;
  VtkRecorder& operator=(const VtkRecorder&) = delete;

  void begin(const std::vector<std::string>& channels) override;
  void record(const State& state, std::span<const double> values) override;
  void flush() override;

  /// Side lengths (m) of the uniform box with mass m and principal moments I (ascending
  /// or not), in the order of I; a side that would be imaginary is 0.
  static Vec3 inertia_box(double mass, const Vec3& principal_moments);

 private:
  void write_piece(const std::string& name, const std::string& text);

  std::filesystem::path dir_, vtk_dir_;
  std::string stem_;
  std::vector<post::BeamResults> beams_;
  std::vector<double> beam_diameters_;
  std::vector<const AncfPlate*> plates_;
  std::vector<const RigidBody*> bodies_;
  std::vector<std::pair<Mat3, Vec3>> boxes_;  // principal axes (body frame), sides
  std::optional<VtkSea> sea_;
  std::FILE* pvd_ = nullptr;
  long rows_ = 0;
  double t_ = 0.0;       // time of the row being written
  std::string entries_;  // this row's DataSet lines
  MatX table_;
  std::string text_;
};

}  // namespace seaflex::io
