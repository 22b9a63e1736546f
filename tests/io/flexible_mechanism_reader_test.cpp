// Flexible bodies in the mechanism sections: a `bodies` entry naming a `flexible_bodies` entry
// gets its modes, markers on its FE nodes (by node id, node set or the ground point of a
// joint), its damping and deflection probe; bad input names file, line and what was expected.
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "input_error_matchers.h"

namespace limber::io {
namespace {

using test::fails_at;
using test::location_of;

// A 1 m steel beam of 10 elements, 3 free-free modes, hinged to ground at its first node and
// carrying a marker on its last.
const std::string kCase = R"(title: flexible pendulum
materials:
  steel: {E: 206.8e9, nu: 0.3, rho: 7820}
sections:
  bar: {shape: rectangle, width: 0.01, height: 0.02}
flexible_bodies:
  beam:
    beams:
      - {from: [0, 0, 0], to: [1, 0, 0], elements: 10, section: bar, material: steel,
         orientation: [0, 1, 0], first_node_id: 1}
    node_sets: {root: [1], tip: [11]}
    modes: {normal: 3}
bodies:
  arm:
    flexible: beam
    position: [0.5, 0, 0]
    damping: [0.01, 0.02, 0.03]
    deflection: {node: 6, chord: [root, tip]}
markers:
  end: {body: arm, node: tip}
joints:
  hinge: {type: revolute, body_i: ground, body_j: arm, position: [0.5, 0, 0],
          orientation: {z_axis: [0, 1, 0], x_axis: [1, 0, 0]}}
)";

std::string edited(const std::string& from, const std::string& to) { return test::replaced(kCase, from, to); }

TEST(FlexibleMechanismReader, BodyMarkersDampingAndProbeLandInTheModel) {
  const Case input = read_case_text(kCase, "test.yaml");
  ASSERT_TRUE(input.mechanism.has_value());
  // Reading computes no modes; the reduction computes those of the one entry the mechanism uses.
  const io::CaseReduction reduction = io::reduce_case(input, io::ReductionScope::kMechanismBodies);
  const io::Mechanism built = io::build_mechanism(input, reduction);
  const multibody::Model& model = built.model;
  const multibody::Body& arm = model.bodies[model.find_body("arm")];
  ASSERT_EQ(arm.kind, multibody::BodyKind::kFlexible);
  // Frame (6) plus 3 modes, those of the flexible_bodies entry's reduction.
  EXPECT_EQ(arm.nv, 9);
  ASSERT_EQ(reduction.bodies.size(), 1u);
  EXPECT_EQ(reduction.bodies[0].name, input.flexible_bodies[0].name);
  EXPECT_EQ(reduction.bodies[0].result.mode_set.shapes.cols(), 3);
  // Mass rho A L; damping c_i = 2 ζ_i ω_i per mode.
  EXPECT_NEAR(arm.mass, 7820 * 0.01 * 0.02, 1e-9);
  const multibody::FlexibleBody& flexible = *arm.flexible;
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(flexible.damping(i), 2 * 0.01 * (i + 1) * std::sqrt(flexible.stiffness(i)), 1e-9);
  }
  // Markers: node set 'tip' = node index 10; the hinge's rod side found at the ground point
  // (0.5, 0, 0) = the body origin = node index 0.
  for (const multibody::Marker& marker : model.markers) {
    if (marker.name == "end") {
      EXPECT_EQ(marker.node, 10);
    }
    if (marker.name == "hinge.j") {
      EXPECT_EQ(marker.node, 0);
    }
  }
  ASSERT_TRUE(flexible.deflection_probe.has_value());
  EXPECT_EQ(flexible.deflection_probe->node, 5);
  EXPECT_EQ(flexible.deflection_probe->chord_end, 10);
  // Drawn as 10 lines, tubes of the section's equal-area radius sqrt(A / pi).
  EXPECT_EQ(flexible.mesh.lines.size(), 10u);
  EXPECT_NEAR(flexible.mesh.beam_radius, std::sqrt(2e-4 / std::numbers::pi), 1e-12);
}

TEST(FlexibleMechanismReader, StagesReadThenReduceThenBuild) {
  // Reading computes no modes, so a reference error fails before any reduction; a per-mode
  // list's length needs the modes and fails in the build, still at its file:line:col.
  std::string text = edited("node: tip}", "node: 12}");
  EXPECT_THROW(read_case_text(text, "test.yaml"), InputError);
  text = edited("[0.01, 0.02, 0.03]", "[0.01, 0.02]");
  const Case input = read_case_text(text, "test.yaml");
  const CaseReduction reduction = reduce_case(input, ReductionScope::kMechanismBodies);
  try {
    build_mechanism(input, reduction);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().to_string(), location_of(text, "[0.01, 0.02]"));
  }
  // The mode requests of `limber select` replace the case's in the reduction only.
  ModeOverrides overrides{{"beam", input.flexible_bodies[0].request}};
  overrides["beam"].normal_count = 2;
  EXPECT_EQ(reduce_case(input, ReductionScope::kAllBodies, overrides).bodies[0].result.mode_set.shapes.cols(), 2);
  EXPECT_EQ(input.flexible_bodies[0].request.normal_count, 3);
  EXPECT_THROW(reduce_case(input, ReductionScope::kAllBodies, {{"bar", {}}}), InputError);
}

TEST(FlexibleMechanismReader, BadInputNamesFileLineAndWhatWasExpected) {
  // A flexible_bodies entry that does not exist.
  std::string text = edited("flexible: beam", "flexible: bar");
  EXPECT_TRUE(fails_at(text, location_of(text, "bar\n"),
                       "expected the name of an entry of 'flexible_bodies' for 'flexible', got 'bar' (defined: beam)"));
  // A joint point off the mesh: the nearest node and its distance.
  text = edited("position: [0.5, 0, 0],\n", "position: [0.53, 0, 0],\n");
  EXPECT_TRUE(fails_at(text, location_of(text, "[0.53, 0, 0]"), "nearest: node 1 at 0.03 m"));
  // A marker on a node set of several nodes, and on an unknown node id.
  text = edited("root: [1]", "root: [1, 2]");
  EXPECT_TRUE(fails_at(text, location_of(text, "root, tip"), "(a set of 2 nodes)"));
  text = edited("node: tip}", "node: 12}");
  EXPECT_TRUE(fails_at(text, location_of(text, "12}"), "expected a node id of flexible body 'beam'"));
  // Damping ratios: one per mode.
  text = edited("[0.01, 0.02, 0.03]", "[0.01, 0.02]");
  EXPECT_TRUE(fails_at(text, location_of(text, "[0.01, 0.02]"), "expected 3 values (one per mode)"));
  // ... each ≥ 0, the bad one named at its place.
  text = edited("[0.01, 0.02, 0.03]", "[0.01, -0.02, 0.03]");
  EXPECT_TRUE(fails_at(text, location_of(text, "-0.02"), "expected a non-negative number for 'damping[1]'"));
  // Geometric stiffening: one of three words.
  text = edited("    damping: [", "    geometric_stiffening: yes please\n    damping: [");
  EXPECT_TRUE(fails_at(text, location_of(text, "yes please"), "for 'geometric_stiffening', got 'yes please'"));
  // A rigid-body key on a flexible body.
  text = edited("    damping: [", "    mass: 2\n    damping: [");
  EXPECT_TRUE(fails_at(text, location_of(text, "mass: 2"), "unknown key 'mass'"));
}

TEST(FlexibleMechanismReader, GeometricStiffeningDefaultsToInertiaAndFullUsesTheJointNodes) {
  // Default: the centrifugal cases, computed from the beam (nonzero for a beam: its tension
  // under ω_y² is the case index 1).
  {
    const Case input = read_case_text(kCase, "test.yaml");
    const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
    const multibody::FlexibleBody& arm = *built.model.bodies[built.model.find_body("arm")].flexible;
    EXPECT_EQ(arm.stiffening, multibody::GeometricStiffening::kInertia);
    EXPECT_GT(arm.geometric.centrifugal[1].norm(), 0.0);
  }
  // true: the load nodes are the nodes with markers, the hinge's (index 0) and 'end' (10).
  {
    const Case input = read_case_text(edited("    damping: [", "    geometric_stiffening: true\n    damping: ["), "test.yaml");
    const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
    const multibody::FlexibleBody& arm = *built.model.bodies[built.model.find_body("arm")].flexible;
    EXPECT_EQ(arm.stiffening, multibody::GeometricStiffening::kFull);
    EXPECT_EQ(arm.geometric.load_nodes, (std::vector<int>{0, 10}));
  }
  // false: nothing computed.
  {
    const Case input = read_case_text(edited("    damping: [", "    geometric_stiffening: false\n    damping: ["), "test.yaml");
    const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
    const multibody::FlexibleBody& arm = *built.model.bodies[built.model.find_body("arm")].flexible;
    EXPECT_EQ(arm.stiffening, multibody::GeometricStiffening::kOff);
    EXPECT_EQ(arm.geometric.centrifugal[1].size(), 0);
  }
}

TEST(FlexibleMechanismReader, StressOutputLandsInTheModelAndBadInputIsNamed) {
  // Elements 1-based in the case, 0-based and sorted in the model, with the modal stresses of
  // every element over the body's modes.
  std::string text = edited("    deflection:", "    stress: {elements: [10, 1, 5, 5], every: 4}\n    deflection:");
  const Case input = read_case_text(text, "test.yaml");
  const io::Mechanism built =
      io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  const multibody::FlexibleBody& arm = *built.model.bodies[static_cast<std::size_t>(built.model.find_body("arm"))].flexible;
  ASSERT_TRUE(arm.stress_output.has_value());
  EXPECT_EQ(arm.stress_output->elements, (std::vector<int>{0, 4, 9}));
  EXPECT_EQ(arm.stress_output->every, 4);
  EXPECT_EQ(arm.modal_stress.beam_count, 10);
  EXPECT_EQ(arm.modal_stress.beam_modal.rows(), 120);
  EXPECT_EQ(arm.modal_stress.beam_modal.cols(), arm.mode_count());

  // An element number beyond the mesh, a word other than all, every < 1, an unknown key.
  text = edited("    deflection:", "    stress: {elements: [3, 12]}\n    deflection:");
  EXPECT_TRUE(fails_at(text, location_of(text, "12]}"), "expected an element number in [1, 10]"));
  text = edited("    deflection:", "    stress: {elements: some}\n    deflection:");
  EXPECT_TRUE(fails_at(text, location_of(text, "some}"), "expected 'all' or a list of element numbers"));
  text = edited("    deflection:", "    stress: {elements: all, every: 0}\n    deflection:");
  EXPECT_TRUE(fails_at(text, location_of(text, "0}\n    deflection"), "expected a positive whole number for 'every'"));
  text = edited("    deflection:", "    stress: {elements: all, each: 2}\n    deflection:");
  EXPECT_TRUE(fails_at(text, location_of(text, "each"), "unknown key 'each'"));
  // A general section without extreme fibres cannot give a bending stress.
  text = edited("bar: {shape: rectangle, width: 0.01, height: 0.02}",
                "bar: {shape: general, A: 2e-4, Iy: 6.67e-9, Iz: 1.67e-9, J: 4.6e-9}");
  text.replace(text.find("    deflection:"), 15, "    stress: {elements: all}\n    deflection:");
  EXPECT_TRUE(fails_at(text, location_of(text, "{elements: all}"),
                       "expected extreme-fibre distances for the beams' stresses, got none for section 'bar'"));
  // ... with them it can.
  text = edited("bar: {shape: rectangle, width: 0.01, height: 0.02}",
                "bar: {shape: general, A: 2e-4, Iy: 6.67e-9, Iz: 1.67e-9, J: 4.6e-9, fibre_y: 0.005, fibre_z: 0.01}");
  text.replace(text.find("    deflection:"), 15, "    stress: {elements: all}\n    deflection:");
  EXPECT_NO_THROW(read_case_text(text, "test.yaml"));
}

}  // namespace
}  // namespace limber::io
