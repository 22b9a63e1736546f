// `limber sweep`'s study as one call (docs/sweep.md): a case over a grid of settings, each
// point a `limber run` child process (process_pool.h), measured against a reference, into the
// work-precision table. The command parses options, prints and maps the outcome to an exit
// code; the MPI ranks come in through RankGroup, so this library needs no MPI.
//
// Files under the request's root: reference/<point>/ (a tight or nonlinear reference), runs/<point>/ (each
// point's results.h5, run.json, run.log, process.json: work_precision.h),
// sweep/{work_precision.csv,work_precision.json,errors.csv} and results.h5 (the reference's).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sweep/work_precision.h"

namespace limber::sweep {

// What a sweep is asked for (`limber sweep`'s options).
struct SweepRequest {
  std::string case_file;
  std::filesystem::path root;            // DIR: created; locked by rank 0 while the sweep runs
  std::vector<std::string> over;         // the axes (sweep_grid.h's parse_over)
  std::string reference = "tight";       // "tight", "nonlinear" or a finished results.h5
  std::optional<double> target;          // error target (fraction)
  bool rms = true;                       // the target's measure: rms, else peak
  std::vector<std::string> quantities;   // compared quantities; empty: default_quantities
  int jobs = 0;                          // runs at a time per rank (0: the number of cores)
  bool fresh = false;                    // rerun finished points and the reference
  std::optional<double> t_end, atol, max_wall;
  std::filesystem::path executable;      // the `limber` executable the points run
};

// The ranks of an MPI job sharing the grid (app/sweep_ranks.h); this default is one rank.
class RankGroup {
 public:
  virtual ~RankGroup() = default;
  virtual int rank() const { return 0; }
  virtual int size() const { return 1; }
  // Rank 0's value on every rank.
  virtual int broadcast(int value) const { return value; }
  // The element-wise maximum over the ranks, on every rank.
  virtual std::vector<int> max_over_ranks(const std::vector<int>& values) const { return values; }
  // Every rank's `text`, on rank 0 in rank order; empty on the other ranks.
  virtual std::vector<std::string> gather_to_lead(const std::string& text) const { return {text}; }
};

struct SweepHooks {
  std::function<void(const std::string&)> text;     // progress lines of rank 0 (the command's text stream)
  std::function<void(const std::string&)> log;      // per-point lines of every rank and warnings (stderr)
  std::function<bool()> should_stop;                // polled; true stops the points (SIGTERM to each)
};

struct SweepOutcome {
  bool lead = true;                       // rank 0: the fields below are set
  bool interrupted = false;               // a stop during the points (finished ones kept)
  bool interrupted_in_reference = false;  // a stop during the reference run: nothing else ran
  std::vector<SweepPoint> points;
  std::filesystem::path reference_file;
  std::string reference_label;            // "tight run <point> (<command line>)", "nonlinear run ...", "the given file ..."
  std::vector<std::string> quantities;
  std::vector<SweepRow> rows;             // in grid order
  std::optional<std::size_t> chosen;      // the cheapest row meeting the target
  std::string document;                   // DIR/sweep/work_precision.json's text (`--json`)
};

// Runs the sweep. Throws InputError for bad input (options, the case, the grid, a given
// reference that is not a finished results file) and NumericalError when the tight reference
// fails or its own accuracy check does; a failed or crashed point is a row.
SweepOutcome run_sweep(const SweepRequest& request, const RankGroup& ranks, const SweepHooks& hooks);

// The `limber run` command line a user types for `point`'s setting.
std::string run_command_line(const SweepRequest& request, const SweepPoint& point);

}  // namespace limber::sweep
