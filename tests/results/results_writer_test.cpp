// ResultsWriter: the file matches docs/results-format.md, read back with the plain HDF5 C API.
// Doubles are stored as IEEE float64, so every value must come back bit-exact (tolerance 0).
#include "results/results_writer.h"

#include "core/error.h"
#include "h5_test_read.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace limber::results {
namespace {

using testing::dataset_dims;
using testing::read_doubles;
using testing::read_string_attribute;

std::filesystem::path fresh_directory(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("limber_results_" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

// A two-node beam with two modes: mode 0 bends in y, mode 1 stretches in x.
FlexibleBodySpec two_node_beam() {
  FlexibleBodySpec beam;
  beam.name = "beam";
  beam.nodes.resize(2, 3);
  beam.nodes << 0, 0, 0, 1, 0, 0;
  beam.lines.resize(1, 2);
  beam.lines << 0, 1;
  beam.beam_radius = 0.01;
  beam.mode_translations.setZero(6, 2);
  beam.mode_translations(4, 0) = 1.0;  // node 1, y, mode 0
  beam.mode_translations(3, 1) = 0.5;  // node 1, x, mode 1
  beam.frequencies_hz.resize(2);
  beam.frequencies_hz << 10.0, 250.0;
  return beam;
}

TEST(ResultsWriter, WritesTheDocumentedLayout) {
  const auto dir = fresh_directory("layout");
  {
    ResultsWriter writer(dir, "a title", "case.yaml");
    RigidBodySpec box{"box", {ShapeSpec{}}};
    box.shapes[0].size = {1.0, 2.0, 3.0};
    EXPECT_EQ(writer.add_rigid_body(box), 0);
    EXPECT_EQ(writer.add_flexible_body(two_node_beam()), 1);
    EXPECT_EQ(writer.add_joint({"hinge", "revolute", "ground", "box"}), 0);
    EXPECT_EQ(writer.add_driver("motor"), 0);
    EXPECT_EQ(writer.add_energy("kinetic"), 0);

    // Three samples whose values encode the sample index k.
    for (int k = 0; k < 3; ++k) {
      Sample sample;
      sample.time = 0.1 * k;
      sample.bodies.resize(2);
      sample.bodies[0].position = {1.0 * k, 2.0, 3.0};
      sample.bodies[1].modal_coordinates = Eigen::Vector2d(0.01 * k, -0.02 * k);
      sample.bodies[1].modal_velocities = Eigen::Vector2d(0.5 * k, 0.25 * k);
      sample.joints.resize(1);
      sample.joints[0].force_ground = {0.0, 0.0, 5.0 * k};
      sample.driver_efforts = {7.0 * k};
      sample.energies = {0.5 * k * k};
      sample.steps = 10 * k;
      writer.append_sample(sample);
    }
    EXPECT_EQ(writer.sample_count(), 3);
    writer.finish(RunStatus::kOk);
  }

  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_string_attribute(file, "/", "format"), "limber-results");
  EXPECT_EQ(read_string_attribute(file, "/", "title"), "a title");
  EXPECT_EQ(read_string_attribute(file, "/", "status"), "ok");
  EXPECT_EQ(read_string_attribute(file, "/", "message"), "");
  EXPECT_EQ(read_string_attribute(file, "/bodies/beam", "kind"), "flexible");
  EXPECT_EQ(read_string_attribute(file, "/bodies/box/shapes/0", "type"), "box");
  EXPECT_EQ(read_string_attribute(file, "/joints/hinge", "body_j"), "box");

  // Per-sample datasets: ns = 3 rows each.
  EXPECT_EQ(dataset_dims(file, "/time"), (std::vector<hsize_t>{3}));
  EXPECT_EQ(dataset_dims(file, "/bodies/box/position"), (std::vector<hsize_t>{3, 3}));
  EXPECT_EQ(dataset_dims(file, "/bodies/box/orientation"), (std::vector<hsize_t>{3, 4}));
  EXPECT_EQ(dataset_dims(file, "/bodies/beam/modal_coordinates"), (std::vector<hsize_t>{3, 2}));
  EXPECT_EQ(dataset_dims(file, "/bodies/beam/modal_velocities"), (std::vector<hsize_t>{3, 2}));
  EXPECT_EQ(dataset_dims(file, "/joints/hinge/indeterminate"), (std::vector<hsize_t>{3}));
  EXPECT_EQ(dataset_dims(file, "/solver/steps"), (std::vector<hsize_t>{3}));
  EXPECT_EQ(read_doubles(file, "/time"), (std::vector<double>{0.0, 0.1, 0.2}));
  EXPECT_EQ(read_doubles(file, "/bodies/box/position"),
            (std::vector<double>{0, 2, 3, 1, 2, 3, 2, 2, 3}));
  EXPECT_EQ(read_doubles(file, "/bodies/box/orientation")[4], 1.0);  // w of sample 1
  EXPECT_EQ(read_doubles(file, "/bodies/beam/modal_coordinates"),
            (std::vector<double>{0, 0, 0.01, -0.02, 0.02, -0.04}));
  EXPECT_EQ(read_doubles(file, "/bodies/beam/modal_velocities"),
            (std::vector<double>{0, 0, 0.5, 0.25, 1.0, 0.5}));
  EXPECT_EQ(read_doubles(file, "/joints/hinge/force_ground")[8], 10.0);
  EXPECT_EQ(read_doubles(file, "/drivers/motor/effort"), (std::vector<double>{0, 7, 14}));
  EXPECT_EQ(read_doubles(file, "/energy/kinetic"), (std::vector<double>{0, 0.5, 2}));
  EXPECT_EQ(read_doubles(file, "/solver/steps"), (std::vector<double>{0, 10, 20}));

  // Mesh and modes: [nm, nn, 3] with mode 0 = y at node 1, mode 1 = 0.5 x at node 1.
  EXPECT_EQ(dataset_dims(file, "/bodies/beam/modes/translations"),
            (std::vector<hsize_t>{2, 2, 3}));
  EXPECT_EQ(read_doubles(file, "/bodies/beam/modes/translations"),
            (std::vector<double>{0, 0, 0, 0, 1, 0, 0, 0, 0, 0.5, 0, 0}));
  EXPECT_EQ(read_doubles(file, "/bodies/beam/mesh/nodes"), (std::vector<double>{0, 0, 0, 1, 0, 0}));
  EXPECT_EQ(dataset_dims(file, "/bodies/beam/mesh/quads"), (std::vector<hsize_t>{0, 4}));
  EXPECT_EQ(read_doubles(file, "/bodies/beam/mesh/beam_radius"), (std::vector<double>{0.01}));
  H5Fclose(file);
}

TEST(ResultsWriter, FailedRunKeepsItsMessage) {
  const auto dir = fresh_directory("failed");
  {
    ResultsWriter writer(dir, "t", "c.yaml");
    writer.finish(RunStatus::kFailed, "Newton did not converge at t = 0.25 s");
  }
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_string_attribute(file, "/", "status"), "failed");
  EXPECT_EQ(read_string_attribute(file, "/", "message"), "Newton did not converge at t = 0.25 s");
  EXPECT_EQ(dataset_dims(file, "/time"), (std::vector<hsize_t>{0}));
  H5Fclose(file);
}

TEST(ResultsWriter, UnwritableDirectoryIsAnInputError) {
  // A regular file where the run directory should be.
  const auto dir = fresh_directory("blocked");
  std::filesystem::create_directories(dir);
  const auto blocker = dir / "not_a_directory";
  { std::ofstream(blocker) << "x"; }
  EXPECT_THROW(ResultsWriter(blocker / "run", "t", "c.yaml"), InputError);
}

}  // namespace
}  // namespace limber::results
