// modes.h5: everything io's conversion and results' writer write reads back bit for bit
// through the one reader of the file (results/modes_reader.h).
#include "io/modes_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "fe/assembly.h"
#include "io/case_reader.h"
#include "modal/modal_stress.h"
#include "modal/rigid_body_modes.h"
#include "modal/static_modes.h"
#include "results/h5_group.h"
#include "results/h5_reader.h"
#include "results/modes_reader.h"

namespace limber::io {
namespace {

// A file name in the test scratch directory, unique to this process.
std::string scratch_path(const std::string& name) {
  return ::testing::TempDir() + "/" + std::to_string(getpid()) + "_" + name;
}

// A body with beams, a plate and a fixed node (the mode data below is synthetic).
fe::FeModel small_model() {
  const std::string text = R"(materials: {steel: {E: 2e11, nu: 0.3, rho: 7800}}
sections: {s: {shape: circle, diameter: 0.01}}
flexible_bodies:
  b:
    beams: [{from: [0, 0, 0], to: [1, 0, 0], elements: 2, section: s, material: steel}]
    plates: [{origin: [0, 0, 1], edge_x: [1, 0, 0], edge_y: [0, 1, 0], nx: 2, ny: 1,
              thickness: 0.01, material: steel}]
    fixed: [{nodes: 1, dofs: [ux, rz]}]
    modes: {normal: 3}
)";
  return read_case_text(text, "small.yaml").flexible_bodies.at(0).model;
}

modal::ModeSet synthetic_modes(int n_dof, int nm) {
  std::srand(7);
  modal::ModeSet set;
  set.shapes = Eigen::MatrixXd::Random(n_dof, nm);
  set.modes = {{modal::ModeKind::kNormal, 12.5, "normal 1"},
               {modal::ModeKind::kConstraint, 340.25, "constraint uz at node 3"},
               {modal::ModeKind::kAttachment, 1e4 / 3.0, "attachment \"rx\" at node 5 (µ)"}};
  set.modal_stiffness = Eigen::VectorXd::Random(nm);
  set.rigid_modes = {{modal::ModeKind::kRigid, 1e-9, "rigid 1"},
                     {modal::ModeKind::kRigid, -2e-9, "rigid 2"}};
  modal::ModalInvariants& inv = set.invariants;
  inv.mass = 12.345;
  inv.first_moment = Eigen::Vector3d::Random();
  inv.inertia = Eigen::Matrix3d::Random();
  inv.translation_coupling = Eigen::MatrixXd::Random(3, nm);
  inv.rotation_coupling = Eigen::MatrixXd::Random(3, nm);
  for (int i = 0; i < nm; ++i) {
    inv.inertia_first_order.push_back(Eigen::Matrix3d::Random());
    inv.rotation_coupling_first_order.push_back(Eigen::MatrixXd::Random(3, nm));
    for (int j = 0; j < nm; ++j) inv.inertia_second_order.push_back(Eigen::Matrix3d::Random());
  }
  return set;
}

using results::read_modes;

void expect_same_infos(const std::vector<results::ModeRecord>& got,
                       const std::vector<modal::ModeInfo>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].kind, modal::to_string(want[i].kind));
    EXPECT_EQ(got[i].frequency_hz, want[i].frequency_hz);
    EXPECT_EQ(got[i].label, want[i].label);
  }
}

TEST(ModesFile, RoundTripIsExact) {
  const fe::FeModel model = small_model();
  const modal::ModeSet set = synthetic_modes(model.dof_count(), 3);
  const std::string path = scratch_path("modes_round_trip.h5");
  write_modes_file(path, "round trip", "small.yaml",
                   {{"first", &model, &set}, {"a_second", &model, &set}});

  const results::ModesData file = read_modes(path);
  EXPECT_EQ(file.title, "round trip");
  EXPECT_EQ(file.case_file, "small.yaml");
  // Bodies keep their written order, not HDF5's alphabetical one.
  ASSERT_EQ(file.bodies.size(), 2u);
  EXPECT_EQ(file.bodies[0].name, "first");
  EXPECT_EQ(file.bodies[1].name, "a_second");

  // Doubles are stored as IEEE float64: every value must come back identical.
  const results::ModesBody& body = file.bodies[0];
  ASSERT_EQ(body.mesh.nodes.rows(), model.node_count());
  for (int n = 0; n < model.node_count(); ++n) {
    EXPECT_EQ(body.mesh.nodes.row(n).transpose(), model.node_positions[static_cast<std::size_t>(n)]);
  }
  EXPECT_EQ(body.mesh.node_ids, model.node_ids);
  ASSERT_EQ(body.mesh.lines.rows(), static_cast<Eigen::Index>(model.beams.size()));
  EXPECT_EQ(body.mesh.lines(1, 0), model.beams[1].nodes[0]);
  EXPECT_EQ(body.mesh.lines(1, 1), model.beams[1].nodes[1]);
  ASSERT_EQ(body.mesh.quads.rows(), static_cast<Eigen::Index>(model.shells.size()));
  for (int c = 0; c < 4; ++c) EXPECT_EQ(body.mesh.quads(1, c), model.shells[1].nodes[static_cast<std::size_t>(c)]);
  ASSERT_EQ(body.fixed.rows(), 2);
  EXPECT_EQ(body.fixed(1, 1), static_cast<int>(fe::Dof::kRz));
  EXPECT_EQ(body.dof_count, model.dof_count());

  EXPECT_EQ(body.shapes, set.shapes);
  EXPECT_EQ(body.modal_stiffness, set.modal_stiffness);
  expect_same_infos(body.modes, set.modes);
  expect_same_infos(body.rigid_modes, set.rigid_modes);

  const results::InvariantsData& got = body.invariants;
  const modal::ModalInvariants& want = set.invariants;
  EXPECT_EQ(got.mass, want.mass);
  EXPECT_EQ(got.first_moment, want.first_moment);
  EXPECT_EQ(got.inertia, want.inertia);
  EXPECT_EQ(got.translation_coupling, want.translation_coupling);
  EXPECT_EQ(got.rotation_coupling, want.rotation_coupling);
  ASSERT_EQ(got.inertia_first_order.size(), 3u);
  ASSERT_EQ(got.inertia_second_order.size(), 9u);
  ASSERT_EQ(got.rotation_coupling_first_order.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(got.inertia_first_order[i], want.inertia_first_order[i]);
    EXPECT_EQ(got.rotation_coupling_first_order[i], want.rotation_coupling_first_order[i]);
  }
  EXPECT_EQ(got.inertia_second_order[7], want.inertia_second_order[7]);

  // Translations are the first three DOFs of every node of every shape: (3 nn) x nm.
  ASSERT_EQ(body.mesh.mode_translations.cols(), 3);
  EXPECT_EQ(body.mesh.mode_translations.rows(), 3 * model.node_count());
  EXPECT_EQ(body.mesh.mode_translations(3 * 4 + 1, 2), set.shapes(6 * 4 + 1, 2));
  EXPECT_EQ(body.mesh.mode_translations(2, 0), set.shapes(2, 0));
  // Modal stresses: 12 rows per beam, 6 per shell.
  const modal::ModalStress stress = modal::modal_stress(model, set.shapes);
  EXPECT_EQ(body.beam_stress_modal, stress.beam_modal);
  EXPECT_EQ(body.shell_stress_modal, stress.shell_modal);
  EXPECT_EQ(body.shell_stress_modal.rows(), 6 * static_cast<Eigen::Index>(model.shells.size()));
  std::filesystem::remove(path);
}

TEST(ModesFile, ModalStressesOfAStaticDeflectionGiveTheCantileversMoments) {
  // A 2 m cantilever (4 beams, clamped at node 1) whose first "mode" is its static deflection
  // under a 100 N tip force along z: the stored resultants per unit η of that mode are the
  // cantilever's at η = 1, N = 0, |Vz| = F and |My| = F L at the root, 0 at the tip (exact for
  // end-loaded Hermite beams). Read back bit for bit as modal_stress computes them.
  const std::string text = R"(materials: {steel: {E: 2e11, nu: 0.3, rho: 7800}}
sections: {s: {shape: circle, diameter: 0.02}}
flexible_bodies:
  b:
    beams: [{from: [0, 0, 0], to: [2, 0, 0], elements: 4, section: s, material: steel}]
    fixed: [{nodes: 1, dofs: [ux, uy, uz, rx, ry, rz]}]
    modes: {normal: 3}
)";
  const fe::FeModel model = read_case_text(text, "cantilever.yaml").flexible_bodies.at(0).model;
  const double force = 100.0, length = 2.0;
  const fe::StructuralMatrices km = fe::assemble(model);
  Eigen::MatrixXd load = Eigen::MatrixXd::Zero(model.dof_count(), 1);
  load(6 * 4 + 2, 0) = force;  // node index 4: the tip
  const modal::StaticModes response = modal::compute_static_responses(
      km.stiffness, km.mass, modal::rigid_body_modes(model), fe::free_dofs(model), load, "tip load");
  ASSERT_EQ(response.status, modal::ModalStatus::kOk);
  modal::ModeSet set = synthetic_modes(model.dof_count(), 3);
  set.shapes.col(0) = response.shapes.col(0);
  const std::string path = scratch_path("modes_stress.h5");
  write_modes_file(path, "stress", "cantilever.yaml", {{"b", &model, &set}});
  const results::ModesBody body = read_modes(path).bodies.at(0);
  EXPECT_EQ(body.beam_stress_modal, modal::modal_stress(model, set.shapes).beam_modal);
  ASSERT_EQ(body.beam_stress_modal.rows(), 12 * 4);
  ASSERT_EQ(body.beam_stress_modal.cols(), 3);
  EXPECT_EQ(body.shell_stress_modal.rows(), 0);
  // Root (element 0, end 0): rows N Vy Vz T My Mz, in the beam's local axes (shear and moment
  // by magnitude across the section's two axes); tip (element 3, end 1). The static solve's
  // round-off: 1e-9.
  const Eigen::VectorXd r = body.beam_stress_modal.col(0);
  const double moment = force * length;
  EXPECT_NEAR(r(0), 0.0, 1e-9 * moment);
  EXPECT_NEAR(std::hypot(r(1), r(2)), force, 1e-9 * force);
  EXPECT_NEAR(std::hypot(r(4), r(5)), moment, 1e-9 * moment);
  EXPECT_NEAR(std::hypot(r(12 * 3 + 6 + 4), r(12 * 3 + 6 + 5)), 0.0, 1e-9 * moment);
  std::filesystem::remove(path);
}

TEST(ModesFile, LayoutHoldsTheDocumentedAttributes) {
  const fe::FeModel model = small_model();
  const modal::ModeSet set = synthetic_modes(model.dof_count(), 3);
  const std::string path = scratch_path("modes_layout.h5");
  write_modes_file(path, "layout", "small.yaml", {{"b", &model, &set}});
  const results::H5Reader file(path, "modes file", "");
  EXPECT_EQ(file.string_attribute("/", "format"), "limber-modes");
  EXPECT_EQ(file.doubles_attribute("/", "version", 1).at(0), 1.0);
  EXPECT_EQ(file.doubles_attribute("/bodies/b", "dof_count", 1).at(0), model.dof_count());
  EXPECT_EQ(file.doubles_attribute("/bodies/b", "mode_count", 1).at(0), 3.0);
  EXPECT_EQ(file.dims("/bodies/b/modes/translations"),
            (results::H5Dims{3, static_cast<hsize_t>(model.node_count()), 3}));
  EXPECT_EQ(file.dims("/bodies/b/modes/shapes"), (results::H5Dims{static_cast<hsize_t>(model.dof_count()), 3}));
  EXPECT_EQ(file.strings("/bodies/b/dofs/names"),
            (std::vector<std::string>{"ux", "uy", "uz", "rx", "ry", "rz"}));
  std::filesystem::remove(path);
}

// Body names are free text: each group sits at the name's link name (results/link_name.h),
// the name in its attribute `name`, and the bodies read back by name.
TEST(ModesFile, BodyNamesWithSlashesAndDotsRoundTrip) {
  const fe::FeModel model = small_model();
  const modal::ModeSet set = synthetic_modes(model.dof_count(), 3);
  const std::string path = scratch_path("modes_names.h5");
  write_modes_file(path, "names", "small.yaml",
                   {{"beam/1", &model, &set}, {"beam%2F1", &model, &set}, {".", &model, &set}});
  const results::ModesData file = read_modes(path);
  ASSERT_EQ(file.bodies.size(), 3u);
  EXPECT_EQ(file.bodies[0].name, "beam/1");
  EXPECT_EQ(file.bodies[1].name, "beam%2F1");
  EXPECT_EQ(file.bodies[2].name, ".");
  EXPECT_EQ(file.bodies[2].shapes, set.shapes);
  const results::H5Reader file_links(path, "modes file", "");
  EXPECT_EQ(file_links.string_attribute("/bodies/beam%2F1", "name"), "beam/1");
  EXPECT_EQ(file_links.string_attribute("/bodies/beam%252F1", "name"), "beam%2F1");
  EXPECT_EQ(file_links.string_attribute("/bodies/%2E", "name"), ".");
  std::filesystem::remove(path);
}

// A flexible body's name with a control character is refused at its key.
TEST(ModesFile, ControlCharactersInNamesAreInputErrors) {
  const std::string text = "materials: {steel: {E: 2e11, nu: 0.3, rho: 7800}}\n"
                           "sections: {s: {shape: circle, diameter: 0.01}}\n"
                           "flexible_bodies:\n"
                           "  \"b\\0eam\":\n"
                           "    beams: [{from: [0, 0, 0], to: [1, 0, 0], elements: 2, section: s, "
                           "material: steel}]\n"
                           "    modes: {normal: 3}\n";
  try {
    read_case_text(text, "nul.yaml");
    FAIL() << "a NUL in a name was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "nul.yaml:4:3: flexible body name: expected text without control characters, got "
              "\"b\\x00eam\" (byte 0x00 at 1)");
  }
}

TEST(ModesFile, ReadingSomethingElseIsAnInputError) {
  EXPECT_THROW(read_modes(scratch_path("does_not_exist.h5")), InputError);
  const std::string path = scratch_path("not_modes.h5");
  results::Hdf5Group::create_file(path).write_attribute("format", "something-else");
  EXPECT_THROW(read_modes(path), InputError);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace limber::io
