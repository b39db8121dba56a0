#include "seaflex/post/mode_shapes.hpp"

#include <stdexcept>

namespace seaflex::post {

DominantCoordinate dominant_coordinate(const VecX& phi, const VecX& m_phi) {
  if (phi.size() == 0 || phi.size() != m_phi.size())
    throw std::invalid_argument("dominant_coordinate: shapes of different sizes");
  const VecX e = phi.cwiseProduct(m_phi);  // kinetic energy shares (Ewins 2000, sec. 2.3)
  DominantCoordinate d;
  e.maxCoeff(&d.index);
  const double total = e.sum();
  d.share = total != 0.0 ? e[d.index] / total : 0.0;
  return d;
}

}  // namespace seaflex::post
