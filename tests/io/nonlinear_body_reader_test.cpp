// `formulation: nonlinear` on a flexible body (docs/nonlinear-beams.md, "In a mechanism"): the
// body becomes one rigid body per FE node with the beams' lumped inertia, joints land on its
// node bodies, no modes are computed for it; a formulation it cannot have, or input its path
// does not treat yet, fails at file:line:col.
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <variant>

#include "input_error_matchers.h"
#include "nonlinear_beam/beam_structure.h"

namespace limber::io {
namespace {

using test::fails_at;
using test::location_of;

// A 1 m steel beam of 10 elements hinged to ground at its first node, a marker on its last.
const std::string kCase = R"(title: nonlinear pendulum
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
    formulation: nonlinear
    position: [0.5, 0, 0]
    deflection: {node: 6, chord: [root, tip]}
  block: {mass: 1, inertia: [1, 1, 1], position: [2, 0, 0]}
markers:
  end: {body: arm, node: tip}
  face: {body: block, position: [0, 0, 0]}
joints:
  hinge: {type: revolute, body_i: ground, body_j: arm, position: [0.5, 0, 0],
          orientation: {z_axis: [0, 1, 0], x_axis: [1, 0, 0]}}
)";

std::string edited(const std::string& from, const std::string& to) {
  std::string text = kCase;
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(NonlinearBodyReader, NodesBecomeBodiesJointsLandOnThemAndNoModesAreComputed) {
  const Case input = read_case_text(kCase, "test.yaml");
  // Nothing to reduce: the only flexible body is nonlinear.
  EXPECT_TRUE(input.mechanism->flexible_components.empty());
  const CaseReduction reduction = reduce_case(input, ReductionScope::kMechanismBodies);
  EXPECT_TRUE(reduction.bodies.empty());
  const multibody::Model model = build_mechanism(input, reduction).model;
  ASSERT_EQ(model.nonlinear_bodies.size(), 1u);
  const multibody::NonlinearBody& arm = model.nonlinear_bodies[0];
  EXPECT_EQ(arm.name, "arm");
  ASSERT_EQ(arm.node_bodies.size(), 11u);
  EXPECT_EQ(arm.structure->elements.size(), 10u);
  // Ground, 11 node bodies, the block (after them).
  EXPECT_EQ(model.bodies.size(), 13u);
  EXPECT_EQ(model.bodies[static_cast<std::size_t>(arm.node_bodies[5])].name, "arm.node6");
  EXPECT_EQ(model.find_body("block"), 12);
  EXPECT_EQ(model.find_body("arm"), -1);
  EXPECT_EQ(model.find_nonlinear_body("arm"), 0);
  // The node masses add up to the beam's: ρ A L = 7820 · 0.01 · 0.02 · 1 kg (lumping keeps the
  // translational mass exactly, beam_inertia.h); round-off only.
  double mass = 0.0;
  for (const int b : arm.node_bodies) mass += model.bodies[static_cast<std::size_t>(b)].mass;
  EXPECT_NEAR(mass, 7820 * 0.01 * 0.02 * 1.0, 1e-12);
  // Node bodies start at the placed nodes: node 11 at x = 0.5 + 1 m.
  EXPECT_NEAR(model.bodies[static_cast<std::size_t>(arm.node_bodies[10])].initial_pose.position.x(), 1.5, 1e-12);
  // The hinge's marker j and the named marker sit on node bodies 1 and 11, at their origins.
  const multibody::Joint& hinge = model.joints[0];
  EXPECT_EQ(model.markers[static_cast<std::size_t>(hinge.marker_j)].body, arm.node_bodies[0]);
  const auto end_at = std::find_if(model.markers.begin(), model.markers.end(),
                                   [](const multibody::Marker& m) { return m.name == "end"; });
  ASSERT_NE(end_at, model.markers.end());
  const multibody::Marker& end = *end_at;
  EXPECT_EQ(end.body, arm.node_bodies[10]);
  EXPECT_TRUE(end.p_BM.isZero());
  // The probe: node indices.
  ASSERT_TRUE(arm.deflection_probe.has_value());
  EXPECT_EQ(arm.deflection_probe->node, 5);
  EXPECT_EQ(arm.deflection_probe->chord_end, 10);
}

// Force elements and acceleration probes on its nodes act on the node bodies: a marker there is
// the node body's origin (NodesBecomeBodies… above), a probe at a node is that origin.
TEST(NonlinearBodyReader, ForceElementsAndProbesLandOnNodeBodies) {
  const std::string text = kCase +
                           "forces:\n  spring: {type: tsda, marker_i: end, marker_j: face, stiffness: 100}\n"
                           "  push: {type: point_load, marker: end, force: [0, 0, -1]}\n"
                           "acceleration_probes:\n  tip: {body: arm, node: tip}\n  at_end: {marker: end}\n";
  const Case input = read_case_text(text, "test.yaml");
  const multibody::Model model = build_mechanism(input, reduce_case(input, ReductionScope::kMechanismBodies)).model;
  const int tip_body = model.nonlinear_bodies[0].node_bodies[10];
  ASSERT_EQ(model.forces.size(), 2u);
  const auto& spring = std::get<multibody::Tsda>(model.forces[0]);
  EXPECT_EQ(model.markers[static_cast<std::size_t>(spring.marker_i)].body, tip_body);
  EXPECT_EQ(model.markers[static_cast<std::size_t>(std::get<multibody::PointLoad>(model.forces[1]).marker)].body, tip_body);
  ASSERT_EQ(model.acceleration_probes.size(), 2u);
  for (const multibody::AccelerationProbe& probe : model.acceleration_probes) {
    EXPECT_EQ(probe.body, tip_body) << probe.name;
    EXPECT_TRUE(probe.p_B.isZero()) << probe.name;
    EXPECT_EQ(probe.node, -1) << probe.name;
  }
}

TEST(NonlinearBodyReader, RayleighDampingReachesTheBodyAndNoKeyLeavesItUndamped) {
  const auto damping_of = [](const std::string& text) {
    const Case input = read_case_text(text, "test.yaml");
    const multibody::NonlinearBody& arm = build_mechanism(input, reduce_case(input, ReductionScope::kMechanismBodies)).model.nonlinear_bodies[0];
    return std::pair{arm.mass_damping, arm.stiffness_damping};
  };
  EXPECT_EQ(damping_of(kCase), (std::pair{0.0, 0.0}));
  EXPECT_EQ(damping_of(edited("    position: [0.5, 0, 0]\n", "    position: [0.5, 0, 0]\n    damping: 0\n")), (std::pair{0.0, 0.0}));
  EXPECT_EQ(damping_of(edited("    position: [0.5, 0, 0]\n", "    position: [0.5, 0, 0]\n    damping: {rayleigh: [2.5, 3e-5]}\n")),
            (std::pair{2.5, 3e-5}));
}

TEST(NonlinearBodyReader, WhatItCannotHaveFailsAtItsKey) {
  // A formulation that does not exist.
  std::string text = edited("formulation: nonlinear", "formulation: exact");
  EXPECT_TRUE(fails_at(text, location_of(text, "exact"), "got 'exact'"));
  // Shells: nonlinear beams only.
  text = edited("    node_sets:", "    plates:\n      - {origin: [0, 0, 1], edge_x: [0.2, 0, 0], edge_y: [0, 0.1, 0], nx: 2, "
                                  "ny: 1, thickness: 0.002, material: steel}\n    node_sets:");
  EXPECT_TRUE(fails_at(text, location_of(text, "nonlinear\n"), "beams only"));
  // Modal input on a body without modes.
  text = edited("    position: [0.5, 0, 0]\n", "    position: [0.5, 0, 0]\n    geometric_stiffening: true\n");
  EXPECT_TRUE(fails_at(text, location_of(text, "true\n"), "'geometric_stiffening' is not available with 'formulation: nonlinear'"));
  text = edited("    position: [0.5, 0, 0]\n", "    position: [0.5, 0, 0]\n    modal_coordinates: [0, 0, 0]\n");
  EXPECT_TRUE(fails_at(text, location_of(text, "[0, 0, 0]\n"), "'modal_coordinates' is not available"));
  // Damping: Rayleigh or none; a ratio, or ratios per mode, need modes.
  text = edited("    position: [0.5, 0, 0]\n", "    position: [0.5, 0, 0]\n    damping: 0.02\n");
  EXPECT_TRUE(fails_at(text, location_of(text, "0.02\n"),
                       "expected 'damping: 0' or 'damping: {rayleigh: [alpha, beta]}' with 'formulation: nonlinear'"));
  text = edited("    position: [0.5, 0, 0]\n", "    position: [0.5, 0, 0]\n    damping: [0.01, 0.02]\n");
  EXPECT_TRUE(fails_at(text, location_of(text, "[0.01, 0.02]\n"), "expected 'damping: 0' or"));
  text = edited("    position: [0.5, 0, 0]\n", "    position: [0.5, 0, 0]\n    damping: {rayleigh: [-1, 0]}\n");
  EXPECT_TRUE(fails_at(text, location_of(text, "-1"), "-1"));
  // Holding it during assembly.
  text = kCase + "assembly:\n  held: [{body: arm, component: x}]\n";
  EXPECT_TRUE(fails_at(text, location_of(text, "arm, component"), "got nonlinear body 'arm'"));
  // A fixed FE DOF: the body is held by its joints only.
  text = edited("    node_sets:", "    fixed: [{nodes: [1], dofs: [ux]}]\n    node_sets:");
  EXPECT_TRUE(fails_at(text, location_of(text, "nonlinear\n"), "expected no fixed DOFs"));
}

}  // namespace
}  // namespace limber::io
