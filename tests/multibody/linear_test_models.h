// Small mechanisms with closed-form linearizations, shared by the modes', the state-space and
// the reactions' tests (linearization_test.cpp, state_space_test.cpp, linear_reactions_test.cpp,
// tests/run/system_mode_files_test.cpp).
#pragma once

#include <string>

#include <gtest/gtest.h>

#include "test_models.h"

namespace limber::multibody::testing {

// A mass m on a translational joint along ground x (markers T.ground, T.mass), held by a
// spring k and damper c (markers S.ground at the origin, S.mass on the mass at x = 1) at their
// free length 1 m: m ẍ + c ẋ + k x = f_x.
inline Model spring_mass_on_slider(double m, double k, double c) {
  ModelBuilder builder;
  builder.add_rigid_body(body_spec("mass", m, Eigen::Vector3d(0.1, 0.1, 0.1), Eigen::Vector3d(1, 0, 0)));
  const Eigen::Matrix3d R_x = frame_from_axes(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY());
  builder.add_marker_at("T.ground", "ground", Eigen::Vector3d(1, 0, 0), R_x);
  builder.add_marker_at("T.mass", "mass", Eigen::Vector3d(1, 0, 0), R_x);
  builder.add_joint("T", JointType::kTranslational, "T.ground", "T.mass");
  builder.add_marker_at("S.ground", "ground", Eigen::Vector3d::Zero());
  builder.add_marker_at("S.mass", "mass", Eigen::Vector3d(1, 0, 0));
  builder.add_tsda({"spring", "S.ground", "S.mass", k, c, 1.0, {}});
  return builder.build();
}

// Two rigid bodies floating free (bus, J1 about z; panel, J2), joined by a revolute about z
// through both centres of mass (markers H.bus, H.panel) with a torsion spring k ("spring"):
// six rigid modes and one relative rotation at ω = √(k (1/J1 + 1/J2)).
inline Model floating_hinged_pair(double J1, double J2, double k) {
  ModelBuilder builder;
  builder.add_rigid_body(body_spec("bus", 50.0, Eigen::Vector3d(4.0, 5.0, J1), Eigen::Vector3d::Zero()));
  builder.add_rigid_body(body_spec("panel", 2.0, Eigen::Vector3d(0.7, 0.9, J2), Eigen::Vector3d(0, 0, 1.0)));
  builder.add_marker_at("H.bus", "bus", Eigen::Vector3d(0, 0, 0.5));
  builder.add_marker_at("H.panel", "panel", Eigen::Vector3d(0, 0, 0.5));
  builder.add_joint("H", JointType::kRevolute, "H.bus", "H.panel");
  builder.add_rsda({"spring", "H.bus", "H.panel", k, 0.0, 0.0, {}, false, {}});
  return builder.build();
}

// A body hinged to ground about y at its frame origin (markers P.ground, P.bob), its centre
// of mass at z = com_z (−l: hanging, +l: balanced upside down), under gravity g along −z.
// Add to the builder, then build().
inline ModelBuilder pendulum_builder(double m, double Jy, double g, double com_z) {
  ModelBuilder builder;
  builder.set_gravity(Eigen::Vector3d(0, 0, -g));
  builder.add_rigid_body(body_spec("bob", m, Eigen::Vector3d(0.1, Jy, 0.1), Eigen::Vector3d::Zero(),
                                   Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, com_z)));
  const Eigen::Matrix3d R_y = frame_from_axes(Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX());
  builder.add_marker_at("P.ground", "ground", Eigen::Vector3d::Zero(), R_y);
  builder.add_marker_at("P.bob", "bob", Eigen::Vector3d::Zero(), R_y);
  builder.add_joint("P", JointType::kRevolute, "P.ground", "P.bob");
  return builder;
}

// The index of the model's marker `name` (−1 and a test failure when there is none).
inline int marker_index(const Model& model, const std::string& name) {
  for (std::size_t m = 0; m < model.markers.size(); ++m) {
    if (model.markers[m].name == name) return static_cast<int>(m);
  }
  ADD_FAILURE() << "no marker " << name;
  return -1;
}

}  // namespace limber::multibody::testing
