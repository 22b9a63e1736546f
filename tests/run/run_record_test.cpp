// The run record (run/run_record.h): what its writer puts, its reader gets back, member by
// member at the record's own level, numbers to the bit (written in the shortest form that reads
// back exactly, core/json_text.h).
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "run/run_record.h"

namespace limber::run {
namespace {

RunSummary finished_summary() {
  RunSummary summary;
  summary.ok = true;
  summary.integrator = "galpha";
  summary.t_end = 0.1;
  summary.t_reached = 0.1;
  summary.samples = 101;
  summary.statistics.steps = 200;
  summary.statistics.rejected_steps = 3;
  summary.statistics.newton_iterations = 612;
  summary.statistics.jacobian_evaluations = 41;
  summary.statistics.residual_evaluations = 813;
  summary.wall_seconds = 0.123456789;
  summary.max_position_violation = 1.0 / 3.0 * 1e-12;
  summary.accuracy.energy_relative = 2.0 / 3.0 * 1e-5;
  summary.accuracy.local_error = 1e-7;
  summary.accuracy.drift_relative = 0.0;
  // Text that holds the record's keys: a reader that looked for keys anywhere would take them.
  summary.accuracy.warnings = {"\"status\": \"failed\", \"steps\": 7"};
  return summary;
}

TEST(RunRecord, WhatTheWriterPutsTheReaderGetsBack) {
  const multibody::Model model;
  const RunSummary summary = finished_summary();
  const RunRecord record = read_run_record(run_record_json(model, summary, "out/x/results.h5"));
  EXPECT_EQ(record.status, summary.accurate() ? "ok" : "ok_inaccurate");
  EXPECT_EQ(record.integrator, "galpha");
  EXPECT_EQ(record.t_end, 0.1);
  EXPECT_EQ(record.samples, 101);
  EXPECT_EQ(record.steps, 200);
  EXPECT_EQ(record.rejected_steps, 3);
  EXPECT_EQ(record.newton_iterations, 612);
  EXPECT_EQ(record.jacobian_evaluations, 41);
  EXPECT_EQ(record.residual_evaluations, 813);
  EXPECT_EQ(record.wall_s, summary.wall_seconds);
  EXPECT_EQ(record.max_constraint_violation, summary.max_position_violation);
  EXPECT_EQ(record.energy_relative, summary.accuracy.energy_relative);
  EXPECT_EQ(record.local_error, 1e-7);
  EXPECT_EQ(record.drift_relative, 0.0);
  EXPECT_EQ(record.results, "out/x/results.h5");
}

TEST(RunRecord, AFailedRunsMessageAndAbsentFigures) {
  const multibody::Model model;
  RunSummary summary;
  summary.message = "at t = 0.05 s: \"Newton\" did not converge\n";
  summary.accuracy.energy_relative = std::nan("");
  const RunRecord record = read_run_record(run_record_json(model, summary, ""));
  EXPECT_EQ(record.status, "failed");
  EXPECT_EQ(record.message, summary.message);
  // NaN is written as null and read back as absent.
  EXPECT_TRUE(std::isnan(record.energy_relative));
}

TEST(RunRecord, NotAnObjectIsAnInputError) {
  EXPECT_THROW(read_run_record(""), InputError);
  EXPECT_THROW(read_run_record("[1, 2]"), InputError);
  EXPECT_THROW(read_run_record("{\"status\" \"ok\"}"), InputError);
}

}  // namespace
}  // namespace limber::run
