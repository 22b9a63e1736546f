#include "case_input_path.h"

#include "core/error.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "run/prepared_start.h"
#include "run/run_driver.h"

namespace limber::fuzz {

const char* to_string(CaseOutcome outcome) {
  switch (outcome) {
    case CaseOutcome::kAccepted: return "accepted";
    case CaseOutcome::kInputError: return "InputError";
    case CaseOutcome::kNumericalError: return "NumericalError";
    case CaseOutcome::kTooLarge: return "too large";
    case CaseOutcome::kNoMechanism: return "no mechanism";
  }
  return "?";
}

CaseOutcome run_case_input(const std::string& text, const std::string& file,
                           const CaseInputLimits& limits, std::string* message) {
  try {
    // Read: every section parsed and checked, the FE models built.
    const io::Case input = io::read_case_text(text, file);
    if (!input.mechanism) return CaseOutcome::kNoMechanism;
    // Bound the reduction's cost (the mechanism's bodies only are reduced, but any may be).
    for (const io::FlexibleBodyCase& body : input.flexible_bodies) {
      if (body.model.node_count() > limits.max_nodes) return CaseOutcome::kTooLarge;
    }
    // Settings first, as `limber run` does, then reduce, build and prepare the start.
    run::check_settings(input.mechanism->run);
    const io::CaseReduction reduction =
        io::reduce_case(input, io::ReductionScope::kMechanismBodies);
    const io::Mechanism mechanism = io::build_mechanism(input, reduction);
    run::prepare_start(mechanism.model, mechanism.assembly);
    return CaseOutcome::kAccepted;
  } catch (const InputError& e) {
    if (message) *message = e.what();
    return CaseOutcome::kInputError;
  } catch (const NumericalError& e) {
    if (message) *message = e.what();
    return CaseOutcome::kNumericalError;
  }
}

}  // namespace limber::fuzz
