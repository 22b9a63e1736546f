#include "nonlinear_beam/beam_structure.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "core/error.h"
#include "nonlinear_beam/rotation.h"

namespace limber::nonlinear_beam {

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// Adds a 12x12 element matrix on nodes (a, b) to a triplet list.
void add_element_matrix(const std::array<int, 2>& nodes, const Matrix12d& matrix,
                        Triplets& triplets) {
  for (int bi = 0; bi < 2; ++bi) {
    for (int bj = 0; bj < 2; ++bj) {
      for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) {
          triplets.emplace_back(6 * nodes[bi] + i, 6 * nodes[bj] + j, matrix(6 * bi + i, 6 * bj + j));
        }
      }
    }
  }
}

ElementResponse response_of(const CorotationalBeam& element, const BeamState& state) {
  const int a = element.nodes[0];
  const int b = element.nodes[1];
  return corotational_beam_response(element, state.positions[a], state.positions[b],
                                    state.rotations[a].toRotationMatrix(),
                                    state.rotations[b].toRotationMatrix());
}

}  // namespace

BeamStructure build_beam_structure(const fe::FeModel& model) {
  // Only beams are treated nonlinearly in this step.
  const auto unsupported = [](const char* what, std::size_t count) {
    if (count > 0) {
      throw InputError(fmt::format(
          "nonlinear beams: expected a model of beams only, got {} {}", count, what));
    }
  };
  unsupported("shell quads", model.shells.size());
  unsupported("shell triangles", model.triangles.size());
  unsupported("DOF stiffness matrices (springs, bushings, rods)", model.dof_stiffnesses.size());
  unsupported("multipoint constraints", model.multipoint_constraints.size());
  if (model.beams.empty()) {
    throw InputError("nonlinear beams: expected at least one beam element, got none");
  }

  BeamStructure out;
  out.reference_positions = model.node_positions;
  out.elements.reserve(model.beams.size());
  for (const fe::BeamElement& beam : model.beams) out.elements.push_back(make_corotational_beam(model, beam));

  // Free DOFs: all but the fixed ones.
  std::vector<bool> fixed(model.dof_count(), false);
  for (const fe::FixedDof& f : model.fixed_dofs) fixed[fe::FeModel::dof_index(f.node, f.dof)] = true;
  for (int i = 0; i < model.dof_count(); ++i) {
    if (!fixed[i]) out.free_dofs.push_back(i);
  }

  // Size scale of the structure.
  Eigen::Vector3d lo = model.node_positions.front();
  Eigen::Vector3d hi = lo;
  for (const Eigen::Vector3d& p : model.node_positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  out.size = (hi - lo).norm();

  // Round-off level of the internal force.
  double k_max = 0.0;
  for (const CorotationalBeam& e : out.elements) k_max = std::max(k_max, e.local_stiffness.cwiseAbs().maxCoeff());
  const double x_max = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
  out.force_roundoff = 100.0 * std::numeric_limits<double>::epsilon() * k_max * (out.size + x_max);
  return out;
}

BeamState reference_state(const BeamStructure& structure) {
  BeamState state;
  state.positions = structure.reference_positions;
  state.rotations.assign(structure.node_count(), Eigen::Quaterniond::Identity());
  return state;
}

void apply_increment(BeamState& state, const Eigen::VectorXd& delta) {
  LIMBER_DEMAND(delta.size() == 6 * static_cast<Eigen::Index>(state.positions.size()));
  for (std::size_t i = 0; i < state.positions.size(); ++i) {
    state.positions[i] += delta.segment<3>(6 * i);
    // Multiplicative update on the group, spatial spin on the left.
    state.rotations[i] = (exp_quaternion(delta.segment<3>(6 * i + 3)) * state.rotations[i]).normalized();
  }
}

Eigen::Matrix<double, 6, 1> node_displacement(const BeamStructure& structure,
                                              const BeamState& state, int node) {
  Eigen::Matrix<double, 6, 1> out;
  out.head<3>() = state.positions[node] - structure.reference_positions[node];
  out.tail<3>() = log_so3(state.rotations[node].toRotationMatrix());
  return out;
}

double strain_energy(const BeamStructure& structure, const BeamState& state) {
  double energy = 0.0;
  for (const CorotationalBeam& element : structure.elements) {
    const int a = element.nodes[0];
    const int b = element.nodes[1];
    energy += corotational_beam_energy(element, state.positions[a], state.positions[b],
                                       state.rotations[a].toRotationMatrix(),
                                       state.rotations[b].toRotationMatrix());
  }
  return energy;
}

Eigen::VectorXd internal_force(const BeamStructure& structure, const BeamState& state) {
  Eigen::VectorXd force = Eigen::VectorXd::Zero(structure.dof_count());
  for (const CorotationalBeam& element : structure.elements) {
    const ElementResponse r = response_of(element, state);
    force.segment<6>(6 * element.nodes[0]) += r.force.head<6>();
    force.segment<6>(6 * element.nodes[1]) += r.force.tail<6>();
  }
  return force;
}

BeamWorkspace make_workspace(const BeamStructure& structure) {
  const int n = structure.dof_count();
  BeamWorkspace workspace;
  workspace.result.force = Eigen::VectorXd::Zero(n);

  // Pattern: the four 6x6 node blocks of every element (duplicates summed away).
  Triplets triplets;
  triplets.reserve(144 * structure.elements.size());
  for (const CorotationalBeam& element : structure.elements) {
    add_element_matrix(element.nodes, Matrix12d::Zero(), triplets);
  }
  SparseMatrix& k = workspace.result.tangent;
  k.resize(n, n);
  k.setFromTriplets(triplets.begin(), triplets.end());
  k.makeCompressed();

  // Slot of each element entry in the value array (sorted row indices per column).
  workspace.slots.resize(structure.elements.size());
  for (std::size_t e = 0; e < structure.elements.size(); ++e) {
    const std::array<int, 2>& nodes = structure.elements[e].nodes;
    for (int i = 0; i < 12; ++i) {
      for (int j = 0; j < 12; ++j) {
        const int row = 6 * nodes[i / 6] + i % 6;
        const int col = 6 * nodes[j / 6] + j % 6;
        const int* begin = k.innerIndexPtr() + k.outerIndexPtr()[col];
        const int* end = k.innerIndexPtr() + k.outerIndexPtr()[col + 1];
        const int* found = std::lower_bound(begin, end, row);
        LIMBER_DEMAND(found != end && *found == row);
        workspace.slots[e][12 * i + j] = static_cast<int>(found - k.innerIndexPtr());
      }
    }
  }
  return workspace;
}

void evaluate_force_and_tangent(const BeamStructure& structure, const BeamState& state,
                                BeamWorkspace& workspace) {
  LIMBER_DEMAND(workspace.slots.size() == structure.elements.size());
  Eigen::VectorXd& force = workspace.result.force;
  SparseMatrix& k = workspace.result.tangent;
  force.setZero();
  std::fill(k.valuePtr(), k.valuePtr() + k.nonZeros(), 0.0);
  double* values = k.valuePtr();
  for (std::size_t e = 0; e < structure.elements.size(); ++e) {
    const CorotationalBeam& element = structure.elements[e];
    const ElementResponse r = response_of(element, state);
    force.segment<6>(6 * element.nodes[0]) += r.force.head<6>();
    force.segment<6>(6 * element.nodes[1]) += r.force.tail<6>();
    // Scatter the 12x12 tangent into its slots.
    const std::array<int, 144>& slots = workspace.slots[e];
    for (int i = 0; i < 12; ++i) {
      for (int j = 0; j < 12; ++j) values[slots[12 * i + j]] += r.tangent(i, j);
    }
  }
}

ForceAndTangent internal_force_and_tangent(const BeamStructure& structure,
                                           const BeamState& state) {
  BeamWorkspace workspace = make_workspace(structure);
  evaluate_force_and_tangent(structure, state, workspace);
  return std::move(workspace.result);
}

SparseMatrix corotational_mass(const BeamStructure& structure, const BeamState& state) {
  Triplets triplets;
  triplets.reserve(144 * structure.elements.size());
  for (const CorotationalBeam& element : structure.elements) {
    // The element frame of the current state, E = diag(R_r, R_r, R_r, R_r).
    const Eigen::Matrix3d frame = response_of(element, state).frame;
    Matrix12d e = Matrix12d::Zero();
    for (int blk = 0; blk < 4; ++blk) e.block<3, 3>(3 * blk, 3 * blk) = frame;
    add_element_matrix(element.nodes, e * element.local_mass * e.transpose(), triplets);
  }
  SparseMatrix mass(structure.dof_count(), structure.dof_count());
  mass.setFromTriplets(triplets.begin(), triplets.end());
  return mass;
}

}  // namespace limber::nonlinear_beam
