// results.h5's typed reader (results/results_reader.h, run_records.h): a run written by the
// results writer reads back as the values written, bit for bit (float64 in and out, so the
// comparisons are exact), with names, masses, mode kinds and the series of every part; a file
// another process still writes reads as what was flushed, with status "running".
#include <gtest/gtest.h>

#include "core/error.h"
#include "results/results_reader.h"
#include "results/results_writer.h"
#include "results/run_records.h"

#include <filesystem>

#include <sys/wait.h>
#include <unistd.h>

namespace limber::results {
namespace {

constexpr int kSamples = 3;

// A rigid crank with mass properties, a flexible rod with two modes, a hinge, a driver and an
// energy: the parts the typed reader returns.
void describe_run(ResultsWriter& writer) {
  RigidBodySpec crank;
  crank.name = "crank";
  crank.mass_properties = MassProperties{2.5, Eigen::Vector3d(0.1, 0.0, 0.0), Eigen::Matrix3d::Identity() * 0.3};
  writer.add_rigid_body(crank);
  FlexibleBodySpec rod;
  rod.name = "rod/1";  // a name whose link name differs
  rod.nodes = Eigen::Matrix<double, 2, 3, Eigen::RowMajor>::Zero();
  rod.nodes(1, 0) = 1.0;
  rod.lines.resize(1, 2);
  rod.lines << 0, 1;
  rod.mode_translations = Eigen::MatrixXd::Zero(6, 2);
  rod.frequencies_hz = Eigen::Vector2d(10.0, 25.0);
  rod.mode_kinds = {"normal", "constraint"};
  rod.mode_labels = {"bending 1", "constraint uz at node 2"};
  rod.component = "rod";
  rod.has_deflection = true;
  writer.add_flexible_body(rod);
  writer.add_joint(JointSpec("R1", "revolute", "crank", "rod/1"));
  writer.add_driver("motor", "N m");
  writer.add_energy("kinetic");
  writer.set_redundant_equations({"R1.rot_x"}, {"R1.z"});
}

Sample sample_at(int k) {
  Sample sample;
  sample.time = 0.25 * k;
  BodySample crank;
  crank.position = Eigen::Vector3d(0.1 * k, 0.0, 0.0);
  BodySample rod;
  rod.modal_coordinates = rod.modal_velocities = Eigen::Vector2d(1e-3 * k, -2e-3 * k);
  rod.deflection = Eigen::Vector3d(0.0, 0.0, 1e-4 * k);
  sample.bodies = {crank, rod};
  JointSample joint;
  joint.position = Eigen::Vector3d(1.0, 0.0, 0.0);
  joint.force_joint = Eigen::Vector3d(1.0 + k, 2.0, 3.0);
  joint.torque_joint = Eigen::Vector3d(0.0, -4.0 * k, 0.0);
  joint.force_ground = Eigen::Vector3d(-1.0, 0.5 * k, 0.0);
  joint.indeterminate = k == 1;
  sample.joints = {joint};
  sample.driver_efforts = {7.0 * k};
  sample.energies = {0.5 * k * k};
  sample.steps = 10 * k;
  return sample;
}

std::filesystem::path fresh_directory(const std::string& name) {
  const std::filesystem::path directory = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(directory);
  return directory;
}

TEST(ResultsReader, ReadsBackTheValuesWritten) {
  const std::filesystem::path directory = fresh_directory("limber_results_reader_test");
  {
    ResultsWriter writer(directory, "typed reader", "case.yaml");
    describe_run(writer);
    for (int k = 0; k < kSamples; ++k) writer.append_sample(sample_at(k));
    writer.finish(RunStatus::kOk);
  }
  Results results = read_results(directory);
  EXPECT_EQ(results.title, "typed reader");
  EXPECT_EQ(results.case_file, "case.yaml");
  EXPECT_EQ(results.status, "ok");
  ASSERT_EQ(results.sample_count(), kSamples);
  EXPECT_EQ(results.time(2), 0.5);
  ASSERT_EQ(results.bodies.size(), 2U);

  // Bodies: the crank's pose and mass; the rod's modes, their kinds and its component.
  const BodyTrack& crank = results.bodies[0];
  EXPECT_EQ(crank.name, "crank");
  EXPECT_FALSE(crank.flexible);
  EXPECT_EQ(crank.position(2, 0), 0.2);
  ASSERT_TRUE(crank.mass.has_value());
  EXPECT_EQ(crank.mass->mass, 2.5);
  EXPECT_EQ(crank.mass->com_B.x(), 0.1);
  EXPECT_EQ(crank.mass->inertia_com_B(1, 1), 0.3);
  const BodyTrack& rod = results.bodies[1];
  EXPECT_EQ(rod.name, "rod/1");
  EXPECT_TRUE(rod.flexible);
  EXPECT_FALSE(rod.mass.has_value());
  EXPECT_EQ(rod.component, "rod");
  EXPECT_EQ(rod.mode_kinds, (std::vector<std::string>{"normal", "constraint"}));
  EXPECT_EQ(rod.mode_labels[1], "constraint uz at node 2");
  EXPECT_EQ(rod.mesh.frequencies_hz(1), 25.0);
  EXPECT_EQ(rod.modal_coordinates(2, 1), -4e-3);

  // Joints: point and ground reaction from the poses' part.
  ASSERT_EQ(results.joints.size(), 1U);
  EXPECT_EQ(results.joints[0].name, "R1");
  EXPECT_EQ(results.joints[0].body_j, "rod/1");
  EXPECT_EQ(results.joints[0].force_ground(2, 1), 1.0);

  // The series: joint-frame reactions, the indeterminate flag, probes, driver, energy, steps.
  const RunRecords records = read_run_records(results);
  ASSERT_EQ(records.joints.size(), 1U);
  EXPECT_EQ(records.joints[0].force_joint(1, 0), 2.0);
  EXPECT_EQ(records.joints[0].torque_joint(2, 1), -8.0);
  ASSERT_EQ(records.joints[0].indeterminate.size(), kSamples);
  EXPECT_EQ(records.joints[0].indeterminate(1), 1.0);
  EXPECT_TRUE(records.joints[0].is_indeterminate());
  ASSERT_EQ(records.deflections.size(), 1U);
  EXPECT_EQ(records.deflections[0].body, "rod/1");
  EXPECT_EQ(records.deflections[0].values(2, 2), 2e-4);
  ASSERT_EQ(records.drivers.size(), 1U);
  EXPECT_EQ(records.drivers[0].name, "motor");
  EXPECT_EQ(records.driver_units[0], "N m");
  EXPECT_EQ(records.drivers[0].values(2), 14.0);
  ASSERT_EQ(records.energies.size(), 1U);
  EXPECT_EQ(records.energies[0].values(2), 2.0);
  EXPECT_EQ(records.steps, 20);
  EXPECT_EQ(records.redundant_equations,
            (std::vector<std::pair<std::string, std::string>>{{"R1.rot_x", "R1.z"}}));
  EXPECT_EQ(results.sample_count(), kSamples);  // nothing cut from a finished file
}

// A writer process that appends kSamples samples, flushes, says so on `ready` and finishes once
// `go` says so (HDF5 refuses a second open of a file its own process writes).
[[noreturn]] void write_in_child(const std::filesystem::path& directory, int ready, int go) {
  int code = 0;
  try {
    ResultsWriter writer(directory, "running", "case.yaml");
    describe_run(writer);
    for (int k = 0; k < kSamples; ++k) writer.append_sample(sample_at(k));
    writer.flush();
    char byte = 1;
    if (write(ready, &byte, 1) != 1 || read(go, &byte, 1) != 1) _exit(2);
    writer.finish(RunStatus::kOk);
  } catch (...) {
    code = 1;
  }
  _exit(code);
}

TEST(ResultsReader, AFileStillBeingWrittenReadsAsFlushed) {
  const std::filesystem::path directory = fresh_directory("limber_results_reader_running_test");
  int ready[2], go[2];
  ASSERT_EQ(pipe(ready), 0);
  ASSERT_EQ(pipe(go), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) write_in_child(directory, ready[1], go[0]);
  char byte = 0;
  ASSERT_EQ(read(ready[0], &byte, 1), 1);
  // The writer holds the file open: the reader sees the flushed samples and status "running".
  EXPECT_EQ(read_run_attributes(directory / kResultsFileName).status, "running");
  Results results = read_results(directory);
  EXPECT_EQ(results.status, "running");
  EXPECT_EQ(results.sample_count(), kSamples);
  const RunRecords records = read_run_records(results);
  EXPECT_EQ(results.sample_count(), kSamples);
  ASSERT_EQ(records.joints.size(), 1U);
  EXPECT_EQ(records.joints[0].force_joint(2, 0), 3.0);
  // The writer goes on and finishes.
  ASSERT_EQ(write(go[1], &byte, 1), 1);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_EQ(read_results(directory).status, "ok");
}

TEST(ResultsReader, MissingFileIsAnInputErrorNamingIt) {
  const std::filesystem::path directory = fresh_directory("limber_results_reader_missing_test");
  try {
    read_results(directory);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find((directory / kResultsFileName).string()), std::string::npos);
  }
  EXPECT_THROW(read_run_attributes(directory / kResultsFileName), InputError);
}

}  // namespace
}  // namespace limber::results
