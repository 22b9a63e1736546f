// The renderer's own reader gets back what limber_results wrote (closed forms of the test
// scene), and bad files give InputErrors with a clear message.
#include "results_reader.h"

#include "core/error.h"
#include "results/results_writer.h"
#include "test_dir.h"
#include "test_results.h"

#include <gtest/gtest.h>

#include <fstream>

namespace limber::render {
namespace {

using testing::fresh_directory;
using testing::TestScene;

TEST(ResultsReader, ReadsTheTestScene) {
  const auto dir = fresh_directory("reader");
  const TestScene scene;
  testing::write_test_results(dir, scene);
  const Results r = read_results(dir);

  EXPECT_EQ(r.title, scene.title);
  EXPECT_EQ(r.status, "ok");
  ASSERT_EQ(r.sample_count(), scene.samples);
  ASSERT_EQ(r.bodies.size(), 3u);  // box, plate0, beam (names sorted)
  EXPECT_EQ(r.bodies[0].name, "beam");
  EXPECT_EQ(r.bodies[1].name, "box");
  EXPECT_EQ(r.bodies[2].name, "plate0");
  const BodyTrack& plate = r.bodies[2];
  EXPECT_TRUE(plate.flexible);
  EXPECT_EQ(plate.mesh.nodes.rows(), (scene.nx + 1) * (scene.ny + 1));
  EXPECT_EQ(plate.mesh.quads.rows(), scene.nx * scene.ny);
  EXPECT_EQ(plate.mesh.mode_translations.cols(), 2);
  // Values are stored as float64: bit-exact round trip (tolerance 0).
  for (Eigen::Index k = 0; k < r.sample_count(); ++k) {
    const double t = r.time(k);
    EXPECT_EQ(t, scene.duration * k / (scene.samples - 1));
    EXPECT_EQ(plate.modal_coordinates(k, 0), testing::plate_eta(scene, t)(0));
    EXPECT_EQ(r.bodies[1].position.row(k).transpose(), testing::box_position(t));
  }
  EXPECT_EQ(r.bodies[1].shapes.size(), 1u);
  EXPECT_EQ(r.bodies[1].shapes[0].color.x(), 0.85);
  EXPECT_EQ(r.bodies[0].mesh.lines.rows(), testing::kBeamNodes - 1);
  EXPECT_EQ(r.bodies[0].mesh.beam_radius, 0.02);
  ASSERT_EQ(r.joints.size(), 1u);
  EXPECT_EQ(r.joints[0].body_j, "box");
}

// The message of the InputError thrown by read_results(dir).
std::string error_of(const std::filesystem::path& dir) {
  try {
    read_results(dir);
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

// Joint markers and the ground-axes force: what the writer was handed comes back (float64:
// bit-exact positions and forces; quaternion to rotation matrix within rounding).
TEST(ResultsReader, ReadsJointMarkersAndForces) {
  const auto dir = fresh_directory("reader_markers");
  std::vector<Eigen::Quaterniond> turns;
  {
    results::ResultsWriter writer(dir, "markers", "results_reader_test.cpp");
    writer.add_rigid_body({"arm", {}});
    writer.add_joint({"pin", "revolute", "ground", "arm", "pin.i", "pin.j"});
    for (int k = 0; k < 5; ++k) {
      results::Sample sample;
      sample.time = 0.1 * k;
      sample.bodies.resize(1);
      results::JointSample joint;
      joint.position = {0.5 * k, 0.0, 1.0};
      joint.force_ground = {1.0, -2.0 * k, 3.0};
      joint.marker_j.position = joint.position;
      turns.emplace_back(Eigen::AngleAxisd(0.2 * k, Eigen::Vector3d(0.0, 1.0, 0.0)));
      joint.marker_j.orientation = turns.back();
      sample.joints = {joint};
      writer.append_sample(sample);
    }
    writer.finish(results::RunStatus::kOk);
  }
  const Results r = read_results(dir);
  ASSERT_EQ(r.joints.size(), 1u);
  const JointTrack& pin = r.joints[0];
  ASSERT_TRUE(pin.has_markers());
  EXPECT_EQ(pin.marker_i.name, "pin.i");
  EXPECT_EQ(pin.marker_j.name, "pin.j");
  for (Eigen::Index k = 0; k < 5; ++k) {
    EXPECT_EQ(pin.marker_j.position.row(k), pin.position.row(k));
    EXPECT_EQ(pin.force_ground(k, 1), -2.0 * static_cast<double>(k));
    EXPECT_TRUE(pin.marker_j.rotation(k).isApprox(turns[static_cast<std::size_t>(k)].toRotationMatrix(), 1e-15));
    EXPECT_TRUE(pin.marker_i.rotation(k).isIdentity(0.0));
  }
}

TEST(ResultsReader, MissingFileIsAClearError) {
  const auto dir = fresh_directory("reader_missing");
  EXPECT_NE(error_of(dir).find("got no such file"), std::string::npos) << error_of(dir);
}

TEST(ResultsReader, TruncatedFileIsAClearError) {
  // Keep the first 2 kB of a valid file: the superblock survives, the objects do not.
  const auto source = fresh_directory("reader_source");
  testing::write_test_results(source, TestScene{});
  const auto dir = fresh_directory("reader_truncated");
  std::filesystem::copy_file(source / "results.h5", dir / "results.h5");
  std::filesystem::resize_file(dir / "results.h5", 2048);
  const std::string message = error_of(dir);
  EXPECT_NE(message.find("results.h5"), std::string::npos) << message;
  EXPECT_NE(message.find("expected"), std::string::npos) << message;
}

TEST(ResultsReader, NonHdf5FileIsAClearError) {
  const auto dir = fresh_directory("reader_text");
  std::ofstream(dir / "results.h5") << "not an HDF5 file\n";
  EXPECT_NE(error_of(dir).find("HDF5 cannot open"), std::string::npos) << error_of(dir);
}

}  // namespace
}  // namespace limber::render
