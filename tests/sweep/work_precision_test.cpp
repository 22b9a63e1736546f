// The pieces of the work-precision table: the error measure shared with `limber select`
// (closed forms), the flat JSON fields read back from `limber run --json`, and the choice of
// the cheapest point meeting a target.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "select/series_error.h"
#include "core/json_text.h"
#include "sweep/flat_json.h"
#include "sweep/work_precision.h"

namespace limber {
namespace {

TEST(SeriesError, ClosedFormsOnSharedAndOffsetSamples) {
  // x_ref = sin(2 pi t) on [0, 1] (sum of squares over 101 samples = 50), x = x_ref + 0.01:
  // peak error 0.01 / 1, rms error sqrt(101 * 1e-4) / sqrt(50).
  const int n = 101;
  Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(n, 0.0, 1.0);
  Eigen::VectorXd x_ref = (2.0 * std::numbers::pi * t.array()).sin().matrix();
  Eigen::VectorXd x = x_ref.array() + 0.01;
  select::SeriesError e = select::series_error(t, x, t, x_ref);
  EXPECT_EQ(e.samples, n);
  EXPECT_NEAR(e.peak, 0.01, 1e-12);
  EXPECT_NEAR(e.rms, std::sqrt(101 * 1e-4) / std::sqrt(x_ref.squaredNorm()), 1e-12);
  EXPECT_NEAR(x_ref.squaredNorm(), 50.0, 1e-9);
  // A run sampled at half the rate, a straight line: interpolation is exact, so no error.
  const Eigen::VectorXd t_coarse = Eigen::VectorXd::LinSpaced(51, 0.0, 1.0);
  e = select::series_error(t_coarse, 3.0 * t_coarse, t, 3.0 * t);
  EXPECT_EQ(e.samples, n);
  EXPECT_NEAR(e.peak, 0.0, 1e-15);
  // A run that stopped at t = 0.5 is compared on its span only (51 reference samples).
  e = select::series_error(t.head(51), x.head(51), t, x_ref);
  EXPECT_EQ(e.samples, 51);
  // A zero reference has no relative error.
  EXPECT_TRUE(std::isnan(select::series_error(t, x, t, Eigen::VectorXd::Zero(n)).peak));
}

TEST(FlatJson, FieldsOfLimberRunJson) {
  const std::string text =
      "{\"status\": \"ok_inaccurate\", \"message\": \"at t = 0.1 s: \\\"why\\\"\\n\", \"steps\": 200, "
      "\"wall_s\": 0.25, \"accuracy\": {\"energy_relative\": 1.5e-05, \"local_error\": null}}";
  EXPECT_EQ(sweep::json_string_field(text, "status"), "ok_inaccurate");
  EXPECT_EQ(sweep::json_string_field(text, "message"), "at t = 0.1 s: \"why\"\n");
  EXPECT_EQ(sweep::json_number_field(text, "steps"), 200.0);
  EXPECT_EQ(sweep::json_number_field(text, "energy_relative"), 1.5e-5);
  EXPECT_FALSE(sweep::json_number_field(text, "local_error").has_value());
  EXPECT_FALSE(sweep::json_number_field(text, "absent").has_value());
  // What json_string writes reads back.
  const std::string quoted = "{\"m\": " + json_string("a \"b\" \\ c\n") + "}";
  EXPECT_EQ(sweep::json_string_field(quoted, "m"), "a \"b\" \\ c\n");
}

sweep::SweepRow row(const std::string& status, double wall, double rms) {
  sweep::SweepRow r;
  r.status = status;
  r.wall_s = wall;
  r.error_rms = rms;
  r.error_peak = 2.0 * rms;
  return r;
}

TEST(CheapestMeeting, FastestAccuratePointWithinTheTarget) {
  const std::vector<sweep::SweepRow> rows = {
      row("ok", 1.0, 0.001),            // meets, slow
      row("ok", 0.3, 0.008),            // meets, fastest accurate
      row("ok_inaccurate", 0.1, 0.005), // meets, faster, but its own check failed: never chosen
      row("failed", 0.05, sweep::kNaN),
      row("ok", 0.2, 0.02),             // fast, misses the target
  };
  EXPECT_EQ(sweep::cheapest_meeting(rows, 0.01, true), 1u);
  // Peak errors are twice the rms here: 0.016 > 0.01, only the first meets.
  EXPECT_EQ(sweep::cheapest_meeting(rows, 0.01, false), 0u);
  EXPECT_FALSE(sweep::cheapest_meeting(rows, 1e-4, true).has_value());
}

// How MPI ranks send rows to rank 0: a row survives row_json -> row_from_json field by field.
TEST(RowJson, RoundTrip) {
  sweep::SweepRow row;
  row.point.integrator = "ida";
  row.point.rtol = 1e-5;
  row.point.modes = 3;
  row.status = "ok_inaccurate";
  row.message = "a \"quoted\", multi\nline message";
  row.exit_code = 5;
  row.wall_s = 0.123456789012;
  row.process_s = 0.5;
  row.steps = 7099;
  row.rejected_steps = 553;
  row.newton_iterations = 10906;
  row.jacobian_evaluations = 647;
  row.residual_evaluations = 20000;
  row.peak_rss_mib = 51.5;
  row.energy_relative = 0.0107;
  row.local_error = 0.0;
  row.error_peak = 0.0576;
  row.error_rms = 0.0433;
  row.worst_quantity = "R3 force y [N]";
  row.errors = {{"R1 force x [N]", 0.01, 0.005},
                {"rod deflection z [m]", 0.0576, 0.0433},
                {"T force y [N]", sweep::kNaN, sweep::kNaN}};
  row.resumed = true;
  row.rank = 3;
  const sweep::SweepRow back = sweep::row_from_json(sweep::row_json(row));
  EXPECT_EQ(back.point.name(), "ida_rtol1e-05_m3");
  EXPECT_FALSE(back.point.step.has_value());
  EXPECT_EQ(back.status, row.status);
  EXPECT_EQ(back.message, row.message);
  EXPECT_EQ(back.exit_code, 5);
  EXPECT_EQ(back.wall_s, row.wall_s);  // shortest exact text: bit for bit
  EXPECT_EQ(back.steps, 7099);
  EXPECT_EQ(back.rejected_steps, 553);
  EXPECT_EQ(back.newton_iterations, 10906);
  EXPECT_EQ(back.jacobian_evaluations, 647);
  EXPECT_EQ(back.residual_evaluations, 20000);
  EXPECT_EQ(back.peak_rss_mib, 51.5);
  EXPECT_EQ(back.energy_relative, 0.0107);
  EXPECT_TRUE(std::isnan(back.drift_relative));
  EXPECT_EQ(back.error_peak, 0.0576);
  EXPECT_EQ(back.error_rms, 0.0433);
  EXPECT_EQ(back.worst_quantity, row.worst_quantity);
  ASSERT_EQ(back.errors.size(), 3u);
  EXPECT_EQ(back.errors[1].quantity, "rod deflection z [m]");
  EXPECT_EQ(back.errors[1].peak, 0.0576);
  EXPECT_TRUE(std::isnan(back.errors[2].rms));
  EXPECT_TRUE(back.resumed);
  EXPECT_EQ(back.rank, 3);
}

}  // namespace
}  // namespace limber
