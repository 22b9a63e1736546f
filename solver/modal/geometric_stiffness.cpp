#include "modal/geometric_stiffness.h"

#include <Eigen/Geometry>

#include "core/error.h"
#include "fe/beam_geometric_stiffness.h"
#include "fe/shell_geometric_stiffness.h"
#include "modal/constrained_matrices.h"
#include "modal/rigid_body_modes.h"
#include "modal/static_modes.h"

namespace limber::modal {

namespace {

constexpr int kInertiaCases = 12;  // 6 centrifugal, 3 angular, 3 translational accelerations

// S_c of the centrifugal field a = S x, in the order xx yy zz xy yz zx.
Eigen::Matrix3d centrifugal_field(int c) {
  Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
  if (c < 3) {
    s = -Eigen::Matrix3d::Identity();
    s(c, c) += 1.0;
    return s;
  }
  const int i = c - 3, j = (c - 2) % 3;
  s(i, j) = s(j, i) = 1.0;
  return s;
}

}  // namespace

Eigen::MatrixXd geometric_stiffness_load_cases(const fe::FeModel& model, const fe::SparseMatrix& mass,
                                               const std::vector<int>& load_nodes) {
  const int n = model.dof_count();
  const Eigen::Index cases = kInertiaCases + 6 * static_cast<Eigen::Index>(load_nodes.size());
  // Rigid acceleration fields a (translational rows; rotational rows of the angular case).
  Eigen::MatrixXd fields = Eigen::MatrixXd::Zero(n, kInertiaCases);
  for (int p = 0; p < model.node_count(); ++p) {
    const Eigen::Vector3d& x = model.node_positions[static_cast<std::size_t>(p)];
    for (int c = 0; c < 6; ++c) fields.block<3, 1>(6 * p, c) = centrifugal_field(c) * x;
    for (int k = 0; k < 3; ++k) {
      fields.block<3, 1>(6 * p, 6 + k) = Eigen::Vector3d::Unit(k).cross(x);
      fields(6 * p + 3 + k, 6 + k) = 1.0;
      fields(6 * p + k, 9 + k) = 1.0;
    }
  }
  Eigen::MatrixXd loads = Eigen::MatrixXd::Zero(n, cases);
  // d'Alembert forces of the fields, then unit node forces and moments.
  loads.leftCols(kInertiaCases) = -(mass * fields);
  for (std::size_t j = 0; j < load_nodes.size(); ++j) {
    LIMBER_DEMAND(load_nodes[j] >= 0 && load_nodes[j] < model.node_count());
    for (int k = 0; k < 6; ++k) loads(6 * load_nodes[j] + k, kInertiaCases + 6 * static_cast<Eigen::Index>(j) + k) = 1.0;
  }
  return loads;
}

Eigen::MatrixXd projected_geometric_stiffness(const fe::FeModel& model, const Eigen::MatrixXd& shapes,
                                              const Eigen::VectorXd& u) {
  const Eigen::Index nm = shapes.cols();
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(nm, nm);
  Eigen::MatrixXd phi_e(12, nm);
  fe::Vector12d u_e;
  for (const fe::BeamElement& beam : model.beams) {
    const fe::BeamProperty& property = model.beam_properties[static_cast<std::size_t>(beam.property)];
    const Eigen::Vector3d& p0 = model.node_positions[static_cast<std::size_t>(beam.nodes[0])];
    const Eigen::Vector3d& p1 = model.node_positions[static_cast<std::size_t>(beam.nodes[1])];
    // The element's DOFs of the displacement and of the modes.
    for (int end = 0; end < 2; ++end) {
      u_e.segment<6>(6 * end) = u.segment<6>(6 * beam.nodes[end]);
      phi_e.middleRows(6 * end, 6) = shapes.middleRows(6 * beam.nodes[end], 6);
    }
    const double axial_force = fe::beam_axial_force(p0, p1, property, u_e);
    k += phi_e.transpose() * fe::beam_geometric_stiffness(p0, p1, beam.orientation, property, axial_force) * phi_e;
  }
  // Shells: membrane forces on the transverse deflection.
  Eigen::MatrixXd phi_s(24, nm);
  fe::Vector24d u_s;
  for (const fe::ShellElement& shell : model.shells) {
    std::array<Eigen::Vector3d, 4> corners;
    for (int c = 0; c < 4; ++c) {
      corners[c] = model.node_positions[static_cast<std::size_t>(shell.nodes[c])];
      u_s.segment<6>(6 * c) = u.segment<6>(6 * shell.nodes[c]);
      phi_s.middleRows(6 * c, 6) = shapes.middleRows(6 * shell.nodes[c], 6);
    }
    const fe::ShellProperty& property = model.shell_properties[static_cast<std::size_t>(shell.property)];
    k += phi_s.transpose() * fe::shell_geometric_stiffness(corners, property, u_s) * phi_s;
  }
  // Symmetric by construction; remove the rounding asymmetry of the products.
  return 0.5 * (k + k.transpose());
}

ModalGeometricStiffnessResult compute_modal_geometric_stiffness(const fe::FeModel& model,
                                                                const fe::StructuralMatrices& matrices,
                                                                const Eigen::MatrixXd& shapes,
                                                                const std::vector<int>& load_nodes) {
  LIMBER_DEMAND(shapes.rows() == model.dof_count());
  ModalGeometricStiffnessResult result;
  ModalGeometricStiffness& out = result.stiffness;
  out.load_nodes = load_nodes;
  // Static stress states of the unit load cases (inertia relief for free parts).
  const Eigen::MatrixXd loads = geometric_stiffness_load_cases(model, matrices.mass, load_nodes);
  StaticModes responses;
  if (model.multipoint_constraints.empty()) {
    responses = compute_static_responses(matrices.stiffness, matrices.mass, rigid_body_modes(model),
                                         fe::free_dofs(model), loads, "geometric stiffness load cases");
  } else {
    // Rigid elements eliminated (constrained_matrices.h); responses as full displacements.
    const ConstrainedMatrices c = constrain(model, matrices, rigid_body_modes(model));
    responses = compute_static_responses(c.stiffness, c.mass, c.psi, c.free_dofs, reduce_loads(c, loads),
                                         "geometric stiffness load cases");
    if (responses.status == ModalStatus::kOk) responses.shapes = expand(c, responses.shapes);
  }
  if (responses.status != ModalStatus::kOk) {
    result.status = responses.status;
    result.message = responses.message;
    return result;
  }
  // Project each case's element geometric stiffness on the modes.
  const auto project = [&](Eigen::Index c) { return projected_geometric_stiffness(model, shapes, responses.shapes.col(c)); };
  for (int c = 0; c < 6; ++c) out.centrifugal[c] = project(c);
  for (int k = 0; k < 3; ++k) {
    out.angular_acceleration[k] = project(6 + k);
    out.translational_acceleration[k] = project(9 + k);
  }
  out.node_forces.resize(load_nodes.size());
  out.node_moments.resize(load_nodes.size());
  for (std::size_t j = 0; j < load_nodes.size(); ++j) {
    const Eigen::Index first = kInertiaCases + 6 * static_cast<Eigen::Index>(j);
    for (int k = 0; k < 3; ++k) {
      out.node_forces[j][k] = project(first + k);
      out.node_moments[j][k] = project(first + 3 + k);
    }
  }
  return result;
}

}  // namespace limber::modal
