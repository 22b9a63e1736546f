#include "run/prepared_start.h"

#include <algorithm>

#include "run/singular_start.h"

namespace limber::run {

PreparedStart prepare_start(const multibody::Model& model,
                            const multibody::AssemblyOptions& options) {
  multibody::Workspace ws(model);
  PreparedStart start;
  start.state = multibody::initial_state(model);
  start.state.t = 0.0;
  start.partition = multibody::full_partition(model);

  // Positions, then velocities: nothing else is meaningful on an open loop.
  start.assembly = multibody::assemble_positions(model, start.state, ws, options);
  if (start.assembly.status != multibody::AssemblyStatus::kOk) return start;
  start.velocity_residual =
      multibody::assemble_velocities(model, start.state, ws, options, &start.velocity_modes_released);

  // Redundancy is a property of the assembled configuration.
  start.partition = multibody::analyse_redundancy(model, start.state, ws);
  const std::vector<std::string> lines = start.partition.describe(model);
  for (std::size_t k = 0; k < start.partition.redundant.size(); ++k) {
    const multibody::RedundantEquation& equation = start.partition.redundant[k];
    RedundantEquationReport report{model.equations[equation.row].name, {}, lines[k]};
    for (int row : equation.depends_on) report.depends_on.push_back(model.equations[row].name);
    start.redundant.push_back(std::move(report));
  }
  // Dependencies through hold-downs released at t = 0 end before the motion starts.
  start.deformation_redundant = deformation_redundancies(model, start.state, start.partition, ws);
  const std::vector<bool> released_at_start = multibody::rows_released_by(model, 0.0);
  std::erase_if(start.deformation_redundant, [&](const DeformationRedundancy& d) {
    return std::any_of(d.group.begin(), d.group.end(), [&](int row) {
      return !released_at_start.empty() && released_at_start[static_cast<std::size_t>(row)];
    });
  });
  for (int row : rows_lost_at_singular_start(model, start.state, start.partition, ws)) {
    start.lost_at_singular_start.push_back(model.equations[row].name);
  }
  return start;
}

}  // namespace limber::run
