// Reads the `run` section of a case file (docs/case-format.md, "run"): the integrator
// (ida | galpha) with its tolerances or step, the step budget, the end time and the output
// sample interval of `limber run`. Unknown keys and out-of-range values throw InputError at
// file:line:col; ranges are those of integrate::IntegratorOptions::validate, and the samples
// (t_end / sample_interval) number at most integrate::kMaxSamples.
#pragma once

#include "io/mechanism_reader.h"
#include "io/yaml_reader.h"

namespace limber::io {

RunSettings read_run_settings(const YamlValue& entry);

}  // namespace limber::io
