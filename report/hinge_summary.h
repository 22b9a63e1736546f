// What a deployment report says about its hinges, computed from run data (no drawing): the
// peaks at each latch-up (the loads deployment hardware is sized for) and the energy balance's
// residual.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "run_data.h"

namespace limber::report {

// Seconds after a latch event searched for its peaks.
inline constexpr double kLatchUpWindow = 0.5;

// The peaks within kLatchUpWindow after one latch locked.
struct LatchUpPeaks {
  int event = 0;                    // index into RunData::events
  double latched_force = 0.0;       // max |reaction| of the latched joint, ground axes [N]
  double latched_force_time = 0.0;  // [s]
  Eigen::Vector3d latched_force_joint = Eigen::Vector3d::Zero();  // max |F_x|, |F_y|, |F_z|, joint frame [N]
  double latch_torque = 0.0;        // max |latch torque| [N m]
  std::string largest_joint;        // the joint with the largest |reaction| in the window
  double largest_force = 0.0;       // [N]
  double largest_force_time = 0.0;  // [s]
};

// One entry per event that locked a latch, in time order. Joints without ground-axes
// reactions in the file are skipped.
std::vector<LatchUpPeaks> latch_up_peaks(const RunData& run);

// The terms of the energy balance, each minus its value at the first sample [J], ns each:
// stored (kinetic + gravity + spring + strain), work put in (driver_work + force_work),
// dissipated, and residual = stored_change + dissipated − work (zero when the balance closes).
struct EnergyBalance {
  Eigen::VectorXd stored_change, work, dissipated, residual;
};
std::optional<EnergyBalance> energy_balance(const RunData& run);

// kinetic + gravity + spring + strain + dissipated − driver_work − force_work minus its value
// at the first sample [J]: zero when the balance closes. Empty unless every energy is present.
std::optional<Series> energy_residual(const RunData& run);

}  // namespace limber::report
