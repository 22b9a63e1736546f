// One generated (or saved) mechanism through `limber run`'s whole path, in process: read,
// reduce, build, run 0.1 s with results.h5 written, for the mechanism fuzz (fuzz_mechanisms.cpp)
// and its regression test (mechanism_regression_test.cpp): docs/fuzzing.md "Generated
// mechanisms".
//
// Expected ends: the run reached t_end (status ok or ok_inaccurate), or it stopped with a named
// failure (assembly, statics or an integrate::StatusCode name, and a message), or the case was
// refused (InputError at its place, NumericalError of a reduction). Findings: a sample with a
// non-finite value, a failure with an empty name or message, a run that claims t_end but did not
// reach it. Anything else (another exception, an abort, a hang) propagates to the caller.
#pragma once

#include <string>

#include "integrate/integrator_options.h"

namespace limber::fuzz {

struct MechanismOutcome {
  // "ok", "ok_inaccurate", "failed: <failure name>", "InputError", "NumericalError".
  std::string status;
  std::string message;  // the failure's or error's message ("" when ok)
  std::string finding;  // "" unless the run broke a rule above (then what it broke)
  int samples = 0;
  double wall_seconds = 0.0;
};

// Runs `text` (named `file` in messages) with `method`, results.h5 in `output_dir`.
MechanismOutcome run_mechanism_case(const std::string& text, const std::string& file,
                                    integrate::Method method, const std::string& output_dir);

}  // namespace limber::fuzz
