// ModelBuilder's nonlinear bodies (model_builder.h, model.h NonlinearBody).
#include <fmt/format.h>

#include "core/names.h"
#include "multibody/model_builder.h"
#include "multibody/nonlinear_body.h"
#include "multibody/rotation.h"

namespace limber::multibody {

namespace {

// The recorded elements are the structure's beams, and every beam has a section.
void check_nonlinear_stress_output(const NonlinearBodySpec& spec, const StressOutput& stress,
                                   const SourceLocation& where) {
  const int elements = static_cast<int>(spec.structure->elements.size());
  for (const int e : stress.elements) {
    if (e < 0 || e >= elements) {
      throw InputError(fmt::format("body \"{}\" stress output: expected element numbers in [1, {}], got {}",
                                   spec.name, elements, e + 1), where);
    }
  }
  if (stress.every < 1) {
    throw InputError(fmt::format("body \"{}\" stress output: expected every ≥ 1, got {}", spec.name, stress.every),
                     where);
  }
  LIMBER_DEMAND(static_cast<int>(spec.beam_sections.size()) == elements);
}

}  // namespace

int ModelBuilder::add_nonlinear_body(const NonlinearBodySpec& spec, const SourceLocation& where) {
  check_new_body(spec.name, spec.initial_pose, where);
  const nonlinear_beam::BeamStructure& structure = *spec.structure;
  const int nodes = structure.node_count();
  LIMBER_DEMAND(static_cast<int>(spec.inertia.mass.size()) == nodes);
  LIMBER_DEMAND(spec.mesh.node_ids.empty() || static_cast<int>(spec.mesh.node_ids.size()) == nodes);
  if (const auto& probe = spec.deflection_probe) {
    for (const int node : {probe->node, probe->chord_start, probe->chord_end}) {
      if (node < 0 || node >= nodes) {
        throw InputError(fmt::format("body \"{}\" deflection: expected node indices in [0, {}), got {}",
                                     spec.name, nodes, node), where);
      }
    }
  }
  if (!(spec.mass_damping >= 0.0 && spec.stiffness_damping >= 0.0)) {
    throw InputError(fmt::format("body \"{}\" damping: expected Rayleigh α, β ≥ 0, got {:g}, {:g}", spec.name,
                                 spec.mass_damping, spec.stiffness_damping), where);
  }
  if (const auto& stress = spec.stress) check_nonlinear_stress_output(spec, *stress, where);
  NonlinearBody body;
  body.name = spec.name;
  body.stress = spec.stress;
  if (spec.stress) body.beam_sections = spec.beam_sections;
  body.mass_damping = spec.mass_damping;
  body.stiffness_damping = spec.stiffness_damping;
  body.structure = spec.structure;
  body.R_WC = rotation_matrix(spec.initial_pose.orientation.normalized());
  body.p_WC = spec.initial_pose.position;
  body.deflection_probe = spec.deflection_probe;
  body.mesh = spec.mesh;
  // Node bodies: at the nodes, along the component axes, moving rigidly with the frame.
  const Eigen::Vector3d w_W = body.R_WC * spec.initial_angular_velocity_B;
  for (int k = 0; k < nodes; ++k) {
    const int id = spec.mesh.node_ids.empty() ? k + 1 : spec.mesh.node_ids[static_cast<std::size_t>(k)];
    RigidBodySpec node;
    node.name = fmt::format("{}.node{}", spec.name, id);
    node.mass = spec.inertia.mass[static_cast<std::size_t>(k)];
    node.inertia_com_B = spec.inertia.inertia[static_cast<std::size_t>(k)];
    const Eigen::Vector3d arm_W = body.R_WC * structure.reference_positions[static_cast<std::size_t>(k)];
    node.initial_pose = Pose{body.p_WC + arm_W, spec.initial_pose.orientation.normalized()};
    node.initial_velocity_W = spec.initial_velocity_W + w_W.cross(arm_W);
    node.initial_angular_velocity_B = spec.initial_angular_velocity_B;
    body.node_bodies.push_back(add_rigid_body(node, where));
  }
  model_.nonlinear_bodies.push_back(std::move(body));
  return static_cast<int>(model_.nonlinear_bodies.size()) - 1;
}

}  // namespace limber::multibody
