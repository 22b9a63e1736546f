// The small case of the hold-down-released-at-an-event tests (run: event_release_run_test.cpp,
// select: event_release_select_test.cpp): an arm swung by a preloaded spring locks in a latch,
// and an independent bar held at its tip lets go as `release` says.
#pragma once

#include <string>

namespace limber::test {

// Arm (hinge RA about ground z at y = 2) with spring and latch `lock`; bar (hinge R about ground
// y at the origin) held at its tip by HD with `release`; gravity along −z; run settings `run`.
inline std::string arm_and_bar_case(const std::string& release, const std::string& run) {
  return "title: a hold-down released at a latch-up\n"
         "gravity: [0, 0, -9.81]\n"
         "bodies:\n"
         "  arm: {mass: 2.0, inertia: [1.0e-6, 0.16666666666666666, 0.16666666666666666],\n"
         "        center_of_mass: [0.5, 0, 0], position: [0, 2, 0]}\n"
         "  bar: {mass: 2.0, inertia: [1.0e-6, 0.16666666666666666, 0.16666666666666666],\n"
         "        center_of_mass: [0.5, 0, 0], position: [0, 0, 0]}\n"
         "joints:\n"
         "  RA: {type: revolute, body_i: ground, body_j: arm, position: [0, 2, 0],\n"
         "       orientation: {z_axis: [0, 0, 1], x_axis: [1, 0, 0]}}\n"
         "  R: {type: revolute, body_i: ground, body_j: bar, position: [0, 0, 0],\n"
         "      orientation: {z_axis: [0, 1, 0], x_axis: [1, 0, 0]}}\n"
         "  HD: {type: spherical, body_i: ground, body_j: bar, position: [1, 0, 0], release: " + release + "}\n"
         "forces:\n"
         "  spring: {type: rsda, marker_i: RA.i, marker_j: RA.j, stiffness: 4.0, free_angle: 0.5}\n"
         "  lock: {type: latch, joint: RA, angle: 0.3, stiffness: 5.0e3, damping: 5.0}\n"
         "run: {" + run + "}\n";
}

}  // namespace limber::test
