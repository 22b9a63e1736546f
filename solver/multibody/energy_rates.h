// The powers a run driver integrates for the energy bookkeeping of the results file
// (docs/results-format.md: dissipated, driver_work, force_work), in one call suitable for
// integrate::Quadrature. Energy balance: T + V_gravity + V_spring + U_strain + dissipated
//   = E(0) + driver_work + force_work, force_work = ∫ (forces + geometric) dt
// (checked in tests/multibody/integration_test.cpp; the geometric stiffening's work, of its
// modal forces −K_geo η, in tests/multibody/geometric_stiffening_test.cpp).
#pragma once

#include <Eigen/Dense>

#include "multibody/model.h"
#include "multibody/redundancy.h"
#include "multibody/state.h"

namespace limber::multibody {

struct EnergyRates {
  double dissipation = 0.0;  // damper power removed, ≥ 0 [W]
  double driver = 0.0;       // Σ effort · ḟ(t) of the drivers [W]
  double forces = 0.0;       // actuators of RSDA/TSDA and point loads [W]
  double geometric = 0.0;    // −Σ η̇ᵀ K_geo η of the geometric stiffening [W]
};

// lambda: multipliers of the independent rows (partition.independent), e.g. from an
// integrator sample; v_dot: accelerations, used only when a driver equation is redundant
// (its effort then comes from the minimum-norm reactions, reactions.h). Updates ws.
EnergyRates energy_rates(const Model& model, const ConstraintPartition& partition, const State& state,
                         const Eigen::VectorXd& v_dot, const Eigen::VectorXd& lambda, Workspace& ws);

}  // namespace limber::multibody
