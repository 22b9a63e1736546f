// The case reader: values land in the FeModel and ModeRequest; every bad-input class
// gives file:line:col and an expected/got message.
#include "io/case_reader.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "input_error_matchers.h"

namespace limber::io {
namespace {

using test::fails_at;
using test::location_of;

const std::string kHappyCase = R"(title: happy path
materials:
  steel: {E: 2.0e11, nu: 0.3, rho: 7800}
  al: {E: 7.0e10, nu: 0.33, rho: 2700}
sections:
  bar: {shape: rectangle, width: 0.01, height: 0.02, shear_factor_z: 0.9}
  pin: {shape: circle, diameter: 0.01}
  gen: {shape: general, A: 1e-4, Iy: 2e-9, Iz: 3e-9, J: 4e-9}
flexible_bodies:
  arm:
    beams:
      - {from: [0, 0, 0], to: [1, 0, 0], elements: 4, section: bar, material: steel,
         orientation: [0, 1, 0], timoshenko: true}
      - {from: [1, 0, 0.5], to: [1, 1, 0.5], elements: 2, section: pin, material: steel,
         first_node_id: 100}
      - {from: [0, 0, 2], to: [0, 0, 3], elements: 1, section: gen, material: al,
         orientation: [1, 0, 0]}
    plates:
      - {origin: [0, 0, 1], edge_x: [0.2, 0, 0], edge_y: [0, 0.1, 0], nx: 2, ny: 1,
         thickness: 0.002, material: al}
    point_masses: [{node: 5, mass: 0.5, inertia: [1e-3, 2e-3, 3e-3]}]
    node_sets: {A: [1], B: [5, 102]}
    fixed: [{nodes: A, dofs: [ux, uy, uz]}]
    modes:
      normal: {count: 3, max_frequency_hz: 1000}
      constraint: [{nodes: B, dofs: [uz]}]
      attachment: [{nodes: 3, dofs: all}]
)";

TEST(CaseReader, ValuesLandInTheModelAndRequest) {
  const Case input = read_case_text(kHappyCase, "test.yaml");
  EXPECT_EQ(input.title, "happy path");
  ASSERT_EQ(input.flexible_bodies.size(), 1u);
  const FlexibleBodyCase& arm = input.flexible_bodies[0];
  const fe::FeModel& model = arm.model;
  EXPECT_EQ(arm.name, "arm");

  // Nodes: 5 + 3 + 2 beam nodes, then the plate's 3 x 2 with ids after the largest so far.
  ASSERT_EQ(model.node_count(), 16);
  EXPECT_EQ(model.node_ids[0], 1);
  EXPECT_EQ(model.node_ids[5], 100);
  EXPECT_EQ(model.node_ids[8], 103);   // third beam continues after 102
  EXPECT_EQ(model.node_ids[10], 105);  // plate continues after 104
  EXPECT_EQ(model.node_positions[4], Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(model.node_positions[15], Eigen::Vector3d(0.2, 0.1, 1));
  EXPECT_EQ(model.beams.size(), 7u);
  EXPECT_EQ(model.shells.size(), 2u);

  // Beam properties: rectangle closed forms (b h^3 / 12), the override, circle pi d^4 / 64.
  ASSERT_EQ(model.beam_properties.size(), 3u);
  const fe::BeamProperty& bar = model.beam_properties[0];
  EXPECT_DOUBLE_EQ(bar.material.youngs_modulus, 2.0e11);
  EXPECT_DOUBLE_EQ(bar.material.density, 7800.0);
  EXPECT_DOUBLE_EQ(bar.section.area, 2e-4);
  EXPECT_DOUBLE_EQ(bar.section.inertia_y, 0.01 * std::pow(0.02, 3) / 12);
  EXPECT_DOUBLE_EQ(bar.section.inertia_z, 0.02 * std::pow(0.01, 3) / 12);
  EXPECT_DOUBLE_EQ(bar.section.shear_factor_z, 0.9);
  EXPECT_DOUBLE_EQ(bar.section.shear_factor_y, 5.0 / 6.0);
  EXPECT_TRUE(bar.timoshenko);
  EXPECT_EQ(model.beams[0].orientation, Eigen::Vector3d(0, 1, 0));
  const fe::BeamProperty& pin = model.beam_properties[1];
  EXPECT_DOUBLE_EQ(pin.section.inertia_y, std::numbers::pi * std::pow(0.01, 4) / 64);
  EXPECT_FALSE(pin.timoshenko);
  // A circle along y without an orientation gets global z.
  EXPECT_EQ(model.beams[4].orientation, Eigen::Vector3d(0, 0, 1));
  const fe::BeamProperty& gen = model.beam_properties[2];
  EXPECT_DOUBLE_EQ(gen.section.torsion_constant, 4e-9);
  EXPECT_DOUBLE_EQ(gen.material.youngs_modulus, 7.0e10);

  // Shell property, point mass, sets, fixed DOFs.
  ASSERT_EQ(model.shell_properties.size(), 1u);
  EXPECT_DOUBLE_EQ(model.shell_properties[0].thickness, 0.002);
  EXPECT_DOUBLE_EQ(model.shell_properties[0].material.poisson_ratio, 0.33);
  ASSERT_EQ(model.point_masses.size(), 1u);
  EXPECT_EQ(model.point_masses[0].node, 4);
  EXPECT_DOUBLE_EQ(model.point_masses[0].mass, 0.5);
  EXPECT_EQ(model.point_masses[0].inertia.diagonal(), Eigen::Vector3d(1e-3, 2e-3, 3e-3));
  EXPECT_EQ(model.node_sets.at("B"), (std::vector<int>{4, 7}));
  ASSERT_EQ(model.fixed_dofs.size(), 3u);
  EXPECT_EQ(model.fixed_dofs[2].node, 0);
  EXPECT_EQ(model.fixed_dofs[2].dof, fe::Dof::kUz);

  // Mode request.
  const modal::ModeRequest& request = arm.request;
  EXPECT_EQ(request.normal_count, 3);
  ASSERT_TRUE(request.max_frequency_hz.has_value());
  EXPECT_DOUBLE_EQ(*request.max_frequency_hz, 1000.0);
  ASSERT_EQ(request.constraint_sites.size(), 2u);
  EXPECT_EQ(request.constraint_sites[1].node, 7);
  EXPECT_EQ(request.constraint_sites[1].dofs, std::vector<fe::Dof>{fe::Dof::kUz});
  ASSERT_EQ(request.attachment_sites.size(), 1u);
  EXPECT_EQ(request.attachment_sites[0].node, 2);
  EXPECT_EQ(request.attachment_sites[0].dofs.size(), 6u);
  EXPECT_EQ(arm.modes_where.to_string(), location_of(kHappyCase, "normal: {"));
}

TEST(CaseReader, PlateSectionRatiosLandInTheShellProperty) {
  // A sandwich plate with all three PSHELL-style keys, and a plain one keeping the defaults.
  const std::string text = R"(materials: {cfrp: {E: 6e10, nu: 0.3, rho: 1600}}
flexible_bodies:
  panel:
    plates:
      - {origin: [0, 0, 0], edge_x: [1, 0, 0], edge_y: [0, 1, 0], nx: 2, ny: 2,
         thickness: 0.0005, bending_ratio: 7650.75, shear_ratio: 0.309,
         nonstructural_mass: 1.6, material: cfrp}
      - {origin: [0, 0, 1], edge_x: [1, 0, 0], edge_y: [0, 1, 0], nx: 1, ny: 1,
         thickness: 0.002, material: cfrp}
    modes: {normal: 2}
)";
  const fe::FeModel& model = read_case_text(text, "test.yaml").flexible_bodies.at(0).model;
  ASSERT_EQ(model.shell_properties.size(), 2u);
  const fe::ShellProperty& sandwich = model.shell_properties[0];
  EXPECT_DOUBLE_EQ(sandwich.thickness, 0.0005);
  EXPECT_DOUBLE_EQ(sandwich.bending_ratio, 7650.75);
  EXPECT_DOUBLE_EQ(sandwich.shear_ratio, 0.309);
  EXPECT_DOUBLE_EQ(sandwich.nonstructural_mass, 1.6);
  const fe::ShellProperty& plain = model.shell_properties[1];
  EXPECT_EQ(plain.bending_ratio, 1.0);
  EXPECT_EQ(plain.shear_ratio, fe::kShellShearFactor);
  EXPECT_EQ(plain.nonstructural_mass, 0.0);
}

TEST(CaseReader, TitleDefaultsToTheFileStem) {
  const std::string text = R"(materials: {steel: {E: 2e11, nu: 0.3, rho: 7800}}
sections: {s: {shape: circle, diameter: 0.01}}
flexible_bodies:
  b: {beams: [{from: [0, 0, 0], to: [1, 0, 0], elements: 2, section: s, material: steel}],
      modes: {normal: 2}}
)";
  EXPECT_EQ(read_case_text(text, "dir/my_case.yaml").title, "my_case");
}

// A valid one-body case with one line replaced, for the error tests below.
std::string rod_case(const std::string& beam_line, const std::string& modes = "{normal: 2}",
                     const std::string& extra_body_keys = "") {
  return "materials:\n"
         "  steel: {E: 2e11, nu: 0.3, rho: 7800}\n"
         "sections:\n"
         "  bar: {shape: rectangle, width: 0.01, height: 0.02}\n"
         "flexible_bodies:\n"
         "  rod:\n"
         "    beams:\n"
         "      - " +
         beam_line + "\n" + extra_body_keys + "    modes: " + modes + "\n";
}

const std::string kGoodBeam =
    "{from: [0, 0, 0], to: [1, 0, 0], elements: 2, section: bar, material: steel, "
    "orientation: [0, 1, 0]}";

// A spider: a new node at its position, and one constraint per (node within the radius, DOF):
// the rod's nodes at x = 0, 0.5 and 1 m, radius 0.5 m around (1, 0, 0) → nodes 2 and 3, six
// DOFs each. An empty bolt pattern is an error at the radius.
TEST(CaseReader, SpidersTieTheNodesWithinTheirRadius) {
  const Case input = read_case_text(
      rod_case(kGoodBeam, "{normal: 2}", "    spiders: [{node: 1001, position: [1, 0, 0], radius: 0.5}]\n"),
      "test.yaml");
  const fe::FeModel& model = input.flexible_bodies[0].model;
  ASSERT_EQ(model.node_count(), 4);
  EXPECT_EQ(model.node_ids.back(), 1001);
  EXPECT_EQ(model.node_positions.back(), Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(model.multipoint_constraints.size(), 12u);
  const std::string lonely =
      rod_case(kGoodBeam, "{normal: 2}", "    spiders: [{node: 1001, position: [3, 0, 0], radius: 0.5}]\n");
  EXPECT_TRUE(fails_at(lonely, location_of(lonely, "0.5}"), "expected at least one node within 'radius'"));
}

TEST(CaseReaderErrors, TheBaseCaseIsValid) {
  EXPECT_NO_THROW(read_case_text(rod_case(kGoodBeam), "test.yaml"));
}

TEST(CaseReaderErrors, UnknownKeys) {
  const std::string beam = kGoodBeam.substr(0, kGoodBeam.size() - 1) + ", colour: red}";
  const std::string text = rod_case(beam);
  EXPECT_TRUE(fails_at(text, location_of(text, "colour"),
                       "unknown key 'colour' in 'beams[0]'; expected one of: from, to, elements"));
  // Unknown top-level sections list the known ones.
  const std::string top = "rigid_bodies: {}\n" + rod_case(kGoodBeam);
  EXPECT_TRUE(fails_at(top, location_of(top, "rigid_bodies"),
                       "unknown key 'rigid_bodies' in 'the case file'; expected one of: title, "
                       "materials, sections, flexible_bodies"));
}

TEST(CaseReader, AxisNamesForReports) {
  EXPECT_TRUE(read_case_text(rod_case(kGoodBeam), "test.yaml").axis_names.empty());
  const std::string named = "axis_names: [X (rail), Y (pin), Z (up)]\n" + rod_case(kGoodBeam);
  EXPECT_EQ(read_case_text(named, "test.yaml").axis_names,
            (std::vector<std::string>{"X (rail)", "Y (pin)", "Z (up)"}));
  const std::string two = "axis_names: [X, Z]\n" + rod_case(kGoodBeam);
  EXPECT_TRUE(fails_at(two, location_of(two, "[X, Z]"),
                       "expected three names for 'axis_names' (ground x, y, z), got 2"));
  const std::string twice = "axis_names: [X, Y, X]\n" + rod_case(kGoodBeam);
  EXPECT_TRUE(fails_at(twice, location_of(twice, "X]"),
                       "expected a distinct name of at most 24 characters without a comma, got 'X'"));
}

TEST(CaseReaderErrors, MissingKeys) {
  const std::string text = rod_case(
      "{from: [0, 0, 0], to: [1, 0, 0], section: bar, "
      "material: steel, orientation: [0, 1, 0]}");
  EXPECT_TRUE(
      fails_at(text, location_of(text, "{from"), "missing required key 'elements' in 'beams[0]'"));
  const std::string no_orientation =
      rod_case("{from: [0, 0, 0], to: [1, 0, 0], elements: 2, section: bar, material: steel}");
  EXPECT_TRUE(fails_at(no_orientation, location_of(no_orientation, "{from"),
                       "missing required key 'orientation' in 'beams[0]'"));
}

TEST(CaseReaderErrors, MissingReferences) {
  const std::string material = rod_case(
      "{from: [0, 0, 0], to: [1, 0, 0], elements: 2, "
      "section: bar, material: stel, orientation: [0, 1, 0]}");
  EXPECT_TRUE(fails_at(material, location_of(material, "stel,"),
                       "unknown material 'stel' for 'material'; defined: steel"));
  const std::string section = rod_case(
      "{from: [0, 0, 0], to: [1, 0, 0], elements: 2, "
      "section: rod, material: steel, orientation: [0, 1, 0]}");
  EXPECT_TRUE(fails_at(section, location_of(section, "rod,"),
                       "unknown section 'rod' for 'section'; defined: bar"));
  const std::string set = rod_case(kGoodBeam, "{normal: 2, constraint: [{nodes: R3, dofs: [uz]}]}",
                                   "    node_sets: {R2: [1]}\n");
  EXPECT_TRUE(
      fails_at(set, location_of(set, "R3"), "unknown node set 'R3' for 'nodes'; defined: R2"));
  const std::string node = rod_case(kGoodBeam, "{normal: 2}", "    node_sets: {R2: [1, 7]}\n");
  EXPECT_TRUE(fails_at(node, location_of(node, "7]"), "node id 7: expected an existing node"));
}

TEST(CaseReaderErrors, NonPositiveValues) {
  const std::string e = "materials:\n  steel: {E: -1, nu: 0.3, rho: 7800}\n";
  EXPECT_TRUE(fails_at(e, location_of(e, "-1"), "expected a positive number for 'E', got '-1'"));
  const std::string rho = "materials:\n  steel: {E: 2e11, nu: 0.3, rho: 0}\n";
  EXPECT_TRUE(
      fails_at(rho, location_of(rho, "0}"), "expected a positive number for 'rho', got '0'"));
  const std::string nu = "materials:\n  steel: {E: 2e11, nu: 0.5, rho: 1}\n";
  EXPECT_TRUE(fails_at(nu, location_of(nu, "0.5"), "expected -1 < nu < 0.5 for 'nu', got '0.5'"));
  const std::string width = "sections:\n  bar: {shape: rectangle, width: 0, height: 0.02}\n";
  EXPECT_TRUE(
      fails_at(width, location_of(width, "0,"), "expected a positive number for 'width', got '0'"));
  const std::string plate = R"(materials: {al: {E: 7e10, nu: 0.33, rho: 2700}}
flexible_bodies:
  p:
    plates: [{origin: [0, 0, 0], edge_x: [1, 0, 0], edge_y: [0, 1, 0], nx: 2, ny: 2,
              thickness: -0.002, material: al}]
    modes: {normal: 2}
)";
  EXPECT_TRUE(fails_at(plate, location_of(plate, "-0.002"),
                       "expected a positive number for 'thickness', got '-0.002'"));
  // Section ratios > 0, non-structural mass >= 0, each at its own value.
  const auto plate_with = [](const std::string& keys) {
    return R"(materials: {al: {E: 7e10, nu: 0.33, rho: 2700}}
flexible_bodies:
  p:
    plates: [{origin: [0, 0, 0], edge_x: [1, 0, 0], edge_y: [0, 1, 0], nx: 2, ny: 2,
              thickness: 0.002, )" +
           keys + R"(, material: al}]
    modes: {normal: 2}
)";
  };
  const std::string bending = plate_with("bending_ratio: 0");
  EXPECT_TRUE(fails_at(bending, location_of(bending, "0, material"),
                       "expected a positive number for 'bending_ratio', got '0'"));
  const std::string shear = plate_with("shear_ratio: -0.8");
  EXPECT_TRUE(fails_at(shear, location_of(shear, "-0.8"),
                       "expected a positive number for 'shear_ratio', got '-0.8'"));
  const std::string nsm = plate_with("nonstructural_mass: -1.5");
  EXPECT_TRUE(fails_at(nsm, location_of(nsm, "-1.5"),
                       "expected a non-negative number for 'nonstructural_mass', got '-1.5'"));
  EXPECT_NO_THROW(read_case_text(plate_with("nonstructural_mass: 0"), "test.yaml"));
  const std::string elements = rod_case(
      "{from: [0, 0, 0], to: [1, 0, 0], elements: 0, "
      "section: bar, material: steel, orientation: [0, 1, 0]}");
  EXPECT_TRUE(fails_at(elements, location_of(elements, "0, section"),
                       "expected a positive whole number for 'elements', got '0'"));
}

TEST(CaseReaderErrors, DegenerateElements) {
  // Zero length: from == to.
  const std::string beam = rod_case(
      "{from: [1, 0, 0], to: [1, 0, 0], elements: 2, "
      "section: bar, material: steel, orientation: [0, 1, 0]}");
  EXPECT_TRUE(fails_at(beam, location_of(beam, "{from"), "expected a positive finite length"));
  // Orientation along the beam axis.
  const std::string parallel = rod_case(
      "{from: [0, 0, 0], to: [1, 0, 0], elements: 2, "
      "section: bar, material: steel, orientation: [2, 0, 0]}");
  EXPECT_TRUE(fails_at(parallel, location_of(parallel, "{from"), "not parallel"));
  // Zero-area quads: both plate edges along x.
  const std::string plate = R"(materials: {al: {E: 7e10, nu: 0.33, rho: 2700}}
flexible_bodies:
  p:
    plates: [{origin: [0, 0, 0], edge_x: [1, 0, 0], edge_y: [2, 0, 0], nx: 2, ny: 2,
              thickness: 0.002, material: al}]
    modes: {normal: 2}
)";
  EXPECT_TRUE(fails_at(plate, location_of(plate, "{origin"), "expected a positive area"));
}

TEST(CaseReaderErrors, ImpossibleModeRequests) {
  // 3 nodes x 6 DOFs = 18 free DOFs.
  const std::string many = rod_case(kGoodBeam, "{normal: 40}");
  EXPECT_TRUE(
      fails_at(many, location_of(many, "{normal"),
               "expected at most 18 modes (the body's free DOFs), got 40 normal + 0 static"));
  const std::string none = rod_case(kGoodBeam, "{normal: 0}");
  EXPECT_TRUE(fails_at(none, location_of(none, "{normal"), "expected at least one mode"));
  const std::string fixed = rod_case(kGoodBeam, "{normal: 2, attachment: [{nodes: 1, dofs: uz}]}",
                                     "    fixed: [{nodes: 1, dofs: all}]\n");
  EXPECT_TRUE(
      fails_at(fixed, location_of(fixed, "{nodes: 1, dofs: uz"),
               "expected free DOFs for attachment modes, got uz at node 1, which 'fixed' holds"));
  const std::string limit = rod_case(kGoodBeam, "{normal: {max_frequency_hz: -5}}");
  EXPECT_TRUE(fails_at(limit, location_of(limit, "-5"),
                       "expected a positive number for 'max_frequency_hz', got '-5'"));
  const std::string missing = rod_case(kGoodBeam, "{}");
  EXPECT_TRUE(fails_at(missing, location_of(missing, "{}"), "expected at least one mode"));
  const std::string dof = rod_case(kGoodBeam, "{normal: 2, constraint: [{nodes: 3, dofs: [uw]}]}");
  EXPECT_TRUE(fails_at(dof, location_of(dof, "uw"),
                       "expected one of ux, uy, uz, rx, ry, rz, all for 'dofs[0]', got 'uw'"));
}

// Text that results.h5 and modes.h5 keep in HDF5 attributes (64 KiB at most each) is bounded
// on input: a 70 000-byte title once ended `limber run` as "internal error: results.h5: HDF5
// failed to write a string attribute" (issue 31).
TEST(CaseReaderErrors, TitlesAndNamesHaveALimit) {
  const std::string longest = "title: '" + std::string(1024, 't') + "'\n" + rod_case(kGoodBeam);
  EXPECT_EQ(read_case_text(longest, "test.yaml").title.size(), 1024u);
  const std::string title = "title: '" + std::string(70000, 't') + "'\n" + rod_case(kGoodBeam);
  EXPECT_TRUE(fails_at(title, location_of(title, "'ttt"),
                       "expected a title of at most 1024 bytes, got '" + std::string(60, 't') +
                           "… (70000 bytes)'"));
  // A name: at most 256 bytes (core/names.h).
  std::string name = rod_case(kGoodBeam);
  name.replace(name.find("  rod:"), 6, "  " + std::string(257, 'r') + ":");
  EXPECT_TRUE(fails_at(name, location_of(name, "rrr"),
                       "flexible body name: expected at most 256 bytes, got \"" + std::string(60, 'r') +
                           "… (257 bytes)\""));
}

TEST(CaseReaderErrors, EmptyAndMalformedFiles) {
  EXPECT_TRUE(fails_at("", "test.yaml", "expected a case"));
  const std::string syntax = "title: x\nmaterials: {steel: {E: 1\n";
  try {
    read_case_text(syntax, "test.yaml");
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, "test.yaml");
    EXPECT_GE(error.where().line, 2);
  }
}

}  // namespace
}  // namespace limber::io

namespace limber::io {
namespace {

// A base case and a variant of it, written to files (a base is found beside its variant).
class CaseBase : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("limber_case_base_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
    write("base.yaml", "title: base\n"
                       "materials:\n  steel: {E: 2e11, nu: 0.3, rho: 7800}\n"
                       "sections:\n  bar: {shape: rectangle, width: 0.01, height: 0.02}\n"
                       "flexible_bodies:\n  rod:\n    beams:\n"
                       "      - {from: [0, 0, 0], to: [1, 0, 0], elements: 10, section: bar, material: steel,\n"
                       "         orientation: [0, 1, 0]}\n"
                       "    modes: {normal: 2}\n");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  std::filesystem::path dir_;
};

TEST_F(CaseBase, AVariantTakesTheBaseSectionsItDoesNotReplace) {
  // The variant replaces flexible_bodies (4 modes) and keeps the base's materials and sections.
  const Case variant = read_case_file(write(
      "variant.yaml", "base: base.yaml\ntitle: variant\nflexible_bodies:\n  rod:\n    beams:\n"
                      "      - {from: [0, 0, 0], to: [1, 0, 0], elements: 10, section: bar, material: steel,\n"
                      "         orientation: [0, 1, 0]}\n    modes: {normal: 4}\n"));
  EXPECT_EQ(variant.title, "variant");
  ASSERT_EQ(variant.flexible_bodies.size(), 1u);
  EXPECT_EQ(variant.flexible_bodies[0].request.normal_count, 4);
  EXPECT_EQ(variant.flexible_bodies[0].model.beam_properties[0].material.youngs_modulus, 2e11);
  // Without its own title, the base's.
  EXPECT_EQ(read_case_file(write("plain.yaml", "base: base.yaml\n")).title, "base");
}

TEST_F(CaseBase, ErrorsPointIntoTheFileThatHasThem) {
  // A bad value in the base is reported at the base's line.
  write("bad_base.yaml", "title: base\nmaterials:\n  steel: {E: -1, nu: 0.3, rho: 7800}\n");
  const std::string variant = write("v.yaml", "base: bad_base.yaml\n");
  try {
    read_case_file(variant);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("bad_base.yaml:3:"), std::string::npos) << error.what();
  }
  // A missing base, and a base that has a base itself.
  EXPECT_THROW(read_case_file(write("missing.yaml", "base: nowhere.yaml\n")), InputError);
  // A name too long for the file system: at the value, not a filesystem exception (issue 31).
  const std::string long_name = write("long.yaml", "title: long\nbase: " + std::string(3000, 'b') + "\n");
  try {
    read_case_file(long_name);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), long_name + ":2:7: expected a case file for 'base', got '" +
                                             std::string(60, 'b') + "… (3000 bytes)' (file name too long)");
  }
  write("chained.yaml", "base: base.yaml\n");
  EXPECT_THROW(read_case_file(write("twice.yaml", "base: chained.yaml\n")), InputError);
}

}  // namespace
}  // namespace limber::io
