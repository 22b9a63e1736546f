// The typed reader of results.h5, part 2: the per-sample series beside the poses that
// results_reader.h reads (docs/results-format.md): joint reactions in the joint frame and
// their indeterminate flags, deflection and acceleration probes, shock spectra, driver efforts,
// energies, hinge latches and stops with their events, clearance, constraint violations, the
// step counter, momentum, redundant equations, the axis names and the solver's settings. Plain
// Eigen and std values, no HDF5 type. Read by `limber report` and `limber sweep`.
#pragma once

#include "results/probe_reader.h"
#include "results/results_reader.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace limber::results {

// Reactions on body_j of one joint, ns x 3 each.
struct JointReactions {
  std::string name;
  RowMatrix3d force_joint;   // joint frame [N]
  RowMatrix3d torque_joint;  // joint frame [N m]
  RowMatrix3d force_ground;  // ground axes [N] (empty when the file has none)
  RowMatrix3d torque_ground; // ground axes, about the joint point [N m] (empty when none)
  Eigen::VectorXd indeterminate;  // ns, 1 where redundancy made the reaction minimum-norm (empty: none)

  bool is_indeterminate() const { return indeterminate.size() > 0 && indeterminate.maxCoeff() > 0.0; }
};

// A flexible body's deflection probe (case key `deflection`): a node's elastic displacement
// relative to a chord, body axes [m], ns x 3.
struct DeflectionProbe {
  std::string body;
  RowMatrix3d values;
};

// A named per-sample series (driver effort, energy, violation).
struct NamedSeries {
  std::string name;
  Eigen::VectorXd values;  // ns
};

// A hinge latch or stop (results.h5 /hinge_limits): its joint's angle, its torque, its mode.
struct HingeLimitTrack {
  std::string name;
  std::string kind;             // "latch" or "stop"
  std::string joint;
  double limit_angle = 0.0;     // [rad]
  Eigen::VectorXd angle;        // ns, joint angle [rad]
  Eigen::VectorXd torque;       // ns, on body j about the joint axis [N m]
};

// A located mode switch (results.h5 /events).
struct HingeEventRow {
  double time = 0.0;     // [s]
  int limit = 0;         // index into RunRecords::hinge_limits
  bool engaged = false;  // mode after the switch
  double angle = 0.0;    // [rad]
  double rate = 0.0;     // [rad/s]
};

struct RunRecords {
  std::vector<JointReactions> joints;     // in the order of Results::joints, those with joint-frame forces
  std::vector<NamedSeries> drivers;            // efforts [N or N m]
  std::vector<std::string> driver_units;  // per driver: "N", "N m", or "" when the file does not say
  // Names of the ground axes x, y, z (root attribute axis_names, case key `axis_names`).
  std::array<std::string, 3> axis_names{"X", "Y", "Z"};
  bool axis_names_from_case = false;
  std::vector<DeflectionProbe> deflections;
  std::vector<AccelerationProbeTrack> acceleration_probes;  // absolute, ground axes [m/s²]
  std::optional<ShockSpectraData> shock_spectra;            // the probes' SRS per window
  std::vector<NamedSeries> energies;           // [J]
  std::vector<HingeLimitTrack> hinge_limits;  // in the model's order
  std::vector<HingeEventRow> events;
  std::optional<NamedSeries> clearance;        // smallest clearance between bodies [m]
  std::vector<std::string> clearance_pairs;  // "body_a, body_b"
  std::vector<int> clearance_pair;        // ns, index into clearance_pairs (−1: none)
  std::optional<NamedSeries> position_violation;
  std::optional<NamedSeries> velocity_violation;
  std::optional<std::int64_t> steps;      // cumulative accepted steps at the last sample
  // Attributes of /solver and unknown root attributes (integrator, tolerances, wall time...),
  // as text, in the file's order.
  std::vector<std::pair<std::string, std::string>> solver_attributes;
  // Redundant constraint equations ("R2.z") and the equations each combines ("R1.z, R3.z").
  std::vector<std::pair<std::string, std::string>> redundant_equations;
  // The system's linear momentum [kg m/s] and angular momentum about the ground origin
  // [kg m²/s], ground axes, ns x 6 (/momentum; 0 rows in files written before it).
  Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor> momentum;
};

// Reads the series of `results.file` (already read by read_results). Every optional series
// absent or of another shape is left empty. Cuts `results` and the series read to the samples
// complete in all of them (a killed run, or one still being written: what was flushed). Throws
// InputError (naming the file) when the file cannot be opened or a probe or spectra group is
// malformed.
RunRecords read_run_records(Results& results);

}  // namespace limber::results
