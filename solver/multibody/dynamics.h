// Mass matrix, generalized forces, energies and powers of a whole model (house style §3):
//   M(q) v̇ + Gᵀ λ = Q(t, q, v),   Q = Σ_bodies (Q_v + gravity) + Σ force elements.
// Force elements (model.h for their conventions) give Q by virtual work through marker
// Jacobians: RSDA τ (J_wj − J_wi)ᵀ u, TSDA f (J_pj − J_pi)ᵀ e, point load J_pᵀ F + J_wᵀ T;
// hinge latches and stops (hinge_limit.h) like an RSDA, in the mode state.engaged gives.
#pragma once

#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "multibody/model.h"
#include "multibody/state.h"

namespace limber::multibody {

// ws.M = M(q), nv x nv, symmetric positive definite.
void mass_matrix(const Model& model, const State& state, Workspace& ws);

// M(q) a, body block by body block (nv): no nv x nv matrix, for models of many bodies.
Eigen::VectorXd mass_times(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& a);

// M = M(q) as a sparse matrix: the bodies' diagonal blocks. A matrix from an earlier call on
// the same model keeps its pattern and only its values are written (no allocation).
void sparse_mass_matrix(const Model& model, const State& state, Eigen::SparseMatrix<double>& M);

// Rates of energy flow into the model at one instant [W].
struct PowerTerms {
  double dissipation = 0.0;  // Σ c θ̇² + Σ c l̇² + Σ c_i η̇_i² ≥ 0, removed by dampers
  double actuators = 0.0;    // Σ a θ̇ (RSDA) + Σ a l̇ (TSDA)
  double loads = 0.0;        // Σ F·ṗ + T·ω of point loads
  double geometric = 0.0;    // −Σ η̇ᵀ K_geo η of the geometric stiffening (geometric_stiffening.h)
};

// ws.Q = Q(t, q, v). Updates ws.markers (velocity stage). When powers is non-null, also
// returns the instantaneous powers of the force elements.
void generalized_forces(const Model& model, const State& state, Workspace& ws,
                        PowerTerms* powers = nullptr);

// ws.M and ws.Q as mass_matrix and generalized_forces give them, in one pass: each flexible
// body's deformed inertia computed once, and ws.markers updated once (velocity stage when the
// model has force elements, else position stage), so that evaluate_constraint_rows
// (constraints.h) can follow without updating them again.
void mass_matrix_and_forces(const Model& model, const State& state, Workspace& ws);

// A force element's load at one of its markers: force and torque about the marker's origin,
// ground axes [N, N·m] (an RSDA or TSDA gives one per marker, equal and opposite).
struct MarkerLoad {
  int marker = 0;
  Eigen::Vector3d force_W = Eigen::Vector3d::Zero(), torque_W = Eigen::Vector3d::Zero();
};

// The loads that generalized_forces applies through the force elements, marker by marker
// (their sum through the marker Jacobians is that part of Q). Updates ws.markers (velocity stage).
void force_element_loads(const Model& model, const State& state, Workspace& ws, std::vector<MarkerLoad>& loads);

struct EnergyTerms {
  double kinetic = 0.0;  // ½ vᵀ M v [J]
  double gravity = 0.0;  // −Σ m g·r_c [J] (zero at the ground origin)
  double spring = 0.0;   // Σ ½ k (θ − θ0)² + Σ ½ k (l − l0)² + locked latches, stops [J]
  double strain = 0.0;   // Σ ½ ηᵀ diag(ω²) η of the flexible bodies [J]
};

// Updates ws.markers (position stage).
EnergyTerms energies(const Model& model, const State& state, Workspace& ws);

}  // namespace limber::multibody
