#include "io/mechanism_builder.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>
#include <variant>

#include "core/error.h"
#include "fe/assembly.h"
#include "fe/beam_element.h"
#include "modal/geometric_stiffness.h"
#include "modal/modal_stress.h"
#include "multibody/model_builder.h"
#include "multibody/nonlinear_body_stress.h"
#include "nonlinear_beam/beam_inertia.h"
#include "nonlinear_beam/beam_structure.h"

namespace limber::io {

namespace {

using multibody::ModelBuilder;

const FlexibleBodyCase& component_named(const std::vector<FlexibleBodyCase>& components,
                                        const std::string& name) {
  const auto found = std::find_if(components.begin(), components.end(),
                                  [&](const FlexibleBodyCase& c) { return c.name == name; });
  LIMBER_DEMAND(found != components.end());
  return *found;
}

// The FE elements, for drawing; beams as tubes of the largest section's equal-area radius.
multibody::FlexibleMesh drawing_mesh(const fe::FeModel& model) {
  multibody::FlexibleMesh mesh;
  mesh.node_ids = model.node_ids;
  for (const fe::BeamElement& beam : model.beams) mesh.lines.push_back(beam.nodes);
  for (const fe::ShellElement& shell : model.shells) mesh.quads.push_back(shell.nodes);
  // Triangles drawn as quads with the last node repeated.
  for (const fe::ShellTriangle& t : model.triangles) {
    mesh.quads.push_back({t.nodes[0], t.nodes[1], t.nodes[2], t.nodes[2]});
  }
  for (const fe::BeamProperty& property : model.beam_properties) {
    mesh.beam_radius = std::max(mesh.beam_radius, std::sqrt(property.section.area / std::numbers::pi));
  }
  // Each beam's section outline (a stand-in when only A and I are known), shared between equal
  // outlines, and its local y axis (beam_element.h).
  std::vector<int> property_outline;
  for (const fe::BeamProperty& property : model.beam_properties) {
    const fe::BeamSection& s = property.section;
    const fe::SectionOutline outline =
        s.outline.empty() ? fe::equivalent_outline(s.area, s.fibre_y, s.fibre_z) : s.outline;
    const auto same = std::find_if(mesh.outlines.begin(), mesh.outlines.end(), [&](const auto& o) {
      return o.points == outline.points && o.hollow == outline.hollow &&
             o.equivalent == outline.equivalent;
    });
    property_outline.push_back(static_cast<int>(same - mesh.outlines.begin()));
    if (same == mesh.outlines.end()) mesh.outlines.push_back(outline);
  }
  for (const fe::BeamElement& beam : model.beams) {
    const Eigen::Matrix3d R_LB = fe::beam_local_axes(model.node_positions[beam.nodes[0]],
                                                     model.node_positions[beam.nodes[1]], beam.orientation);
    mesh.beam_y_axes.push_back(R_LB.row(1).transpose());
    mesh.beam_outlines.push_back(property_outline[beam.property]);
  }
  return mesh;
}

// Per-mode values of the right length nm (empty stays empty), else an error at the list.
Eigen::VectorXd per_mode(const PerModeValues& values, Eigen::Index nm) {
  if (values.values.size() != 0 && values.values.size() != nm) {
    throw InputError(fmt::format("expected {} values (one per mode) for '{}', got {}", nm, values.key,
                                 values.values.size()),
                     values.where);
  }
  return values.values;
}

// The modes of `component`: NumericalError when its reduction failed.
const modal::ModeSet& mode_set(const CaseReduction& reduction, const FlexibleBodyCase& component) {
  const BodyReduction* body = reduction.find(component.name);
  LIMBER_DEMAND(body != nullptr);
  const modal::ModalResult& result = body->result;
  if (result.status != modal::ModalStatus::kOk) {
    throw NumericalError("modes of flexible body '" + component.name + "' (" +
                         component.modes_where.to_string() + "): " +
                         modal::to_string(result.status) + ": " + result.message);
  }
  return result.mode_set;
}

// Nodes of body `name` that carry markers (its joints' and the named ones): the load nodes of
// the geometric stiffness's node-force cases, ascending.
std::vector<int> marker_nodes(const MechanismCase& mechanism, const std::string& name) {
  std::vector<int> nodes;
  const auto add = [&](const MarkerEntry& m) {
    if (m.body == name && m.frame == MarkerEntry::Frame::kNode) nodes.push_back(m.node);
  };
  for (const MarkerEntry& m : mechanism.markers) add(m);
  for (const JointEntry& joint : mechanism.joints) {
    for (const MarkerEntry& m : joint.markers) add(m);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

// The modal geometric stiffness of `component` for `modes` (modal/geometric_stiffness.h).
// NumericalError when the static solve fails.
void add_geometric_stiffness(const FlexibleBodyCase& component, const std::vector<int>& load_nodes,
                             multibody::FlexibleBodySpec& spec) {
  if (spec.stiffening == multibody::GeometricStiffening::kOff) return;
  const modal::ModalGeometricStiffnessResult result = modal::compute_modal_geometric_stiffness(
      component.model, fe::assemble(component.model), spec.modes.shapes, load_nodes);
  if (result.status != modal::ModalStatus::kOk) {
    throw NumericalError("geometric stiffness of flexible body '" + component.name + "' (" +
                         component.where.to_string() + "): " + result.message);
  }
  spec.geometric = result.stiffness;
}

// A flexible body with its modes, or as an outline when `reduction` is null.
void add_flexible_body(const FlexibleBodyEntry& entry, const std::vector<FlexibleBodyCase>& components,
                       const MechanismCase& mechanism, const CaseReduction* reduction, ModelBuilder& builder) {
  const FlexibleBodyCase& component = component_named(components, entry.component);
  multibody::FlexibleBodySpec spec;
  spec.name = entry.name;
  spec.component = entry.component;
  spec.node_positions_B = component.model.node_positions;
  spec.mesh = drawing_mesh(component.model);
  spec.initial_pose = entry.initial_pose;
  spec.initial_velocity_W = entry.initial_velocity_W;
  spec.initial_angular_velocity_B = entry.initial_angular_velocity_B;
  spec.deflection_probe = entry.deflection_probe;
  spec.stress = entry.stress;
  if (!reduction) {
    builder.add_flexible_body_outline(spec, entry.where);
    return;
  }
  // The modes fix the lengths of the per-mode lists.
  spec.modes = mode_set(*reduction, component);
  const Eigen::Index nm = spec.modes.shapes.cols();
  spec.damping = entry.damping;
  if (entry.damping_ratios.values.size() != 0) {
    spec.damping = multibody::ModalDamping::per_mode(per_mode(entry.damping_ratios, nm));
  }
  spec.initial_modal_coordinates = per_mode(entry.modal_coordinates, nm);
  spec.initial_modal_velocities = per_mode(entry.modal_velocities, nm);
  spec.stiffening = entry.stiffening;
  // Node-force cases only where they are used.
  const bool full = spec.stiffening == multibody::GeometricStiffening::kFull;
  add_geometric_stiffness(component, full ? marker_nodes(mechanism, entry.name) : std::vector<int>{}, spec);
  // Modal stresses of every element, once per mode set.
  if (spec.stress) spec.modal_stress = modal::modal_stress(component.model, spec.modes.shapes);
  builder.add_flexible_body(spec, entry.where);
}

// A body with `formulation: nonlinear`: its FE beams co-rotational, one rigid body per node
// (multibody/model_builder.h). What the co-rotational structure cannot treat (springs, rigid
// elements, general masses) and held FE DOFs fail at the formulation key.
void add_nonlinear_body(const FlexibleBodyEntry& entry, const std::vector<FlexibleBodyCase>& components,
                        ModelBuilder& builder) {
  const FlexibleBodyCase& component = component_named(components, entry.component);
  multibody::NonlinearBodySpec spec;
  spec.name = entry.name;
  try {
    if (!component.model.fixed_dofs.empty()) {
      throw InputError(fmt::format("expected no fixed DOFs in '{}' ({} given): a nonlinear body is held by "
                                   "its joints only", component.name, component.model.fixed_dofs.size()));
    }
    spec.structure =
        std::make_shared<const nonlinear_beam::BeamStructure>(nonlinear_beam::build_beam_structure(component.model));
    spec.inertia = nonlinear_beam::lumped_inertia(component.model);
  } catch (const InputError& e) {
    throw InputError("formulation: nonlinear: " + e.message(), entry.formulation_where);
  }
  spec.initial_pose = entry.initial_pose;
  spec.initial_velocity_W = entry.initial_velocity_W;
  spec.initial_angular_velocity_B = entry.initial_angular_velocity_B;
  spec.mesh = drawing_mesh(component.model);
  spec.deflection_probe = entry.deflection_probe;
  // Output: the beams' stresses, with their sections for the extreme fibres.
  spec.stress = entry.stress;
  if (spec.stress) spec.beam_sections = multibody::beam_sections_of(component.model);
  // `damping: {rayleigh: [α, β]}`; absent or 0: undamped (the reader refuses ratios).
  if (entry.damping.kind == multibody::ModalDamping::Kind::kRayleigh) {
    spec.mass_damping = entry.damping.alpha;
    spec.stiffness_damping = entry.damping.beta;
  }
  builder.add_nonlinear_body(spec, entry.where);
}

void add_marker(const MarkerEntry& marker, ModelBuilder& builder) {
  switch (marker.frame) {
    case MarkerEntry::Frame::kBody:
      builder.add_marker(marker.name, marker.body, marker.position, marker.rotation, marker.where);
      break;
    case MarkerEntry::Frame::kGround:
      builder.add_marker_at(marker.name, marker.body, marker.position, marker.rotation, marker.where);
      break;
    case MarkerEntry::Frame::kNode:
      builder.add_node_marker(marker.name, marker.body, marker.node, marker.rotation, marker.where);
      break;
  }
}

void add_force(const ForceEntry& force, ModelBuilder& builder) {
  std::visit(
      [&](const auto& spec) {
        using Spec = std::decay_t<decltype(spec)>;
        if constexpr (std::is_same_v<Spec, multibody::RsdaSpec>) builder.add_rsda(spec, force.where);
        else if constexpr (std::is_same_v<Spec, multibody::TsdaSpec>) builder.add_tsda(spec, force.where);
        else if constexpr (std::is_same_v<Spec, multibody::PointLoadSpec>) builder.add_point_load(spec, force.where);
        else builder.add_hinge_limit(spec, force.where);
      },
      force.spec);
}

// Every entry in the order of the case file's sections (each refers to the ones before).
void add_mechanism(const MechanismCase& mechanism, const std::vector<FlexibleBodyCase>& components,
                   const CaseReduction* reduction, ModelBuilder& builder) {
  if (mechanism.gravity_W) builder.set_gravity(*mechanism.gravity_W);
  for (const BodyEntry& body : mechanism.bodies) {
    if (const auto* rigid = std::get_if<RigidBodyEntry>(&body)) {
      builder.add_rigid_body(rigid->spec, rigid->where);
    } else if (const auto& flexible = std::get<FlexibleBodyEntry>(body); flexible.nonlinear) {
      add_nonlinear_body(flexible, components, builder);
    } else {
      add_flexible_body(flexible, components, mechanism, reduction, builder);
    }
  }
  for (const MarkerEntry& marker : mechanism.markers) add_marker(marker, builder);
  for (const JointEntry& joint : mechanism.joints) {
    for (const MarkerEntry& marker : joint.markers) add_marker(marker, builder);
    builder.add_joint(joint.name, joint.type, joint.marker_i, joint.marker_j, joint.where);
    if (joint.release) builder.release_joint(joint.name, *joint.release, joint.release_where);
  }
  for (const DriverEntry& driver : mechanism.drivers) {
    builder.add_driver(driver.name, driver.joint, driver.coordinate, driver.motion, driver.where);
  }
  for (const ForceEntry& force : mechanism.forces) add_force(force, builder);
  // Releases at an event name a latch or stop: after the forces.
  for (const JointEntry& joint : mechanism.joints) {
    if (!joint.release_after.empty()) {
      builder.release_joint_after(joint.name, joint.release_after, joint.release_delay, joint.release_where);
    }
    if (joint.release_duration) {
      builder.set_release_duration(joint.name, *joint.release_duration, joint.release_duration_where);
    }
  }
  for (const AccelerationProbeEntry& probe : mechanism.acceleration_probes) {
    builder.add_acceleration_probe(probe.spec, probe.where);
  }
}

const std::string& body_name(const BodyEntry& body) {
  if (const auto* rigid = std::get_if<RigidBodyEntry>(&body)) return rigid->spec.name;
  return std::get<FlexibleBodyEntry>(body).name;
}

}  // namespace

Mechanism build_mechanism(const Case& input, const CaseReduction& reduction) {
  LIMBER_DEMAND(input.mechanism.has_value());
  const MechanismCase& mechanism = *input.mechanism;
  ModelBuilder builder;
  add_mechanism(mechanism, input.flexible_bodies, &reduction, builder);
  Mechanism built{builder.build(), mechanism.flexible_components, mechanism.assembly, mechanism.run};
  // Held bodies by model index: a nonlinear body's node bodies shift the bodies after it.
  for (multibody::HeldCoordinate& held : built.assembly.held) {
    held.body = built.model.find_body(body_name(mechanism.bodies[static_cast<std::size_t>(held.body - 1)]));
  }
  return built;
}

void check_mechanism(const MechanismCase& mechanism, const std::vector<FlexibleBodyCase>& components) {
  ModelBuilder builder;
  add_mechanism(mechanism, components, nullptr, builder);
}

}  // namespace limber::io
