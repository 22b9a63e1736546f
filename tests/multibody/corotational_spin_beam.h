// A geometrically nonlinear, unreduced second method for the spin-up beam of Kane, Ryan &
// Banerjee (J. Guidance Control Dyn. 10(2), 1987): the cantilever as a planar co-rotational
// beam (corotational_beam.h) clamped to a hub at the origin, node 0's rotation the prescribed
// hub angle θ(t). No rotating frame and no centrifugal term written by hand: the stiffening
// comes out of the kinematics.
#pragma once

#include <cmath>
#include <functional>
#include <vector>

#include "corotational_beam.h"

namespace limber::test {

// The tip's deflection normal to the hub's x axis (the rotating frame's y) [m], every `sample`
// s from t = 0 to t_end, the beam starting straight and at rest, the hub turned by hub_angle(t).
// `beam.x_start` is 0 (the hub at the origin).
inline std::vector<double> corotational_tip_deflection(const CorotationalBeam& beam,
                                                       const std::function<double(double)>& hub_angle,
                                                       double t_end, double sample) {
  CorotationalMotion motion;
  motion.prescribed = {0, 1, 2};  // the clamp: node 0 at the hub, turned with it
  motion.prescribe = [&](double t, Eigen::VectorXd& u) {
    u(0) = 0.0;
    u(1) = 0.0;
    u(2) = hub_angle(t);
  };
  std::vector<double> out;
  const int tip = 3 * beam.elements;
  integrate_corotational_beam(beam, motion, t_end, sample, [&](double t, const Eigen::VectorXd& u) {
    const double theta = hub_angle(t);
    out.push_back(-std::sin(theta) * (beam.length + u(tip)) + std::cos(theta) * u(tip + 1));
  });
  return out;
}

}  // namespace limber::test
