// The summary at the top of a report (docs/report.md "Summary"): what a reviewer reads in one
// minute, computed from run data (no drawing). Per run: the status with each accuracy measure
// against its threshold, the model (bodies with their masses, flexible bodies with their mode
// counts and shared components, joints), the
// events (latches, stops, joints released), the peak reaction of each joint with its time
// (largest first), the peak deflection, stress and probe acceleration, the energy balance's
// closure, a free-floating system's momentum drift; and links to the plots that reproduce the seed paper's figures.
#pragma once

#include "momentum_drift.h"
#include "report_html.h"
#include "run_data.h"
#include "stress_summary.h"

#include <optional>
#include <string>
#include <vector>

namespace limber::report {

// The thresholds of `limber run`'s accuracy check (solver/run/accuracy_check.h,
// AccuracyThresholds; docs/integrators.md "Accuracy check"), relative measures. report/ reads
// results files only and does not link the solver, so they are repeated here; a run above one
// of them has status "ok_inaccurate".
inline constexpr double kEnergyThreshold = 1e-2;      // energy balance residual / energy scale
inline constexpr double kLocalErrorThreshold = 1e-2;  // generalized-α local error / largest increment
inline constexpr double kDriftThreshold = 1e-3;       // position violation / mechanism size

// One accuracy measure as results.h5 stores it (root attributes accuracy_*), with its threshold.
struct AccuracyMeasure {
  std::string name;        // "energy balance", "local error", "constraint drift"
  double value = 0.0;      // relative (see the thresholds above)
  double threshold = 0.0;
  bool passed() const { return value <= threshold; }
};

// A joint's largest reaction over the run, on body j, read at the output samples.
struct JointPeakRow {
  std::string joint;
  std::string type;         // "revolute", "spherical", ...
  double force = 0.0;       // max |F| [N]
  double force_time = 0.0;  // [s]
  double torque = 0.0;      // max |T| about the joint point [N m]; 0 when the file has none
  double torque_time = 0.0; // [s]
};

// Joints whose reaction is exactly 0 from some sample to the end while it was not before:
// released (hold-downs with a case `release` time; results.h5 does not store the time itself).
struct ReleaseRow {
  double time = 0.0;  // first sample of the zero reaction [s]
  std::vector<std::string> joints;
};

struct RunDigest {
  std::string status;   // ok | ok_inaccurate | failed | running | interrupted
  std::string message;
  std::vector<AccuracyMeasure> accuracy;  // those the file holds
  std::string accuracy_warnings;          // root attribute accuracy_warnings, "" when none
  int rigid_bodies = 0;
  std::vector<std::pair<std::string, int>> flexible_bodies;  // name, mode count
  int joints = 0;
  std::optional<double> total_mass;       // [kg], when results.h5 holds every body's mass
  std::optional<MomentumDrift> momentum;  // a free-floating system's (momentum_drift.h)
  std::vector<ReleaseRow> releases;       // in time order
  std::vector<JointPeakRow> peaks;        // largest |F| first
  // The largest relative deflection over the flexible bodies (max_relative_deflection).
  std::optional<double> deflection;       // [m]
  double deflection_time = 0.0;           // [s]
  std::string deflection_body;
  std::optional<StressPeak> stress;       // the largest over the bodies
  // The largest |a| of any acceleration probe (absolute, ground axes) [g = 9.80665 m/s²].
  std::optional<double> acceleration_g;
  double acceleration_time = 0.0;         // [s]
  std::string acceleration_probe;
  // The energy balance's worst residual [J] and the peak kinetic energy [J] (0: none).
  std::optional<double> energy_residual;
  double peak_kinetic = 0.0;
};

// What the summary says about `run`.
RunDigest digest_run(const RunData& run);

// A plot reproducing one of the seed paper's figures: "seed Fig. 9" and the figure's HTML id.
struct SeedFigureLink {
  std::string figure;  // "Fig. 9", "Figs. 4–5"
  std::string what;    // "R1 reaction force, normal modes"
  std::string target;  // id of the <figure> ("fig-<png stem>")
};

// The seed paper's figures the report holds, in figure order (docs/seed-paper.md): for a run of
// cases/slider_crank*.yaml, Figs. 4–5 (R2 and R3 in ground axes) and Fig. 6 (the mode sets'
// R3 force, from `limber select`, or the comparison of R3's Z over the runs); for
// cases/satellite_deployment*.yaml, Fig. 9 (R1's reaction, the first run) and Fig. 10 (the
// overlay over the runs of R1's dominant component, the one of largest peak: the paper's "X" is
// its own axis; present when two or more runs hold R1). Figures whose plot is absent are left
// out.
std::vector<SeedFigureLink> seed_figure_links(const ReportContent& content);

// The summary section (HTML, every text escaped), placed above the contents.
std::string summary_section(const ReportContent& content);

// How many reaction rows the summary shows before folding the rest into <details>.
inline constexpr std::size_t kSummaryPeakRows = 8;

}  // namespace limber::report
