#include "run/sample_record.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "core/error.h"
#include "multibody/acceleration_probe.h"
#include "multibody/clearance_minimum.h"
#include "multibody/constraints.h"
#include "multibody/dynamics.h"
#include "multibody/energy_rates.h"
#include "multibody/evaluated.h"
#include "multibody/hinge_limit.h"
#include "multibody/momentum.h"
#include "multibody/nonlinear_body.h"
#include "multibody/nonlinear_body_stress.h"
#include "multibody/reactions.h"
#include "multibody/rotation.h"

namespace limber::run {

namespace {

results::ShapeSpec to_shape_spec(const multibody::Shape& shape) {
  results::ShapeSpec spec;
  spec.type = shape.type == multibody::ShapeType::kBox        ? results::ShapeSpec::Type::kBox
              : shape.type == multibody::ShapeType::kCylinder ? results::ShapeSpec::Type::kCylinder
                                                              : results::ShapeSpec::Type::kSphere;
  spec.size = shape.size;
  spec.offset_position = shape.offset.position;
  const Eigen::Vector4d& p = shape.offset.orientation;
  spec.offset_orientation = Eigen::Quaterniond(p(0), p(1), p(2), p(3)).normalized();
  spec.color = shape.color;
  return spec;
}

// The beams' axes and outline table in the file's form (results/beam_sections.h).
results::BeamSections beam_sections(const multibody::FlexibleMesh& mesh) {
  results::BeamSections out;
  if (mesh.beam_outlines.empty()) return out;
  const auto nl = static_cast<Eigen::Index>(mesh.beam_y_axes.size());
  out.y_axes.resize(nl, 3);
  for (Eigen::Index e = 0; e < nl; ++e) {
    out.y_axes.row(e) = mesh.beam_y_axes[static_cast<std::size_t>(e)].transpose();
  }
  out.outline = mesh.beam_outlines;
  out.offsets.push_back(0);
  std::vector<Eigen::Vector2d> points;
  for (const fe::SectionOutline& o : mesh.outlines) {
    points.insert(points.end(), o.points.begin(), o.points.end());
    out.offsets.push_back(static_cast<int>(points.size()));
    out.hollow.push_back(o.hollow ? 1 : 0);
    out.equivalent.push_back(o.equivalent ? 1 : 0);
  }
  out.points.resize(static_cast<Eigen::Index>(points.size()), 2);
  for (std::size_t k = 0; k < points.size(); ++k) {
    out.points.row(static_cast<Eigen::Index>(k)) = points[k].transpose();
  }
  return out;
}

// The mesh of a flexible body's declaration: undeformed nodes (3 x nn, body frame), elements,
// sections (docs/results-format.md).
results::FlexibleBodySpec mesh_spec(const std::string& name, const Eigen::MatrixXd& node_positions,
                                    const multibody::FlexibleMesh& mesh) {
  results::FlexibleBodySpec spec;
  spec.name = name;
  spec.nodes = node_positions.transpose();
  spec.node_ids = mesh.node_ids;
  spec.lines.resize(static_cast<Eigen::Index>(mesh.lines.size()), 2);
  for (std::size_t e = 0; e < mesh.lines.size(); ++e) {
    for (int k = 0; k < 2; ++k) spec.lines(static_cast<Eigen::Index>(e), k) = mesh.lines[e][k];
  }
  spec.quads.resize(static_cast<Eigen::Index>(mesh.quads.size()), 4);
  for (std::size_t e = 0; e < mesh.quads.size(); ++e) {
    for (int k = 0; k < 4; ++k) spec.quads(static_cast<Eigen::Index>(e), k) = mesh.quads[e][k];
  }
  spec.beam_radius = mesh.beam_radius;
  spec.beam_sections = beam_sections(mesh);
  return spec;
}

// A body's mass, centre of mass and inertia about it (a flexible body's undeformed ones).
results::MassProperties mass_properties(const multibody::Body& body) {
  return {body.mass, body.com_B, body.inertia_com_B};
}

// Mesh, translational mode shapes, frequencies, kinds and labels of a flexible body, its
// component and undeformed mass properties (docs/results-format.md).
results::FlexibleBodySpec flexible_body_spec(const multibody::Body& body,
                                             std::vector<results::ShapeSpec> shapes) {
  const multibody::FlexibleBody& flexible = *body.flexible;
  const int nn = flexible.node_count(), nm = flexible.mode_count();
  results::FlexibleBodySpec spec = mesh_spec(body.name, flexible.node_positions, flexible.mesh);
  spec.mode_translations.resize(3 * nn, nm);
  for (int n = 0; n < nn; ++n) spec.mode_translations.middleRows(3 * n, 3) = flexible.translation_shapes(n);
  spec.frequencies_hz = flexible.stiffness.cwiseMax(0.0).cwiseSqrt() / (2.0 * std::numbers::pi);
  if (static_cast<int>(flexible.mode_info.size()) == nm) {
    for (const modal::ModeInfo& mode : flexible.mode_info) {
      spec.mode_kinds.emplace_back(modal::to_string(mode.kind));
      spec.mode_labels.push_back(mode.label);
    }
  }
  spec.component = flexible.component;
  spec.mass_properties = mass_properties(body);
  spec.shapes = std::move(shapes);
  spec.has_deflection = flexible.deflection_probe.has_value();
  if (const auto& stress = flexible.stress_output) {
    spec.has_stress = true;
    spec.stress_elements = stress->elements;
    spec.stress_every = stress->every;
  }
  return spec;
}

// A nonlinear body's undeformed mass, centre of mass and inertia about it, component axes (its
// recorded frame at t = 0): the node bodies' point masses at the nodes plus their rotary
// inertias (node axes along the component axes when undeformed).
results::MassProperties nonlinear_mass_properties(const multibody::Model& model, const multibody::NonlinearBody& body) {
  const std::vector<Eigen::Vector3d>& X = body.structure->reference_positions;
  results::MassProperties out;
  for (std::size_t k = 0; k < X.size(); ++k) {
    const multibody::Body& node = model.bodies[static_cast<std::size_t>(body.node_bodies[k])];
    out.mass += node.mass;
    out.com_B += node.mass * X[k];
  }
  out.com_B /= out.mass;
  for (std::size_t k = 0; k < X.size(); ++k) {
    const multibody::Body& node = model.bodies[static_cast<std::size_t>(body.node_bodies[k])];
    const Eigen::Vector3d d = X[k] - out.com_B;
    out.inertia_com_B += node.inertia_com_B + node.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  return out;
}

// A nonlinear body as a flexible body of no modes (docs/results-format.md): its mesh in the
// component frame, its node displacements, its deflection probe and its mass properties.
results::FlexibleBodySpec nonlinear_body_spec(const multibody::Model& model, const multibody::NonlinearBody& body) {
  const std::vector<Eigen::Vector3d>& X = body.structure->reference_positions;
  Eigen::MatrixXd nodes(3, static_cast<Eigen::Index>(X.size()));
  for (std::size_t k = 0; k < X.size(); ++k) nodes.col(static_cast<Eigen::Index>(k)) = X[k];
  results::FlexibleBodySpec spec = mesh_spec(body.name, nodes, body.mesh);
  spec.mode_translations.resize(nodes.size(), 0);
  spec.has_deflection = body.deflection_probe.has_value();
  spec.has_node_displacements = true;
  spec.mass_properties = nonlinear_mass_properties(model, body);
  if (const auto& stress = body.stress) {
    spec.has_stress = true;
    spec.stress_elements = stress->elements;
    spec.stress_every = stress->every;
  }
  return spec;
}

// The node farthest from the first in the undeformed mesh: the chord of the recorded frame.
std::size_t chord_end_node(const std::vector<Eigen::Vector3d>& X) {
  std::size_t end = 0;
  for (std::size_t k = 1; k < X.size(); ++k) {
    if ((X[k] - X.front()).squaredNorm() > (X[end] - X.front()).squaredNorm()) end = k;
  }
  return end;
}

// The results' name of a model body: a node body's is its nonlinear body's.
const std::string& recorded_name(const multibody::Model& model, const std::vector<int>& nonlinear_of, int body) {
  const int owner = nonlinear_of[static_cast<std::size_t>(body)];
  return owner >= 0 ? model.nonlinear_bodies[static_cast<std::size_t>(owner)].name
                    : model.bodies[static_cast<std::size_t>(body)].name;
}

// A marker's origin and orientation (ground <- marker) from its kinematics.
results::MarkerPose marker_pose(const multibody::FrameKinematics& frame) {
  return {frame.p_W, Eigen::Quaterniond(frame.R_WF).normalized()};
}

}  // namespace

void declare_model(const multibody::Model& model, results::ResultsWriter& writer) {
  // Moving bodies (ground has no pose to record); a nonlinear body once, at its first node body.
  const std::vector<int> nonlinear_of = multibody::nonlinear_body_of(model);
  for (std::size_t b = 1; b < model.bodies.size(); ++b) {
    const multibody::Body& body = model.bodies[b];
    if (const int owner = nonlinear_of[b]; owner >= 0) {
      const multibody::NonlinearBody& nonlinear = model.nonlinear_bodies[static_cast<std::size_t>(owner)];
      if (nonlinear.node_bodies.front() == static_cast<int>(b)) writer.add_flexible_body(nonlinear_body_spec(model, nonlinear));
      continue;
    }
    std::vector<results::ShapeSpec> shapes;
    for (const multibody::Shape& shape : body.shapes) shapes.push_back(to_shape_spec(shape));
    if (body.kind == multibody::BodyKind::kFlexible) {
      writer.add_flexible_body(flexible_body_spec(body, std::move(shapes)));
    } else {
      writer.add_rigid_body({body.name, std::move(shapes), mass_properties(body)});
    }
  }
  for (const multibody::Joint& joint : model.joints) {
    writer.add_joint({joint.name, multibody::to_string(joint.type),
                      recorded_name(model, nonlinear_of, model.markers[joint.marker_i].body),
                      recorded_name(model, nonlinear_of, model.markers[joint.marker_j].body),
                      model.markers[joint.marker_i].name, model.markers[joint.marker_j].name});
  }
  for (const multibody::Driver& driver : model.drivers) {
    writer.add_driver(driver.name,
                      driver.coordinate == multibody::DriverCoordinate::kRotation ? "N m" : "N");
  }
  for (const char* name : kEnergyNames) writer.add_energy(name);
  writer.record_momentum();
  for (const multibody::ForceElement& force : model.forces) {
    if (const auto* limit = std::get_if<multibody::HingeLimit>(&force)) {
      writer.add_hinge_limit({limit->name, multibody::to_string(limit->kind),
                              model.joints[limit->joint].name, limit->angle});
    }
  }
  // Acceleration probes: body, node (user id) or point.
  for (const multibody::AccelerationProbe& probe : model.acceleration_probes) {
    const multibody::Body& body = model.bodies[static_cast<std::size_t>(probe.body)];
    int node = -1;
    if (probe.node >= 0) {
      const std::vector<int>& ids = body.flexible->mesh.node_ids;
      node = ids.empty() ? probe.node + 1 : ids[static_cast<std::size_t>(probe.node)];
    }
    writer.add_acceleration_probe({probe.name, body.name, node, probe.p_B});
  }
  // Clearance pairs, only where there is something to check.
  const std::vector<multibody::ClearancePair> pairs = multibody::clearance_pairs(model);
  if (!pairs.empty()) {
    std::vector<std::string> names;
    for (const multibody::ClearancePair& pair : pairs) names.push_back(multibody::pair_name(model, pair));
    writer.set_clearance_pairs(names);
  }
}

integrate::Quadrature energy_quadrature(const multibody::Model& model,
                                        const multibody::ConstraintPartition& partition,
                                        const std::vector<unsigned char>& engaged,
                                        const multibody::State& start, double rtol,
                                        const std::vector<multibody::FadingLoad>* fading,
                                        const std::vector<multibody::StiffeningLoads>* stiffening) {
  // The integrand runs inside the integrator: it gets its own workspace.
  auto ws = std::make_shared<multibody::Workspace>(model);
  integrate::Quadrature quadrature;
  quadrature.size = kEnergyIntegrals;
  quadrature.integrand = [&model, &partition, &engaged, fading, stiffening, ws](
                              double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                              const Eigen::VectorXd& v_dot, const Eigen::VectorXd& lambda, Eigen::VectorXd& f) {
    const multibody::State state{t, q, v, engaged,
                                 stiffening != nullptr ? *stiffening : std::vector<multibody::StiffeningLoads>{}};
    const multibody::EnergyRates rates = multibody::energy_rates(model, partition, state, v_dot, lambda, *ws);
    // force_work counts the geometric stiffening's modal forces and fading loads too
    // (docs/results-format.md).
    const double fade = fading != nullptr ? multibody::fading_load_power(model, *fading, state, *ws) : 0.0;
    f << rates.dissipation, rates.driver, rates.forces + rates.geometric + fade;
  };
  // At a velocity jump of a prescribed motion the constraint impulses change the kinetic
  // energy; only the drivers' rows move with time (the joints' impulses do no work, G v = 0
  // before and after), so the change is the drivers' work.
  quadrature.jump = [&model, &engaged, ws](double t, const Eigen::VectorXd& q,
                                           const Eigen::VectorXd& v_before,
                                           const Eigen::VectorXd& v_after, Eigen::VectorXd& dz) {
    const double before = multibody::energies(model, multibody::State{t, q, v_before, engaged}, *ws).kinetic;
    const double after = multibody::energies(model, multibody::State{t, q, v_after, engaged}, *ws).kinetic;
    dz << 0.0, after - before, 0.0;
  };
  // Energy scale at the start, for the integrals' absolute tolerance.
  const multibody::EnergyTerms energy = multibody::energies(model, start, *ws);
  const double scale =
      std::max(1.0, energy.kinetic + std::abs(energy.gravity) + std::abs(energy.spring));
  quadrature.atol = rtol * scale;
  return quadrature;
}

namespace {

// Recorded stresses of one body from its elements' stresses (beams first, `beam_count` of
// them): the mesh's peak, and the declared elements' history row on every `every`-th sample
// (docs/stress-recovery.md). Modal and nonlinear bodies alike, so the file's layout is one.
void record_element_stresses(const multibody::StressOutput& output, const modal::ElementStresses& stresses,
                             int beam_count, results::BodySample& pose, std::int64_t index) {
  Eigen::Index peak = 0;
  pose.stress_peak = stresses.equivalent.size() > 0 ? stresses.equivalent.maxCoeff(&peak) : 0.0;
  pose.stress_peak_element = static_cast<int>(peak);
  if (index % output.every != 0) return;
  pose.stress_recorded = true;
  const auto n = static_cast<Eigen::Index>(output.elements.size());
  const int nb = beam_count;
  const auto beams = static_cast<Eigen::Index>(
      std::count_if(output.elements.begin(), output.elements.end(), [nb](int e) { return e < nb; }));
  pose.stress_equivalent.resize(n);
  pose.stress_beam_resultants.resize(12 * beams);
  pose.stress_shell_resultants.resize(8 * (n - beams));
  Eigen::Index b = 0, s = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const int e = output.elements[static_cast<std::size_t>(k)];
    pose.stress_equivalent(k) = stresses.equivalent(e);
    if (e < nb) {
      pose.stress_beam_resultants.segment<12>(12 * b++) = stresses.beam_resultants.segment<12>(12 * e);
    } else {
      pose.stress_shell_resultants.segment<6>(8 * s) = stresses.shell_resultants.segment<6>(6 * (e - nb));
      pose.stress_shell_resultants.segment<2>(8 * s + 6) = stresses.shell_von_mises.segment<2>(2 * (e - nb));
      ++s;
    }
  }
}

// A modal body's stresses at its modal coordinates.
void record_stress(const multibody::FlexibleBody& flexible, results::BodySample& pose, std::int64_t index) {
  const modal::ModalStress& modal = flexible.modal_stress;
  record_element_stresses(*flexible.stress_output, modal::recover_stresses(modal, pose.modal_coordinates),
                          modal.beam_count, pose, index);
}

// A nonlinear body's stresses at its configuration (multibody/nonlinear_body_stress.h).
void record_nonlinear_stress(const multibody::NonlinearBody& body, const nonlinear_beam::BeamState& state,
                             results::BodySample& pose, std::int64_t index) {
  modal::ElementStresses stresses;
  stresses.beam_resultants = multibody::nonlinear_beam_resultants(*body.structure, state);
  stresses.equivalent = multibody::nonlinear_beam_fibre_stresses(stresses.beam_resultants, body.beam_sections);
  record_element_stresses(*body.stress, stresses, static_cast<int>(body.structure->elements.size()), pose, index);
}

}  // namespace

SampleRecorder::SampleRecorder(const multibody::Model& model,
                               const multibody::ConstraintPartition& partition,
                               const std::vector<unsigned char>& engaged)
    : model_(model),
      partition_(partition),
      engaged_(engaged),
      workspace_(model),
      check_clearance_(!multibody::clearance_pairs(model).empty()),
      nonlinear_of_(multibody::nonlinear_body_of(model)) {}

results::BodySample SampleRecorder::record_nonlinear(const multibody::NonlinearBody& body,
                                                     const Eigen::VectorXd& q, std::int64_t index) const {
  // The node configurations in the component axes C of t = 0.
  const nonlinear_beam::BeamState state = multibody::nonlinear_body_state(model_, body, q);
  const std::vector<Eigen::Vector3d>& X = body.structure->reference_positions;
  const std::vector<Eigen::Vector3d>& x = state.positions;
  // The chord frame F: the first node's axes turned by the smallest rotation that takes the
  // chord to the farthest node, carried with them, onto the current chord; its origin puts the
  // first node at its mesh place (docs/results-format.md, "Nonlinear bodies").
  const std::size_t end = chord_end_node(X);
  const Eigen::Vector3d carried = state.rotations.front() * (X[end] - X.front());
  const Eigen::Matrix3d R_CF =
      (Eigen::Quaterniond::FromTwoVectors(carried, x[end] - x.front()) * state.rotations.front())
          .toRotationMatrix();
  const Eigen::Vector3d p_CF = x.front() - R_CF * X.front();
  results::BodySample pose;
  pose.orientation = Eigen::Quaterniond(body.R_WC * R_CF).normalized();
  pose.position = body.p_WC + body.R_WC * p_CF;
  pose.modal_coordinates.resize(0);
  pose.modal_velocities.resize(0);
  // Each node's displacement from its mesh place in F.
  pose.node_displacements.resize(3 * static_cast<Eigen::Index>(X.size()));
  for (std::size_t k = 0; k < X.size(); ++k) {
    pose.node_displacements.segment<3>(3 * static_cast<Eigen::Index>(k)) = R_CF.transpose() * (x[k] - p_CF) - X[k];
  }
  if (body.deflection_probe) pose.deflection = multibody::nonlinear_probe_deflection(model_, body, q);
  if (body.stress) record_nonlinear_stress(body, state, pose, index);
  return pose;
}

results::Sample SampleRecorder::record(const integrate::Sample& sample) {
  LIMBER_DEMAND(sample.integrals.size() == kEnergyIntegrals);
  const multibody::State state{sample.t, sample.q, sample.v, engaged_};
  results::Sample out;
  out.time = sample.t;
  out.steps = sample.statistics.steps;
  // Counts this call's sample, for the stress history's `every`.
  const std::int64_t index = recorded_++;

  // Body poses: frame origin and quaternion (w, x, y, z), ground <- body.
  for (std::size_t b = 1; b < model_.bodies.size(); ++b) {
    const multibody::Body& body = model_.bodies[b];
    if (const int owner = nonlinear_of_[b]; owner >= 0) {
      const multibody::NonlinearBody& nonlinear = model_.nonlinear_bodies[static_cast<std::size_t>(owner)];
      if (nonlinear.node_bodies.front() == static_cast<int>(b)) {
        out.bodies.push_back(record_nonlinear(nonlinear, sample.q, index));
      }
      continue;
    }
    const Eigen::Vector4d p = sample.q.segment<4>(body.q_offset + 3).normalized();
    results::BodySample pose;
    pose.position = sample.q.segment<3>(body.q_offset);
    pose.orientation = Eigen::Quaterniond(p(0), p(1), p(2), p(3));
    if (body.kind == multibody::BodyKind::kFlexible) {
      pose.modal_coordinates = sample.q.segment(body.q_offset + 7, body.flexible->mode_count());
      pose.modal_velocities = sample.v.segment(body.v_offset + 6, body.flexible->mode_count());
      if (const auto& probe = body.flexible->deflection_probe) {
        pose.deflection = multibody::probe_deflection(*body.flexible, *probe, pose.modal_coordinates);
      }
      if (body.flexible->stress_output) record_stress(*body.flexible, pose, index);
    }
    out.bodies.push_back(pose);
  }

  // The sample's one pass: M, Q and the markers (mass_matrix_and_forces), then every
  // constraint row from those markers.
  multibody::mass_matrix_and_forces(model_, state, workspace_);
  multibody::evaluate_constraint_rows(model_, state, multibody::Stage::kPosition, workspace_);

  // Reactions on body j (joint frame = marker j's axes) and driver efforts.
  const multibody::Reactions reactions =
      multibody::reactions_of_evaluation(model_, state, sample.vdot, partition_, workspace_);
  for (std::size_t k = 0; k < reactions.joints.size(); ++k) {
    const multibody::JointReaction& r = reactions.joints[k];
    results::JointSample joint;
    joint.position = r.point_W;
    joint.force_joint = r.force_j_J;
    joint.torque_joint = r.torque_j_J;
    joint.force_ground = r.force_j_W;
    joint.torque_ground = r.torque_j_W;
    joint.indeterminate = r.indeterminate;
    // Marker poses of the pass (this sample's q).
    joint.marker_i = marker_pose(workspace_.markers[model_.joints[k].marker_i]);
    joint.marker_j = marker_pose(workspace_.markers[model_.joints[k].marker_j]);
    out.joints.push_back(joint);
  }
  out.driver_efforts = reactions.driver_efforts;

  // Energies: stored ones from the state, flows from the integrals.
  const multibody::EnergyTerms energy = multibody::energies_at_markers(model_, state, workspace_);
  out.energies = {energy.kinetic,      energy.gravity,      energy.spring,      energy.strain,
                  sample.integrals(0), sample.integrals(1), sample.integrals(2)};
  out.momentum = multibody::momentum_of(model_, state, workspace_.M);

  // Hinge latches and stops (force elements: the pass's markers are at the velocity stage):
  // joint angle, torque on body j about the joint axis, and mode.
  for (std::size_t k = 0; k < model_.forces.size(); ++k) {
    const auto* limit = std::get_if<multibody::HingeLimit>(&model_.forces[k]);
    if (!limit) continue;
    const unsigned char mode = k < engaged_.size() ? engaged_[k] : multibody::kLimitFree;
    const multibody::RelativeAngle angle = multibody::hinge_limit_state(*limit, workspace_);
    out.hinge_limit_angles.push_back(angle.theta);
    out.hinge_limit_torques.push_back(
        multibody::hinge_limit_force(*limit, angle.theta, angle.rate, mode).torque);
    out.hinge_limits_engaged.push_back(mode != multibody::kLimitFree ? 1 : 0);
  }

  // Acceleration probes: absolute, ground axes.
  for (const multibody::AccelerationProbe& probe : model_.acceleration_probes) {
    out.probe_accelerations.push_back(
        multibody::probe_motion(model_, probe, sample.q, sample.v, sample.vdot, probe_frame_).a_W);
  }

  // Constraint violations over all rows (redundant ones included).
  const multibody::ConstraintViolation violation =
      multibody::violation_of_rows(model_, state, workspace_, partition_.row_released);
  out.position_violation = violation.position;
  out.velocity_violation = violation.velocity;

  // Minimum clearance between the bodies' surfaces (default joint band).
  if (check_clearance_) {
    const multibody::ClearanceMinimum clearance = multibody::minimum_clearance(model_, state);
    out.clearance_minimum = clearance.minimum;
    out.clearance_pair = clearance.pair;
  }
  return out;
}

}  // namespace limber::run
