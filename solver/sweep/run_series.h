// The quantities `limber sweep` compares, read from a run's results.h5
// (docs/results-format.md): every joint reaction component on body_j in the joint frame
// (/joints/<j>/force_joint, torque_joint) and every deflection probe axis
// (/bodies/<b>/deflection, body axes). Names: "R3 force x [N]", "R3 torque y [N m]",
// "rod deflection z [m]".
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace limber::sweep {

struct RunSeries {
  std::string status;               // root attribute: ok, ok_inaccurate, failed, interrupted, running
  std::string message;              // root attribute `message`
  Eigen::VectorXd time;             // ns [s]
  std::vector<std::string> names;   // one per column of `values`
  Eigen::MatrixXd values;           // ns x quantities
  // Reaction components in a redundant equation's dependency group (/constraints/redundant and
  // redundant_with, "R2.z" -> "R2 force z [N]", "R2.rot_x" -> "R2 torque x [N m]"): minimum-norm
  // values the dynamics leaves undetermined.
  std::vector<std::string> indeterminate;
  // The highest natural frequency of the flexible bodies' modes (/bodies/<b>/modes/
  // frequencies_hz) [Hz]; 0 without flexible bodies.
  double f_max_hz = 0.0;
};

// Reads `file`. Throws InputError (naming the file) when it cannot be read as a results file.
RunSeries read_run_series(const std::filesystem::path& file);

// The root attribute `status` alone; "" when the file is missing or unreadable.
std::string read_run_status(const std::filesystem::path& file);

// True for a status a run ends with on its own (ok, ok_inaccurate, failed); "running" (a
// killed run) and "interrupted" are not final, so such a point runs again on resume.
bool final_status(const std::string& status);

// The quantities compared by default: those of `reference` that are determinate (not in
// `indeterminate`) and whose peak is at least 1 % of the largest peak of their kind (forces,
// torques, each body's deflection axes); a smaller one is noise on a relative scale (an
// out-of-plane component of a planar mechanism), and, for reactions, at least 1e-6 of the
// largest reaction component (below it: round-off, or motion round-off seeds).
std::vector<std::string> default_quantities(const RunSeries& reference);

// `requested` (from --quantities) resolved against `reference`: each must name a quantity of
// the file, with or without its unit. Throws InputError listing the names there are.
std::vector<std::string> named_quantities(const RunSeries& reference, const std::vector<std::string>& requested);

// Column of `name` in `series`, or -1.
int quantity_column(const RunSeries& series, const std::string& name);

}  // namespace limber::sweep
