// The beams of one FE model as a geometrically nonlinear structure: the frozen model
// (BeamStructure), its configuration (BeamState: node positions and rotations on the Lie
// group), and the assembled internal force and sparse tangent stiffness.
//
// Generalized variations are 6 per node in FeModel's DOF order: translations (ux uy uz) [m]
// and spatial spins (rx ry rz) [rad] in component axes, applied by apply_increment as
// x <- x + du, R <- exp(dw) R (never by adding angles). On the undeformed state the tangent is
// the linear stiffness of fe::assemble restricted to the beams.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

#include "fe/fe_model.h"
#include "nonlinear_beam/corotational_beam.h"

namespace limber::nonlinear_beam {

using SparseMatrix = Eigen::SparseMatrix<double>;

// Frozen after build_beam_structure.
struct BeamStructure {
  std::vector<Eigen::Vector3d> reference_positions;  // undeformed node positions [m]
  std::vector<CorotationalBeam> elements;
  std::vector<int> free_dofs;  // DOFs not in FeModel::fixed_dofs, ascending
  double size = 0.0;           // diagonal of the nodes' bounding box [m] (convergence scale)
  // Round-off level of an internal force [N, N m]: 100 eps max|K_l| (size + max |X|). Local
  // deformations are differences of absolute coordinates, so f_int carries an error of about
  // eps |X| times the stiffest local stiffness (EA / l0) whatever the load.
  double force_roundoff = 0.0;

  int node_count() const { return static_cast<int>(reference_positions.size()); }
  int dof_count() const { return fe::kDofsPerNode * node_count(); }
};

// The co-rotational structure of `model`'s beams with its fixed DOFs. Throws InputError (with
// expected/got) when the model has elements or matrices this step does not treat nonlinearly:
// shells, triangles, DOF stiffness matrices (springs, bushings, rods) or multipoint
// constraints; or as fe::beam_local_axes. Point and DOF masses do not enter statics.
BeamStructure build_beam_structure(const fe::FeModel& model);

// Configuration: current node positions [m] and rotations from the undeformed state (unit
// quaternions, component axes).
struct BeamState {
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Quaterniond> rotations;
};

// The undeformed configuration.
BeamState reference_state(const BeamStructure& structure);

// x_i += delta(6i..6i+2), R_i <- exp(delta(6i+3..6i+5)) R_i (renormalised quaternion).
// Precondition: delta.size() == dof_count.
void apply_increment(BeamState& state, const Eigen::VectorXd& delta);

// Displacement (position minus reference) [m] and rotation vector log(R_i) [rad] of a node, in
// the DOF order of FeModel; the rotation vector is principal (|angle| <= pi).
Eigen::Matrix<double, 6, 1> node_displacement(const BeamStructure& structure,
                                              const BeamState& state, int node);

// Internal force vector f_int (dof_count) of the structure in `state`.
Eigen::VectorXd internal_force(const BeamStructure& structure, const BeamState& state);

// Strain energy of the beams [J]; internal_force is its gradient.
double strain_energy(const BeamStructure& structure, const BeamState& state);

struct ForceAndTangent {
  Eigen::VectorXd force;  // f_int, dof_count
  SparseMatrix tangent;   // d f_int / d(translations, spins), dof_count square, compressed
};

// Scratch space of evaluate_force_and_tangent, sized from the structure: the tangent's sparsity
// pattern (full 6x6 blocks for the node pairs of every element, built once) and, per element,
// the position in the value array of each of its 144 entries, so that evaluations write in
// place and allocate nothing.
struct BeamWorkspace {
  ForceAndTangent result;
  std::vector<std::array<int, 144>> slots;  // per element, row-major over its 12x12 matrix
};

BeamWorkspace make_workspace(const BeamStructure& structure);

// f_int and its exact tangent (corotational_beam.h) assembled into workspace.result.
void evaluate_force_and_tangent(const BeamStructure& structure, const BeamState& state,
                                BeamWorkspace& workspace);

// The same, returned as a value (a fresh workspace per call; for tests and one-off uses).
ForceAndTangent internal_force_and_tangent(const BeamStructure& structure,
                                           const BeamState& state);

// Consistent mass of the beams in `state`: each element's linear consistent mass rotated into
// its current element frame, E M_l E^T (the co-rotational mass of Crisfield 1997, ch. 17, with
// the inertia of the frame's own rotation left out). Sparse, dof_count square, symmetric.
SparseMatrix corotational_mass(const BeamStructure& structure, const BeamState& state);

}  // namespace limber::nonlinear_beam
