// ModelBuilder members for flexible bodies (model_builder.h): checks of the mode set and
// the body's node markers.
#include <cmath>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "multibody/flexible_dynamics.h"
#include "multibody/model_builder.h"
#include "multibody/rotation.h"

namespace limber::multibody {

namespace {

// Throws unless every array of the mode set has the size nm modes over `nodes` nodes imply.
void check_mode_set_sizes(const std::string& name, const modal::ModeSet& set, int nodes,
                          const SourceLocation& where) {
  const Eigen::Index nm = set.shapes.cols();
  const modal::ModalInvariants& inv = set.invariants;
  const auto fail = [&](const std::string& what, const std::string& expected, const std::string& got) {
    throw InputError(fmt::format("flexible body \"{}\" {}: expected {}, got {}", name, what, expected, got), where);
  };
  if (nm < 1) fail("modes", "at least one mode", "none");
  if (set.shapes.rows() != 6 * nodes) {
    fail("mode shapes", fmt::format("6 x {} nodes = {} rows", nodes, 6 * nodes), std::to_string(set.shapes.rows()));
  }
  if (set.modal_stiffness.size() != nm || (set.modal_stiffness.array() < 0.0).any()) {
    fail("modal stiffness", fmt::format("{} values ≥ 0", nm), fmt::format("{} values", set.modal_stiffness.size()));
  }
  const bool couplings_ok = inv.translation_coupling.rows() == 3 && inv.translation_coupling.cols() == nm &&
                            inv.rotation_coupling.rows() == 3 && inv.rotation_coupling.cols() == nm;
  const bool expansions_ok = static_cast<Eigen::Index>(inv.inertia_first_order.size()) == nm &&
                             static_cast<Eigen::Index>(inv.inertia_second_order.size()) == nm * nm &&
                             static_cast<Eigen::Index>(inv.rotation_coupling_first_order.size()) == nm;
  if (!couplings_ok || !expansions_ok) {
    fail("invariants", fmt::format("couplings 3 x {} and {} / {} / {} first/second-order terms", nm, nm, nm * nm, nm),
         "other sizes (invariants of another mode set?)");
  }
  for (const Eigen::MatrixXd& B : inv.rotation_coupling_first_order) {
    if (B.rows() != 3 || B.cols() != nm) fail("rotation coupling first order", fmt::format("3 x {}", nm), "other sizes");
  }
  if (!(inv.mass > 0.0)) fail("mass", "> 0 kg", fmt::format("{}", inv.mass));
}

// Throws unless the geometric-stiffness matrices are nm x nm, one set per load node in range.
void check_geometric_stiffness(const std::string& name, const modal::ModalGeometricStiffness& g, Eigen::Index nm,
                               int nodes, const SourceLocation& where) {
  const auto square = [&](const Eigen::MatrixXd& k) { return k.rows() == nm && k.cols() == nm; };
  bool ok = g.node_forces.size() == g.load_nodes.size() && g.node_moments.size() == g.load_nodes.size();
  for (const Eigen::MatrixXd& k : g.centrifugal) ok = ok && square(k);
  for (int i = 0; i < 3; ++i) ok = ok && square(g.angular_acceleration[i]) && square(g.translational_acceleration[i]);
  for (const auto* cases : {&g.node_forces, &g.node_moments}) {
    for (const auto& node : *cases) {
      for (const Eigen::MatrixXd& k : node) ok = ok && square(k);
    }
  }
  for (int node : g.load_nodes) ok = ok && node >= 0 && node < nodes;
  if (!ok) {
    throw InputError(fmt::format("flexible body \"{}\" geometric stiffness: expected {} x {} matrices per load case "
                                 "and load nodes within the {} nodes, got other sizes", name, nm, nm, nodes), where);
  }
}

// Throws unless the damping values are ≥ 0 and there are 1 or nm ratios.
void check_damping(const std::string& name, const ModalDamping& damping, Eigen::Index nm, const SourceLocation& where) {
  if (damping.kind == ModalDamping::Kind::kRayleigh) {
    if (damping.alpha >= 0.0 && damping.beta >= 0.0) return;
    throw InputError(fmt::format("flexible body \"{}\" Rayleigh damping: expected α, β ≥ 0, got {}, {}", name,
                                 damping.alpha, damping.beta), where);
  }
  const Eigen::Index n = damping.ratios.size();
  if (n != 1 && n != nm) {
    throw InputError(fmt::format("flexible body \"{}\" damping ratios: expected 1 or {} values, got {} values",
                                 name, nm, n), where);
  }
  // Name the first bad ratio: a long list with one sign slip is otherwise a hunt.
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!(damping.ratios(i) >= 0.0) || !std::isfinite(damping.ratios(i))) {
      throw InputError(fmt::format("flexible body \"{}\" damping ratio of mode {}: expected a finite "
                                   "value ≥ 0, got {}", name, i + 1, damping.ratios(i)), where);
    }
  }
}

// Initial η or η̇: empty means zero.
Eigen::VectorXd initial_modal_values(const std::string& name, const char* what, const Eigen::VectorXd& values,
                                     Eigen::Index nm, const SourceLocation& where) {
  if (values.size() == 0) return Eigen::VectorXd::Zero(nm);
  if (values.size() != nm) {
    throw InputError(fmt::format("flexible body \"{}\" {}: expected {} values, got {}", name, what, nm,
                                 values.size()), where);
  }
  return values;
}

}  // namespace

std::shared_ptr<FlexibleBody> ModelBuilder::flexible_outline(const FlexibleBodySpec& spec,
                                                            const SourceLocation& where) const {
  check_new_body(spec.name, spec.initial_pose, where);
  const int nodes = static_cast<int>(spec.node_positions_B.size());
  auto flexible = std::make_shared<FlexibleBody>();
  flexible->node_positions.resize(3, nodes);
  for (int p = 0; p < nodes; ++p) flexible->node_positions.col(p) = spec.node_positions_B[p];
  flexible->size = nodes > 0 ? (flexible->node_positions.rowwise().maxCoeff() -
                                flexible->node_positions.rowwise().minCoeff()).norm() : 0.0;
  flexible->mesh = spec.mesh;
  if (const auto& probe = spec.deflection_probe) {
    for (int node : {probe->node, probe->chord_start, probe->chord_end}) {
      if (node < 0 || node >= nodes) {
        throw InputError(fmt::format("flexible body \"{}\" deflection probe: expected node indices in [0, {}), got {}",
                                     spec.name, nodes, node), where);
      }
    }
    if (probe->chord_start == probe->chord_end) {
      throw InputError(fmt::format("flexible body \"{}\" deflection probe: expected two different chord nodes",
                                   spec.name), where);
    }
  }
  flexible->deflection_probe = spec.deflection_probe;
  if (const auto& stress = spec.stress) {
    const int elements = static_cast<int>(spec.mesh.lines.size() + spec.mesh.quads.size());
    for (int e : stress->elements) {
      if (e < 0 || e >= elements) {
        throw InputError(fmt::format("flexible body \"{}\" stress output: expected element numbers in [1, {}], "
                                     "got {}", spec.name, elements, e + 1), where);
      }
    }
    if (stress->every < 1) {
      throw InputError(fmt::format("flexible body \"{}\" stress output: expected every ≥ 1, got {}", spec.name,
                                   stress->every), where);
    }
  }
  flexible->stress_output = spec.stress;
  return flexible;
}

int ModelBuilder::add_flexible_body_outline(const FlexibleBodySpec& spec, const SourceLocation& where) {
  // The frame alone: no modes, so no modal coordinates yet.
  Body body;
  body.name = spec.name;
  body.kind = BodyKind::kFlexible;
  body.flexible = flexible_outline(spec, where);
  body.initial_pose = spec.initial_pose;
  body.initial_pose.orientation.normalize();
  body.shapes = spec.shapes;
  body.nq = 7;
  body.nv = 6;
  ++outlines_;
  return append_body(std::move(body));
}

int ModelBuilder::add_flexible_body(const FlexibleBodySpec& spec, const SourceLocation& where) {
  // Name, pose, nodes, probe, and a mode set whose pieces fit together.
  std::shared_ptr<FlexibleBody> flexible = flexible_outline(spec, where);
  const int nodes = static_cast<int>(spec.node_positions_B.size());
  check_mode_set_sizes(spec.name, spec.modes, nodes, where);
  const Eigen::Index nm = spec.modes.shapes.cols();
  check_damping(spec.name, spec.damping, nm, where);
  if (spec.stiffening != GeometricStiffening::kOff) check_geometric_stiffness(spec.name, spec.geometric, nm, nodes, where);
  // The body's constant data, shared by every copy of the model.
  flexible->shapes = spec.modes.shapes;
  flexible->stiffness = spec.modes.modal_stiffness;
  flexible->damping = modal_damping_coefficients(spec.damping, flexible->stiffness);
  flexible->invariants = spec.modes.invariants;
  flexible->component = spec.component;
  flexible->mode_info = spec.modes.modes;
  flexible->stiffening = spec.stiffening;
  if (spec.stiffening != GeometricStiffening::kOff) flexible->geometric = spec.geometric;
  if (spec.stress) {
    // The modal stresses must be those of this mesh and mode set.
    const modal::ModalStress& stress = spec.modal_stress;
    const bool fits = stress.beam_count == static_cast<int>(spec.mesh.lines.size()) &&
                      stress.shell_count == static_cast<int>(spec.mesh.quads.size()) &&
                      stress.beam_modal.cols() == nm && stress.shell_modal.cols() == nm;
    if (!fits) {
      throw InputError(fmt::format("flexible body \"{}\" modal stresses: expected {} beams and {} shells over {} "
                                   "modes, got {}, {} over {}", spec.name, spec.mesh.lines.size(),
                                   spec.mesh.quads.size(), nm, stress.beam_count, stress.shell_count,
                                   stress.beam_modal.cols()), where);
    }
    flexible->modal_stress = stress;
  }
  flexible->initial_modal_coordinates =
      initial_modal_values(spec.name, "initial modal coordinates", spec.initial_modal_coordinates, nm, where);
  flexible->initial_modal_velocities =
      initial_modal_values(spec.name, "initial modal velocities", spec.initial_modal_velocities, nm, where);
  // Undeformed rigid properties, for information: m, c, J_c = J_o + m c̃ c̃.
  const modal::ModalInvariants& inv = flexible->invariants;
  Body body;
  body.name = spec.name;
  body.kind = BodyKind::kFlexible;
  body.mass = inv.mass;
  body.com_B = inv.first_moment / inv.mass;
  const Eigen::Matrix3d c_x = skew(body.com_B);
  body.inertia_com_B = inv.inertia + inv.mass * c_x * c_x;
  body.initial_pose = spec.initial_pose;
  body.initial_pose.orientation.normalize();
  body.initial_velocity_W = spec.initial_velocity_W;
  body.initial_angular_velocity_B = spec.initial_angular_velocity_B;
  body.shapes = spec.shapes;
  body.flexible = flexible;
  body.nq = 7 + static_cast<int>(nm);
  body.nv = 6 + static_cast<int>(nm);
  // Frame and modes must be independent: the undeformed mass block, scaled to unit
  // diagonal, must be positive definite (a mode holding rigid motion makes it singular).
  Eigen::VectorXd q0 = Eigen::VectorXd::Zero(body.nq);
  q0(3) = 1.0;
  const Eigen::MatrixXd M = flexible_mass_block(body, q0);
  const Eigen::VectorXd scale = M.diagonal().cwiseSqrt().cwiseInverse();
  const double lowest =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(scale.asDiagonal() * M * scale.asDiagonal()).eigenvalues()(0);
  if (!(lowest > 1e-8)) {
    throw InputError(fmt::format("flexible body \"{}\" modes: expected modes independent of the frame's rigid "
                                 "motion (scaled mass matrix eigenvalue > 1e-8), got {:.3g}: a mode holds "
                                 "rigid-body motion", spec.name, lowest), where);
  }
  return append_body(std::move(body));
}

int ModelBuilder::add_node_marker(const std::string& name, const std::string& body, int node,
                                  const Eigen::Matrix3d& R_BM, const SourceLocation& where) {
  if (const int k = model_.find_nonlinear_body(body); k >= 0) {
    const NonlinearBody& nonlinear = model_.nonlinear_bodies[static_cast<std::size_t>(k)];
    const int nodes = static_cast<int>(nonlinear.node_bodies.size());
    if (node < 0 || node >= nodes) {
      throw InputError(fmt::format("node marker \"{}\": expected a node index in [0, {}), got {}", name,
                                   nodes, node), where);
    }
    // At the node body's origin, axes as given in the component axes (the node frame at t = 0).
    const std::string& node_body = model_.bodies[static_cast<std::size_t>(nonlinear.node_bodies[node])].name;
    const int b = check_new_marker(name, node_body, R_BM, where);
    model_.markers.push_back(Marker{name, b, Eigen::Vector3d::Zero(), R_BM, -1});
    return static_cast<int>(model_.markers.size()) - 1;
  }
  const int b = check_new_marker(name, body, R_BM, where);
  const Body& owner = model_.bodies[b];
  if (owner.kind != BodyKind::kFlexible) {
    throw InputError(fmt::format("node marker \"{}\": expected a flexible body, got {} body \"{}\"", name,
                                 owner.kind == BodyKind::kGround ? "the ground" : "rigid", body), where);
  }
  if (node < 0 || node >= owner.flexible->node_count()) {
    throw InputError(fmt::format("node marker \"{}\": expected a node index in [0, {}), got {}", name,
                                 owner.flexible->node_count(), node), where);
  }
  model_.markers.push_back(Marker{name, b, owner.flexible->node_positions.col(node), R_BM, node});
  return static_cast<int>(model_.markers.size()) - 1;
}

}  // namespace limber::multibody
