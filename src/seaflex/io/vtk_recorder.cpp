#include "seaflex/io/vtk_recorder.hpp"
#include "seaflex/core/output_file.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <numbers>
#include <stdexcept>

#include "seaflex/post/plate_results.hpp"

namespace seaflex::io {

namespace {

constexpr const char* kPvdFooter = "  </Collection>\n</VTKFile>\n";

// the XML of one PolyData piece: points, then lines or polygons as connectivity lists
struct Piece {
  std::vector<Vec3> points;
  std::vector<std::vector<long>> lines, polys;
  std::vector<std::pair<std::string, std::vector<double>>> point_data;
};

void append_cells(std::string& out, const char* tag, const std::vector<std::vector<long>>& cells) {
  if (cells.empty()) return;
  fmt::format_to(std::back_inserter(out),
                 "      <{}>\n        <DataArray type=\"Int64\" Name=\"connectivity\" "
                 "format=\"ascii\">\n",
                 tag);
  for (const auto& c : cells)
    for (long i : c) fmt::format_to(std::back_inserter(out), " {}", i);
  out +=
      "\n        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" "
      "format=\"ascii\">\n";
  long offset = 0;
  for (const auto& c : cells) {
    offset += static_cast<long>(c.size());
    fmt::format_to(std::back_inserter(out), " {}", offset);
  }
  fmt::format_to(std::back_inserter(out), "\n        </DataArray>\n      </{}>\n", tag);
}

void render(const Piece& p, std::string& out) {
  out.clear();
  fmt::format_to(std::back_inserter(out),
                 "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
                 "byte_order=\"LittleEndian\">\n  <PolyData>\n    <Piece NumberOfPoints=\"{}\" "
                 "NumberOfVerts=\"0\" NumberOfLines=\"{}\" NumberOfStrips=\"0\" "
                 "NumberOfPolys=\"{}\">\n",
                 p.points.size(), p.lines.size(), p.polys.size());
  out += "      <PointData>\n";
  for (const auto& [name, values] : p.point_data) {
    fmt::format_to(std::back_inserter(out),
                   "        <DataArray type=\"Float64\" Name=\"{}\" format=\"ascii\">\n", name);
    // 17 significant digits: the numbers of the other result files, exactly
    for (double v : values) fmt::format_to(std::back_inserter(out), " {:.17g}", v);
    out += "\n        </DataArray>\n";
  }
  out +=
      "      </PointData>\n      <Points>\n        <DataArray type=\"Float64\" "
      "NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Vec3& x : p.points)
    fmt::format_to(std::back_inserter(out), " {:.17g} {:.17g} {:.17g}", x.x(), x.y(), x.z());
  out += "\n        </DataArray>\n      </Points>\n";
  append_cells(out, "Lines", p.lines);
  append_cells(out, "Polys", p.polys);
  out += "    </Piece>\n  </PolyData>\n</VTKFile>\n";
}

[[noreturn]] void fail(const std::filesystem::path& path) {
  throw OutputError(path, std::strerror(errno));
}

}  // namespace

Vec3 VtkRecorder::inertia_box(double mass, const Vec3& I) {
  // I_k = m (b^2 + c^2) / 12 for the sides b, c across axis k
  Vec3 sides;
  for (int k = 0; k < 3; ++k) {
    const double sq = 6.0 * (I[(k + 1) % 3] + I[(k + 2) % 3] - I[k]) / mass;
    sides[k] = sq > 0.0 ? std::sqrt(sq) : 0.0;
  }
  return sides;
}

VtkRecorder::VtkRecorder(const std::filesystem::path& dir, const std::string& stem,
                         std::vector<post::BeamResults> beams, std::vector<const AncfPlate*> plates,
                         std::vector<const RigidBody*> bodies, std::optional<VtkSea> sea)
    : dir_(dir),
      vtk_dir_(dir / "vtk" / stem),
      stem_(stem),
      beams_(std::move(beams)),
      plates_(std::move(plates)),
      bodies_(std::move(bodies)),
      sea_(std::move(sea)) {
  std::error_code ec;
  std::filesystem::create_directories(vtk_dir_, ec);
  if (ec)
    throw std::runtime_error(fmt::format("cannot create {}: {}", vtk_dir_.string(), ec.message()));
  for (const auto& b : beams_) {
    // one tube diameter per beam: its first section's
    const BeamSection& s = b.beam().section(0);
    const double d = b.pressure().external_diameter > 0.0 ? b.pressure().external_diameter
                     : s.outer_diameter > 0.0             ? s.outer_diameter
                                              : std::sqrt(4.0 * s.area / std::numbers::pi);
    beam_diameters_.push_back(d);
  }
  for (const RigidBody* body : bodies_) {
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(body->inertia());
    boxes_.emplace_back(eig.eigenvectors(), inertia_box(body->mass(), eig.eigenvalues()));
  }
  const auto path = dir_ / fmt::format("{}.pvd", stem_);
  pvd_ = std::fopen(path.c_str(), "w");
  if (!pvd_) fail(path);
}

VtkRecorder::~VtkRecorder() {
  if (pvd_) std::fclose(pvd_);
}

void VtkRecorder::begin(const std::vector<std::string>&) {
  std::fputs(
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" "
      "byte_order=\"LittleEndian\">\n  <Collection>\n",
      pvd_);
  std::fputs(kPvdFooter, pvd_);
  std::fflush(pvd_);
}

void VtkRecorder::write_piece(const std::string& name, const std::string& text) {
  const std::string file = fmt::format("{}_{:06d}.vtp", name, rows_);
  const auto path = vtk_dir_ / file;
  write_file_atomically(path, text);  // complete or absent
  const int part = static_cast<int>(std::count(entries_.begin(), entries_.end(), '\n'));
  fmt::format_to(std::back_inserter(entries_),
                 "    <DataSet timestep=\"{:.17g}\" group=\"\" part=\"{}\" name=\"{}\" "
                 "file=\"vtk/{}/{}\"/>\n",
                 t_, part, name, stem_, file);
}

void VtkRecorder::record(const State& state, std::span<const double>) {
  entries_.clear();
  t_ = state.t;
  const auto& info = post::beam_quantities();
  for (std::size_t b = 0; b < beams_.size(); ++b) {
    beams_[b].compute(state, table_);
    Piece p;
    std::vector<long> line;
    for (Index i = 0; i < table_.rows(); ++i) {
      p.points.emplace_back(table_(i, 0), table_(i, 1), table_(i, 2));
      line.push_back(static_cast<long>(i));
    }
    p.lines.push_back(std::move(line));
    std::vector<double> s;
    for (const auto& st : beams_[b].stations()) s.push_back(st.s);
    p.point_data.emplace_back("s", std::move(s));
    p.point_data.emplace_back("outer_diameter",
                              std::vector<double>(p.points.size(), beam_diameters_[b]));
    for (int q = static_cast<int>(post::BeamQuantity::kStrain); q < post::kBeamQuantityCount; ++q) {
      const auto c = table_.col(q);
      p.point_data.emplace_back(std::string(info[static_cast<std::size_t>(q)].name),
                                std::vector<double>(c.data(), c.data() + c.size()));
    }
    render(p, text_);
    write_piece(beams_[b].beam().name(), text_);
  }
  for (const AncfPlate* plate : plates_) {
    Piece p;
    for (int i = 0; i <= plate->nx(); ++i)
      for (int j = 0; j <= plate->ny(); ++j)
        p.points.push_back(state.q.segment<3>(plate->node_index(i, j)));
    for (int i = 0; i < plate->nx(); ++i)
      for (int j = 0; j < plate->ny(); ++j)
        p.polys.push_back({plate->node_number(i, j), plate->node_number(i + 1, j),
                           plate->node_number(i + 1, j + 1), plate->node_number(i, j + 1)});
    // section moments, membrane forces and surface stresses (points in node order)
    post::compute_plate_results(*plate, state, table_);
    for (int q = 0; q < post::kPlateQuantityCount; ++q) {
      const auto c = table_.col(q);
      p.point_data.emplace_back(
          std::string(post::plate_quantities()[static_cast<std::size_t>(q)].name),
          std::vector<double>(c.data(), c.data() + c.size()));
    }
    render(p, text_);
    write_piece(plate->name(), text_);
  }
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    const RigidBody& body = *bodies_[k];
    const auto& [axes, sides] = boxes_[k];
    const Mat3 R = body.orientation(state) * axes;  // principal axes in the world
    const Vec3 c = body.position(state);
    Piece p;
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3 unit((corner & 1) ? 0.5 : -0.5, (corner & 2) ? 0.5 : -0.5,
                      (corner & 4) ? 0.5 : -0.5);
      p.points.push_back(c + R * unit.cwiseProduct(sides));
    }
    // outward faces (corner bits: 1 = +x, 2 = +y, 4 = +z)
    p.polys = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    render(p, text_);
    write_piece(body.name(), text_);
  }
  if (sea_) {
    const VtkSea& sea = *sea_;
    Piece p;
    std::vector<double> eta;
    for (int i = 0; i < sea.n; ++i)
      for (int j = 0; j < sea.n; ++j) {
        const double x = sea.x0 + (sea.x1 - sea.x0) * i / (sea.n - 1);
        const double y = sea.y0 + (sea.y1 - sea.y0) * j / (sea.n - 1);
        eta.push_back(sea.ocean->elevation(x, y, state.t));
        p.points.emplace_back(x, y, eta.back());
      }
    for (long i = 0; i + 1 < sea.n; ++i)
      for (long j = 0; j + 1 < sea.n; ++j)
        p.polys.push_back(
            {i * sea.n + j, (i + 1) * sea.n + j, (i + 1) * sea.n + j + 1, i * sea.n + j + 1});
    p.point_data.emplace_back("elevation", std::move(eta));
    render(p, text_);
    write_piece("sea_surface", text_);
  }
  // this row's entries, then the footer again: the file stays valid
  const auto pvd = dir_ / fmt::format("{}.pvd", stem_);
  if (std::fseek(pvd_, -static_cast<long>(std::strlen(kPvdFooter)), SEEK_END) != 0 ||
      std::fputs(entries_.c_str(), pvd_) < 0 || std::fputs(kPvdFooter, pvd_) < 0 ||
      std::fflush(pvd_) != 0)
    fail(pvd);
  ++rows_;
}

void VtkRecorder::flush() {
  std::fflush(pvd_);
}

}  // namespace seaflex::io
