// Reads the case section `linearize` (docs/linearize.md, "The linearize section"): the named
// inputs and outputs of the state-space model that `limber linearize` writes.
//   linearize:
//     inputs:
//       wheels: {torque: bus_center}                  # channels wheels.x/.y/.z [N m], ground axes
//       thruster: {force: thruster_mount, axes: marker}   # [N], the marker's axes
//       hinge_motor: {rsda: spring_R3}                # one channel [N m]: an actuator torque on the RSDA
//       crank_torque: {driver: crank_drive}           # one channel [N m or N]: the driver released,
//                                                     # its effort the input
//     outputs:
//       attitude: {rotation: bus_center, axes: marker}    # [rad]; also position [m], velocity,
//       rate: {angular_velocity: bus_center, axes: marker}  # acceleration, angular_acceleration
//       root_load: {reaction_force: hinge_R1, axes: joint}  # [N] on the joint's body j; also
//                                                           # reaction_torque [N m]
// Each entry names exactly one quantity and its marker (or RSDA force, driver, or joint), and
// optionally `axes` (ground, the default, or marker: the marker's axes at the linearization
// point; for a reaction, joint: its marker j's axes as they turn; none for an RSDA or a driver).
// Every error is an InputError at file:line:col: unknown keys, a marker, RSDA, driver or joint
// the case lacks (the names there are listed), two quantities in one entry.
#pragma once

#include <string>
#include <vector>

#include "core/error.h"
#include "io/yaml_reader.h"
#include "multibody/model.h"
#include "multibody/state_space.h"

namespace limber::io {

// One input or output as read: the spec without indices, the name it refers to.
struct LinearInputEntry {
  multibody::LinearInput spec;  // marker and force indices unset
  std::string target;           // the marker, the RSDA force (kRsdaTorque) or the driver (kDriverEffort)
  SourceLocation where;         // the target's value
};
struct LinearOutputEntry {
  multibody::LinearOutput spec;  // marker and joint indices unset
  std::string target;            // the marker, or the joint for a reaction
  SourceLocation where;
};

struct LinearizeCase {
  std::vector<LinearInputEntry> inputs;
  std::vector<LinearOutputEntry> outputs;
};

// The names of the case an entry may refer to, each checked here.
struct LinearizeTargets {
  std::vector<std::string> markers;  // joints' own markers included
  std::vector<std::string> rsdas;    // RSDA forces
  std::vector<std::string> drivers;
  std::vector<std::string> joints;
};

LinearizeCase read_linearize(const YamlValue& section, const LinearizeTargets& targets);

// The entries with their marker, force, driver and joint indices in `model` (built from the
// same case).
// Throws InputError at the entry when a name is missing (a model built from other data).
std::vector<multibody::LinearInput> linear_inputs(const LinearizeCase& section, const multibody::Model& model);
std::vector<multibody::LinearOutput> linear_outputs(const LinearizeCase& section, const multibody::Model& model);

}  // namespace limber::io
