// The case section `linearize` (io/linearize_reader.h): inputs and outputs on markers (a
// joint's own markers included), an RSDA and a joint's reaction land with their kinds, axes
// and indices in the model; bad input names file:line:col and what was expected.
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/linearize_reader.h"
#include "io/mechanism_builder.h"

#include <gtest/gtest.h>

#include "input_error_matchers.h"

namespace limber::io {
namespace {

using test::fails_at;
using test::location_of;

// A hub and a panel on a sprung, driven hinge given at a point (markers hinge.i, hinge.j).
const std::string kCase = R"(title: linearize
bodies:
  hub: {mass: 50, inertia: [4, 5, 3], position: [0, 0, 0]}
  panel: {mass: 2, inertia: [0.7, 0.9, 0.5], position: [0, 0, 1]}
markers:
  hub_center: {body: hub}
  tip: {body: panel, position: [0, 0, 0.5]}
joints:
  hinge: {type: revolute, body_i: hub, body_j: panel, position: [0, 0, 0.5]}
drivers:
  hinge_drive: {joint: hinge, motion: {type: constant, value: 0}}
forces:
  spring: {type: rsda, marker_i: hinge.i, marker_j: hinge.j, stiffness: 20}
linearize:
  inputs:
    wheels: {torque: hub_center, axes: marker}
    motor: {rsda: spring}
    push: {force: hinge.j}
    hinge_torque: {driver: hinge_drive}
  outputs:
    attitude: {rotation: hub_center}
    tip_acceleration: {acceleration: tip, axes: marker}
    hinge_load: {reaction_torque: hinge, axes: joint}
)";

std::string edited(const std::string& from, const std::string& to) { return test::replaced(kCase, from, to); }

TEST(LinearizeReader, InputsAndOutputsLandWithTheirModelIndices) {
  const Case input = read_case_text(kCase, test::kCaseName);
  const Mechanism built = build_mechanism(input, reduce_case(input, ReductionScope::kMechanismBodies));
  const std::vector<multibody::LinearInput> inputs = linear_inputs(input.mechanism->linearize, built.model);
  const std::vector<multibody::LinearOutput> outputs = linear_outputs(input.mechanism->linearize, built.model);
  ASSERT_EQ(inputs.size(), 4u);
  ASSERT_EQ(outputs.size(), 3u);
  const auto& markers = built.model.markers;
  EXPECT_EQ(inputs[0].name, "wheels");
  EXPECT_EQ(inputs[0].kind, multibody::LinearInputKind::kTorque);
  EXPECT_EQ(inputs[0].axes, multibody::ChannelAxes::kMarker);
  EXPECT_EQ(markers[static_cast<std::size_t>(inputs[0].marker)].name, "hub_center");
  EXPECT_EQ(inputs[1].kind, multibody::LinearInputKind::kRsdaTorque);
  EXPECT_EQ(multibody::force_name(built.model.forces[static_cast<std::size_t>(inputs[1].force)]), "spring");
  EXPECT_EQ(inputs[2].kind, multibody::LinearInputKind::kForce);
  EXPECT_EQ(inputs[2].axes, multibody::ChannelAxes::kGround);
  EXPECT_EQ(markers[static_cast<std::size_t>(inputs[2].marker)].name, "hinge.j");
  EXPECT_EQ(inputs[3].kind, multibody::LinearInputKind::kDriverEffort);
  EXPECT_EQ(built.model.drivers[static_cast<std::size_t>(inputs[3].driver)].name, "hinge_drive");
  EXPECT_EQ(outputs[0].kind, multibody::LinearOutputKind::kRotation);
  EXPECT_EQ(outputs[1].kind, multibody::LinearOutputKind::kAcceleration);
  EXPECT_EQ(outputs[1].axes, multibody::ChannelAxes::kMarker);
  EXPECT_EQ(markers[static_cast<std::size_t>(outputs[1].marker)].name, "tip");
  EXPECT_EQ(outputs[2].kind, multibody::LinearOutputKind::kReactionTorque);
  EXPECT_EQ(outputs[2].axes, multibody::ChannelAxes::kMarker);
  EXPECT_EQ(built.model.joints[static_cast<std::size_t>(outputs[2].joint)].name, "hinge");
}

TEST(LinearizeReader, NoSectionIsNoChannels) {
  const Case input = read_case_text(kCase.substr(0, kCase.find("linearize:")), test::kCaseName);
  EXPECT_TRUE(input.mechanism->linearize.inputs.empty());
  EXPECT_TRUE(input.mechanism->linearize.outputs.empty());
}

TEST(LinearizeReader, BadEntriesAreLocated) {
  // A marker the case lacks: at its name, the markers listed.
  const std::string unknown = edited("rotation: hub_center", "rotation: hub_centre");
  EXPECT_TRUE(fails_at(unknown, location_of(unknown, "hub_centre"),
                       "expected a marker of the case (hub_center, tip, hinge.i, hinge.j), got 'hub_centre'"));
  // An RSDA that is not one.
  const std::string not_rsda = edited("rsda: spring", "rsda: hinge");
  EXPECT_TRUE(fails_at(not_rsda, location_of(not_rsda, "hinge}"), "expected an rsda force of the case (spring)"));
  // Two quantities in one entry; none; an unknown key; bad axes; axes on an RSDA torque.
  const std::string two = edited("{rotation: hub_center}", "{rotation: hub_center, position: tip}");
  EXPECT_TRUE(fails_at(two, location_of(two, "tip}"), "expected one quantity for linearize output 'attitude', got a second ('position')"));
  const std::string none = edited("{rotation: hub_center}", "{axes: ground}");
  EXPECT_TRUE(fails_at(none, location_of(none, "{axes: ground}"), "expected one of position, velocity"));
  const std::string unknown_key = edited("{rotation: hub_center}", "{rotation: hub_center, frame: body}");
  EXPECT_TRUE(fails_at(unknown_key, location_of(unknown_key, "frame"), "frame"));
  const std::string axes = edited("axes: marker}\n    motor", "axes: body}\n    motor");
  EXPECT_TRUE(fails_at(axes, location_of(axes, "body}"), "ground, marker"));
  const std::string rsda_axes = edited("{rsda: spring}", "{rsda: spring, axes: marker}");
  EXPECT_TRUE(fails_at(rsda_axes, location_of(rsda_axes, "marker}", 1), "expected no 'axes' for the RSDA torque"));
  // A driver the case lacks (the drivers listed); axes on a driver's effort.
  const std::string no_driver = edited("driver: hinge_drive", "driver: hinge");
  EXPECT_TRUE(fails_at(no_driver, location_of(no_driver, "hinge}"), "expected a driver of the case (hinge_drive), got 'hinge'"));
  const std::string driver_axes = edited("{driver: hinge_drive}", "{driver: hinge_drive, axes: marker}");
  EXPECT_TRUE(fails_at(driver_axes, location_of(driver_axes, "marker}", 1), "expected no 'axes' for the driver effort"));
  // A reaction of a joint the case lacks; a marker's axes on a reaction.
  const std::string no_joint = edited("reaction_torque: hinge,", "reaction_torque: hinge_R1,");
  EXPECT_TRUE(fails_at(no_joint, location_of(no_joint, "hinge_R1"), "expected a joint of the case (hinge), got 'hinge_R1'"));
  const std::string marker_axes = edited("hinge, axes: joint}", "hinge, axes: marker}");
  EXPECT_TRUE(fails_at(marker_axes, location_of(marker_axes, "marker}", 2), "ground, joint"));
  // A key of the section that is neither inputs nor outputs.
  const std::string section = edited("  outputs:", "  output:");
  EXPECT_TRUE(fails_at(section, location_of(section, "output:"), "output"));
}

}  // namespace
}  // namespace limber::io
