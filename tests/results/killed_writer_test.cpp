// A run killed by SIGKILL leaves a results file that opens, with every per-sample dataset at the
// same row count, and loses no more than results_writer.h promises: at most kBlockRows − 1 of the
// samples the writer had reported as appended, all appended less than kFlushInterval after the
// last flush. A second run into a directory a live run writes is refused and leaves the live
// file intact.
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

// What the writer reports after each append: the sample count and when it was appended.
struct Report {
  std::int64_t count = 0;
  std::chrono::steady_clock::time_point appended;
};

// Declares a rigid and a flexible body, a joint, a driver and an energy, then appends samples
// forever (a pause between them stands for the solver's work), reporting each on report_fd.
[[noreturn]] void write_forever(const std::filesystem::path& dir, int report_fd,
                                std::chrono::microseconds pause) {
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
    const Report report{k, std::chrono::steady_clock::now()};
    if (write(report_fd, &report, sizeof report) != sizeof report) _exit(1);
    std::this_thread::sleep_for(pause);
  }
}

// A child process running write_forever into `dir`, and the parent's end of its report pipe.
struct WriterProcess {
  pid_t pid = -1;
  int reports = -1;
};
WriterProcess start_writer(const std::filesystem::path& dir,
                           std::chrono::microseconds pause = std::chrono::microseconds(500)) {
  int fds[2];
  LIMBER_DEMAND(pipe(fds) == 0);
  const pid_t child = fork();
  LIMBER_DEMAND(child >= 0);
  if (child == 0) {
    close(fds[0]);
    write_forever(dir, fds[1], pause);
  }
  close(fds[1]);
  return {child, fds[0]};
}

// Blocks until the writer reported at least `count` samples; returns every report read.
std::vector<Report> wait_for_samples(const WriterProcess& writer, std::int64_t count) {
  std::vector<Report> reports;
  Report report;
  while ((reports.empty() || reports.back().count < count) &&
         read(writer.reports, &report, sizeof report) == sizeof report) {
    reports.push_back(report);
  }
  return reports;
}

// Kills the writer after `count` reported samples plus a random pause of up to `jitter`; checks
// the file it leaves against the promise of results_writer.h and returns its sample count.
hsize_t kill_and_check(const std::filesystem::path& dir, std::chrono::microseconds pause,
                       std::int64_t count, std::chrono::microseconds jitter) {
  const WriterProcess writer = start_writer(dir, pause);
  std::vector<Report> reports = wait_for_samples(writer, count);
  std::mt19937 random(std::random_device{}());
  std::this_thread::sleep_for(std::chrono::microseconds(
      std::uniform_int_distribution<std::int64_t>(0, jitter.count())(random)));
  EXPECT_EQ(kill(writer.pid, SIGKILL), 0);
  int status = 0;
  EXPECT_EQ(waitpid(writer.pid, &status, 0), writer.pid);
  EXPECT_TRUE(WIFSIGNALED(status));
  // Drain reports written before the kill.
  Report report;
  while (read(writer.reports, &report, sizeof report) == sizeof report) reports.push_back(report);
  close(writer.reports);
  EXPECT_GE(static_cast<std::int64_t>(reports.size()), count);
  if (reports.empty()) return 0;
  const std::int64_t reported = reports.back().count;

  // The file opens without h5clear and every per-sample dataset has the same rows.
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(file, 0);
  if (file < 0) return 0;
  const hsize_t ns = testing::dataset_dims(file, "/time").at(0);
  // Lost: the samples after the last flush, fewer than a block (the kill may fall between an
  // append that flushed and its report: one sample more than reported) ...
  EXPECT_LE(static_cast<std::int64_t>(ns), reported + 1);
  EXPECT_LE(reported - static_cast<std::int64_t>(ns), static_cast<std::int64_t>(kBlockRows) - 1);
  // ... and appended within kFlushInterval: from the first lost sample to the last reported.
  if (static_cast<std::int64_t>(ns) < reported) {
    // reports[ns] is sample ns + 1, the first one not in the file.
    const auto span = reports.back().appended - reports[ns].appended;
    EXPECT_LT(span, kFlushInterval) << "lost samples " << ns + 1 << " to " << reported;
  }
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
  // Status says the run did not finish.
  EXPECT_EQ(testing::read_string_attribute(file, "/", "status"), "running");
  H5Fclose(file);
  return ns;
}

TEST(KilledWriter, FastSamplesLoseLessThanABlock) {
  const auto dir = std::filesystem::temp_directory_path() / ("limber_results_killed_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  // 2000 samples/s: blocks fill before the interval; kill after two blocks, at a random moment.
  const hsize_t ns = kill_and_check(dir, std::chrono::microseconds(500), 2 * kBlockRows + 20,
                                    std::chrono::microseconds(100'000));
  EXPECT_GE(ns, 2 * kBlockRows);
}

TEST(KilledWriter, SlowSamplesAreFlushedWithinTheInterval) {
  const auto dir = std::filesystem::temp_directory_path() / ("limber_results_slow_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  // 50 samples/s: a block would take 5 s; the interval flushes about every 50 samples. After
  // 2.4 s at least one interval flush happened (without it the file would be empty).
  const hsize_t ns = kill_and_check(dir, std::chrono::microseconds(20'000), 120,
                                    std::chrono::microseconds(20'000));
  EXPECT_GE(ns, 1u);
  EXPECT_LT(ns, kBlockRows);
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
