#include "run/accuracy_check.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "run/sample_record.h"

namespace limber::run {

namespace {

// kinetic + gravity + spring + strain + dissipated − driver work − force work (kEnergyNames).
double energy_balance(const std::vector<double>& e) { return e[0] + e[1] + e[2] + e[3] + e[4] - e[5] - e[6]; }

// Diagonal of the bounding box of the joint points and the body origins.
double mechanism_spread(const results::Sample& sample) {
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d high = -low;
  const auto include = [&](const Eigen::Vector3d& p) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  };
  for (const results::JointSample& joint : sample.joints) include(joint.position);
  for (const results::BodySample& body : sample.bodies) include(body.position);
  return sample.joints.empty() && sample.bodies.empty() ? 0.0 : (high - low).norm();
}

// The option that would make the run more accurate.
std::string finer_setting(const integrate::IntegratorOptions& options) {
  if (options.method == integrate::Method::kGeneralizedAlpha) {
    return fmt::format("a smaller step, e.g. --step {:g}", options.step / 4.0);
  }
  return fmt::format("a tighter tolerance, e.g. --rtol {:g} --atol {:g}", options.rtol / 10.0, options.atol / 10.0);
}

}  // namespace

void AccuracyMonitor::add(const results::Sample& sample) {
  const std::vector<double>& e = sample.energies;
  if (!started_) {
    started_ = true;
    balance_start_ = energy_balance(e);
    gravity_start_ = e[1];
    term_peaks_.assign(e.size(), 0.0);
    // The mechanism's size, at least 1 mm (a drift check needs a length).
    size_ = std::max(1e-3, mechanism_spread(sample));
  }
  residual_ = std::max(residual_, std::abs(energy_balance(e) - balance_start_));
  for (std::size_t k = 0; k < e.size(); ++k) {
    const double value = k == 1 ? e[k] - gravity_start_ : e[k];
    term_peaks_[k] = std::max(term_peaks_[k], std::abs(value));
  }
  position_violation_ = std::max(position_violation_, sample.position_violation);
}

AccuracyEstimate AccuracyMonitor::estimate(const integrate::Statistics& statistics,
                                           const integrate::IntegratorOptions& options,
                                           const AccuracyThresholds& thresholds) const {
  AccuracyEstimate result;
  result.energy_residual = residual_;
  for (double peak : term_peaks_) result.energy_scale += peak;
  // A mechanism at rest has no scale to measure against.
  result.energy_relative = result.energy_scale > 0.0 ? residual_ / result.energy_scale : 0.0;
  result.local_error = statistics.max_local_error;
  result.position_violation = position_violation_;
  result.size = size_;
  result.drift_relative = size_ > 0.0 ? position_violation_ / size_ : 0.0;

  const std::string fix = finer_setting(options);
  if (result.energy_relative > thresholds.energy) {
    result.warnings.push_back(fmt::format(
        "the energy balance is off by {:.3g} J, {:.3g} % of the run's energy scale ({:.3g} J; "
        "threshold {:g} %): the answer is not accurate; use {}",
        residual_, 100.0 * result.energy_relative, result.energy_scale, 100.0 * thresholds.energy, fix));
  }
  if (result.local_error > thresholds.local_error) {
    result.warnings.push_back(fmt::format(
        "generalized-alpha's local error estimate reaches {:.3g} % of a step's increment "
        "(threshold {:g} %): the step does not resolve the motion; use {}",
        100.0 * result.local_error, 100.0 * thresholds.local_error, fix));
  }
  if (result.drift_relative > thresholds.drift) {
    result.warnings.push_back(fmt::format(
        "the joints come apart by {:.3g} (m or rad), {:.3g} % of the mechanism's size {:.3g} m "
        "(threshold {:g} %); use {}",
        position_violation_, 100.0 * result.drift_relative, size_, 100.0 * thresholds.drift, fix));
  }
  return result;
}

}  // namespace limber::run
