// The typed reader of results.h5, part 3: the file as written, for the Python module
// (limber.read_results, limber.run; docs/python.md). Every per-sample series comes with all the
// rows the file holds, not cut to the samples complete in all of them as results_reader.h and
// run_records.h cut them, so a killed run's datasets come back as they were flushed; the file
// may be on disk or an image in memory (ResultsWriter::file_image()). Plain Eigen and std
// values, no HDF5 type. Callers on several threads hold results::hdf5_lock() (hdf5_lock.h)
// around a read. Dimensions: ns samples, nm modes, nss stress history rows, ne recorded elements.
#pragma once

#include "results/event_peaks.h"
#include "results/probe_reader.h"
#include "results/run_records.h"

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace limber::results {

using RowMatrixXd = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using VectorXi64 = Eigen::Matrix<std::int64_t, Eigen::Dynamic, 1>;
// An int8 flag dataset (indeterminate, engaged), true where it is not 0.
using FlagVector = Eigen::Array<bool, Eigen::Dynamic, 1>;

// /bodies/<body>/stress (docs/stress-recovery.md): each dataset, or none when the file has none.
struct StressArrays {
  std::optional<Eigen::VectorXd> peak;            // ns [Pa]
  std::optional<VectorXi64> peak_element;         // ns (0-based: lines, then quads)
  std::optional<VectorXi64> elements;             // ne recorded elements
  std::optional<Eigen::VectorXd> time;            // nss [s]
  std::optional<RowMatrixXd> equivalent;          // nss x ne [Pa]
  std::optional<RowMatrixXd> beam_resultants;     // nss x 12 beams
  std::optional<RowMatrixXd> shell_resultants;    // nss x 8 shells
};

// /bodies/<body>: the optional parts are none when the file has none (a rigid body's modes).
struct BodyArrays {
  std::string name;
  std::string kind;                                // "rigid" or "flexible"
  RowMatrixXd position;                            // ns x 3 [m]
  RowMatrixXd orientation;                         // ns x 4, quaternion w x y z, ground <- body
  std::optional<RowMatrixXd> modal_coordinates;    // ns x nm [kg^0.5 m]
  std::optional<RowMatrixXd> modal_velocities;     // ns x nm [kg^0.5 m/s]
  std::optional<Eigen::VectorXd> frequencies_hz;   // nm [Hz]
  std::optional<RowMatrixXd> deflection;           // ns x 3, body axes [m]
  std::optional<StressArrays> stress;
};

// /joints/<joint>: the reaction on body_j, each ns x 3.
struct JointArrays {
  std::string name, type, body_i, body_j;
  RowMatrixXd position;                   // joint point in ground [m]
  RowMatrixXd force_ground, torque_ground;  // ground axes [N], [N m] about the joint point
  RowMatrixXd force_joint, torque_joint;    // joint frame [N], [N m]
  FlagVector indeterminate;               // ns, where redundancy made the reaction minimum-norm
};

// /hinge_limits/<limit>: a latch or stop and its series.
struct HingeLimitArrays {
  std::string name, kind, joint;  // kind "latch" or "stop"
  int index = 0;                  // place in the model's order (events name limits by it)
  double limit_angle = 0.0;       // [rad]
  Eigen::VectorXd angle;          // ns [rad]
  Eigen::VectorXd torque;         // ns [N m]
  FlagVector engaged;             // ns
};

// /events: one entry per located switch of a hinge limit.
struct EventArrays {
  Eigen::VectorXd time;            // [s]
  std::vector<std::string> limit;  // the limit's name (its index as text when no limit has it)
  FlagVector engaged;              // the mode after the switch
  Eigen::VectorXd angle;           // [rad]
  Eigen::VectorXd rate;            // [rad/s]
};

// The root's accuracy attributes (docs/integrators.md): none before a run finished.
struct AccuracyAttributes {
  std::optional<double> energy_relative, local_error, drift_relative;
  std::vector<std::string> warnings;  // the attribute's lines, empty ones left out
};

struct ResultsArrays {
  std::string status;                               // required: a results file has one
  std::string message, title, case_file, integrator;  // "" when absent
  AccuracyAttributes accuracy;
  Eigen::VectorXd time;                             // ns [s]
  VectorXi64 steps;                                 // ns, cumulative accepted integrator steps
  std::vector<BodyArrays> bodies;                   // in link-name order, as every group below
  std::vector<JointArrays> joints;
  std::vector<NamedSeries> drivers;                 // efforts [N or N m]
  std::vector<NamedSeries> energy;                  // [J]
  Eigen::VectorXd position_violation, velocity_violation;  // ns
  // Redundant constraint equations ("R2.z") and the equations each combines; empty when none.
  std::vector<std::string> redundant, redundant_with;
  std::vector<HingeLimitArrays> hinge_limits;
  std::optional<EventArrays> events;                // none in a file without /events
  std::vector<AccelerationProbeTrack> acceleration_probes;  // ns x 3 each [m/s²]
  EventPeaks event_peaks;                           // empty when the file has none
};

// Reads the results file `file`. Throws InputError (naming the file, expected/got) when it is
// missing, not HDF5, lacks a required dataset or attribute, or one is of another rank.
ResultsArrays read_results_arrays(const std::filesystem::path& file);
// The same for a results file in memory (ResultsWriter::file_image()), named "results.h5".
ResultsArrays read_results_arrays(const std::vector<unsigned char>& image);

}  // namespace limber::results
