// The acceleration probes' record at every integrator step (IntegratorOptions::on_step: the
// start, each accepted step and each located event), from which their shock response spectra
// are computed (docs/shock-response-spectrum.md): the steps are the finest states a run has,
// so the spectra's band is set by the step, not by the output interval. The output samples
// still carry the probes' accelerations to results.h5 (sample_record.h).
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

#include "multibody/acceleration_probe.h"
#include "multibody/model.h"
#include "results/shock_spectra.h"

namespace limber::run {

class ProbeStepRecord {
 public:
  // `model` must outlive the record.
  explicit ProbeStepRecord(const multibody::Model& model);

  // The probes' absolute accelerations at (t, q, v, v̇), appended in call order. A state at the
  // same time as the last one is kept (a release restarts the integrator there, and the
  // acceleration may jump); one earlier than the last is a broken invariant (DEMAND).
  void observe(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& v_dot);

  Eigen::Index size() const { return static_cast<Eigen::Index>(time_.size()); }
  // Whether the record spans a positive time (what its spectra need).
  bool spans_time() const { return time_.size() >= 2 && time_.back() > time_.front(); }
  // The record's times [s] and each probe's history (model.acceleration_probes order).
  Eigen::VectorXd time() const;
  std::vector<results::ProbeHistory> histories() const;

 private:
  const multibody::Model& model_;
  multibody::FrameKinematics frame_;  // scratch of probe_motion
  std::vector<double> time_;
  std::vector<Eigen::Vector3d> rows_;  // time_.size() × probes, probe-fastest
};

}  // namespace limber::run
