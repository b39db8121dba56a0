// Section results of an ANCF thin plate at its nodes: bending and twisting moments,
// membrane forces and the stresses at the two surfaces (Kirchhoff plate theory).
//
// Symbols (as in elements/ancf_plate_elastic.hpp, thesis eq. 75-83): p1, p2 the material
// coordinates along edge1 and edge2, r_i = dr/dp_i, n = r_1 x r_2,
//   eps_ij = 1/2 (r_i . r_j - delta_ij)                      (thesis eq. 80)
//   k_ij   = r_ij . n / |n|^3                                 (thesis eq. 82-83)
// The section forces are the derivatives of the strain energy of thesis eq. (75-79) with
// respect to the strains (Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells
// (1959) eq. (101) and (21)-(23)):
//   membrane (N/m):  n11 = C (eps11 + nu eps22),  n22 = C (eps22 + nu eps11),
//                    n12 = C (1 - nu) eps12,                C = E h / (1 - nu^2)
//   moments (N m/m): m11 = D (k11 + nu k22),  m22 = D (k22 + nu k11),  m12 = D (1 - nu) k12,
//                    D = E h^3 / (12 (1 - nu^2))
// k_ij is positive when the plate bends towards its normal n (a plate with n up sagging
// under a downward load has k11 > 0), so m11 > 0 puts the bottom surface (-n side) in
// tension: the sign of Timoshenko's M_x for a load along -n.
// Surface stresses (plane stress, linear through the thickness):
//   sigma_ij = n_ij / h -+ 6 m_ij / h^2   (top: the +n side, "-"; bottom: "+")
//   von Mises: sqrt(s11^2 - s11 s22 + s22^2 + 3 s12^2).
// Components are in the plate's material axes (edge1, edge2). At a node the values of the
// elements around it are averaged (the bicubic Hermite second derivatives jump between
// elements).
#pragma once

#include <array>
#include <string_view>

#include "seaflex/elements/ancf_plate.hpp"
#include "seaflex/model/state.hpp"

namespace seaflex::post {

/// The quantities at a node, in output order.
enum class PlateQuantity {
  kM11,
  kM22,
  kM12,
  kN11,
  kN22,
  kN12,
  kS11Top,
  kS22Top,
  kS12Top,
  kVonMisesTop,
  kS11Bottom,
  kS22Bottom,
  kS12Bottom,
  kVonMisesBottom,
};
inline constexpr int kPlateQuantityCount = 14;

struct PlateQuantityInfo {
  std::string_view name;  ///< output column / VTK array name
  std::string_view unit;
};
/// Names and units, indexed by PlateQuantity.
const std::array<PlateQuantityInfo, kPlateQuantityCount>& plate_quantities();

/// Every quantity at every node: out(node, quantity), node = plate.node_number(i, j);
/// resized to num_nodes x kPlateQuantityCount. Cost linear in the number of elements.
void compute_plate_results(const AncfPlate& plate, const State& state, MatX& out);

}  // namespace seaflex::post
