#include "multibody/model_builder.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "core/names.h"
#include "multibody/rotation.h"

namespace limber::multibody {

namespace {

// Largest m |c|² / I1 of a rigid body (centre of mass c from the body origin, I1 the smallest
// principal moment about the centre): see add_rigid_body.
constexpr double kMaxComLever = 1e10;

// One scalar equation of a joint: primitive, axes and component name (docs/multibody.md).
struct EquationTemplate {
  EquationKind kind;
  int axis_i, axis_j;
  const char* component;
};

std::vector<EquationTemplate> joint_equations(JointType type) {
  // d = p_j − p_i in marker-i axes; rot_x: y_i·z_j, rot_y: x_i·z_j, rot_z: x_i·y_j.
  const EquationTemplate x{EquationKind::kDot2, 0, 0, "x"}, y{EquationKind::kDot2, 1, 0, "y"},
      z{EquationKind::kDot2, 2, 0, "z"};
  const EquationTemplate rx{EquationKind::kDot1, 1, 2, "rot_x"}, ry{EquationKind::kDot1, 0, 2, "rot_y"},
      rz{EquationKind::kDot1, 0, 1, "rot_z"};
  switch (type) {
    case JointType::kSpherical: return {x, y, z};
    case JointType::kRevolute: return {x, y, z, rx, ry};
    case JointType::kBracket: return {x, y, z, rx, ry, rz};
    case JointType::kUniversal: return {x, y, z, {EquationKind::kDot1, 2, 2, "rot"}};
    case JointType::kCylindrical: return {x, y, rx, ry};
    case JointType::kTranslational: return {x, y, rx, ry, rz};
  }
  return {};
}

bool is_rotation(const Eigen::Matrix3d& R) {
  return (R.transpose() * R - Eigen::Matrix3d::Identity()).norm() < 1e-9 && R.determinant() > 0;
}

// Marker pose in ground at the owning body's initial pose.
void initial_marker_pose(const Model& model, const Marker& m, Eigen::Vector3d& p_W,
                         Eigen::Matrix3d& R_W) {
  const Pose& X = model.bodies[m.body].initial_pose;
  const Eigen::Matrix3d A = rotation_matrix(X.orientation);
  p_W = X.position + A * m.p_BM;
  R_W = A * m.R_BM;
}

}  // namespace

ModelBuilder::ModelBuilder() {
  Body ground;
  ground.name = "ground";
  ground.kind = BodyKind::kGround;
  model_.bodies.push_back(ground);
}

void ModelBuilder::set_gravity(const Eigen::Vector3d& g_W) { model_.gravity_W = g_W; }

int ModelBuilder::add_rigid_body(const RigidBodySpec& spec, const SourceLocation& where) {
  // Name, mass and pose.
  check_new_body(spec.name, spec.initial_pose, where);
  if (!(spec.mass > 0.0) || !std::isfinite(spec.mass)) {
    throw InputError(fmt::format("body \"{}\" mass: expected > 0 kg, got {}", spec.name, spec.mass), where);
  }
  // Inertia: symmetric, positive definite, and physically realisable (triangle inequality).
  const Eigen::Matrix3d& J = spec.inertia_com_B;
  const double scale = J.norm();
  if (!((J - J.transpose()).norm() <= 1e-9 * scale)) {
    throw InputError(fmt::format("body \"{}\" inertia: expected a symmetric tensor, got asymmetry {:.3g}",
                                 spec.name, (J - J.transpose()).norm()), where);
  }
  const Eigen::Vector3d principal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(J).eigenvalues();
  if (!(principal(0) > 0.0) ||
      principal(0) + principal(1) < principal(2) * (1.0 - 1e-9)) {
    throw InputError(fmt::format("body \"{}\" inertia: expected positive principal moments with "
                                 "I1 + I2 ≥ I3, got ({:.6g}, {:.6g}, {:.6g}) kg m²",
                                 spec.name, principal(0), principal(1), principal(2)), where);
  }
  // Centre of mass: the mass matrix about the body origin holds J_o = J_c - m c~ c~ (body.cpp),
  // whose Schur complement J_c the factorisations recover only to eps m |c|² / I1; at
  // kMaxComLever that keeps six digits of I1 (a needle of radius 1e-4 m held at its end: 5e7).
  const double com_lever = spec.mass * spec.com_B.squaredNorm() / principal(0);
  if (!(com_lever <= kMaxComLever)) {
    throw InputError(fmt::format("body \"{}\" center_of_mass: expected m |c|² / I1 ≤ {:g} (the centre "
                                 "of mass near the body origin for its inertia), got {:.6g} "
                                 "(|c| = {:.6g} m, m = {:.6g} kg, I1 = {:.6g} kg m²)",
                                 spec.name, kMaxComLever, com_lever, spec.com_B.norm(), spec.mass,
                                 principal(0)), where);
  }
  Body body;
  body.name = spec.name;
  body.kind = BodyKind::kRigid;
  body.mass = spec.mass;
  body.com_B = spec.com_B;
  body.inertia_com_B = 0.5 * (J + J.transpose());
  body.initial_pose = spec.initial_pose;
  body.initial_pose.orientation.normalize();
  body.initial_velocity_W = spec.initial_velocity_W;
  body.initial_angular_velocity_B = spec.initial_angular_velocity_B;
  body.shapes = spec.shapes;
  body.nq = 7;
  body.nv = 6;
  return append_body(std::move(body));
}

void ModelBuilder::check_new_body(const std::string& name, const Pose& pose, const SourceLocation& where) const {
  check_name_text("body", name, where);
  if (model_.find_body(name) >= 0 || model_.find_nonlinear_body(name) >= 0) {
    throw InputError(fmt::format("body \"{}\": expected a unique name, got a duplicate", name), where);
  }
  if (!(pose.orientation.norm() > 0.0)) {
    throw InputError(fmt::format("body \"{}\" orientation: expected a non-zero quaternion, got zero", name),
                     where);
  }
}

int ModelBuilder::append_body(Body body) {
  // Number the body's blocks at the end of q and v.
  body.q_offset = model_.nq;
  body.v_offset = model_.nv;
  model_.nq += body.nq;
  model_.nv += body.nv;
  model_.bodies.push_back(std::move(body));
  return static_cast<int>(model_.bodies.size()) - 1;
}

int ModelBuilder::add_marker(const std::string& name, const std::string& body,
                             const Eigen::Vector3d& p_BM, const Eigen::Matrix3d& R_BM,
                             const SourceLocation& where) {
  const int b = check_new_marker(name, body, R_BM, where);
  if (model_.bodies[b].kind == BodyKind::kFlexible) {
    throw InputError(fmt::format("marker \"{}\": expected a node marker on flexible body \"{}\" "
                                 "(add_node_marker), got a point of its frame", name, body), where);
  }
  model_.markers.push_back(Marker{name, b, p_BM, R_BM});
  return static_cast<int>(model_.markers.size()) - 1;
}

int ModelBuilder::check_new_marker(const std::string& name, const std::string& body,
                                   const Eigen::Matrix3d& R_BM, const SourceLocation& where) const {
  check_name_text("marker", name, where);
  for (const Marker& m : model_.markers) {
    if (m.name == name) {
      throw InputError(fmt::format("marker \"{}\": expected a unique name, got a duplicate", name), where);
    }
  }
  const int b = model_.find_body(body);
  if (b < 0) throw InputError(fmt::format("marker \"{}\": expected an existing body, got \"{}\"", name, body), where);
  if (!is_rotation(R_BM)) {
    throw InputError(fmt::format("marker \"{}\" orientation: expected a rotation matrix "
                                 "(orthonormal, det +1), got det {:.6g}", name, R_BM.determinant()), where);
  }
  return b;
}

int ModelBuilder::add_marker_at(const std::string& name, const std::string& body,
                                const Eigen::Vector3d& p_WM, const Eigen::Matrix3d& R_WM,
                                const SourceLocation& where) {
  const int b = model_.find_body(body);
  if (b < 0) throw InputError(fmt::format("marker \"{}\": expected an existing body, got \"{}\"", name, body), where);
  // Express the ground pose in the body frame at the body's initial pose.
  const Pose& X = model_.bodies[b].initial_pose;
  const Eigen::Matrix3d A = rotation_matrix(X.orientation);
  return add_marker(name, body, A.transpose() * (p_WM - X.position), A.transpose() * R_WM, where);
}

int ModelBuilder::marker_index(const std::string& name, const SourceLocation& where) const {
  for (size_t k = 0; k < model_.markers.size(); ++k) {
    if (model_.markers[k].name == name) return static_cast<int>(k);
  }
  throw InputError(fmt::format("marker: expected an existing marker, got \"{}\"", name), where);
}

void ModelBuilder::claim_element_name(const char* kind, const std::string& name,
                                      const SourceLocation& where) {
  check_name_text(kind, name, where);
  if (std::find(element_names_.begin(), element_names_.end(), name) != element_names_.end()) {
    throw InputError(fmt::format("\"{}\": expected a unique joint/driver/force name, got a duplicate", name),
                     where);
  }
  element_names_.push_back(name);
}

int ModelBuilder::add_joint(const std::string& name, JointType type, const std::string& marker_i,
                            const std::string& marker_j, const SourceLocation& where) {
  // The name first: messages below quote it.
  check_name_text("joint", name, where);
  const int mi = marker_index(marker_i, where), mj = marker_index(marker_j, where);
  if (model_.markers[mi].body == model_.markers[mj].body) {
    throw InputError(fmt::format("joint \"{}\": expected markers on two different bodies, got both on \"{}\"",
                                 name, model_.bodies[model_.markers[mi].body].name), where);
  }
  claim_element_name("joint", name, where);
  model_.joints.push_back(Joint{name, type, mi, mj, 0, 0});
  return static_cast<int>(model_.joints.size()) - 1;
}

Joint& ModelBuilder::releasable_joint(const std::string& joint, const std::string& when,
                                      const SourceLocation& where) {
  const int j = model_.find_joint(joint);
  if (j < 0) throw InputError(fmt::format("release: expected an existing joint, got \"{}\"", joint), where);
  Joint& released = model_.joints[static_cast<std::size_t>(j)];
  if (std::isfinite(released.release_time) || released.release_after >= 0) {
    const std::string first =
        released.release_after >= 0
            ? fmt::format("after \"{}\"", force_name(model_.forces[static_cast<std::size_t>(released.release_after)]))
            : fmt::format("at {} s", released.release_time);
    throw InputError(fmt::format("joint \"{}\": expected one release, got a second ({} after one {})", joint,
                                 when, first), where);
  }
  for (const Driver& driver : model_.drivers) {
    if (driver.joint == j) {
      throw InputError(fmt::format("joint \"{}\": expected an undriven joint to release, got one driven "
                                   "by \"{}\"", joint, driver.name), where);
    }
  }
  return released;
}

void ModelBuilder::release_joint(const std::string& joint, double time, const SourceLocation& where) {
  if (!std::isfinite(time) || time < 0.0) {
    throw InputError(fmt::format("joint \"{}\": expected a release time >= 0 s, got {}", joint, time), where);
  }
  releasable_joint(joint, fmt::format("at {} s", time), where).release_time = time;
}

void ModelBuilder::release_joint_after(const std::string& joint, const std::string& limit, double delay,
                                       const SourceLocation& where) {
  if (!std::isfinite(delay) || delay < 0.0) {
    throw InputError(fmt::format("joint \"{}\": expected a release delay >= 0 s, got {}", joint, delay), where);
  }
  int force = -1;
  for (std::size_t k = 0; k < model_.forces.size(); ++k) {
    const auto* hinge = std::get_if<HingeLimit>(&model_.forces[k]);
    if (hinge != nullptr && hinge->name == limit) force = static_cast<int>(k);
  }
  if (force < 0) {
    throw InputError(fmt::format("joint \"{}\": expected the release's 'after' to name a latch or stop, got "
                                 "\"{}\" (no such latch or stop)", joint, limit), where);
  }
  Joint& released = releasable_joint(joint, fmt::format("after \"{}\"", limit), where);
  released.release_after = force;
  released.release_delay = delay;
}

void ModelBuilder::set_release_duration(const std::string& joint, double duration, const SourceLocation& where) {
  const int j = model_.find_joint(joint);
  if (j < 0) throw InputError(fmt::format("release_duration: expected an existing joint, got \"{}\"", joint), where);
  Joint& released = model_.joints[static_cast<std::size_t>(j)];
  if (!std::isfinite(released.release_time) && released.release_after < 0) {
    throw InputError(fmt::format("joint \"{}\": expected a 'release' with 'release_duration', got none", joint),
                     where);
  }
  if (!std::isfinite(duration) || duration < 0.0) {
    throw InputError(fmt::format("joint \"{}\": expected a release duration >= 0 s, got {}", joint, duration),
                     where);
  }
  released.release_duration = duration;
}

int ModelBuilder::add_driver(const std::string& name, const std::string& joint,
                             DriverCoordinate coordinate, TimeFunction motion,
                             const SourceLocation& where) {
  // The name first: messages below quote it.
  check_name_text("driver", name, where);
  const int j = model_.find_joint(joint);
  if (j < 0) throw InputError(fmt::format("driver \"{}\": expected an existing joint, got \"{}\"", name, joint), where);
  if (const Joint& held = model_.joints[static_cast<std::size_t>(j)];
      std::isfinite(held.release_time) || held.release_after >= 0) {
    throw InputError(fmt::format("driver \"{}\": expected a joint that is not released, got \"{}\"", name, joint),
                     where);
  }
  // The joint must leave the driven coordinate free.
  const JointType type = model_.joints[j].type;
  const bool rotation_ok = type == JointType::kRevolute || type == JointType::kCylindrical;
  const bool translation_ok = type == JointType::kTranslational || type == JointType::kCylindrical;
  if (coordinate == DriverCoordinate::kRotation && !rotation_ok) {
    throw InputError(fmt::format("driver \"{}\": expected a revolute or cylindrical joint for a rotation, "
                                 "got {} joint \"{}\"", name, to_string(type), joint), where);
  }
  if (coordinate == DriverCoordinate::kTranslation && !translation_ok) {
    throw InputError(fmt::format("driver \"{}\": expected a translational or cylindrical joint for a "
                                 "translation, got {} joint \"{}\"", name, to_string(type), joint), where);
  }
  for (const Driver& d : model_.drivers) {
    if (d.joint == j && d.coordinate == coordinate) {
      throw InputError(fmt::format("driver \"{}\": expected one driver per joint coordinate, got a second "
                                   "on joint \"{}\" (first: \"{}\")", name, joint, d.name), where);
    }
  }
  claim_element_name("driver", name, where);
  model_.drivers.push_back(Driver{name, j, coordinate, std::move(motion), 0});
  return static_cast<int>(model_.drivers.size()) - 1;
}

void ModelBuilder::add_rsda(const RsdaSpec& spec, const SourceLocation& where) {
  const int mi = marker_index(spec.marker_i, where), mj = marker_index(spec.marker_j, where);
  if (!(spec.stiffness >= 0.0) || !(spec.damping >= 0.0)) {
    throw InputError(fmt::format("RSDA \"{}\": expected stiffness and damping ≥ 0, got k = {}, c = {}",
                                 spec.name, spec.stiffness, spec.damping), where);
  }
  claim_element_name("RSDA", spec.name, where);
  // Reference angle for unwrapping: θ of the markers at the initial poses.
  Eigen::Vector3d p_i, p_j;
  Eigen::Matrix3d R_i, R_j;
  initial_marker_pose(model_, model_.markers[mi], p_i, R_i);
  initial_marker_pose(model_, model_.markers[mj], p_j, R_j);
  const double theta0 = std::atan2(R_j.col(0).dot(R_i.col(1)), R_j.col(0).dot(R_i.col(0)));
  model_.forces.push_back(Rsda{spec.name, mi, mj, spec.stiffness, spec.damping, spec.free_angle,
                               spec.actuator, spec.actuator_of_angle,
                               spec.angle_center.value_or(theta0)});
}

void ModelBuilder::add_hinge_limit(const HingeLimitSpec& spec, const SourceLocation& where) {
  const char* kind = to_string(spec.kind);
  const int j = model_.find_joint(spec.joint);
  if (j < 0) {
    throw InputError(fmt::format("{} \"{}\": expected a joint name, got \"{}\" (no such joint)", kind,
                                 spec.name, spec.joint), where);
  }
  const Joint& joint = model_.joints[j];
  if (joint.type != JointType::kRevolute) {
    throw InputError(fmt::format("{} \"{}\": expected a revolute joint, got {} joint \"{}\"", kind,
                                 spec.name, to_string(joint.type), spec.joint), where);
  }
  if (!(spec.stiffness > 0.0) || !(spec.damping >= 0.0) || !(spec.damping_depth >= 0.0) ||
      !std::isfinite(spec.damping_depth)) {
    throw InputError(fmt::format("{} \"{}\": expected stiffness > 0, damping ≥ 0 and damping_depth ≥ 0, "
                                 "got k = {}, c = {}, depth = {}", kind, spec.name, spec.stiffness,
                                 spec.damping, spec.damping_depth), where);
  }
  // The joint angle at the initial poses, as for a rotation driver: x_j from x_i towards y_i.
  Eigen::Vector3d p_i, p_j;
  Eigen::Matrix3d R_i, R_j;
  initial_marker_pose(model_, model_.markers[joint.marker_i], p_i, R_i);
  initial_marker_pose(model_, model_.markers[joint.marker_j], p_j, R_j);
  const double theta0 = std::atan2(R_j.col(0).dot(R_i.col(1)), R_j.col(0).dot(R_i.col(0)));
  const double travel = spec.angle - theta0;
  if (!(std::abs(travel) > 1e-9) || !(std::abs(travel) < 2.0 * std::numbers::pi)) {
    throw InputError(fmt::format("{} \"{}\": expected an angle within one turn of the joint's initial "
                                 "angle {:.6g} rad and not equal to it (0 < |angle − {:.6g}| < 2π), "
                                 "got {:.6g} rad", kind, spec.name, theta0, theta0, spec.angle), where);
  }
  claim_element_name(kind, spec.name, where);
  // Unwrap about the middle of the travel: start and limit both lie within ±π of it.
  model_.forces.push_back(HingeLimit{spec.name, spec.kind, j, joint.marker_i, joint.marker_j,
                                     spec.angle, travel > 0.0 ? 1.0 : -1.0, spec.stiffness,
                                     spec.damping, theta0 + 0.5 * travel, spec.damping_depth});
}

void ModelBuilder::add_acceleration_probe(const AccelerationProbeSpec& spec, const SourceLocation& where) {
  check_name_text("acceleration probe", spec.name, where);
  for (const AccelerationProbe& probe : model_.acceleration_probes) {
    if (probe.name == spec.name) {
      throw InputError(fmt::format("acceleration probe \"{}\": expected a unique name, got a duplicate", spec.name),
                       where);
    }
  }
  AccelerationProbe probe{spec.name, 0, spec.p_B, spec.node};
  if (!spec.marker.empty()) {
    // At a marker: its body, point and node.
    const Marker& marker = model_.markers[static_cast<std::size_t>(marker_index(spec.marker, where))];
    probe.body = marker.body;
    probe.p_B = marker.p_BM;
    probe.node = marker.node;
  } else {
    probe.body = model_.find_body(spec.body);
    if (const int k = model_.find_nonlinear_body(spec.body); k >= 0) {
      // At an FE node of a nonlinear body: the origin of that node's rigid body.
      const std::vector<int>& node_bodies = model_.nonlinear_bodies[static_cast<std::size_t>(k)].node_bodies;
      if (spec.node < 0 || spec.node >= static_cast<int>(node_bodies.size())) {
        throw InputError(fmt::format("acceleration probe \"{}\": expected a node index in [0, {}) of nonlinear body "
                                     "\"{}\", got {}", spec.name, node_bodies.size(), spec.body, spec.node), where);
      }
      probe.body = node_bodies[static_cast<std::size_t>(spec.node)];
      probe.p_B = Eigen::Vector3d::Zero();
      probe.node = -1;
    }
    if (probe.body < 0) {
      throw InputError(fmt::format("acceleration probe \"{}\": expected an existing body, got \"{}\"", spec.name,
                                   spec.body), where);
    }
  }
  const Body& body = model_.bodies[static_cast<std::size_t>(probe.body)];
  if (body.kind == BodyKind::kGround) {
    throw InputError(fmt::format("acceleration probe \"{}\": expected a moving body, got ground (it does not "
                                 "accelerate)", spec.name), where);
  }
  if (body.kind == BodyKind::kFlexible) {
    const int nodes = body.flexible->node_count();
    if (probe.node < 0 || probe.node >= nodes) {
      throw InputError(fmt::format("acceleration probe \"{}\": expected a node index in [0, {}) of flexible body "
                                   "\"{}\", got {}", spec.name, nodes, body.name, probe.node), where);
    }
    probe.p_B = body.flexible->node_positions.col(probe.node);
  } else if (probe.node >= 0) {
    throw InputError(fmt::format("acceleration probe \"{}\": expected a point of rigid body \"{}\", got a node",
                                 spec.name, body.name), where);
  }
  model_.acceleration_probes.push_back(probe);
}

void ModelBuilder::add_tsda(const TsdaSpec& spec, const SourceLocation& where) {
  const int mi = marker_index(spec.marker_i, where), mj = marker_index(spec.marker_j, where);
  if (!(spec.stiffness >= 0.0) || !(spec.damping >= 0.0) || !(spec.free_length >= 0.0)) {
    throw InputError(fmt::format("TSDA \"{}\": expected stiffness, damping and free length ≥ 0, "
                                 "got k = {}, c = {}, l0 = {}", spec.name, spec.stiffness, spec.damping,
                                 spec.free_length), where);
  }
  claim_element_name("TSDA", spec.name, where);
  model_.forces.push_back(Tsda{spec.name, mi, mj, spec.stiffness, spec.damping, spec.free_length,
                               spec.actuator});
}

void ModelBuilder::add_point_load(const PointLoadSpec& spec, const SourceLocation& where) {
  const int m = marker_index(spec.marker, where);
  claim_element_name("point load", spec.name, where);
  model_.forces.push_back(PointLoad{spec.name, m, spec.force, spec.torque, spec.scale, spec.frame});
}

Model ModelBuilder::build() const {
  LIMBER_DEMAND(outlines_ == 0);
  Model model = model_;
  model.equations.clear();
  // Joint equations first, named "<joint>.<component>".
  for (size_t j = 0; j < model.joints.size(); ++j) {
    Joint& joint = model.joints[j];
    joint.first_row = model.num_equations();
    for (const EquationTemplate& e : joint_equations(joint.type)) {
      model.equations.push_back(ConstraintEquation{joint.name + "." + e.component, e.kind,
                                                   joint.marker_i, joint.marker_j, e.axis_i,
                                                   e.axis_j, static_cast<int>(j), -1});
    }
    joint.rows = model.num_equations() - joint.first_row;
  }
  // Then one equation per driver: rotation about z_i or displacement along z_i.
  for (size_t d = 0; d < model.drivers.size(); ++d) {
    Driver& driver = model.drivers[d];
    const Joint& joint = model.joints[driver.joint];
    driver.row = model.num_equations();
    const EquationKind kind =
        driver.coordinate == DriverCoordinate::kRotation ? EquationKind::kAngle : EquationKind::kDot2;
    model.equations.push_back(ConstraintEquation{driver.name, kind, joint.marker_i, joint.marker_j,
                                                 2, 0, -1, static_cast<int>(d)});
  }
  return model;
}

}  // namespace limber::multibody
