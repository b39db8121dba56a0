// The dominant degree of freedom of a mode shape: the coordinate that holds the largest
// share of the mode's kinetic energy. For a mass-normalised shape phi (phi^T M phi = 1)
// the shares e_i = phi_i (M phi)_i sum to 1 (the modal mass split over the coordinates,
// Ewins, Modal Testing (2000) sec. 2.3 "kinetic energy distribution"); unlike the largest
// |phi_i| it compares positions, slopes and rotations on one scale.
#pragma once

#include "seaflex/core/types.hpp"

namespace seaflex::post {

struct DominantCoordinate {
  Index index = -1;    ///< the coordinate
  double share = 0.0;  ///< its share of the kinetic energy, e_i / sum(e)
};

/// phi: a mode shape; m_phi = M phi. Throws std::invalid_argument for sizes that differ
/// or an empty shape.
DominantCoordinate dominant_coordinate(const VecX& phi, const VecX& m_phi);

}  // namespace seaflex::post
