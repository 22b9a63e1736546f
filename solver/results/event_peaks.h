// A run's event peaks as results.h5 holds them (/event_peaks, docs/results-format.md "Event
// peaks"): per joint, the largest reaction in a window after each event that loads the
// structure (the start, each latch engagement), tracked at every integrator step
// (run/event_peaks.h computes them; ResultsWriter::set_event_peaks writes them;
// read_event_peaks reads them back).
//
// Reactions are on body j about the origin of marker j, as the samples' force_joint and
// torque_joint (results_layout.h, joint::): magnitudes [N, N m] and the largest |component| in
// the joint frame (marker j's axes), each with its time [s] (NaN while the window saw nothing).
#pragma once

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace limber::results {

class H5Reader;

// The largest reaction of one joint in one window.
struct JointPeak {
  double force = 0.0;   // max |F| [N]
  double torque = 0.0;  // max |T| [N m]
  double force_time = std::numeric_limits<double>::quiet_NaN();   // [s]
  double torque_time = std::numeric_limits<double>::quiet_NaN();  // [s]
  // max |F_x|, |F_y|, |F_z| and |T_x|, |T_y|, |T_z| in the joint frame, with their times.
  Eigen::Vector3d force_component = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque_component = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_component_time = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  Eigen::Vector3d torque_component_time = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
};

// Where a window starts and why.
struct WindowStart {
  double t = 0.0;     // [s]
  std::string label;  // "start", "latch latch_R3", "latch latch_R3 #2"
};

struct PeakWindow {
  WindowStart start;
  double end = 0.0;   // start.t + the window length [s]
  long states = 0;    // integrator states seen inside it (0: it opened after the run ended)
  std::vector<JointPeak> joints;  // per joint, in the order of EventPeaks::joints
};

struct EventPeaks {
  double window = 0.0;              // window length [s]
  std::vector<std::string> joints;  // joint names, model order
  std::vector<PeakWindow> windows;  // in the order they were opened
};

// /event_peaks of `file`; an empty EventPeaks (no joints, no windows) when the file has none
// (a run that failed before integrating, or an older file). Throws InputError naming the file
// when it cannot be read or the group is malformed.
EventPeaks read_event_peaks(const std::filesystem::path& file);
// The same from a file already open (a file on disk or an image in memory).
EventPeaks read_event_peaks(const H5Reader& reader);

}  // namespace limber::results
