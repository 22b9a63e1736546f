#include "run/probe_step_record.h"

#include "core/error.h"

namespace limber::run {

ProbeStepRecord::ProbeStepRecord(const multibody::Model& model) : model_(model) {}

void ProbeStepRecord::observe(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                              const Eigen::VectorXd& v_dot) {
  LIMBER_DEMAND(time_.empty() || t >= time_.back());
  time_.push_back(t);
  for (const multibody::AccelerationProbe& probe : model_.acceleration_probes) {
    rows_.push_back(multibody::probe_motion(model_, probe, q, v, v_dot, frame_).a_W);
  }
}

Eigen::VectorXd ProbeStepRecord::time() const {
  return Eigen::Map<const Eigen::VectorXd>(time_.data(), size());
}

std::vector<results::ProbeHistory> ProbeStepRecord::histories() const {
  const std::size_t probes = model_.acceleration_probes.size();
  std::vector<results::ProbeHistory> out;
  for (std::size_t p = 0; p < probes; ++p) {
    results::ProbeHistory history{model_.acceleration_probes[p].name, {}};
    history.acceleration.resize(size(), 3);
    for (std::size_t k = 0; k < time_.size(); ++k) {
      history.acceleration.row(static_cast<Eigen::Index>(k)) = rows_[k * probes + p].transpose();
    }
    out.push_back(std::move(history));
  }
  return out;
}

}  // namespace limber::run
