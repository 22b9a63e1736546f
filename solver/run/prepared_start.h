// The start of a run (docs/multibody.md, "Initial conditions" and "Redundant constraints"):
// assembly of the approximate initial poses onto the constraints at t = 0, consistent
// velocities, then the redundancy analysis of the assembled configuration.
#pragma once

#include <string>
#include <vector>

#include "multibody/assembly.h"
#include "multibody/model.h"
#include "multibody/redundancy.h"
#include "multibody/state.h"
#include "run/deformation_redundancy.h"

namespace limber::run {

// One redundant equation, by name ("R2.z") and the independent ones it combines.
struct RedundantEquationReport {
  std::string name;
  std::vector<std::string> depends_on;
  std::string description;  // "R2.z is redundant with R1.z, R3.z"
};

struct PreparedStart {
  multibody::AssemblyResult assembly;     // status kNotConverged: `state` is not usable
  multibody::State state;                 // assembled q, consistent v, at t = 0
  double velocity_residual = 0.0;         // max |G v + g_t| after the velocity projection
  bool velocity_modes_released = false;   // the projection changed modal rates (assembly.h)
  multibody::ConstraintPartition partition;  // independent rows (all rows after a failure)
  std::vector<RedundantEquationReport> redundant;
  // Redundant rows that a flexible body's deformation makes independent (deformation_redundancy.h):
  // the run watches them (redundant_row_watch.h). Dependencies through a hold-down released at
  // t = 0 are left out: they end before the motion starts.
  std::vector<DeformationRedundancy> deformation_redundant;
  // Equations the start's singular configuration made dependent (singular_start.h), by name;
  // empty at a regular start. A run cannot hold them: it refuses to start.
  std::vector<std::string> lost_at_singular_start;
};

// Assembles positions (options.held kept), projects velocities, analyses redundancy (with the
// rows that hold only while flexible bodies are undeformed) and checks that the start is not a
// singular configuration.
// A failing assembly is returned in `assembly` (its message names the equation, its joint and
// the residual); bad held coordinates throw InputError.
PreparedStart prepare_start(const multibody::Model& model,
                            const multibody::AssemblyOptions& options);

}  // namespace limber::run
