// `limber select` as a user runs it (popen), on the coarse flexible slider-crank: --json holds
// the ranking, the comparison and the choice; the files for the report and the user are there;
// bad options are input errors (exit 1) that name the option.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "coarse_slider_crank.h"
#include "mini_json.h"

namespace limber {
namespace {

test::CommandRun run_limber(const std::string& args) { return test::run_command(LIMBER_EXE, args); }

TEST(SelectCli, JsonFilesAndTheChosenRun) {
  const auto dir = test::fresh_directory("select_cli");
  const test::CommandRun run =
      run_limber("select " + test::coarse_slider_crank_file() + " -o " + dir.string() +
                 " --t-end 0.15 --max-single 2 --target 0.05 --norm peak --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const test::JsonValue json = test::parse_json(run.out);
  EXPECT_EQ(json["status"].string(), "ok");
  // 12 components (2 joints x 6), the four in-plane forces kept.
  const test::JsonValue::Array& ranking = json["ranking"].array();
  ASSERT_EQ(ranking.size(), 12u);
  int kept = 0;
  for (const test::JsonValue& row : ranking) kept += std::get<bool>(row["kept"].value) ? 1 : 0;
  EXPECT_EQ(kept, 4);
  // normal, two singles, kept, more_normal, reference.
  const test::JsonValue::Array& comparison = json["comparison"].array();
  ASSERT_EQ(comparison.size(), 6u);
  EXPECT_EQ(comparison.front()["set"].string(), "normal");
  EXPECT_EQ(comparison.back()["set"].string(), "reference");
  // The target is met: the chosen set's error is at most 5 %, and it has no more modes than
  // any other set that meets it.
  EXPECT_TRUE(std::get<bool>(json["target_met"].value));
  const std::string chosen = json["chosen"].string();
  double chosen_modes = 0.0;
  for (const test::JsonValue& row : comparison) {
    if (row["set"].string() == chosen) {
      chosen_modes = row["modes"].number();
      EXPECT_LE(row["error_peak"].number(), 0.05);
    }
  }
  for (const test::JsonValue& row : comparison) {
    if (row["set"].string() != "reference" && row["error_peak"].number() <= 0.05) {
      EXPECT_LE(chosen_modes, row["modes"].number()) << row["set"].string();
    }
  }
  EXPECT_NE(json["fragment"].string().find("flexible_bodies:\n  rod:\n    modes:\n"), std::string::npos);
  // Every set at a step that resolves its highest frequency (20 steps per period, at most 8
  // times shorter than the case's 1 ms), and its event peaks against the reference's: one
  // window ("start"), every joint.
  EXPECT_EQ(json["steps_per_period_needed"].number(), 20.0);
  for (const test::JsonValue& row : comparison) {
    const double step = row["step"].number(), f_max = row["f_max_hz"].number();
    EXPECT_LE(step, 1e-3 * (1 + 1e-12)) << row["set"].string();
    EXPECT_NEAR(row["steps_per_period"].number(), 1.0 / (step * f_max), 1e-9 * row["steps_per_period"].number());
    EXPECT_EQ(std::get<bool>(row["resolved"].value), step * f_max * 20.0 <= 1.0 + 1e-9) << row["set"].string();
    if (row["set"].string() == "reference") continue;
    EXPECT_FALSE(row["event_peaks"].array().empty()) << row["set"].string();
    double worst = 0.0;
    for (const test::JsonValue& peak : row["event_peaks"].array()) {
      EXPECT_EQ(peak["window"].string(), "start");
      // Not compared (null) below 1 % of the window's largest.
      if (std::holds_alternative<std::nullptr_t>(peak["force_error"].value)) continue;
      const double error = std::abs(peak["force"].number() - peak["reference_force"].number()) /
                           peak["reference_force"].number();
      EXPECT_NEAR(peak["force_error"].number(), error, 1e-12);
      worst = std::max(worst, error);
    }
    EXPECT_GE(row["error_event"].number(), worst);
  }
  // The reference at half its step: its peaks move by the reported change, measured.
  const test::JsonValue& check = json["reference_check"];
  EXPECT_EQ(check["half_step_status"].string(), "ok");
  EXPECT_NEAR(check["half_step"].number(), 0.5 * check["step"].number(), 1e-15);
  EXPECT_EQ(std::get<bool>(check["converged"].value), check["peak_change"].number() < 0.03);

  // Files: every set's results, the CSVs, the fragment, and the chosen run's results in DIR.
  for (const char* file : {"results.h5", "selected_modes.yaml", "selection/ranking.csv",
                           "selection/comparison.csv", "selection/key_series.csv", "selection/event_peaks.csv",
                           "runs/normal/results.h5", "runs/reference/results.h5",
                           "runs/reference_half_step/1_start/results.h5"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
  }
  const std::string comparison_csv = test::read_text((dir / "selection/comparison.csv").string());
  EXPECT_EQ(comparison_csv.rfind("set,description,modes,reduction_s,run_s,status,error_peak,error_rms,"
                                 "worst_quantity,directory,role,f_max_hz,step,steps_per_period,resolved,"
                                 "error_event,worst_event\n", 0), 0u);
  EXPECT_NE(comparison_csv.find(",reference,"), std::string::npos);
  EXPECT_NE(comparison_csv.find(",chosen,"), std::string::npos);
  const std::string series = test::read_text((dir / "selection/key_series.csv").string());
  EXPECT_NE(series.find("normal|R3 force z on rod [N]"), std::string::npos);
  // A header and one row per sample (every 1 ms from 0 to 0.15 s).
  EXPECT_EQ(std::count(series.begin(), series.end(), '\n'), 152);
}

TEST(SelectCli, BadOptionsAreInputErrors) {
  const std::string file = test::coarse_slider_crank_file();
  const test::CommandRun keep = run_limber("select " + file + " --keep 0");
  EXPECT_EQ(keep.exit_code, 1);
  EXPECT_NE(keep.err.find("expected --keep in (0, 1], got 0"), std::string::npos) << keep.err;
  const test::CommandRun target = run_limber("select " + file + " --target -1");
  EXPECT_EQ(target.exit_code, 1);
  EXPECT_NE(target.err.find("expected --target > 0"), std::string::npos) << target.err;
  // --reference: modal or nonlinear; a body the nonlinear reference cannot take is refused at
  // its entry before any set runs (the shipped rod has modal damping ratios).
  const test::CommandRun reference = run_limber("select " + file + " --reference exact");
  EXPECT_EQ(reference.exit_code, 1);
  EXPECT_NE(reference.err.find("--reference"), std::string::npos) << reference.err;
  const auto refused_dir = test::fresh_directory("select_cli_refused");
  const test::CommandRun refused = run_limber("select " + std::string(LIMBER_CASES_DIR) +
                                              "/slider_crank.yaml --reference nonlinear -o " + refused_dir.string());
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("slider_crank.yaml:88:5: --reference nonlinear: body 'rod': expected 'damping: 0' or"),
            std::string::npos)
      << refused.err;
  EXPECT_FALSE(std::filesystem::exists(refused_dir));
  // A rigid mechanism has nothing to select.
  const test::CommandRun rigid = run_limber("select " + std::string(LIMBER_CASES_DIR) + "/slider_crank_rigid.yaml");
  EXPECT_EQ(rigid.exit_code, 1);
  EXPECT_NE(rigid.err.find("expected a mechanism with at least one flexible body"), std::string::npos) << rigid.err;
}

}  // namespace
}  // namespace limber
