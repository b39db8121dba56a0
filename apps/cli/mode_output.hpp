// Mode shapes of `seaflex modes`: DIR/mode_shapes.csv (every coordinate of every mode,
// named by the System) and a ParaView animation per mode (DIR/mode<k>.pvd, DIR/vtk/mode<k>/):
// one period of q0 + a sin(2 pi t / T) phi in 24 frames.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "seaflex/io/model_loader.hpp"
#include "seaflex/solvers/modal.hpp"

namespace seaflex::cli {

/// Frames of one period in each mode's animation.
inline constexpr int kModeFrames = 24;

/// Writes DIR/mode_shapes.csv and, when vtk, the animations. The animation's amplitude a
/// makes the largest node or body displacement 5 % of the extent of the model's positions
/// (at least 0.05 m). Throws std::runtime_error when a file cannot be written.
void write_mode_shapes(const io::Model& model, const State& state, const ModalResult& modes,
                       const std::filesystem::path& dir, bool vtk);

/// Removes what an earlier `modes` left in dir: mode_shapes.csv, mode<k>.pvd, vtk/mode<k>/.
void clear_mode_shapes(const std::filesystem::path& dir);

/// The positions of the model's nodes and bodies in q (indices of x; y and z follow).
std::vector<Index> position_coordinates(const io::Model& model);

}  // namespace seaflex::cli
