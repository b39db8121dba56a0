// Channels that a model writes only when its output section asks for them (so the
// columns of existing result files keep their places; docs/model-format.md section 14):
//   node_slopes: true            <beam>.n<k>.slope_x|slope_y|slope_z, the node slope r'
//                                 (dimensionless; |r'| is the stretch, thesis eq. 3)
//   support_reactions: true      the force of each support on the body it holds,
//                                 -C_q^T lambda on the held coordinates (C = q_k - value,
//                                 so C_q rows are unit rows and the force is -lambda):
//                                 <beam>.n<k>.reaction.fx|fy|fz (N, world axes) for a held
//                                 position; .mx|my|mz (N m) = r' x Q_s for a node whose three
//                                 slope components are held (Q_s the generalized force on
//                                 r': a rotation dtheta moves r' by dtheta x r', so the
//                                 virtual work Q_s . (dtheta x r') = dtheta . (r' x Q_s));
//                                 .slope_x|slope_y|slope_z (N, the generalized force Q_s)
//                                 when only some are; plate nodes alike,
//                                 <plate>.n<i>_<j>.reaction.fx|fy|fz and
//                                 .reaction.<r_p1|r_p2|r_p1p2>.<x|y|z>
//   energies: true               <body>.energy.kinetic (1/2 v^T M v), .gravity (the
//                                 potential of gravity, zero at the origin: -m g . r_G),
//                                 .strain (elastic strain energy), all J
//   body_angular_velocity: true  <body>.body.wx|wy|wz: a rigid body's angular velocity in
//                                 its own axes, w' = 2 Gbar(p) p' (Nikravesh 1988, ch. 6),
//                                 deg/s; equals R^T w of the world-axis channels
#pragma once

#include "seaflex/io/model_loader.hpp"

namespace seaflex::io {

/// Appends the optional channels that model.output selects, in the order of the table
/// above (each kind body by body, or support by support, in file order).
void add_optional_channels(const Model& model, ChannelList& channels);

}  // namespace seaflex::io
