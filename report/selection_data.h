// What `limber select` left in a run directory's `selection/` folder, read from its three CSV
// files (UTF-8, header row, comma separated; a field may be wrapped in double quotes, "" inside
// quotes being one quote): the ranking of the reaction components acting on flexible bodies,
// the comparison of the mode sets run, and the key quantities of every set versus time
// (docs/report.md, "Mode selection"). Columns are found by their header names, in any order;
// further columns are ignored.
#pragma once

#include <Eigen/Core>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace limber::report {

// One reaction component on a flexible body (ranking.csv), in the body's own axes.
struct RankingRow {
  std::string body;            // flexible body
  std::string joint;
  long long node = 0;          // FE node id
  std::string quantity;        // "force" or "torque"
  std::string axis;            // "x", "y" or "z"
  double peak = 0.0;           // [N or N m]
  double rms = 0.0;            // [N or N m]
  double relative = 0.0;       // fraction of the body's largest, 0..1
  bool kept = false;           // kept as a static-mode boundary condition
  bool indeterminate = false;  // minimum-norm reaction of a redundant joint
};

// One mode set run (comparison.csv).
struct ComparisonRow {
  std::string set;                    // e.g. "normal", "normal+R3.force.z", "reference"
  std::string description;
  long long modes = 0;                // modes of all flexible bodies together
  std::optional<double> reduction_s;  // modal reduction wall time [s]
  std::optional<double> run_s;        // run wall time [s]
  std::string status;                 // "ok" or the failure
  std::optional<double> error_peak;   // relative (fraction) against the reference
  std::optional<double> error_rms;    // relative (fraction)
  std::string worst_quantity;
  std::string directory;              // the set's run, relative to the run directory
  std::string role;                   // "chosen", "reference" or ""
};

// One column `<set>|<quantity>` of key_series.csv: the samples where it has a value.
struct KeySeries {
  std::string set;
  std::string quantity;  // with its unit, e.g. "R3 force z on rod [N]"
  Eigen::VectorXd time;  // [s]
  Eigen::VectorXd values;
};

struct SelectionData {
  std::filesystem::path directory;  // DIR/selection
  // Each part is empty when its file is missing or malformed (and a note says so).
  std::vector<RankingRow> ranking;   // in the file's order (relative descending)
  std::vector<ComparisonRow> comparison;
  std::vector<KeySeries> key_series; // in the file's column order
};

// Reads `run_directory`/selection. Returns nullopt when that folder does not exist. A missing
// or malformed file adds one line to `notes` (naming the file, and for a malformed one the line,
// with what was expected and what was found) and leaves its part empty; nothing throws.
std::optional<SelectionData> read_selection(const std::filesystem::path& run_directory,
                                            std::vector<std::string>& notes);

}  // namespace limber::report
