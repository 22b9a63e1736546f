// The run record: what `limber run --json` prints, and what `limber sweep` keeps of each point
// as DIR/runs/<point>/run.json and reads back (docs/sweep.md). One writer (from a RunSummary)
// and one reader (into RunRecord), so the format has an owner. The document:
//   {"status", "message", "integrator", "t_end", "t_reached", "samples", "steps",
//    "rejected_steps", "newton_failures", "newton_iterations", "jacobian_evaluations",
//    "residual_evaluations", "wall_s", "max_constraint_violation", "max_velocity_violation",
//    "redundant": [...], "redundant_details": [...], "events": [...], "statics", "releases",
//    "clearance", "accuracy": {"energy_relative", "energy_residual", "energy_scale",
//    "local_error", "drift_relative", "warnings"}, "event_peaks", "results"}
// (the nested members' fields in `limber run --help`).
#pragma once

#include <limits>
#include <string>

#include "multibody/model.h"
#include "run/run_driver.h"

namespace limber::run {

// The record's scalar members, as read back; NaN (numbers) or "" (text) when absent or null.
struct RunRecord {
  static constexpr double kAbsent = std::numeric_limits<double>::quiet_NaN();
  std::string status;   // ok, ok_inaccurate, failed (results/results_layout.h, layout::status)
  std::string message;
  std::string integrator;
  double t_end = kAbsent, t_reached = kAbsent;
  long samples = 0, steps = 0, rejected_steps = 0, newton_failures = 0, newton_iterations = 0,
       jacobian_evaluations = 0, residual_evaluations = 0;
  double wall_s = kAbsent;
  double max_constraint_violation = kAbsent, max_velocity_violation = kAbsent;
  // "accuracy" (accuracy_check.h)
  double energy_relative = kAbsent, local_error = kAbsent, drift_relative = kAbsent;
  std::string results;  // the results.h5 written
};

// The record of a run of `model` that wrote `results_path`.
std::string run_record_json(const multibody::Model& model, const RunSummary& summary,
                            const std::string& results_path);

// Reads a record's members at their own level (a "status" inside a nested object or a string
// is never taken for the record's). Throws InputError when `text` is not a JSON object.
RunRecord read_run_record(const std::string& text);

}  // namespace limber::run
