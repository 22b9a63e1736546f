// A run killed by SIGKILL leaves a results file that opens, with every per-sample dataset at the
// same row count and at least every sample the writer had reported as appended. A second run
// into a directory a live run writes is refused and leaves the live file intact.
#include "results/results_writer.h"

#include "core/error.h"

#include "h5_test_read.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <random>
#include <thread>

namespace limber::results {
namespace {

// Declares a rigid and a flexible body, a joint, a driver and an energy, then appends samples
// forever (a short pause between them stands for the solver's work), reporting each count on fd.
[[noreturn]] void write_forever(const std::filesystem::path& dir, int report_fd) {
  ResultsWriter writer(dir, "killed", "none");
  writer.add_rigid_body({"box", {}});
  FlexibleBodySpec plate;
  plate.name = "plate";
  plate.nodes = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>::Random(50, 3);
  plate.mode_translations = Eigen::MatrixXd::Random(150, 4);
  plate.frequencies_hz = Eigen::Vector4d(1, 2, 3, 4);
  writer.add_flexible_body(plate);
  writer.add_joint({"hinge", "revolute", "ground", "box"});
  writer.add_driver("motor");
  writer.add_energy("kinetic");
  Sample sample;
  sample.bodies.resize(2);
  sample.bodies[1].modal_coordinates = Eigen::Vector4d::Zero();
  sample.bodies[1].modal_velocities = Eigen::Vector4d::Zero();
  sample.joints.resize(1);
  sample.driver_efforts = {0.0};
  sample.energies = {0.0};
  for (std::int64_t k = 1;; ++k) {
    sample.time = 1e-3 * static_cast<double>(k);
    writer.append_sample(sample);
    if (write(report_fd, &k, sizeof k) != sizeof k) _exit(1);
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
}

// A child process running write_forever into `dir`, and the parent's end of its report pipe.
struct WriterProcess {
  pid_t pid = -1;
  int reports = -1;
};
WriterProcess start_writer(const std::filesystem::path& dir) {
  int fds[2];
  LIMBER_DEMAND(pipe(fds) == 0);
  const pid_t child = fork();
  LIMBER_DEMAND(child >= 0);
  if (child == 0) {
    close(fds[0]);
    write_forever(dir, fds[1]);
  }
  close(fds[1]);
  return {child, fds[0]};
}

// Blocks until the writer reported at least `count` samples; returns the last count read.
std::int64_t wait_for_samples(const WriterProcess& writer, std::int64_t count) {
  std::int64_t reported = 0;
  while (reported < count && read(writer.reports, &reported, sizeof reported) == sizeof reported) {
  }
  return reported;
}

TEST(KilledWriter, FileOpensWithEveryReportedSample) {
  const auto dir = std::filesystem::temp_directory_path() / ("limber_results_killed_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);

  // Child: writes forever; parent: waits for 20 reported samples, then kills at a random moment.
  const WriterProcess writer = start_writer(dir);
  std::int64_t reported = wait_for_samples(writer, 20);
  std::mt19937 random(std::random_device{}());
  std::this_thread::sleep_for(
      std::chrono::microseconds(std::uniform_int_distribution<int>(0, 3000)(random)));
  ASSERT_EQ(kill(writer.pid, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(waitpid(writer.pid, &status, 0), writer.pid);
  ASSERT_TRUE(WIFSIGNALED(status));
  // Drain reports written before the kill.
  std::int64_t k = 0;
  while (read(writer.reports, &k, sizeof k) == sizeof k) reported = k;
  close(writer.reports);
  ASSERT_GE(reported, 20);

  // The file opens without h5clear and every per-sample dataset has the same rows.
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const hsize_t ns = testing::dataset_dims(file, "/time").at(0);
  EXPECT_GE(ns, static_cast<hsize_t>(reported));
  for (const char* path :
       {"/bodies/box/position", "/bodies/box/orientation", "/bodies/plate/position",
        "/bodies/plate/orientation", "/bodies/plate/modal_coordinates", "/joints/hinge/position",
        "/joints/hinge/force_joint", "/joints/hinge/torque_joint", "/joints/hinge/force_ground",
        "/joints/hinge/torque_ground", "/joints/hinge/indeterminate", "/drivers/motor/effort",
        "/energy/kinetic", "/constraints/position_violation", "/constraints/velocity_violation",
        "/solver/steps"}) {
    EXPECT_EQ(testing::dataset_dims(file, path).at(0), ns) << path;
  }
  // The times are the ones written: t_k = k ms (exact: the same double expression).
  const std::vector<double> time = testing::read_doubles(file, "/time");
  for (std::size_t i = 0; i < time.size(); ++i) {
    EXPECT_EQ(time[i], 1e-3 * static_cast<double>(i + 1));
  }
  EXPECT_EQ(testing::read_string_attribute(file, "/", "status"), "running");
  H5Fclose(file);
}

TEST(KilledWriter, ASecondRunIntoALiveDirectoryIsRefusedAndTruncatesNothing) {
  const auto dir = std::filesystem::temp_directory_path() / ("limber_results_locked_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  const WriterProcess writer = start_writer(dir);
  wait_for_samples(writer, 5);
  // The live run holds the directory: a second writer is refused, naming it.
  const auto size_before = std::filesystem::file_size(dir / "results.h5");
  try {
    ResultsWriter second(dir, "second", "none");
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(dir.string()), std::string::npos) << error.what();
  }
  // ... and the live file was not truncated (before the lock, HDF5's create emptied it; the
  // file cannot be opened here while HDF5's own lock is held by the live run).
  EXPECT_GE(std::filesystem::file_size(dir / "results.h5"), size_before);
  // Once that run is gone, killed or not, the directory is free.
  ASSERT_EQ(kill(writer.pid, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(waitpid(writer.pid, &status, 0), writer.pid);
  close(writer.reports);
  EXPECT_NO_THROW(ResultsWriter(dir, "after", "none"));
}

}  // namespace
}  // namespace limber::results
