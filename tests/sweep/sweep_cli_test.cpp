// `limber sweep` as a user runs it (popen) on the rigid slider-crank shortened to 0.1 s: a real
// convergence check of generalized-alpha, the choice for --target, resume, a failed point as a
// row, and bad input.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "../results/h5_test_read.h"
#include "mini_json.h"
#include "run_test_support.h"

namespace limber {
namespace {

test::CommandRun run_limber(const std::string& args) { return test::run_command(LIMBER_EXE, args); }

const std::string kCase = std::string(LIMBER_CASES_DIR) + "/slider_crank_rigid.yaml";

std::map<std::string, test::JsonValue> points_by_name(const test::JsonValue& json) {
  std::map<std::string, test::JsonValue> points;
  for (const test::JsonValue& point : json["points"].array()) points[point["point"].string()] = point;
  return points;
}

TEST(SweepCli, ConvergenceTargetAndResume) {
  const auto dir = test::fresh_directory("sweep_cli");
  const std::string command = "sweep " + kCase + " --over integrator=galpha step=1e-3,5e-4 --t-end 0.1 -o " +
                              dir.string() + " --target 0.002 --jobs 2 --json";
  const test::CommandRun first = run_limber(command);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const test::JsonValue json = test::parse_json(first.out);
  auto points = points_by_name(json);
  ASSERT_EQ(points.size(), 2u);
  const test::JsonValue& coarse = points.at("galpha_step0.001");
  const test::JsonValue& fine = points.at("galpha_step0.0005");
  EXPECT_EQ(coarse["status"].string(), "ok");
  EXPECT_EQ(fine["status"].string(), "ok");
  // Fixed steps: 0.1 s / h steps exactly.
  EXPECT_EQ(coarse["steps"].number(), 100.0);
  EXPECT_EQ(fine["steps"].number(), 200.0);
  EXPECT_GT(fine["jacobian_evaluations"].number(), 0.0);
  EXPECT_GT(fine["peak_rss_mib"].number(), 1.0);
  // Generalized-alpha is second order (Arnold & Bruels 2007): halving the step divides the error
  // by 4. Against a reference at 1/8 of the finest step (error 1/64 of it) the measured ratio is
  // (1 - 1/256) / (1/4 - 1/256) = 4.05; +-0.5 leaves room for the O(h^3) terms (measured: 4.06).
  const double peak_ratio = coarse["error_peak"].number() / fine["error_peak"].number();
  const double rms_ratio = coarse["error_rms"].number() / fine["error_rms"].number();
  EXPECT_NEAR(peak_ratio, 4.0, 0.5);
  EXPECT_NEAR(rms_ratio, 4.0, 0.5);
  EXPECT_LT(fine["error_rms"].number(), 0.002);
  EXPECT_GT(coarse["error_rms"].number(), 0.002);
  // Only the fine point meets 0.2 % rms: it is the answer, printed as the options to use.
  EXPECT_TRUE(std::get<bool>(json["target_met"].value));
  EXPECT_EQ(json["chosen"].string(), "galpha_step0.0005");
  EXPECT_NE(json["run_options"].string().find("--integrator galpha --step 0.0005 --t-end 0.1"), std::string::npos);
  EXPECT_NE(json["reference"]["label"].string().find("galpha_step6.25e-05"), std::string::npos);
  for (const char* file : {"sweep/work_precision.csv", "sweep/work_precision.json", "sweep/errors.csv", "results.h5",
                           "reference/galpha_step6.25e-05/results.h5", "runs/galpha_step0.001/results.h5",
                           "runs/galpha_step0.001/run.json", "runs/galpha_step0.001/process.json"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
  }
  // Default quantities: the determinate in-plane forces; no indeterminate (minimum-norm) one.
  bool has_r1_force_x = false;
  for (const test::JsonValue& q : json["quantities"].array()) {
    has_r1_force_x |= q.string() == "R1 force x [N]";
    EXPECT_EQ(q.string().find("R2 force z"), std::string::npos);
  }
  EXPECT_TRUE(has_r1_force_x);

  // `limber report DIR` shows the sweep: its section, the log-log plots, the table.
  const test::CommandRun report = run_limber("report " + dir.string());
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const std::string page = test::read_text((dir / "report/index.html").string());
  EXPECT_NE(page.find("Work-precision sweep"), std::string::npos);
  EXPECT_NE(page.find("<tr class=\"chosen\"><td>galpha_step0.0005</td>"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir / "report/images/run1_sweep_rms.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "report/images/run1_sweep_peak.png"));

  // The same command again resumes: nothing reruns, the table is the same.
  const auto written = std::filesystem::last_write_time(dir / "runs/galpha_step0.001/results.h5");
  const test::CommandRun second = run_limber(command);
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_NE(second.err.find("galpha_step0.001: finished in an earlier sweep, not rerun"), std::string::npos) << second.err;
  EXPECT_NE(second.err.find("reused from"), std::string::npos) << second.err;
  EXPECT_EQ(std::filesystem::last_write_time(dir / "runs/galpha_step0.001/results.h5"), written);
  const auto again = points_by_name(test::parse_json(second.out));
  for (const auto& [name, point] : again) {
    EXPECT_TRUE(std::get<bool>(point["resumed"].value)) << name;
    EXPECT_EQ(point["error_rms"].number(), points.at(name)["error_rms"].number()) << name;
  }
  // --fresh reruns every point and the reference: the same errors again (deterministic runs).
  const test::CommandRun fresh = run_limber(command + " --fresh");
  ASSERT_EQ(fresh.exit_code, 0) << fresh.err;
  EXPECT_EQ(fresh.err.find("not rerun"), std::string::npos) << fresh.err;
  EXPECT_NE(std::filesystem::last_write_time(dir / "runs/galpha_step0.001/results.h5"), written);
  for (const auto& [name, point] : points_by_name(test::parse_json(fresh.out))) {
    EXPECT_FALSE(std::get<bool>(point["resumed"].value)) << name;
    EXPECT_EQ(point["error_rms"].number(), points.at(name)["error_rms"].number()) << name;
  }
}

TEST(SweepCli, FailedPointIsARowAgainstAGivenReference) {
  const auto dir = test::fresh_directory("sweep_cli_failed");
  // The reference: one run made by the user.
  const test::CommandRun reference =
      run_limber("run " + kCase + " --integrator galpha --step 2.5e-4 --t-end 0.1 -o " + (dir / "ref").string());
  ASSERT_EQ(reference.exit_code, 0) << reference.err;
  // 1e-8 s steps cannot finish 0.1 s within a 0.5 s budget: that point fails, the sweep does not.
  const test::CommandRun run = run_limber(
      "sweep " + kCase + " --over integrator=galpha step=1e-3,1e-8 --t-end 0.1 --max-wall 0.5 --quantities 'R3 force x' "
      "--reference " + (dir / "ref/results.h5").string() + " -o " + (dir / "s").string() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const test::JsonValue json = test::parse_json(run.out);
  ASSERT_EQ(json["quantities"].array().size(), 1u);
  EXPECT_EQ(json["quantities"].array()[0].string(), "R3 force x [N]");
  const auto points = points_by_name(json);
  EXPECT_EQ(points.at("galpha_step0.001")["status"].string(), "ok");
  const test::JsonValue& failed = points.at("galpha_step1e-08");
  EXPECT_EQ(failed["status"].string(), "failed");
  EXPECT_EQ(failed["exit_code"].number(), 2.0);
  EXPECT_NE(failed["message"].string().find("wall"), std::string::npos) << failed["message"].string();
  EXPECT_EQ(failed["error_rms"].value.index(), 0u);  // null: not measured
  const std::string table = test::read_text((dir / "s/sweep/work_precision.csv").string());
  EXPECT_NE(table.find("galpha_step1e-08,galpha,galpha,,1e-08,,failed,"), std::string::npos) << table;
}

// SIGTERM (a batch system's stop) to a running sweep: the running child is stopped and closes its
// file as interrupted, the table of what finished is written, exit code 4; the same command
// again resumes: the finished point is not rerun, the interrupted one is.
TEST(SweepCli, InterruptedSweepResumes) {
  const auto dir = test::fresh_directory("sweep_cli_interrupt");
  const test::CommandRun reference =
      run_limber("run " + kCase + " --integrator galpha --step 2.5e-4 --t-end 0.1 -o " + (dir / "ref").string());
  ASSERT_EQ(reference.exit_code, 0) << reference.err;
  // 1e-7 s steps: 10^6 steps, far longer than the test waits.
  const std::vector<std::string> args = {LIMBER_EXE, "sweep", kCase, "--over", "integrator=galpha", "step=1e-3,1e-7",
                                         "--t-end", "0.1", "--jobs", "1", "--reference",
                                         (dir / "ref/results.h5").string(), "-o", (dir / "s").string()};
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    // The child: quiet, then the sweep.
    std::freopen((dir / "out.txt").c_str(), "w", stdout);
    std::freopen((dir / "err.txt").c_str(), "w", stderr);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  // Wait until the slow point runs (its results file exists), then stop the sweep.
  const auto slow = dir / "s/runs/galpha_step1e-07/results.h5";
  for (int k = 0; k < 300 && !std::filesystem::exists(slow); ++k) usleep(50000);
  usleep(300000);
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 4) << test::read_text((dir / "err.txt").string());
  const std::string table = test::read_text((dir / "s/sweep/work_precision.csv").string());
  EXPECT_NE(table.find("galpha_step0.001,galpha,galpha,,0.001,,ok,"), std::string::npos) << table;
  EXPECT_NE(table.find("galpha_step1e-07,galpha,galpha,,1e-07,,interrupted,"), std::string::npos) << table;

  // Resume, with a budget so the slow point ends (as a failed row).
  std::string command;
  for (std::size_t k = 1; k < args.size(); ++k) command += " '" + args[k] + "'";
  const test::CommandRun again = run_limber(command + " --max-wall 0.5");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("galpha_step0.001: finished in an earlier sweep, not rerun"), std::string::npos) << again.err;
  EXPECT_EQ(again.err.find("galpha_step1e-07: finished in an earlier sweep"), std::string::npos) << again.err;
  const std::string resumed = test::read_text((dir / "s/sweep/work_precision.csv").string());
  EXPECT_NE(resumed.find("galpha_step1e-07,galpha,galpha,,1e-07,,failed,"), std::string::npos) << resumed;
}

// `limber run --modes N`, which the modes axis uses: N normal modes on the rod in results.h5.
TEST(SweepCli, RunModesOption) {
  const auto dir = test::fresh_directory("sweep_cli_modes");
  const std::string flexible = std::string(LIMBER_CASES_DIR) + "/slider_crank.yaml";
  const test::CommandRun run =
      run_limber("run " + flexible + " --modes 3 --t-end 0.005 --json -o " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const test::JsonValue json = test::parse_json(run.out);
  EXPECT_GT(json["jacobian_evaluations"].number(), 0.0);
  // At least one residual per Newton iteration (generalized-alpha's structured iteration
  // matrix needs no more; a finite-difference refresh adds some).
  EXPECT_GE(json["residual_evaluations"].number(), json["newton_iterations"].number());
  EXPECT_GT(json["newton_iterations"].number(), 0.0);
  EXPECT_NE(run.err.find("reduction: rod 3 modes"), std::string::npos) << run.err;
  const test::CommandRun bad = run_limber("run " + flexible + " --modes -1 -o " + dir.string());
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("expected --modes >= 0, got -1"), std::string::npos) << bad.err;
}

// `--reference nonlinear` on a short window of the seed set-up (0.2 m crank, 20 ms: the rod's
// first bending swing, peak 38.4 mm at 14 ms). The reference is the case with the rod nonlinear
// (`limber run --formulation nonlinear`): its deflection equals the run of the case that says
// `formulation: nonlinear` (cases/slider_crank_seed_setup_nonlinear.yaml, at the sweep point's
// step), the same model built two ways, to 1e-12 of the peak (deterministic runs of one model; measured: equal). The modal
// point's error against it is the modal model's: against a run of the same modal case at 1/8 of
// the step (the integration error alone) it is 2.1e-4 (peak), against the nonlinear rod 0.41 —
// the linear rod overshoots to 41.9 mm; asserted: more than 100 times the integration error.
TEST(SweepCli, NonlinearReferenceMeasuresTheModalModel) {
  const auto dir = test::fresh_directory("sweep_cli_nonlinear");
  const std::string seed = std::string(LIMBER_CASES_DIR) + "/slider_crank_seed_setup.yaml";
  const std::string grid = " --over integrator=galpha step=1e-4 --t-end 0.02 --quantities 'rod deflection z' --json";
  const test::CommandRun nonlinear =
      run_limber("sweep " + seed + grid + " --reference nonlinear -o " + (dir / "nonlinear").string());
  ASSERT_EQ(nonlinear.exit_code, 0) << nonlinear.err;
  const test::JsonValue json = test::parse_json(nonlinear.out);
  const std::string label = json["reference"]["label"].string();
  EXPECT_NE(label.find("nonlinear_galpha_step0.0001"), std::string::npos) << label;
  EXPECT_NE(label.find("--formulation nonlinear --integrator galpha --step 0.0001"), std::string::npos) << label;
  const double model_error = points_by_name(json).at("galpha_step0.0001")["error_peak"].number();

  // The same model from the case key.
  const test::CommandRun keyed = run_limber("run " + std::string(LIMBER_CASES_DIR) +
                                            "/slider_crank_seed_setup_nonlinear.yaml --step 1e-4 --t-end 0.02 -o " +
                                            (dir / "keyed").string());
  ASSERT_EQ(keyed.exit_code, 0) << keyed.err;
  const auto deflection = [](const std::filesystem::path& file) {
    const hid_t h = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const std::vector<double> values = results::testing::read_doubles(h, "/bodies/rod/deflection");
    H5Fclose(h);
    return values;
  };
  const std::vector<double> reference =
      deflection(dir / "nonlinear/reference/nonlinear_galpha_step0.0001/results.h5");
  const std::vector<double> expected = deflection(dir / "keyed/results.h5");
  ASSERT_EQ(reference.size(), expected.size());
  double peak = 0.0, difference = 0.0;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    peak = std::max(peak, std::abs(expected[k]));
    difference = std::max(difference, std::abs(reference[k] - expected[k]));
  }
  EXPECT_GT(peak, 0.03);
  EXPECT_LE(difference, 1e-12 * peak);

  // The integration error alone: the same point against the modal case at 1/8 of its step (the
  // modal run leaves the linear range: ok_inaccurate, exit 5, accepted as a given reference).
  const test::CommandRun fine = run_limber("run " + seed + " --integrator galpha --step 1.25e-5 --t-end 0.02 -o " +
                                           (dir / "fine").string());
  ASSERT_EQ(fine.exit_code, 5) << fine.err;
  const test::CommandRun integration = run_limber("sweep " + seed + grid + " --reference " +
                                                  (dir / "fine/results.h5").string() + " -o " + (dir / "modal").string());
  ASSERT_EQ(integration.exit_code, 0) << integration.err;
  const double integration_error =
      points_by_name(test::parse_json(integration.out)).at("galpha_step0.0001")["error_peak"].number();
  EXPECT_GT(integration_error, 0.0);
  EXPECT_GT(model_error, 100.0 * integration_error) << model_error << " against " << integration_error;
}

TEST(SweepCli, BadInputNamesTheOption) {
  const auto dir = test::fresh_directory("sweep_cli_bad");
  const auto expect_bad = [&](const std::string& args, const std::string& part) {
    const test::CommandRun run = run_limber("sweep " + kCase + " -o " + dir.string() + " " + args);
    EXPECT_EQ(run.exit_code, 1) << args;
    EXPECT_NE(run.err.find(part), std::string::npos) << run.err;
  };
  expect_bad("--over mesh", "'mesh' (mesh density is not a variable");
  expect_bad("--over modes", "a case with flexible bodies for the modes axis");
  expect_bad("--over step=fast", "expected a number, got 'fast'");
  // The case integrates with IDA: a step axis alone has no point to act on.
  expect_bad("--over step=1e-3", "expected integrator galpha in the grid for the step axis");
  expect_bad("--over rtol --reference /nonexistent/results.h5", "--reference: expected 'tight', 'nonlinear' or a finished");
  expect_bad("--over rtol --target -1", "expected --target > 0");
}

}  // namespace
}  // namespace limber
