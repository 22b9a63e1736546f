// Static equilibrium of a co-rotational beam structure (beam_structure.h) under dead nodal
// forces and moments, by load increments and Newton-Raphson on the Lie group.
//
// Load factor lambda runs 1/n, 2/n, ..., 1 (n = StaticOptions::load_increments). At each
// lambda, Newton solves K_t delta = -r on the free DOFs with r = f_int - lambda f_ext and
// updates x += delta_u, R <- exp(delta_w) R (apply_increment). The tangent K_t is the exact
// derivative of f_int (dead loads have no load stiffness on spatial spins) and is not symmetric
// off equilibrium: it is factorised by sparse LU (Eigen's SparseLU, COLAMD ordering).
// Converged when both
//   |r_free| <= residual_tolerance |f_ext|  or  |r_free| <= BeamStructure::force_roundoff
//     (2-norm, N and N m; the second: the residual is at the round-off of f_int itself)
//   max |delta_u| <= increment_tolerance * size  and  max |delta_w| <= increment_tolerance
// hold (size: BeamStructure::size). A failed increment is halved (at most max_bisections
// times) before the solve gives up.
//
// Failure is a returned status (house style §11): status != kConverged, `state` the last
// converged configuration, `load_factor` its lambda, `message` saying at which load factor
// Newton failed and why. require_converged turns it into a NumericalError.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "nonlinear_beam/beam_structure.h"

namespace limber::nonlinear_beam {

// A dead load at a node, component axes. Spell out Eigen::Vector3d::Zero() for an absent
// component in a braced list: `{}` value-initialises an Eigen vector, which leaves it
// uninitialised.
struct NodalLoad {
  int node = 0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // [N]
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // [N m]
};

struct StaticOptions {
  int load_increments = 10;           // n >= 1
  int max_iterations = 30;            // Newton iterations per increment
  int max_bisections = 6;             // halvings of a failed increment
  double residual_tolerance = 1e-9;   // relative to |f_ext|
  double increment_tolerance = 1e-10; // relative to the structure size (translations), rad
};

enum class StaticStatus { kConverged, kNotConverged, kSingularTangent };

struct StaticSolution {
  StaticStatus status = StaticStatus::kConverged;
  BeamState state;                  // last converged configuration
  double load_factor = 0.0;         // its lambda (1 when converged)
  std::vector<int> iterations;      // Newton iterations of each accepted increment
  std::string message;              // empty when converged
};

// Precondition (LIMBER_DEMAND): loads name existing nodes; options are positive.
StaticSolution solve_static(const BeamStructure& structure, const std::vector<NodalLoad>& loads,
                            const StaticOptions& options = {});

// Throws NumericalError with solution.message unless solution.status is kConverged.
void require_converged(const StaticSolution& solution);

}  // namespace limber::nonlinear_beam
