// FeModelBuilder input checks: each bad input throws InputError with an expected/got
// message and the case-file location.
#include <gtest/gtest.h>

#include "fe/fe_model_builder.h"
#include "fe_test_support.h"

namespace limber::fe {
namespace {

using testing::input_error_of;
using testing::paper_rod_property;

const SourceLocation kWhere{"case.yaml", 12, 5};

ShellProperty plate_property() {
  ShellProperty p;
  p.name = "plate";
  p.material = testing::paper_steel();
  p.thickness = 0.002;
  return p;
}

// Two beam nodes (ids 1, 2) and a unit square of shell nodes (ids 11..14).
struct Fixture {
  FeModelBuilder builder;
  int beam_property = 0;
  int shell_property = 0;
  Fixture() {
    builder.add_node(1, {0.0, 0.0, 0.0});
    builder.add_node(2, {1.0, 0.0, 0.0});
    builder.add_node(11, {0.0, 0.0, 1.0});
    builder.add_node(12, {1.0, 0.0, 1.0});
    builder.add_node(13, {1.0, 1.0, 1.0});
    builder.add_node(14, {0.0, 1.0, 1.0});
    beam_property = builder.add_beam_property(paper_rod_property());
    shell_property = builder.add_shell_property(plate_property());
  }
};

TEST(FeModelBuilder, ValidModelBuilds) {
  Fixture f;
  f.builder.add_beam({{0, 1}, Eigen::Vector3d::UnitZ(), f.beam_property});
  f.builder.add_shell({{2, 3, 4, 5}, f.shell_property});
  f.builder.fix(0, Dof::kUx);
  f.builder.fix(0, Dof::kUx);  // twice is harmless
  f.builder.add_node_set("tip", {1});
  EXPECT_EQ(f.builder.node_index(13), 4);
  EXPECT_EQ(f.builder.node_set("tip"), std::vector<int>{1});
  const FeModel model = std::move(f.builder).build();
  EXPECT_EQ(model.node_count(), 6);
  EXPECT_EQ(model.dof_count(), 36);
  EXPECT_EQ(model.fixed_dofs.size(), 1u);
  EXPECT_EQ(model.beams.size(), 1u);
  EXPECT_EQ(model.shells.size(), 1u);
}

TEST(FeModelBuilder, NodeErrors) {
  Fixture f;
  EXPECT_EQ(input_error_of([&] {
              f.builder.add_node(2, {0.0, 0.0, 0.0}, kWhere);
            }),
            "case.yaml:12:5: node 2: expected a unique node id, got a duplicate");
  EXPECT_EQ(input_error_of([&] {
              f.builder.add_node(3, {NAN, 0.0, 0.0}, kWhere);
            }),
            "case.yaml:12:5: node 3: expected a finite position, got (nan, 0, 0)");
  EXPECT_EQ(input_error_of([&] { f.builder.node_index(99, kWhere); }),
            "case.yaml:12:5: node id 99: expected an existing node, got an unknown id");
  EXPECT_EQ(input_error_of([&] { f.builder.node_set("none", kWhere); }),
            "case.yaml:12:5: node set 'none': expected an existing node set, got an unknown name");
}

TEST(FeModelBuilder, BeamPropertyErrors) {
  Fixture f;
  const auto error_with = [&](auto change) {
    BeamProperty p = paper_rod_property();
    change(p);
    return input_error_of([&] { f.builder.add_beam_property(p, kWhere); });
  };
  EXPECT_EQ(error_with([](BeamProperty& p) { p.material.youngs_modulus = 0.0; }),
            "case.yaml:12:5: beam property 'rod' Young's modulus E [Pa]: expected a positive "
            "value, got 0");
  EXPECT_EQ(error_with([](BeamProperty& p) { p.material.density = -1.0; }),
            "case.yaml:12:5: beam property 'rod' density rho [kg/m^3]: expected a positive value, "
            "got -1");
  EXPECT_EQ(error_with([](BeamProperty& p) { p.material.poisson_ratio = 0.5; }),
            "case.yaml:12:5: beam property 'rod' Poisson ratio: expected -1 < nu < 0.5, got 0.5");
  EXPECT_EQ(error_with([](BeamProperty& p) { p.material.poisson_ratio = -1.0; }),
            "case.yaml:12:5: beam property 'rod' Poisson ratio: expected -1 < nu < 0.5, got -1");
  EXPECT_EQ(error_with([](BeamProperty& p) { p.section.area = 0.0; }),
            "case.yaml:12:5: beam property 'rod' area A [m^2]: expected a positive value, got 0");
  EXPECT_EQ(error_with([](BeamProperty& p) { p.section.inertia_y = -2.0; }),
            "case.yaml:12:5: beam property 'rod' second moment Iy [m^4]: expected a positive "
            "value, got -2");
  EXPECT_EQ(error_with([](BeamProperty& p) { p.section.inertia_z = 0.0; }),
            "case.yaml:12:5: beam property 'rod' second moment Iz [m^4]: expected a positive "
            "value, got 0");
  EXPECT_EQ(error_with([](BeamProperty& p) { p.section.torsion_constant = 0.0; }),
            "case.yaml:12:5: beam property 'rod' torsion constant J [m^4]: expected a positive "
            "value, got 0");
  EXPECT_EQ(
      error_with([](BeamProperty& p) { p.section.shear_factor_z = 0.0; }),
      "case.yaml:12:5: beam property 'rod' shear factor kz: expected a positive value, got 0");
}

TEST(FeModelBuilder, ShellPropertyErrors) {
  Fixture f;
  ShellProperty p = plate_property();
  p.thickness = 0.0;
  EXPECT_EQ(input_error_of([&] { f.builder.add_shell_property(p, kWhere); }),
            "case.yaml:12:5: shell property 'plate' thickness [m]: expected a positive value, "
            "got 0");
  p = plate_property();
  p.material.poisson_ratio = 0.7;
  EXPECT_EQ(
      input_error_of([&] { f.builder.add_shell_property(p, kWhere); }),
      "case.yaml:12:5: shell property 'plate' Poisson ratio: expected -1 < nu < 0.5, got 0.7");
  // Section ratios (PSHELL 12I/T³, TS/T) must be > 0, the non-structural mass >= 0.
  p = plate_property();
  p.bending_ratio = 0.0;
  EXPECT_EQ(input_error_of([&] { f.builder.add_shell_property(p, kWhere); }),
            "case.yaml:12:5: shell property 'plate' bending ratio 12I/T^3: expected a positive "
            "value, got 0");
  p = plate_property();
  p.shear_ratio = -0.5;
  EXPECT_EQ(input_error_of([&] { f.builder.add_shell_property(p, kWhere); }),
            "case.yaml:12:5: shell property 'plate' shear ratio TS/T: expected a positive value, "
            "got -0.5");
  p = plate_property();
  p.nonstructural_mass = -0.1;
  EXPECT_EQ(input_error_of([&] { f.builder.add_shell_property(p, kWhere); }),
            "case.yaml:12:5: shell property 'plate' non-structural mass [kg/m^2]: expected a "
            "value >= 0, got -0.1");
  p.nonstructural_mass = 0.0;
  EXPECT_EQ(input_error_of([&] { f.builder.add_shell_property(p, kWhere); }), "no InputError");
}

TEST(FeModelBuilder, BeamElementErrors) {
  Fixture f;
  f.builder.add_node(3, {0.0, 0.0, 0.0});  // same place as node 1
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  EXPECT_EQ(input_error_of([&] {
              f.builder.add_beam({{0, 17}, z, 0}, kWhere);
            }),
            "case.yaml:12:5: beam node: expected a node index in [0, 7), got 17");
  EXPECT_EQ(input_error_of([&] {
              f.builder.add_beam({{0, 1}, z, 3}, kWhere);
            }),
            "case.yaml:12:5: beam: expected a beam property index in [0, 1), got 3");
  EXPECT_EQ(input_error_of([&] {
              f.builder.add_beam({{0, 6}, z, 0}, kWhere);
            }),
            "case.yaml:12:5: beam 1-3: expected a positive finite length, got 0");
  // Nodes 2e200 m apart: the length overflows (issue 31).
  f.builder.add_node(4, {1e200, 0.0, 0.0});
  f.builder.add_node(5, {-1e200, 0.0, 0.0});
  EXPECT_EQ(input_error_of([&] {
              f.builder.add_beam({{7, 8}, z, 0}, kWhere);
            }),
            "case.yaml:12:5: beam 4-5: expected a positive finite length, got inf");
  // 2e131 m: a finite length whose cube, in the stiffness, overflows (the deck fuzzer, issue 31);
  // 1e-110 m: one whose cube underflows. 1e100 m and 1e-100 m pass it (cubes 1e300, 1e-300).
  f.builder.add_node(21, {2e131, 0.0, 0.0});
  f.builder.add_node(22, {1e-110, 0.0, 0.0});
  f.builder.add_node(23, {1e100, 0.0, 0.0});
  f.builder.add_node(24, {1e-100, 0.0, 0.0});
  EXPECT_EQ(input_error_of([&] {
              f.builder.add_beam({{0, 9}, z, 0}, kWhere);
            }),
            "case.yaml:12:5: beam 1-21: expected a length whose cube is a normal number, about 1e-102 "
            "to 1e102 m, got 2e+131");
  EXPECT_EQ(input_error_of([&] {
              f.builder.add_beam({{0, 10}, z, 0}, kWhere);
            }),
            "case.yaml:12:5: beam 1-22: expected a length whose cube is a normal number, about 1e-102 "
            "to 1e102 m, got 1e-110");
  EXPECT_EQ(input_error_of([&] { f.builder.add_beam({{0, 11}, z, 0}, kWhere); }), "no InputError");
  // 1e-100 m passes the length check, but not the matrices' range (FeModelBuilder's magnitudes):
  // 12 E Iz / L^3 = 12 * 206.8e9 * 6.6667e-9 / 1e-300 = 1.6544e304 N/m.
  EXPECT_EQ(input_error_of([&] { f.builder.add_beam({{0, 12}, z, 0}, kWhere); }),
            "case.yaml:12:5: beam 1-24 stiffness: expected diagonal entries within 1e-300 to 1e300 "
            "(SI units), got 1.6544e+304 at uy at node 1; check E, nu and the section (A, Iy, Iz, "
            "J) against the length");
  EXPECT_EQ(input_error_of([&] {
              f.builder.add_beam({{0, 1}, {-2.0, 0.0, 0.0}, 0}, kWhere);
            }),
            "case.yaml:12:5: beam 1-2: expected an orientation vector not parallel to the axis "
            "(1, 0, 0), got (-2, 0, 0)");
  EXPECT_EQ(input_error_of([&] {
              f.builder.add_beam({{0, 1}, Eigen::Vector3d::Zero(), 0}, kWhere);
            }),
            "case.yaml:12:5: beam 1-2: expected an orientation vector not parallel to the axis "
            "(1, 0, 0), got (0, 0, 0)");
}

TEST(FeModelBuilder, ShellElementErrors) {
  Fixture f;
  f.builder.add_node(15, {0.3, 0.3, 1.0});  // inside the square: makes a reflex corner
  f.builder.add_node(16, {2.0, 0.0, 1.0});  // on the line of 11-12: a straight corner
  EXPECT_EQ(input_error_of([&] {
              f.builder.add_shell({{2, 3, 4, 9}, 0}, kWhere);
            }),
            "case.yaml:12:5: shell node: expected a node index in [0, 8), got 9");
  EXPECT_EQ(input_error_of([&] {
              f.builder.add_shell({{2, 3, 4, 5}, 1}, kWhere);
            }),
            "case.yaml:12:5: shell: expected a shell property index in [0, 1), got 1");
  EXPECT_EQ(input_error_of([&] {
              f.builder.add_shell({{2, 3, 3, 5}, 0}, kWhere);
            }),
            "case.yaml:12:5: shell 11-12-12-14: expected 4 distinct nodes, got 3");
  EXPECT_EQ(input_error_of([&] {
              f.builder.add_shell({{2, 3, 6, 5}, 0}, kWhere);
            }),
            "case.yaml:12:5: shell 11-12-15-14: expected a convex quad, got a corner at node 15 "
            "with turn -0.4 m^2 (reflex or straight)");
  EXPECT_EQ(input_error_of([&] {
              f.builder.add_shell({{2, 3, 7, 5}, 0}, kWhere);
            }),
            "case.yaml:12:5: shell 11-12-16-14: expected a convex quad, got a corner at node 12 "
            "with turn 0 m^2 (reflex or straight)");
  // Collinear nodes: zero area.
  f.builder.add_node(17, {3.0, 0.0, 1.0});
  EXPECT_EQ(input_error_of([&] {
              f.builder.add_shell({{2, 3, 7, 8}, 0}, kWhere);
            }),
            "case.yaml:12:5: shell 11-12-16-17: expected a positive area, got 0 m^2");
  // Clockwise order (normal reversed) is fine: the quad is convex about its own normal.
  f.builder.add_shell({{5, 4, 3, 2}, 0}, kWhere);
}

TEST(FeModelBuilder, PointMassNodeSetAndFixErrors) {
  Fixture f;
  PointMass m;
  m.node = 7;
  EXPECT_EQ(input_error_of([&] { f.builder.add_point_mass(m, kWhere); }),
            "case.yaml:12:5: point mass node: expected a node index in [0, 6), got 7");
  m.node = 1;
  m.mass = -1.0;
  EXPECT_EQ(input_error_of([&] { f.builder.add_point_mass(m, kWhere); }),
            "case.yaml:12:5: point mass at node 2: expected a mass >= 0 kg, got -1");
  m.mass = 2.0;
  m.inertia << 1.0, 0.5, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0;
  EXPECT_EQ(input_error_of([&] { f.builder.add_point_mass(m, kWhere); }),
            "case.yaml:12:5: point mass at node 2: expected a symmetric inertia, got an "
            "asymmetry of 0.5 kg m^2");
  m.inertia = Eigen::Vector3d(1.0, -2.0, 1.0).asDiagonal();
  EXPECT_EQ(input_error_of([&] { f.builder.add_point_mass(m, kWhere); }),
            "case.yaml:12:5: point mass at node 2: expected a positive semi-definite inertia, "
            "got a principal moment -2 kg m^2");
  f.builder.add_node_set("a", {0});
  EXPECT_EQ(input_error_of([&] { f.builder.add_node_set("a", {1}, kWhere); }),
            "case.yaml:12:5: node set 'a': expected a unique name, got a duplicate");
  EXPECT_EQ(input_error_of([&] { f.builder.add_node_set("b", {}, kWhere); }),
            "case.yaml:12:5: node set 'b': expected at least 1 node, got 0");
  EXPECT_EQ(input_error_of([&] {
              f.builder.add_node_set("c", {0, -1}, kWhere);
            }),
            "case.yaml:12:5: node set member: expected a node index in [0, 6), got -1");
  EXPECT_EQ(input_error_of([&] { f.builder.fix(6, Dof::kRz, kWhere); }),
            "case.yaml:12:5: fixed DOF node: expected a node index in [0, 6), got 6");
}

TEST(FeModelBuilder, BuildErrors) {
  {
    Fixture f;
    EXPECT_EQ(input_error_of([&] { std::move(f.builder).build(kWhere); }),
              "case.yaml:12:5: FE model: expected at least 1 element, got 0 (6 nodes)");
  }
  {
    Fixture f;
    f.builder.add_beam({{0, 1}, Eigen::Vector3d::UnitZ(), 0});
    EXPECT_EQ(input_error_of([&] { std::move(f.builder).build(kWhere); }),
              "case.yaml:12:5: FE model: expected every node to belong to an element or carry a "
              "point mass, got 4 unused node(s): 11, 12, 13, 14");
  }
  {
    // A point mass makes a node used.
    Fixture f;
    f.builder.add_shell({{2, 3, 4, 5}, 0});
    PointMass m;
    m.mass = 1.0;
    m.node = 0;
    f.builder.add_point_mass(m);
    EXPECT_EQ(input_error_of([&] { std::move(f.builder).build(kWhere); }),
              "case.yaml:12:5: FE model: expected every node to belong to an element or carry a "
              "point mass, got 1 unused node(s): 2");
  }
}

}  // namespace
}  // namespace limber::fe
