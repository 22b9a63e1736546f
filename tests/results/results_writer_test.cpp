// ResultsWriter: the file matches docs/results-format.md, read back with the plain HDF5 C API.
// Doubles are stored as IEEE float64, so every value must come back bit-exact (tolerance 0).
#include "results/results_writer.h"

#include "core/error.h"
#include "h5_test_read.h"

#include <gtest/gtest.h>

#include <cmath>
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

// A flexible body without modes (the case reader refuses one, the writer must not rely on it):
// its modal datasets are [ns, 0], its modes [0, nn, 3] and [0], over more than one block of
// samples (kBlockRows), beside a body whose datasets keep their values.
TEST(ResultsWriter, FlexibleBodyWithoutModesGetsEmptyColumns) {
  const auto dir = fresh_directory("no_modes");
  FlexibleBodySpec bare = two_node_beam();
  bare.name = "bare";
  bare.mode_translations.resize(6, 0);
  bare.frequencies_hz.resize(0);
  const int ns = static_cast<int>(kBlockRows) + 44;
  {
    ResultsWriter writer(dir, "no modes", "case.yaml");
    EXPECT_EQ(writer.add_flexible_body(bare), 0);
    EXPECT_EQ(writer.add_flexible_body(two_node_beam()), 1);
    for (int k = 0; k < ns; ++k) {
      Sample sample;
      sample.time = 0.1 * k;
      sample.bodies.resize(2);
      sample.bodies[0].position = {1.0 * k, 0.0, 0.0};
      sample.bodies[1].modal_coordinates = Eigen::Vector2d(0.01 * k, -0.02 * k);
      sample.bodies[1].modal_velocities = Eigen::Vector2d(0.5 * k, 0.25 * k);
      writer.append_sample(sample);
    }
    writer.finish(RunStatus::kOk);
  }
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_string_attribute(file, "/", "status"), "ok");
  const auto rows = static_cast<hsize_t>(ns);
  EXPECT_EQ(dataset_dims(file, "/time"), (std::vector<hsize_t>{rows}));
  EXPECT_EQ(dataset_dims(file, "/bodies/bare/modal_coordinates"), (std::vector<hsize_t>{rows, 0}));
  EXPECT_EQ(dataset_dims(file, "/bodies/bare/modal_velocities"), (std::vector<hsize_t>{rows, 0}));
  EXPECT_EQ(dataset_dims(file, "/bodies/bare/modes/translations"), (std::vector<hsize_t>{0, 2, 3}));
  EXPECT_EQ(dataset_dims(file, "/bodies/bare/modes/frequencies_hz"), (std::vector<hsize_t>{0}));
  EXPECT_EQ(read_doubles(file, "/bodies/bare/position")[3 * (ns - 1)], ns - 1.0);
  EXPECT_EQ(dataset_dims(file, "/bodies/beam/modal_coordinates"), (std::vector<hsize_t>{rows, 2}));
  EXPECT_EQ(read_doubles(file, "/bodies/beam/modal_coordinates")[2 * (ns - 1) + 1], -0.02 * (ns - 1));
  H5Fclose(file);
}

// A real attribute's single value (NaN when absent).
double read_double_attribute(hid_t file, const std::string& path, const char* name) {
  if (H5Aexists_by_name(file, path.c_str(), name, H5P_DEFAULT) <= 0) return std::nan("");
  const hid_t attribute = H5Aopen_by_name(file, path.c_str(), name, H5P_DEFAULT, H5P_DEFAULT);
  double value = 0.0;
  H5Aread(attribute, H5T_NATIVE_DOUBLE, &value);
  H5Aclose(attribute);
  return value;
}

TEST(ResultsWriter, WritesStressPeaksEverySampleAndHistoryEveryNth) {
  // A beam (element 0) and a quad (element 1) on 5 nodes, both recorded, every 2nd sample.
  const auto dir = fresh_directory("stress");
  {
    ResultsWriter writer(dir, "stress", "case.yaml");
    FlexibleBodySpec body;
    body.name = "part";
    body.nodes.resize(5, 3);
    body.nodes << 0, 0, 0, 1, 0, 0, 1, 1, 0, 2, 1, 0, 1, 2, 0;
    body.lines.resize(1, 2);
    body.lines << 0, 1;
    body.quads.resize(1, 4);
    body.quads << 1, 2, 3, 4;
    body.mode_translations.setZero(15, 1);
    body.frequencies_hz = Eigen::VectorXd::Constant(1, 5.0);
    body.has_stress = true;
    body.stress_elements = {0, 1};
    body.stress_every = 2;
    writer.add_flexible_body(body);
    // Five samples: the peak is largest at sample 3 (not a history sample).
    const double peaks[5] = {1.0, 2.0, 3.0, 7.0, 4.0};
    for (int k = 0; k < 5; ++k) {
      Sample sample;
      sample.time = 0.5 * k;
      sample.bodies.resize(1);
      BodySample& b = sample.bodies[0];
      b.modal_coordinates = Eigen::VectorXd::Zero(1);
      b.modal_velocities = Eigen::VectorXd::Zero(1);
      b.stress_peak = peaks[k];
      b.stress_peak_element = k % 2;
      b.stress_recorded = k % 2 == 0;
      if (b.stress_recorded) {
        b.stress_equivalent = Eigen::Vector2d(10.0 * k, 10.0 * k + 1.0);
        b.stress_beam_resultants = Eigen::VectorXd::LinSpaced(12, 0.0, 11.0) + Eigen::VectorXd::Constant(12, 100.0 * k);
        b.stress_shell_resultants = Eigen::VectorXd::LinSpaced(8, 0.0, 7.0) + Eigen::VectorXd::Constant(8, 1000.0 * k);
      }
      writer.append_sample(sample);
    }
    writer.finish(RunStatus::kOk);
  }
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const std::string g = "/bodies/part/stress/";
  EXPECT_EQ(read_doubles(file, g + "elements"), (std::vector<double>{0, 1}));
  EXPECT_EQ(read_doubles(file, g + "peak"), (std::vector<double>{1, 2, 3, 7, 4}));
  EXPECT_EQ(read_doubles(file, g + "peak_element"), (std::vector<double>{0, 1, 0, 1, 0}));
  EXPECT_EQ(read_doubles(file, g + "time"), (std::vector<double>{0.0, 1.0, 2.0}));
  EXPECT_EQ(read_doubles(file, g + "equivalent"), (std::vector<double>{0, 1, 20, 21, 40, 41}));
  EXPECT_EQ(dataset_dims(file, g + "beam_resultants"), (std::vector<hsize_t>{3, 12}));
  EXPECT_EQ(dataset_dims(file, g + "shell_resultants"), (std::vector<hsize_t>{3, 8}));
  EXPECT_EQ(read_doubles(file, g + "beam_resultants")[12 + 4], 204.0);   // row 1 (k = 2), My0
  EXPECT_EQ(read_doubles(file, g + "shell_resultants")[16 + 7], 4007.0);  // row 2, von Mises bottom
  // The run's peak, where and when.
  EXPECT_EQ(read_double_attribute(file, "/bodies/part/stress", "peak_value"), 7.0);
  EXPECT_EQ(read_double_attribute(file, "/bodies/part/stress", "peak_element"), 1.0);
  EXPECT_EQ(read_double_attribute(file, "/bodies/part/stress", "peak_time"), 1.5);
  EXPECT_EQ(read_double_attribute(file, "/bodies/part/stress", "every"), 2.0);
  H5Fclose(file);
}

// The joint's two marker frames: names as attributes, origin and quaternion per sample, each
// value bit-exact (float64 stored as float64).
TEST(ResultsWriter, WritesJointMarkerPoses) {
  const auto dir = fresh_directory("markers");
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.0, 1.0, 0.0)));
  {
    ResultsWriter writer(dir, "markers", "case.yaml");
    writer.add_rigid_body({"crank", {}});
    writer.add_joint({"R1", "revolute", "ground", "crank", "R1.i", "R1.j"});
    for (int k = 0; k < 300; ++k) {  // more than one block (kBlockRows = 256)
      Sample sample;
      sample.time = 0.01 * k;
      sample.bodies.resize(1);
      sample.joints.resize(1);
      sample.joints[0].marker_i.position = {0.0, 0.0, 1.0 * k};
      sample.joints[0].marker_j.position = {2.0 * k, 0.0, 0.0};
      sample.joints[0].marker_j.orientation = k == 1 ? turn : Eigen::Quaterniond::Identity();
      writer.append_sample(sample);
    }
    writer.finish(RunStatus::kOk);
  }
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_string_attribute(file, "/joints/R1/marker_i", "name"), "R1.i");
  EXPECT_EQ(read_string_attribute(file, "/joints/R1/marker_j", "name"), "R1.j");
  EXPECT_EQ(dataset_dims(file, "/joints/R1/marker_i/position"), (std::vector<hsize_t>{300, 3}));
  EXPECT_EQ(dataset_dims(file, "/joints/R1/marker_j/orientation"), (std::vector<hsize_t>{300, 4}));
  const std::vector<double> p_i = read_doubles(file, "/joints/R1/marker_i/position");
  const std::vector<double> p_j = read_doubles(file, "/joints/R1/marker_j/position");
  EXPECT_EQ(p_i[3 * 299 + 2], 299.0);
  EXPECT_EQ(p_j[3 * 257], 514.0);
  const std::vector<double> q_j = read_doubles(file, "/joints/R1/marker_j/orientation");
  EXPECT_EQ((std::vector<double>(q_j.begin() + 4, q_j.begin() + 8)),
            (std::vector<double>{turn.w(), turn.x(), turn.y(), turn.z()}));
  EXPECT_EQ(q_j[8], 1.0);  // w of sample 2: identity
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

// A string attribute holds at most 64 KiB in the file's 1.8 format: a 70 000-byte title once
// ended a run as "results.h5: HDF5 failed to write a string attribute" after a page of HDF5's
// own diagnostics (issue 31). Longer text is kept cut at 16 KiB with its length, and HDF5
// prints nothing. (The case reader bounds titles and names well below: io/case_reader.cpp.)
TEST(ResultsWriter, LongTextIsKeptCutWithItsLength) {
  const auto dir = fresh_directory("long_text");
  const std::string text(70000, 'm');
  ::testing::internal::CaptureStderr();
  {
    ResultsWriter writer(dir, text, "c.yaml");
    writer.finish(RunStatus::kFailed, text);
  }
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const std::string cut = std::string(16384, 'm') + "… (70000 bytes)";
  EXPECT_EQ(read_string_attribute(file, "/", "title"), cut);
  EXPECT_EQ(read_string_attribute(file, "/", "message"), cut);
  EXPECT_EQ(read_string_attribute(file, "/", "status"), "failed");
  H5Fclose(file);
}

// finish() closes the file, every group and dataset included, while the writer still lives: an
// acceleration probe's group and series once stayed open until the writer died, so the file
// stayed open, and a reader in the same process (limber.run reading back its output) failed.
TEST(ResultsWriter, FinishClosesEveryObjectOfTheFile) {
  const auto dir = fresh_directory("closed");
  ResultsWriter writer(dir, "t", "c.yaml");
  writer.add_rigid_body({"box", {ShapeSpec{}}});
  writer.add_joint({"R1", "revolute", "ground", "box"});
  writer.add_hinge_limit({"stop", "stop", "R1", 0.5});
  writer.add_acceleration_probe({"tip", "box", -1, Eigen::Vector3d(1, 0, 0)});
  Sample sample;
  sample.bodies.resize(1);
  sample.joints.resize(1);
  sample.hinge_limit_angles = {0.1};
  sample.hinge_limit_torques = {0.0};
  sample.hinge_limits_engaged = {0};
  sample.probe_accelerations = {Eigen::Vector3d(0, 0, -9.81)};
  writer.append_sample(sample);
  EXPECT_GT(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
  writer.finish(RunStatus::kOk);
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
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
