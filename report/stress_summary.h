// What a report says about recovered stresses (results.h5 "Stress", docs/stress-recovery.md),
// computed from run data (no drawing): each body's peak stress over the run, where on the mesh
// and when, and the hinge event it follows.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "run_data.h"

namespace limber::report {

struct StressPeak {
  std::string body;
  double value = 0.0;     // largest equivalent stress over mesh and samples [Pa]
  double time = 0.0;      // [s]
  int element = 0;        // 0-based: lines, then quads
  std::string element_name;  // "quad 36", "beam 50" (1-based, the case's numbering)
  Eigen::Vector3d centre_B = Eigen::Vector3d::Zero();  // element centre, body frame [m]
  std::string after;      // e.g. "0.048 s after latch_R3 locked", or ""
};

// One entry per body with stress output and at least one sample, in body order.
std::vector<StressPeak> stress_peaks(const RunData& run);

}  // namespace limber::report
