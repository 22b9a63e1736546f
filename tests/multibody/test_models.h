// Small models shared by the multibody tests: helpers to declare bodies, and the seed
// paper's slider-crank (docs/seed-paper.md, example 1) with a rigid rod.
#pragma once

#include <numbers>
#include <string>

#include <Eigen/Dense>

#include "multibody/model_builder.h"
#include "multibody/rotation.h"

namespace limber::multibody::testing {

// Rigid body with diagonal central inertia, origin at `position`, orientation R.
inline RigidBodySpec body_spec(const std::string& name, double mass, const Eigen::Vector3d& inertia,
                               const Eigen::Vector3d& position,
                               const Eigen::Matrix3d& R = Eigen::Matrix3d::Identity(),
                               const Eigen::Vector3d& com_B = Eigen::Vector3d::Zero()) {
  RigidBodySpec spec;
  spec.name = name;
  spec.mass = mass;
  spec.inertia_com_B = inertia.asDiagonal();
  spec.com_B = com_B;
  spec.initial_pose.position = position;
  spec.initial_pose.orientation = quaternion_from_matrix(R);
  return spec;
}

// Slender uniform rod along its body x axis: central inertia m L²/12 about y and z.
inline Eigen::Vector3d rod_inertia(double mass, double length) {
  const double j = mass * length * length / 12.0;
  return Eigen::Vector3d(1e-6 * j, j, j);
}

// The seed slider-crank, planar in ground x-z, joint axes along ground y:
// R1 ground-crank at the origin (driven), R2 crank-rod, R3 rod-slider, T slider-ground
// along x. Crank length a = 0.15 m (0.5 kg), rod b = 1 m steel 0.01 x 0.02 m (1.564 kg),
// slider 1 kg. Crank angle θ about +y: crank tip at a (cos θ, 0, −sin θ), slider at
// x = a cos θ + sqrt(b² − a² sin² θ). Bodies start at the exact positions for θ0.
// non_redundant: R2 becomes a universal joint (cross pins: y on the crank, the in-plane
// normal of the rod on the rod) and R3 a spherical joint: 17 + 1 independent equations.
struct SliderCrankParameters {
  double a = 0.15, b = 1.0;
  double crank_mass = 0.5, rod_mass = 7820.0 * 0.01 * 0.02 * 1.0, slider_mass = 1.0;
  double theta0 = 0.0;
  double speed = 2.0 * std::numbers::pi * 20.0;  // 20 rev/s
  double gravity = 9.81;
  bool non_redundant = false;
};

inline Model slider_crank(const SliderCrankParameters& p) {
  ModelBuilder builder;
  builder.set_gravity(Eigen::Vector3d(0, 0, -p.gravity));
  const Eigen::Vector3d y = Eigen::Vector3d::UnitY();
  const double c = std::cos(p.theta0), s = std::sin(p.theta0);
  const Eigen::Vector3d tip(p.a * c, 0, -p.a * s);
  const Eigen::Vector3d slider(p.a * c + std::sqrt(p.b * p.b - p.a * p.a * s * s), 0, 0);
  const Eigen::Vector3d e_rod = (slider - tip).normalized();
  // Crank: body frame at R1 rotated by θ0 about y, centre of mass at mid-length.
  const Eigen::Matrix3d R_crank = axis_angle_matrix(y, p.theta0);
  builder.add_rigid_body(body_spec("crank", p.crank_mass, rod_inertia(p.crank_mass, p.a),
                                   Eigen::Vector3d::Zero(), R_crank, Eigen::Vector3d(p.a / 2, 0, 0)));
  // Rod: body frame at its centre, x along the rod, y along ground y.
  Eigen::Matrix3d R_rod;
  R_rod << e_rod, y, e_rod.cross(y);
  builder.add_rigid_body(body_spec("rod", p.rod_mass, rod_inertia(p.rod_mass, p.b), 0.5 * (tip + slider), R_rod));
  builder.add_rigid_body(body_spec("slider", p.slider_mass, Eigen::Vector3d(1e-3, 1e-3, 1e-3), slider));
  // Joint markers: revolute axes (z) along ground y, x along ground x.
  const Eigen::Matrix3d R_y = frame_from_axes(y, Eigen::Vector3d::UnitX());
  builder.add_marker_at("R1.ground", "ground", Eigen::Vector3d::Zero(), R_y);
  builder.add_marker_at("R1.crank", "crank", Eigen::Vector3d::Zero(), R_y);
  builder.add_joint("R1", JointType::kRevolute, "R1.ground", "R1.crank");
  builder.add_driver("D1", "R1", DriverCoordinate::kRotation,
                     TimeFunction::constant_speed(p.theta0, p.speed));
  if (p.non_redundant) {
    builder.add_marker_at("R2.crank", "crank", tip, R_y);
    builder.add_marker_at("R2.rod", "rod", tip, frame_from_axes(e_rod.cross(y), y));
    builder.add_joint("R2", JointType::kUniversal, "R2.crank", "R2.rod");
    builder.add_marker_at("R3.rod", "rod", slider, R_y);
    builder.add_marker_at("R3.slider", "slider", slider, R_y);
    builder.add_joint("R3", JointType::kSpherical, "R3.rod", "R3.slider");
  } else {
    builder.add_marker_at("R2.crank", "crank", tip, R_y);
    builder.add_marker_at("R2.rod", "rod", tip, R_y);
    builder.add_joint("R2", JointType::kRevolute, "R2.crank", "R2.rod");
    builder.add_marker_at("R3.rod", "rod", slider, R_y);
    builder.add_marker_at("R3.slider", "slider", slider, R_y);
    builder.add_joint("R3", JointType::kRevolute, "R3.rod", "R3.slider");
  }
  // Translational joint along ground x (marker z axis).
  const Eigen::Matrix3d R_x = frame_from_axes(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY());
  builder.add_marker_at("T.ground", "ground", Eigen::Vector3d::Zero(), R_x);
  builder.add_marker_at("T.slider", "slider", slider, R_x);
  builder.add_joint("T", JointType::kTranslational, "T.ground", "T.slider");
  return builder.build();
}

}  // namespace limber::multibody::testing
