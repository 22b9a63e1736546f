// `limber run` as a user runs it (popen): the seed slider-crank lists its redundant equations
// by joint and direction on stdout, in --json and in results.h5; the results file holds every
// documented dataset with one row per sample; an interference is printed with its pair and
// time; bad case files give file:line:col (exit 1); a failed run exits with 2 and leaves a
// readable file with status "failed".
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "../results/h5_test_read.h"
#include "mini_json.h"
#include "run_test_support.h"

namespace limber {
namespace {

using results::testing::dataset_dims;
using results::testing::read_doubles;
using results::testing::read_string_attribute;

test::CommandRun run_limber(const std::string& args) { return test::run_command(LIMBER_EXE, args); }

const std::string kCase = std::string(LIMBER_CASES_DIR) + "/slider_crank_rigid.yaml";

// Equations out of the plane of motion (x-z): revolute axes (marker z) are along ground y, so
// R*.z (position along y), R*.rot_x and R*.rot_y (tilts of the axis) leave the plane; the
// translational's marker z is along ground x and its marker x along ground y, so T.x (along
// y), T.rot_y and T.rot_z (about ground z and x) do too. T.rot_x is the in-plane rotation.
bool out_of_plane(const std::string& name) {
  static const std::set<std::string> names = {"R1.z", "R1.rot_x", "R1.rot_y", "R2.z", "R2.rot_x",
                                              "R2.rot_y", "R3.z", "R3.rot_x", "R3.rot_y", "T.x",
                                              "T.rot_y", "T.rot_z"};
  return names.contains(name);
}

TEST(RunCli, SliderCrankListsItsRedundantEquationsEverywhere) {
  const auto dir = test::fresh_directory("cli_redundant");
  const test::CommandRun run = run_limber("run " + kCase + " -o " + dir.string() + " --t-end 0.05 --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;

  // --json: exactly one object with the documented fields.
  const test::JsonValue json = test::parse_json(run.out);
  EXPECT_EQ(json["status"].string(), "ok");
  EXPECT_EQ(json["integrator"].string(), "ida");
  EXPECT_EQ(json["t_end"].number(), 0.05);
  EXPECT_EQ(json["samples"].number(), 51.0);  // every 1 ms from 0 to 50 ms
  EXPECT_GT(json["steps"].number(), 10.0);
  EXPECT_GE(json["wall_s"].number(), 0.0);
  // Positions at IDA's interpolated samples, rtol 1e-6 of the case: well below 1e-5 m.
  EXPECT_LT(json["max_constraint_violation"].number(), 1e-5);
  // Three bodies with box shapes: the minimum clearance, its time and pair, also on the text.
  const test::JsonValue& clearance = json["clearance"];
  EXPECT_GE(clearance["time"].number(), 0.0);
  ASSERT_EQ(clearance["pair"].array().size(), 2u);
  EXPECT_NE(run.err.find("minimum clearance: "), std::string::npos) << run.err;

  // 18 velocities, 21 equations, rank 18: 3 redundant, every one out of the plane and named
  // "<joint>.<direction>" of a revolute (the 3D model's surplus is at the crank pins).
  const test::JsonValue::Array& redundant = json["redundant"].array();
  ASSERT_EQ(redundant.size(), 3u);
  std::vector<std::string> names;
  for (const test::JsonValue& name : redundant) {
    names.push_back(name.string());
    EXPECT_TRUE(out_of_plane(name.string())) << name.string();
    // Listed on stdout's text (stderr under --json) with what it depends on.
    EXPECT_NE(run.err.find("  " + name.string() + " is redundant with "), std::string::npos) << run.err;
  }
  EXPECT_NE(run.err.find("3 of 21 equations are redundant (rank 18)"), std::string::npos) << run.err;

  // results.h5: the same names, and the equations each depends on, all out of plane too.
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(test::read_fixed_strings(file, "/constraints/redundant"), names);
  const std::vector<std::string> depends = test::read_fixed_strings(file, "/constraints/redundant_with");
  ASSERT_EQ(depends.size(), 3u);
  for (const std::string& list : depends) {
    std::size_t start = 0;
    while (start < list.size()) {
      const std::size_t end = std::min(list.find(", ", start), list.size());
      EXPECT_TRUE(out_of_plane(list.substr(start, end - start))) << list;
      start = end + 2;
    }
  }
  H5Fclose(file);
}

TEST(RunCli, ResultsHoldEveryDocumentedDataset) {
  // The shipped case started at full speed (the seed's start, its commented motion line), so
  // that 20 ms are 0.4 crank turns and the slider's position has the constant-speed closed form.
  const std::string path = test::write_case(
      "cli_constant_speed",
      test::edited_case(kCase, "motion: {type: ramp, initial: 0, speed: 125.66370614359172, duration: 0.1, shape: quintic}",
                        "motion: {type: constant_speed, initial: 0, speed: 125.66370614359172}"));
  const auto dir = test::fresh_directory("cli_layout");
  const test::CommandRun run =
      run_limber("run " + path + " -o " + dir.string() + " --integrator galpha --step 1e-4 --t-end 0.02");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("finished: t = 0.02 s, 21 samples, 200 steps"), std::string::npos) << run.out;

  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_string_attribute(file, "/", "format"), "limber-results");
  EXPECT_EQ(read_string_attribute(file, "/", "status"), "ok");
  EXPECT_EQ(read_string_attribute(file, "/", "integrator"), "galpha");
  EXPECT_EQ(read_string_attribute(file, "/", "title"), "Slider-crank, rigid rod, crank at 20 rev/s");
  const hsize_t ns = 21;
  using Dims = std::vector<hsize_t>;
  EXPECT_EQ(dataset_dims(file, "/time"), Dims{ns});
  for (const char* body : {"crank", "rod", "slider"}) {
    const std::string group = std::string("/bodies/") + body;
    EXPECT_EQ(read_string_attribute(file, group, "kind"), "rigid");
    EXPECT_EQ(dataset_dims(file, group + "/position"), (Dims{ns, 3}));
    EXPECT_EQ(dataset_dims(file, group + "/orientation"), (Dims{ns, 4}));
    EXPECT_EQ(read_string_attribute(file, group + "/shapes/0", "type"), "box");
  }
  for (const char* joint : {"R1", "R2", "R3", "T"}) {
    const std::string group = std::string("/joints/") + joint;
    for (const char* name : {"position", "force_joint", "torque_joint", "force_ground", "torque_ground"}) {
      EXPECT_EQ(dataset_dims(file, group + "/" + name), (Dims{ns, 3})) << group << "/" << name;
    }
    EXPECT_EQ(dataset_dims(file, group + "/indeterminate"), Dims{ns});
  }
  EXPECT_EQ(read_string_attribute(file, "/joints/T", "type"), "translational");
  EXPECT_EQ(read_string_attribute(file, "/joints/R2", "body_i"), "crank");
  EXPECT_EQ(dataset_dims(file, "/drivers/D1/effort"), Dims{ns});
  for (const char* energy : {"kinetic", "gravity", "spring", "dissipated", "driver_work", "force_work"}) {
    EXPECT_EQ(dataset_dims(file, std::string("/energy/") + energy), Dims{ns}) << energy;
  }
  EXPECT_EQ(dataset_dims(file, "/constraints/position_violation"), Dims{ns});
  EXPECT_EQ(dataset_dims(file, "/constraints/velocity_violation"), Dims{ns});
  EXPECT_EQ(dataset_dims(file, "/constraints/redundant"), Dims{3});
  EXPECT_EQ(dataset_dims(file, "/solver/steps"), Dims{ns});

  // Values: the slider on the closed form (gen-α holds g = 0 at its steps to the Newton
  // tolerance and the crank angle is the driver's: the samples, Hermite interpolants between
  // steps of h = 0.1 ms, are off by O(h²) with (ωh)² = 1.6e-4 on a (1 + a/b) = 0.0525 m of
  // swing, at most ~1e-5 m; bound 1e-4 m); the R1 joint point stays at the origin; the
  // position violation at the samples stays below 1e-6.
  const std::vector<double> time = read_doubles(file, "/time");
  const std::vector<double> slider = read_doubles(file, "/bodies/slider/position");
  const double a = 0.05, b = 1.0, omega = 2 * std::numbers::pi * 20;
  for (std::size_t k = 0; k < time.size(); ++k) {
    const double s = std::sin(omega * time[k]);
    EXPECT_NEAR(slider[3 * k], a * std::cos(omega * time[k]) + std::sqrt(b * b - a * a * s * s), 1e-4);
  }
  for (double x : read_doubles(file, "/joints/R1/position")) EXPECT_NEAR(x, 0.0, 1e-12);
  for (double g : read_doubles(file, "/constraints/position_violation")) EXPECT_LT(g, 1e-6);
  const std::vector<double> steps = read_doubles(file, "/solver/steps");
  EXPECT_EQ(steps.back(), 200.0);  // 0.02 s at h = 0.1 ms
  H5Fclose(file);
}

TEST(RunCli, InterferenceIsWarnedWithPairAndTime) {
  // A bar turned about ground z whose 1 m box starts with its tip 0.1 m inside a block's
  // face at x = 0.9 (tests/run/clearance_run_test.cpp has the numbers).
  const std::string path = test::write_case("cli_interference",
      "title: Bar through a block\n"
      "bodies:\n"
      "  bar:\n"
      "    mass: 1.0\n"
      "    inertia: [1e-4, 0.0833, 0.0833]\n"
      "    center_of_mass: [0.5, 0, 0]\n"
      "    position: [0, 0, 0]\n"
      "    shapes:\n"
      "      - {type: box, size: [1.0, 0.05, 0.05], position: [0.5, 0, 0]}\n"
      "  block:\n"
      "    mass: 1.0\n"
      "    inertia: [0.2, 0.2, 0.2]\n"
      "    position: [1.4, 0, 0]\n"
      "    shapes:\n"
      "      - {type: box, size: [1, 1, 1]}\n"
      "joints:\n"
      "  R: {type: revolute, body_i: ground, body_j: bar, position: [0, 0, 0],\n"
      "      orientation: {z_axis: [0, 0, 1], x_axis: [1, 0, 0]}}\n"
      "drivers:\n"
      "  D: {joint: R, motion: {type: constant_speed, initial: 0, speed: 6.283185307179586}}\n"
      "run:\n"
      "  t_end: 0.5\n"
      "  sample_interval: 0.05\n");
  const auto dir = test::fresh_directory("cli_interference");
  const test::CommandRun run = run_limber("run " + path + " -o " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("minimum clearance: -0.1 m between bar and block at t = 0 s"), std::string::npos) << run.out;
  EXPECT_NE(run.err.find("limber: warning: bar passes through block at t = 0 s"), std::string::npos) << run.err;
}

// A probe on the rigid slider-crank's crank pin (0.05 m from R1): the run prints its spectra's
// peak and CSV file, and the CSV holds its header.
TEST(RunCli, AccelerationProbesGetSpectraOnStdoutAndInCsv) {
  const std::string path = test::write_case(
      "cli_probe", test::read_text(kCase) + "\nacceleration_probes:\n  pin: {body: crank, position: [0.05, 0, 0]}\n");
  const auto dir = test::fresh_directory("cli_probe");
  const test::CommandRun run = run_limber("run " + path + " -o " + dir.string() + " --t-end 0.2");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("shock response spectra: Q 10, 5 to "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("  pin: peak "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("srs_pin.csv"), std::string::npos) << run.out;
  std::ifstream csv(dir / "srs_pin.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "window,window_start_s,window_end_s,frequency_hz,x_m_s2,y_m_s2,z_m_s2,x_g,y_g,z_g");
}

TEST(RunCli, CoarseSettingsAreReportedAsInaccurate) {
  // The flexible slider-crank at a 10 ms step (50 steps per crank turn where the case uses 250,
  // against rod modes up to 290 Hz): it finishes, but R2 peaks near 20 kN instead of 2 kN and
  // the energy balance is off by more than half the energy scale (docs/integrators.md,
  // "Accuracy check"). The run must say so: exit 5, status "ok_inaccurate", the fix named.
  const auto dir = test::fresh_directory("cli_inaccurate");
  const std::string flexible = std::string(LIMBER_CASES_DIR) + "/slider_crank.yaml";
  const test::CommandRun run = run_limber("run " + flexible + " -o " + dir.string() + " --step 1e-2 --json");
  EXPECT_EQ(run.exit_code, 5) << run.err;
  const test::JsonValue json = test::parse_json(run.out);
  EXPECT_EQ(json["status"].string(), "ok_inaccurate");
  EXPECT_GT(json["accuracy"]["energy_relative"].number(), 0.1);
  EXPECT_FALSE(json["accuracy"]["warnings"].array().empty());
  EXPECT_NE(run.err.find("use a smaller step, e.g. --step 0.0025"), std::string::npos) << run.err;
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_string_attribute(file, "/", "status"), "ok_inaccurate");
  EXPECT_NE(read_string_attribute(file, "/", "accuracy_warnings").find("energy balance"), std::string::npos);
  H5Fclose(file);

  // The same at the case's own step is accurate: exit 0, status ok. A short run keeps it quick.
  const test::CommandRun fine = run_limber("run " + flexible + " -o " + dir.string() + " --t-end 0.2 --json");
  EXPECT_EQ(fine.exit_code, 0) << fine.err;
  EXPECT_EQ(test::parse_json(fine.out)["status"].string(), "ok");
  EXPECT_LT(test::parse_json(fine.out)["accuracy"]["energy_relative"].number(), 1e-3);
}

TEST(RunCli, BudgetsAndToleranceFloorStopRunsThatCannotFinish) {
  // IDA tighter than double precision delivers on a mechanism is refused up front (exit 1,
  // nothing written); a wall-clock budget stops a run that has not finished by then (exit 2,
  // status "failed" with the reason, every sample before it kept). The deployment needs ~4 s
  // for its 6 s at its own step, so 0.3 s of wall clock cannot be enough on any machine.
  const auto dir = test::fresh_directory("cli_budgets");
  const test::CommandRun tight = run_limber("run " + kCase + " -o " + dir.string() + " --rtol 1e-12");
  EXPECT_EQ(tight.exit_code, 1);
  EXPECT_NE(tight.err.find("expected rtol >= 1e-11 for IDA on a mechanism"), std::string::npos) << tight.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "results.h5"));

  const std::string deployment = std::string(LIMBER_CASES_DIR) + "/satellite_deployment.yaml";
  const test::CommandRun budget =
      run_limber("run " + deployment + " -o " + dir.string() + " --max-wall 0.3 --json");
  EXPECT_EQ(budget.exit_code, 2) << budget.err;
  const test::JsonValue json = test::parse_json(budget.out);
  EXPECT_EQ(json["status"].string(), "failed");
  EXPECT_NE(json["message"].string().find("the wall-clock budget of 0.3 s is spent"), std::string::npos);
  EXPECT_GT(json["samples"].number(), 0.0);
  EXPECT_LT(json["t_reached"].number(), 6.0);
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_string_attribute(file, "/", "status"), "failed");
  H5Fclose(file);
}

TEST(RunCli, JointFarFromItsBodyIsWarned) {
  // Joints given at ground points put their markers wherever the bodies are at t = 0: a slider
  // placed 1.95 m off its pin is no assembly error, just another mechanism. The run says so:
  // the slider's shapes reach 0.061 m from its centre of mass, its pins sit 1.95 m away (32 x).
  const auto dir = test::fresh_directory("cli_distant_joint");
  const std::string moved = test::write_case(
      "distant_joint", test::edited_case(kCase, "position: [1.05, 0, 0]\n    shapes:", "position: [3.0, 0, 0]\n    shapes:"));
  const test::CommandRun run = run_limber("run " + moved + " -o " + dir.string() + " --t-end 0.01");
  EXPECT_NE(run.err.find("limber: warning: joint R3 sits 1.95 m from the centre of mass of slider"),
            std::string::npos) << run.err;
  // The shipped case is placed right: no such warning.
  const test::CommandRun shipped = run_limber("run " + kCase + " -o " + dir.string() + " --t-end 0.01");
  EXPECT_EQ(shipped.err.find("sits"), std::string::npos) << shipped.err;
}

TEST(RunCli, BadCaseFileGivesFileLineAndExitOne) {
  const std::string path = test::write_case(
      "bad_joint", test::edited_case(kCase, "R2: {type: revolute,", "R2: {type: hinge,"));
  const test::CommandRun run = run_limber("run " + path + " -o " + test::fresh_directory("bad").string());
  EXPECT_EQ(run.exit_code, 1);
  // "R2: {type: hinge," sits on the line of R2; 'hinge' at the column after "type: ".
  const std::string text = test::read_text(path);
  const std::size_t at = text.find("hinge");
  const long line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(at), '\n');
  const std::size_t column = at - text.rfind('\n', at);
  EXPECT_EQ(run.err, "limber: error: " + path + ":" + std::to_string(line) + ":" + std::to_string(column) +
                         ": expected one of revolute, translational, spherical, bracket, universal, "
                         "cylindrical for 'type', got 'hinge'\n");
  // A case without a mechanism.
  const test::CommandRun modes_only = run_limber("run " + std::string(LIMBER_CASES_DIR) + "/plate_modes.yaml -o " +
                                                 test::fresh_directory("no_mechanism").string());
  EXPECT_EQ(modes_only.exit_code, 1);
  EXPECT_NE(modes_only.err.find("expected a mechanism (a 'bodies' section), got none"), std::string::npos);
  // Options out of range.
  EXPECT_EQ(run_limber("run " + kCase + " --rtol -1").exit_code, 1);
  EXPECT_EQ(run_limber("run " + kCase + " --integrator euler").exit_code, 1);
}

TEST(RunCli, FailedRunExitsWithTwoAndKeepsAReadableFile) {
  // A step budget of 50 stops IDA after a few ms of the 0.1 s.
  const std::string path =
      test::write_case("cli_budget", test::edited_case(kCase, "  t_end: 1.0 ", "  max_steps: 50\n  t_end: 0.1 "));
  const auto dir = test::fresh_directory("cli_budget");
  const test::CommandRun run = run_limber("run " + path + " -o " + dir.string() + " --json");
  EXPECT_EQ(run.exit_code, 2);
  const test::JsonValue json = test::parse_json(run.out);
  EXPECT_EQ(json["status"].string(), "failed");
  EXPECT_NE(json["message"].string().find("at t = "), std::string::npos);
  EXPECT_NE(run.err.find("limber: error: run failed: at t = "), std::string::npos) << run.err;

  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_string_attribute(file, "/", "status"), "failed");
  EXPECT_EQ(read_string_attribute(file, "/", "message"), json["message"].string());
  const std::vector<double> time = read_doubles(file, "/time");
  EXPECT_EQ(static_cast<double>(time.size()), json["samples"].number());
  EXPECT_GT(time.size(), 1u);
  EXPECT_EQ(dataset_dims(file, "/joints/R3/force_ground"), (std::vector<hsize_t>{time.size(), 3}));
  H5Fclose(file);
}

}  // namespace
}  // namespace limber

namespace limber {
namespace {

TEST(RunCli, SigtermClosesTheFileAsInterrupted) {
  // The deployment, run on to 30 s of latched ringing, takes several times 3 s (its 6 s took
  // 2.2 s on an idle machine after issue 16's speed-up): SIGTERM 3 s in lands mid-run.
  const auto dir = test::fresh_directory("sigterm");
  const test::CommandRun run = test::run_command(
      "timeout", "--preserve-status -s TERM 3 " + std::string(LIMBER_EXE) + " run " +
                     std::string(LIMBER_CASES_DIR) + "/satellite_deployment.yaml --t-end 30 -o " + dir.string());
  EXPECT_EQ(run.exit_code, 4) << run.err;
  EXPECT_NE(run.err.find("interrupted by signal 15"), std::string::npos) << run.err;
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_string_attribute(file, "/", "status"), "interrupted");
  EXPECT_GT(dataset_dims(file, "/time").at(0), 0u);
  H5Fclose(file);
}

}  // namespace
}  // namespace limber

namespace limber {
namespace {

TEST(RunCli, SigkillLeavesAReadableFileOfWholeBlocks) {
  // SIGKILL 3 s in: the deployment run on to 30 s (2 ms samples, over 1000 per second of wall
  // time) has written several blocks (results_writer.h: 256 samples or 1 s of wall time each)
  // and is mid-run.
  const auto dir = test::fresh_directory("sigkill");
  const test::CommandRun run = test::run_command(
      "timeout", "--preserve-status -s KILL 3 " + std::string(LIMBER_EXE) + " run " +
                     std::string(LIMBER_CASES_DIR) + "/satellite_deployment.yaml --t-end 30 -o " + dir.string());
  EXPECT_NE(run.exit_code, 0);
  // The file opens as it was left: no h5clear, status still "running" (the run did not finish).
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_string_attribute(file, "/", "status"), "running");
  // Whole samples only: every per-sample dataset has the rows of /time, the times the grid's.
  const std::vector<double> time = read_doubles(file, "/time");
  ASSERT_GT(time.size(), 0u);
  EXPECT_LT(time.back(), 30.0);
  for (std::size_t k = 0; k < time.size(); ++k) {
    ASSERT_NEAR(time[k], 2e-3 * static_cast<double>(k), 1e-12) << k;
  }
  for (const char* path : {"/bodies/bus/position", "/joints/R3/force_ground", "/energy/kinetic",
                           "/solver/steps", "/constraints/position_violation"}) {
    EXPECT_EQ(dataset_dims(file, path).at(0), time.size()) << path;
  }
  H5Fclose(file);
}

}  // namespace
}  // namespace limber
