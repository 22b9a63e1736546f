// Event peaks (issue 25, docs/results-format.md "Event peaks"): per joint, the largest reaction
// in a stated window after each event that loads the structure — the release of the run's
// start (t = 0) and each latch engagement — tracked at every state the integrator steps
// through (IntegratorOptions::on_step), not only at the output samples, whose interval can
// miss a latch-up peak by 15 % (the satellite's R1: 9.71 N at 4.272 s from 2 ms samples,
// 11.02 N at 4.191 s every 0.5 ms).
//
// Reactions are those of the samples (multibody/reactions.h, as run/sample_record.cpp records
// them): on body j about the origin of marker j; magnitudes |F| [N] and |T| [N m], and the
// largest |component| in the joint frame (marker j's axes), each with its time. They are
// computed only at states inside an open window, so a run pays for them only there.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "multibody/hinge_limit.h"
#include "multibody/model.h"
#include "multibody/redundancy.h"
#include "multibody/state.h"
#include "results/event_peaks.h"

namespace limber::run {

// Tracks EventPeaks along a run; one per run (holds a Workspace).
class EventPeakTracker {
 public:
  // `window` > 0 [s] (RunSettings::peak_window). References must outlive the tracker;
  // `engaged` are the modes the integrator switches (MultibodySystem::engaged).
  EventPeakTracker(const multibody::Model& model, const multibody::ConstraintPartition& partition,
                   const std::vector<unsigned char>& engaged, double window);

  // Opens the window [start.t, start.t + window] (run_driver.cpp opens t = 0, "start", before
  // the run). Windows may overlap; a state counts in each.
  void open(const results::WindowStart& start);
  // A located hinge event: a latch engaging opens a window at its time, "latch <name>" (its
  // n-th engagement: "latch <name> #n"); other events open none.
  void on_event(const multibody::HingeEvent& event);
  // One integrator state (t ascending over the calls) with its multipliers of the independent
  // rows: reactions computed when t lies inside an open window (from the multipliers:
  // multibody::reactions_from_multipliers), each such window's peaks raised.
  void observe(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& lambda);

  const results::EventPeaks& peaks() const { return peaks_; }

 private:
  const multibody::Model& model_;
  const multibody::ConstraintPartition& partition_;
  const std::vector<unsigned char>& engaged_;
  multibody::Workspace workspace_;
  results::EventPeaks peaks_;
  std::vector<int> engagements_;  // per model force: latch engagements seen
};

}  // namespace limber::run
