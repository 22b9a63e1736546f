// Which components of a joint's reaction the model does not determine, per frame.
//
// A redundant set of constraint equations (results.h5 /constraints/redundant, redundant_with)
// leaves the multipliers of its equations free along a null space; the solver reports the
// minimum-norm choice (multibody/reactions.h). Each equation of a joint in such a set carries
// its reaction along one direction (docs/multibody.md "Joint equations", Haug 1989 §9.2):
//   x, y, z        (a_i·d)     force along marker i's axis a_i;
//   rot_x, rot_y, rot_z, rot (a_i·b_j)  torque along a_i × b_j (rot_x: y_i × z_j ≈ x_i, ...).
// Only that direction of the reaction is undetermined. A component along a frame axis f is
// therefore indeterminate when f is not perpendicular to every such direction:
// |f·e| > kDirectionTolerance at some sample the joint is flagged indeterminate. So the
// slider-crank's R2.z (the pin axis, ground Y) marks R2's force Y in ground axes and Fz in the
// joint frame, and leaves X and Z (Fx, Fy) determined.
// Needs the joints' marker orientations (results.h5 since issue 15); without them, or when the
// joint is flagged but no set names its equations, the whole quantity is indeterminate.
#pragma once

#include "run_data.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace limber::report {

// |cos| between a frame axis and an undetermined direction above which the component counts
// as indeterminate: 1e-6, i.e. the axis is more than 1e-6 rad away from perpendicular (a
// planar mechanism gives 0 to rounding, ~1e-16).
inline constexpr double kDirectionTolerance = 1e-6;

// The components of `joint` ("x", "rot_x", ...) that a comma-separated list of equation names
// ("R1.rot_x, R2.z") names, in order, once each.
std::vector<std::string> joint_components(const std::string& list, const std::string& joint);

// Unit directions in ground along which the joint's force and torque are undetermined, per
// sample (empty lists where the joint is not flagged).
struct UndeterminedDirections {
  std::vector<std::vector<Eigen::Vector3d>> force, torque;  // [ns][...]
};

// Nothing when it cannot be told per component (see above): then treat the quantity whole.
std::optional<UndeterminedDirections> undetermined_directions(const RunData& run,
                                                              const JointReactions& joint);

// Components x, y, z of a frame that are indeterminate; R_WF per sample (ground <- frame), or
// empty for ground axes.
std::array<bool, 3> indeterminate_components(const UndeterminedDirections& directions, bool torque,
                                             const std::vector<Eigen::Matrix3d>& R_WF);

}  // namespace limber::report
