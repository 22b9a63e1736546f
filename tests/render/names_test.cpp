// Names that are not HDF5 link names or file names as they are ("arm/left", ".", names that
// equal another's escaped form): render's readers show the names and find their groups, VTU
// files and mode folders get distinct safe names, and files written before groups held their
// name read with the link names.
#include "file_stem.h"
#include "results_reader.h"
#include "vtk_export.h"

#include "io/case_reader.h"
#include "io/modes_file.h"
#include "results/link_name.h"
#include "results/modes_reader.h"
#include "results/results_writer.h"
#include "test_dir.h"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

namespace limber::render {
namespace {

using testing::fresh_directory;

// Bodies whose link names or old file stems would collide; body b sits at x = b.
const std::vector<std::string> kBodies = {"arm/left", "arm%2Fleft", "arm.left", "arm_left", "."};

void write_named_results(const std::filesystem::path& dir) {
  results::ResultsWriter writer(dir, "names", "names.yaml");
  for (const std::string& body : kBodies) writer.add_rigid_body({body, {results::ShapeSpec{}}});
  writer.add_joint({"R.1", "revolute", "arm/left", "."});
  for (int k = 0; k < 2; ++k) {
    results::Sample sample;
    sample.time = 0.1 * k;
    sample.bodies.resize(kBodies.size());
    for (std::size_t b = 0; b < kBodies.size(); ++b) sample.bodies[b].position.x() = b;
    sample.joints.resize(1);
    sample.joints[0].position = {0.0, 0.0, 7.0};
    writer.append_sample(sample);
  }
  writer.finish(results::RunStatus::kOk);
}

TEST(Names, ReaderShowsNamesAndKeepsTheirGroups) {
  const auto dir = fresh_directory("names_reader");
  write_named_results(dir);
  const Results r = read_results(dir);
  ASSERT_EQ(r.bodies.size(), kBodies.size());
  for (const BodyTrack& body : r.bodies) {
    const auto b = std::find(kBodies.begin(), kBodies.end(), body.name) - kBodies.begin();
    ASSERT_LT(b, static_cast<long>(kBodies.size())) << body.name;
    EXPECT_EQ(body.group, "/bodies/" + results::link_name(body.name));
    // Each body's own track: positions exact (float64 round trip).
    EXPECT_EQ(body.position(1, 0), static_cast<double>(b)) << body.name;
  }
  ASSERT_EQ(r.joints.size(), 1u);
  EXPECT_EQ(r.joints[0].name, "R.1");
  EXPECT_EQ(r.joints[0].group, "/joints/R.1");
  EXPECT_EQ(r.joints[0].body_i, "arm/left");
  EXPECT_EQ(r.joints[0].position(1, 2), 7.0);
}

// A file written before groups held their name: the link names are the names.
TEST(Names, OlderFilesShowTheLinkNames) {
  const auto dir = fresh_directory("names_older");
  write_named_results(dir);
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  for (const std::string& body : kBodies) {
    const std::string group = "/bodies/" + results::link_name(body);
    ASSERT_GE(H5Adelete_by_name(file, group.c_str(), results::kNameAttribute, H5P_DEFAULT), 0);
  }
  H5Fclose(file);
  std::set<std::string> names;
  for (const BodyTrack& body : read_results(dir).bodies) names.insert(body.name);
  EXPECT_EQ(names, (std::set<std::string>{"arm%2Fleft", "arm%252Fleft", "arm.left", "arm_left",
                                          "%2E"}));
}

TEST(Names, FileStemsAreSafeAndDistinct) {
  EXPECT_EQ(file_stem("R3"), "R3");
  EXPECT_EQ(file_stem("arm_left-2"), "arm_left-2");
  EXPECT_EQ(file_stem("R.1"), "R~2E1");
  EXPECT_EQ(file_stem("arm/left"), "arm~2Fleft");
  EXPECT_EQ(file_stem("R~2E1"), "R~7E2E1");
  EXPECT_EQ(file_stem(".."), "~2E~2E");
  EXPECT_EQ(file_stem(""), "~");
  std::set<std::string> stems;
  for (const std::string& body : kBodies) stems.insert(file_stem(body));
  EXPECT_EQ(stems.size(), kBodies.size());
}

TEST(Names, VtkSeriesNamesFilesByStemAndPartsByName) {
  const auto dir = fresh_directory("names_vtk");
  write_named_results(dir);
  const Results r = read_results(dir);
  EXPECT_EQ(write_vtk_series(r, dir / "vtk", 0.0, 1.0), 10);
  for (const std::string& body : kBodies) {
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "vtk" / (file_stem(body) + "_00001.vtu")))
        << body;
  }
  std::ifstream pvd(dir / "vtk" / "scene.pvd");
  std::stringstream text;
  text << pvd.rdbuf();
  EXPECT_NE(text.str().find("name=\"arm/left\" file=\"arm~2Fleft_00000.vtu\""), std::string::npos)
      << text.str();
}

// modes.h5 with such names, read by render's reader (the groups at link names).
TEST(Names, ModesReaderFindsBodiesByName) {
  const auto dir = fresh_directory("names_modes");
  const std::string text = R"(materials: {steel: {E: 2e11, nu: 0.3, rho: 7800}}
sections: {s: {shape: circle, diameter: 0.01}}
flexible_bodies:
  "beam/1":
    beams: [{from: [0, 0, 0], to: [1, 0, 0], elements: 2, section: s, material: steel}]
    modes: {normal: 1}
)";
  const fe::FeModel model = io::read_case_text(text, "names.yaml").flexible_bodies.at(0).model;
  modal::ModeSet set;
  set.shapes = Eigen::MatrixXd::Ones(model.dof_count(), 1);
  set.modes = {{modal::ModeKind::kNormal, 12.5, "normal 1"}};
  set.modal_stiffness = Eigen::VectorXd::Ones(1);
  set.invariants.inertia_first_order.resize(1, Eigen::Matrix3d::Zero());
  set.invariants.inertia_second_order.resize(1, Eigen::Matrix3d::Zero());
  set.invariants.rotation_coupling_first_order.resize(1, Eigen::MatrixXd::Zero(3, 1));
  set.invariants.translation_coupling = Eigen::MatrixXd::Zero(3, 1);
  set.invariants.rotation_coupling = Eigen::MatrixXd::Zero(3, 1);
  io::write_modes_file((dir / "modes.h5").string(), "names", "names.yaml",
                       {{"beam/1", &model, &set}, {".", &model, &set}});
  const results::ModesData shapes = results::read_modes(dir / "modes.h5", results::ModesContent::kDrawing);
  ASSERT_EQ(shapes.bodies.size(), 2u);
  EXPECT_EQ(shapes.bodies[0].name, "beam/1");
  EXPECT_EQ(shapes.bodies[1].name, ".");
  ASSERT_EQ(shapes.bodies[1].modes.size(), 1u);
  EXPECT_EQ(shapes.bodies[1].modes[0].label, "normal 1");
  EXPECT_EQ(shapes.bodies[1].mesh.nodes.rows(), model.node_count());
}

}  // namespace
}  // namespace limber::render
