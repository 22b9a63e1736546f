// The frozen multibody model (house style §1-2): bodies, markers, joints, drivers and force
// elements, built and validated by ModelBuilder (model_builder.h), then read-only.
//
// Coordinates (house style §8 names: X_WB pose of body B in ground W):
//   per moving body  q_b = [r_WB (3), p_WB (4, unit quaternion w,x,y,z)],
//                    v_b = [ṙ_WB in ground (3), ω_WB in body axes (3)];
//   ground has none. Body b owns q[q_offset, q_offset+nq) and v[v_offset, v_offset+nv).
//   A flexible body appends its modal coordinates η (nm) to both blocks:
//                    q_b = [r_WB, p_WB, η],  v_b = [ṙ_WB, ω_WB, η̇]  (flexible_body.h).
// Constraint equations: every joint contributes named scalar equations ("R2.x", "R2.rot_y"),
// every driver one ("D1"); rows are numbered in that order (joints first, then drivers).
// See docs/multibody.md for each joint's equations.
#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Dense>

#include "multibody/flexible_body.h"
#include "multibody/time_function.h"

namespace limber::nonlinear_beam {
struct BeamStructure;
}

namespace limber::multibody {

// A pose X_WB: origin and orientation (unit quaternion w,x,y,z, ground <- body).
struct Pose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector4d orientation = Eigen::Vector4d(1.0, 0.0, 0.0, 0.0);
};

// Rendering primitive carried through to the results (docs/results-format.md).
enum class ShapeType { kBox, kCylinder, kSphere };
const char* to_string(ShapeType type);

struct Shape {
  ShapeType type = ShapeType::kBox;
  Eigen::Vector3d size = Eigen::Vector3d::Ones();  // box: edges; cylinder: r, r, length (z)
  Pose offset;                                     // in the body frame
  Eigen::Vector3d color = Eigen::Vector3d(0.7, 0.7, 0.7);
};

enum class BodyKind { kGround, kRigid, kFlexible };

struct Body {
  std::string name;
  BodyKind kind = BodyKind::kRigid;
  double mass = 0.0;                                              // [kg]
  Eigen::Vector3d com_B = Eigen::Vector3d::Zero();                // centre of mass, body frame [m]
  Eigen::Matrix3d inertia_com_B = Eigen::Matrix3d::Zero();        // about the CoM, body axes [kg m²]
  Pose initial_pose;                                              // X_WB, approximate before assembly
  Eigen::Vector3d initial_velocity_W = Eigen::Vector3d::Zero();   // ṙ_WB [m/s]
  Eigen::Vector3d initial_angular_velocity_B = Eigen::Vector3d::Zero();  // ω in body axes [rad/s]
  std::vector<Shape> shapes;
  // Flexible bodies only: modes, invariants, nodes (mass, com_B and inertia_com_B then
  // hold the undeformed values, for information).
  std::shared_ptr<const FlexibleBody> flexible;
  int q_offset = 0, nq = 0;  // coordinate block
  int v_offset = 0, nv = 0;  // velocity block
};

// A frame fixed on a body: X_BM = (p_BM, R_BM). On a flexible body the marker sits on FE
// node `node` (p_BM = its undeformed position) and follows the node's elastic translation
// and small rotation (flexible_marker.h); node = −1 on rigid bodies and ground.
struct Marker {
  std::string name;
  int body = 0;
  Eigen::Vector3d p_BM = Eigen::Vector3d::Zero();
  Eigen::Matrix3d R_BM = Eigen::Matrix3d::Identity();
  int node = -1;
};

enum class JointType { kRevolute, kTranslational, kSpherical, kBracket, kUniversal, kCylindrical };
const char* to_string(JointType type);

// A joint between marker i (on body_i) and marker j (on body_j); its equations are rows
// [first_row, first_row + rows) of the full constraint vector. A joint with a finite
// release_time (a hold-down) holds up to that time and is then removed: its rows leave the
// equations and its reaction is zero from then on (docs/multibody.md, "Hold-downs"). A joint
// with release_after ≥ 0 is released instead release_delay after that hinge limit first
// engages (a latch locks, a stop first touches), a time known only when the run gets there
// (event_releases.h).
struct Joint {
  std::string name;
  JointType type = JointType::kRevolute;
  int marker_i = 0, marker_j = 0;
  int first_row = 0, rows = 0;
  double release_time = std::numeric_limits<double>::infinity();  // [s]
  int release_after = -1;      // index into Model::forces of a HingeLimit, or −1
  double release_delay = 0.0;  // [s] ≥ 0, after that limit's first engagement
  // [s] ≥ 0: 0 lets go at once; > 0 leaves the last reaction as a load that fades over it
  // (fading_loads.h).
  double release_duration = 0.0;
};

// What a driver prescribes on its joint: the rotation angle of marker j about z_i (x_j
// measured from x_i towards y_i) [rad], or the displacement z_i·(p_j − p_i) [m].
enum class DriverCoordinate { kRotation, kTranslation };

struct Driver {
  std::string name;
  int joint = 0;
  DriverCoordinate coordinate = DriverCoordinate::kRotation;
  TimeFunction motion;  // prescribed coordinate f(t)
  int row = 0;
};

// Scalar equation primitives on markers i and j (Haug 1989, §9.2; a, b marker axes, d = p_j − p_i):
//   kDot1: a_i·b_j = 0     kDot2: a_i·d − f(t) = 0     kAngle: wrap(θ_ij − f(t)) = 0
enum class EquationKind { kDot1, kDot2, kAngle };

struct ConstraintEquation {
  std::string name;  // "<joint>.<component>" or the driver's name
  EquationKind kind = EquationKind::kDot1;
  int marker_i = 0, marker_j = 0;
  int axis_i = 0, axis_j = 0;  // 0, 1, 2 = x, y, z of the marker
  int joint = -1;              // owning joint, or -1
  int driver = -1;             // owning driver (supplies f(t)), or -1
};

// Rotational spring-damper-actuator about z_i of marker i; θ as for a rotation driver,
// unwrapped within ±π of reference_angle (by default its value at the initial poses; a hinge
// that turns by π or more needs the middle of its travel there).
// Torque on body j about z_i: τ = −k (θ − θ0) − c θ̇ + a, with a = actuator(t) or actuator(θ).
struct Rsda {
  std::string name;
  int marker_i = 0, marker_j = 0;
  double stiffness = 0.0, damping = 0.0, free_angle = 0.0;  // [N·m/rad], [N·m·s/rad], [rad]
  TimeFunction actuator;
  bool actuator_of_angle = false;
  double reference_angle = 0.0;
};

// Translational spring-damper-actuator between the marker origins, l = |p_j − p_i|.
// Force on body j along e = (p_j − p_i)/l: f = −k (l − l0) − c l̇ + a(t) (body i gets −f e).
struct Tsda {
  std::string name;
  int marker_i = 0, marker_j = 0;
  double stiffness = 0.0, damping = 0.0, free_length = 0.0;  // [N/m], [N·s/m], [m]
  TimeFunction actuator;
};

// Force and torque at a marker origin: (force, torque) · scale(t), in ground or marker axes.
enum class LoadFrame { kGround, kMarker };
struct PointLoad {
  std::string name;
  int marker = 0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // [N]
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();  // [N·m]
  TimeFunction scale = TimeFunction::constant(1.0);
  LoadFrame frame = LoadFrame::kGround;
};

// A latch or a one-sided stop on a revolute joint (hinge_limit.h: force law and events).
// θ is the joint's angle as for a rotation driver, unwrapped within ±π of angle_center; the
// hinge starts on the free side, and direction = sign(angle − θ at the initial poses) says
// which way it travels towards the limit. Penetration p = direction (θ − angle).
//   latch: engages (for good) when p rises through 0; locked, τ = −k (θ − angle) − s c θ̇.
//   stop:  in contact while p > 0;  τ = −direction max(0, k p + s c ṗ)  (pushes, never pulls).
// s, the share of the damping, rises from 0 at p = 0 to 1 at p = damping_depth (1 throughout
// when it is 0), so that the torque is continuous at engagement (hinge_limit.h).
// Torque on body j about z_i, like an RSDA's. Switches are events located by the integrator.
enum class HingeLimitKind { kLatch, kStop };
const char* to_string(HingeLimitKind kind);

struct HingeLimit {
  std::string name;
  HingeLimitKind kind = HingeLimitKind::kLatch;
  int joint = 0, marker_i = 0, marker_j = 0;
  double angle = 0.0;                     // [rad]
  double direction = 1.0;                 // ±1
  double stiffness = 0.0, damping = 0.0;  // [N·m/rad], [N·m·s/rad]
  double angle_center = 0.0;              // [rad]
  double damping_depth = 0.0;             // [rad] ≥ 0
};

using ForceElement = std::variant<Rsda, Tsda, PointLoad, HingeLimit>;

// Output only: a point whose absolute acceleration is recorded (acceleration_probe.h): p_B in
// the frame of a rigid body, or FE node `node` of a flexible body (then p_B is the node's
// undeformed position and the point follows the node's elastic motion).
struct AccelerationProbe {
  std::string name;
  int body = 1;
  Eigen::Vector3d p_B = Eigen::Vector3d::Zero();  // [m]
  int node = -1;                                  // flexible bodies: node index; else −1
};

// A flexible body with `formulation: nonlinear` (docs/nonlinear-beams.md): no modes; each FE
// node is a rigid body of the model (node_bodies, with the node's lumped mass and rotary
// inertia, its frame along the FE component axes at t = 0), and the co-rotational beams of
// `structure` (FE component axes) are internal forces between them (nonlinear_body.h).
// Joints, markers and probes on the body sit on its node bodies.
struct NonlinearBody {
  std::string name;
  std::shared_ptr<const nonlinear_beam::BeamStructure> structure;
  std::vector<int> node_bodies;                       // model body of each FE node
  Eigen::Matrix3d R_WC = Eigen::Matrix3d::Identity();  // FE component axes in ground, t = 0
  Eigen::Vector3d p_WC = Eigen::Vector3d::Zero();      // FE component origin in ground, t = 0 [m]
  std::optional<DeflectionProbe> deflection_probe;     // output only; node indices
  FlexibleMesh mesh;                                   // for drawing (results), as a modal body's
  // Rayleigh damping of the deformation only (nonlinear_body_damping.h): α on the node
  // velocities relative to the body's rigid motion, β on the elements' deformation rates.
  double mass_damping = 0.0;       // α ≥ 0 [1/s]
  double stiffness_damping = 0.0;  // β ≥ 0 [s]
  // Output only: which elements' stresses to record (0-based, FeModel::beams order), and with
  // it every beam's section for the extreme-fibre stress (nonlinear_body_stress.h).
  std::optional<StressOutput> stress;
  std::vector<fe::BeamSection> beam_sections;  // one per element when stress is set, else empty
};

struct Model {
  std::vector<Body> bodies;  // bodies[0] is ground
  std::vector<Marker> markers;
  std::vector<Joint> joints;
  std::vector<Driver> drivers;
  std::vector<ForceElement> forces;
  std::vector<ConstraintEquation> equations;  // full set, joints then drivers
  std::vector<AccelerationProbe> acceleration_probes;  // output only
  std::vector<NonlinearBody> nonlinear_bodies;
  Eigen::Vector3d gravity_W = Eigen::Vector3d::Zero();  // [m/s²]
  int nq = 0, nv = 0;

  int num_equations() const { return static_cast<int>(equations.size()); }
  // Index by name, or -1.
  int find_body(const std::string& name) const;
  // Index into nonlinear_bodies by name, or -1.
  int find_nonlinear_body(const std::string& name) const;
  int find_joint(const std::string& name) const;
  int find_driver(const std::string& name) const;
  int find_equation(const std::string& name) const;
  // The release times of the joints that have one, ascending, without repeats [s].
  std::vector<double> release_times() const;
};

const std::string& force_name(const ForceElement& force);

}  // namespace limber::multibody
