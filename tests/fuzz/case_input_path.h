// The whole input path of `limber run` up to the integration, as one function, for the
// case-reader fuzz target (fuzz_case_reader.cpp) and its regression test
// (case_input_regression_test.cpp): docs/fuzzing.md.
//
//   io::read_case_text -> io::reduce_case (kMechanismBodies) -> io::build_mechanism
//   -> run::check_settings -> run::prepare_start (assembly, velocities, redundancy analysis)
//
// The expected ends are success, InputError (bad input, with its location) and NumericalError
// (a reduction that failed); both are caught here and returned as the outcome. Anything else
// (another exception, an abort from LIMBER_DEMAND, a sanitizer report) is a finding and is
// left to propagate.
#pragma once

#include <string>

namespace limber::fuzz {

enum class CaseOutcome {
  kAccepted,        // read, reduced, built, settings checked, start prepared
  kInputError,      // io::InputError
  kNumericalError,  // NumericalError (e.g. the eigen-solver of a flexible body)
  kTooLarge,        // skipped before the reduction: an FE model above max_nodes (see below)
  kNoMechanism,     // read and checked, but the case has no mechanism to build
};

const char* to_string(CaseOutcome outcome);

// Bounds that keep one input cheap, so that a fuzzer is not stalled by legitimate work.
struct CaseInputLimits {
  // Flexible bodies with more FE nodes than this are not reduced (ARPACK and the static modes
  // on a large model take seconds); the read stage, which built the FE model, has run.
  int max_nodes = 64;
};

// Feeds `text` (named `file` in messages) through the path above. Throws only what is a
// finding; `message` (when given) receives the caught error's message.
CaseOutcome run_case_input(const std::string& text, const std::string& file,
                           const CaseInputLimits& limits = {}, std::string* message = nullptr);

}  // namespace limber::fuzz
