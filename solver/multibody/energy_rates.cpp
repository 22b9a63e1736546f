#include "multibody/energy_rates.h"

#include <algorithm>

#include "multibody/dynamics.h"
#include "multibody/reactions.h"
#include "multibody/released_joints.h"

namespace limber::multibody {

EnergyRates energy_rates(const Model& model, const ConstraintPartition& partition, const State& state,
                         const Eigen::VectorXd& v_dot, const Eigen::VectorXd& lambda, Workspace& ws) {
  EnergyRates rates;
  // Force elements: dampers, actuators, loads.
  // Released joints' markers carry no force element: left out.
  const PowerTerms powers = power_terms(model, state, released_joints(model, partition.row_released), ws);
  rates.dissipation = powers.dissipation;
  rates.forces = powers.actuators + powers.loads;
  rates.geometric = powers.geometric;
  // Drivers: effort = −λ of their (independent) row; a redundant driver row falls back on
  // the minimum-norm multipliers.
  bool all_independent = true;
  for (const Driver& d : model.drivers) {
    const auto it = std::lower_bound(partition.independent.begin(), partition.independent.end(), d.row);
    if (it == partition.independent.end() || *it != d.row) {
      all_independent = false;
      break;
    }
    rates.driver += -lambda(it - partition.independent.begin()) * d.motion.evaluate(state.t).first;
  }
  if (!all_independent) rates.driver = compute_reactions(model, state, v_dot, partition, ws).driver_power;
  return rates;
}

}  // namespace limber::multibody
