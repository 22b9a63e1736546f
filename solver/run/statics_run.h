// `limber statics`: the static equilibrium of a mechanism at t = 0 (multibody/statics.h),
// every joint holding (hold-downs included), written to results.h5 as one sample at t = 0 so
// that render and report show the deformed shape and the reactions (docs/statics.md).
// Failures are returned (status "failed" in the summary and the file), never thrown; bad
// input throws InputError before anything is written.
#pragma once

#include <string>

#include "multibody/assembly.h"
#include "multibody/model.h"
#include "multibody/statics.h"
#include "results/results_writer.h"
#include "run/prepared_start.h"

namespace limber::run {

struct StaticsSummary {
  bool ok = false;
  std::string message;          // why it failed ("" when ok)
  std::string failure;          // "assembly", "statics" or ""
  PreparedStart start;          // assembly and redundancy of the undeformed start
  multibody::StaticsResult statics;
  double wall_seconds = 0.0;
};

// Assembles `model`, solves its statics and, with a writer, writes the equilibrium as the
// file's one sample (declared, filled and finished here).
StaticsSummary solve_mechanism_statics(const multibody::Model& model,
                                       const multibody::AssemblyOptions& assembly,
                                       results::ResultsWriter* writer = nullptr);

}  // namespace limber::run
