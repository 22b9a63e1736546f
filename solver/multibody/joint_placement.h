// A plausibility check of where joints sit on rigid bodies. A joint given at a ground point
// (docs/case-format.md) puts its markers wherever the bodies are at t = 0, so a rigid body placed
// wrongly is no assembly error: the run silently becomes that of another mechanism, with the
// body's mass far from its pins. A joint marker much farther from a body's centre of mass than
// the body is large is reported so the user can check the body's position.
#pragma once

#include <string>
#include <vector>

#include "multibody/model.h"

namespace limber::multibody {

// A joint's marker further than this many body sizes from the body's centre of mass is reported.
inline constexpr double kDistantJointFactor = 3.0;

// One warning per joint marker on a rigid body farther than kDistantJointFactor × the body's
// size from its centre of mass. The size is the radius of a sphere about the centre of mass
// that holds the body's shapes, or, for a body without shapes, twice its largest radius of
// gyration.
std::vector<std::string> distant_joint_warnings(const Model& model);

}  // namespace limber::multibody
