// Mutable, checked construction of a multibody Model (house style §2). Every add_* call
// validates its input at once and throws InputError (expected/got, with the caller's
// SourceLocation, e.g. a case-file line); build() returns the frozen Model.
// Body 0 is "ground". Names of joints, drivers and force elements share one namespace. Names
// are free text, but neither empty nor holding control characters (core/names.h: InputError).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/error.h"
#include "multibody/model.h"
#include "nonlinear_beam/beam_inertia.h"

namespace limber::multibody {

struct RigidBodySpec {
  std::string name;
  double mass = 0.0;                                        // > 0 [kg]
  Eigen::Vector3d com_B = Eigen::Vector3d::Zero();          // [m]
  Eigen::Matrix3d inertia_com_B = Eigen::Matrix3d::Zero();  // symmetric positive definite [kg m²]
  Pose initial_pose;                                        // quaternion normalised here
  Eigen::Vector3d initial_velocity_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d initial_angular_velocity_B = Eigen::Vector3d::Zero();
  std::vector<Shape> shapes;
};

// A flexible body from a component's mode set (modal/component_modes.h): mass-normalised
// mode shapes over the FE nodes (6 DOFs per node, rotations included), their modal
// stiffness and the floating-frame invariants, all in the FE component frame, which
// becomes the body frame. The mode set fixes the reference-frame condition
// (docs/multibody.md, "Flexible bodies"): free-free modes → a linearised mean-axis frame,
// modes clamped at a node → the frame attached to that node.
struct FlexibleBodySpec {
  std::string name;
  std::string component;                          // output only: the case's component ("" none)
  modal::ModeSet modes;                           // shapes (6 nodes x nm), modal_stiffness, invariants
  std::vector<Eigen::Vector3d> node_positions_B;  // fe::FeModel::node_positions [m]
  ModalDamping damping;                           // default: kDefaultModalDampingRatio in every mode
  Pose initial_pose;                              // quaternion normalised here
  Eigen::Vector3d initial_velocity_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d initial_angular_velocity_B = Eigen::Vector3d::Zero();
  Eigen::VectorXd initial_modal_coordinates;      // nm, or empty for 0 [kg^½ m]
  Eigen::VectorXd initial_modal_velocities;       // nm, or empty for 0 [kg^½ m/s]
  std::vector<Shape> shapes;
  FlexibleMesh mesh;                              // for drawing; indices into node_positions_B
  std::optional<DeflectionProbe> deflection_probe;  // output only; node indices
  GeometricStiffening stiffening = GeometricStiffening::kOff;  // flexible_body.h
  modal::ModalGeometricStiffness geometric;         // of `modes`, unless kOff
  // Output only: which elements' stresses to record, and the modal stresses of every element of
  // the mesh (modal::modal_stress of the FE model and `modes`), needed when stress is set.
  std::optional<StressOutput> stress;
  modal::ModalStress modal_stress;
};

// A flexible body with `formulation: nonlinear` (model.h, NonlinearBody): its co-rotational
// beams, the lumped inertia of its nodes (nonlinear_beam/beam_inertia.h), and the pose and
// velocity of its FE component frame at t = 0 (the node bodies start there, moving rigidly
// with it).
struct NonlinearBodySpec {
  std::string name;
  std::shared_ptr<const nonlinear_beam::BeamStructure> structure;
  nonlinear_beam::NodalInertia inertia;
  Pose initial_pose;  // X_WC; quaternion normalised here
  Eigen::Vector3d initial_velocity_W = Eigen::Vector3d::Zero();          // of the frame origin [m/s]
  Eigen::Vector3d initial_angular_velocity_B = Eigen::Vector3d::Zero();  // component axes [rad/s]
  FlexibleMesh mesh;                                // for drawing; node_ids name the node bodies
  std::optional<DeflectionProbe> deflection_probe;  // output only; node indices
  double mass_damping = 0.0, stiffness_damping = 0.0;  // Rayleigh α [1/s], β [s] ≥ 0 (model.h)
  // Output only: the elements whose stresses to record and every beam's section (one per
  // element; nonlinear_body_stress.h beam_sections_of), both or neither.
  std::optional<StressOutput> stress;
  std::vector<fe::BeamSection> beam_sections;
};

struct RsdaSpec {
  std::string name, marker_i, marker_j;
  double stiffness = 0.0, damping = 0.0, free_angle = 0.0;  // k ≥ 0, c ≥ 0
  TimeFunction actuator;
  bool actuator_of_angle = false;
  std::optional<double> angle_center{};  // θ unwrapped within ±π of it; default θ at the initial poses
};

// A latch or stop on revolute joint `joint` at `angle` [rad] (model.h, HingeLimit). The
// defaults are of the order of a spacecraft deployment hinge: locked-hinge stiffness is
// measured at 1e3-1e4 N·m/rad; 5 N·m·s/rad damps a ~1 kg·m² panel's latch ringing at a few
// per cent of critical.
inline constexpr double kDefaultHingeLimitStiffness = 5e3;  // [N·m/rad]
inline constexpr double kDefaultHingeLimitDamping = 5.0;    // [N·m·s/rad]
struct HingeLimitSpec {
  std::string name, joint;
  HingeLimitKind kind = HingeLimitKind::kLatch;
  double angle = 0.0;
  double stiffness = kDefaultHingeLimitStiffness;  // > 0
  double damping = kDefaultHingeLimitDamping;      // ≥ 0
  double damping_depth = 0.0;                      // [rad] ≥ 0: the damping's ramp (model.h)
};

struct TsdaSpec {
  std::string name, marker_i, marker_j;
  double stiffness = 0.0, damping = 0.0, free_length = 0.0;  // k ≥ 0, c ≥ 0, l0 ≥ 0
  TimeFunction actuator;
};

struct PointLoadSpec {
  std::string name, marker;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  TimeFunction scale = TimeFunction::constant(1.0);
  LoadFrame frame = LoadFrame::kGround;
};

// An acceleration probe (output only, model.h): at marker `marker`'s origin (its node on a
// flexible body) when given, else on body `body`: at p_B (body frame) of a rigid body, or at FE
// node `node` (0-based index) of a flexible one.
struct AccelerationProbeSpec {
  std::string name, marker, body;
  Eigen::Vector3d p_B = Eigen::Vector3d::Zero();  // [m], rigid bodies
  int node = -1;                                  // flexible bodies
};

class ModelBuilder {
 public:
  ModelBuilder();

  void set_gravity(const Eigen::Vector3d& g_W);
  // Returns the body index (ground is 0). Throws InputError for a mass that is not positive, an
  // inertia that is not symmetric positive definite or not realisable (I1 + I2 ≥ I3), and a
  // centre of mass so far from the origin that the mass matrix about the origin cannot be
  // factorised reliably (m |c|² / I1 > 1e10).
  int add_rigid_body(const RigidBodySpec& spec, const SourceLocation& where = {});
  // Throws InputError unless the shapes, stiffness and invariants agree in size (nm ≥ 1),
  // the mass is positive, damping values are ≥ 0, and the undeformed mass matrix of frame
  // plus modes is positive definite (modes holding rigid motion the frame already carries
  // make it singular).
  int add_flexible_body(const FlexibleBodySpec& spec, const SourceLocation& where = {});
  // A flexible body whose modes are not known yet (spec.modes, damping and initial modal
  // values ignored): name, pose, nodes and deflection probe are checked as above, so that the
  // markers, joints and forces on it can be checked before the modal reduction (the case
  // reader's check). A builder holding such a body cannot build() (it aborts).
  int add_flexible_body_outline(const FlexibleBodySpec& spec, const SourceLocation& where = {});
  // One rigid body per FE node, "<name>.node<id>" (mesh.node_ids, else 1..n), with the node's
  // mass and rotary inertia about the node (com at the node), its frame along the component
  // axes; returns the index into Model::nonlinear_bodies. Throws InputError as add_rigid_body
  // for each node body, for a name taken, and for a deflection probe's node out of range.
  // Markers on it: add_node_marker. Force elements and acceleration probes on its markers are
  // refused (InputError: not available yet).
  int add_nonlinear_body(const NonlinearBodySpec& spec, const SourceLocation& where = {});
  // Marker given in the body frame; R_BM must be a rotation (orthonormal, det +1). Not on
  // flexible bodies (their markers sit on nodes: add_node_marker).
  int add_marker(const std::string& name, const std::string& body, const Eigen::Vector3d& p_BM,
                 const Eigen::Matrix3d& R_BM = Eigen::Matrix3d::Identity(),
                 const SourceLocation& where = {});
  // Marker given in ground axes at the body's initial pose.
  int add_marker_at(const std::string& name, const std::string& body, const Eigen::Vector3d& p_WM,
                    const Eigen::Matrix3d& R_WM = Eigen::Matrix3d::Identity(),
                    const SourceLocation& where = {});
  // Marker on FE node `node` (0-based index into the body's node_positions_B) of flexible
  // body `body`, axes R_BM in body axes of the undeformed body; it follows the node's
  // elastic translation and rotation. On a nonlinear body: a marker at the origin of the
  // node's body (whose axes are the component axes at t = 0).
  int add_node_marker(const std::string& name, const std::string& body, int node,
                      const Eigen::Matrix3d& R_BM = Eigen::Matrix3d::Identity(),
                      const SourceLocation& where = {});
  // The markers must lie on different bodies.
  int add_joint(const std::string& name, JointType type, const std::string& marker_i,
                const std::string& marker_j, const SourceLocation& where = {});
  // The joint holds up to `time` and is then removed (a hold-down: Joint::release_time).
  // Throws InputError for an unknown joint, a time that is negative or not finite, a joint
  // released already, or a driven joint (its driver would prescribe a coordinate of nothing).
  void release_joint(const std::string& joint, double time, const SourceLocation& where = {});
  // The joint holds until `delay` after the hinge limit `limit` (a latch or stop, added
  // before) first engages, and is then removed (Joint::release_after). Throws InputError as
  // release_joint does, and for a name that is no latch or stop, or a delay < 0 or not finite.
  void release_joint_after(const std::string& joint, const std::string& limit, double delay,
                           const SourceLocation& where = {});
  // The released joint `joint` lets go over `duration` [s] (Joint::release_duration; 0: at
  // once). Throws InputError for a joint without a release or a duration < 0 or not finite.
  void set_release_duration(const std::string& joint, double duration, const SourceLocation& where = {});
  // Rotation drivers need a revolute or cylindrical joint, translation drivers a
  // translational or cylindrical one; at most one driver per joint coordinate; none on a
  // released joint.
  int add_driver(const std::string& name, const std::string& joint, DriverCoordinate coordinate,
                 TimeFunction motion, const SourceLocation& where = {});
  void add_rsda(const RsdaSpec& spec, const SourceLocation& where = {});
  void add_tsda(const TsdaSpec& spec, const SourceLocation& where = {});
  void add_point_load(const PointLoadSpec& spec, const SourceLocation& where = {});
  // Throws unless the joint is a revolute, k > 0, c ≥ 0, and the angle is reachable from the
  // joint's angle at the initial poses θ0: 0 < |angle − θ0| < 2π (within one turn, and not
  // where the hinge starts).
  void add_hinge_limit(const HingeLimitSpec& spec, const SourceLocation& where = {});
  // Throws unless the name is unique among probes, the marker (or body) exists and moves (not
  // ground), and the point fits the body: p_B on a rigid body, a node index in range on a
  // flexible one.
  void add_acceleration_probe(const AccelerationProbeSpec& spec, const SourceLocation& where = {});

  // Numbers the coordinates and the constraint equations; the builder stays usable.
  // Precondition: no body was added by add_flexible_body_outline.
  Model build() const;

 private:
  int marker_index(const std::string& name, const SourceLocation& where) const;
  void check_new_body(const std::string& name, const Pose& pose, const SourceLocation& where) const;
  // Checks name, body and axes of a new marker; returns the body index.
  int check_new_marker(const std::string& name, const std::string& body, const Eigen::Matrix3d& R_BM,
                       const SourceLocation& where) const;
  int append_body(Body body);
  // Checks the text of a joint/driver/force name (core/names.h; `kind` for messages, e.g.
  // "joint") and that no element has it yet.
  void claim_element_name(const char* kind, const std::string& name, const SourceLocation& where);
  // The joint `joint` checked for a release (`when` for messages): it exists, is not released
  // yet and carries no driver.
  Joint& releasable_joint(const std::string& joint, const std::string& when, const SourceLocation& where);

  // The frame-independent part of a flexible body: node positions, mesh, checked probe.
  std::shared_ptr<FlexibleBody> flexible_outline(const FlexibleBodySpec& spec, const SourceLocation& where) const;

  Model model_;
  std::vector<std::string> element_names_;
  int outlines_ = 0;  // bodies added by add_flexible_body_outline
};

}  // namespace limber::multibody
