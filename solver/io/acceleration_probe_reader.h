// Reads the case sections `acceleration_probes` and `shock_spectrum` (docs/case-format.md,
// "Acceleration probes and shock response spectra"):
//   acceleration_probes:
//     panel_tip: {body: panel4, node: 4021}       # flexible body: an FE node (id or one-node set)
//     hub: {body: hub, position: [0, 0, 0.2]}     # rigid body: a point in its frame [m]
//     hinge: {marker: H1.j}                       # a marker's origin (its node on a flexible body)
//   shock_spectrum:          # optional; the defaults below
//     min_frequency: 5       # [Hz], lowest natural frequency of the 1/6-octave grid
//     max_frequency: 1000    # [Hz], default: the band the steps support, 1/(10 h_max)
//     q: 10                  # amplification, ζ = 1/(2Q)
//     window: 0.3            # [s], length of each event window
// Every error is an InputError at file:line:col (expected/got); whether the body or marker
// exists is checked by the model builder at the location kept here (check_mechanism).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/error.h"
#include "integrate/integrator_options.h"
#include "io/yaml_reader.h"
#include "multibody/model_builder.h"
#include "results/shock_spectra.h"

namespace limber::io {

struct PlacedFlexibleBody;  // flexible_mechanism_body.h

struct AccelerationProbeEntry {
  multibody::AccelerationProbeSpec spec;
  SourceLocation where;  // the value of `body` or `marker`
};

// The entries of `section` (the acceleration_probes map); `flexible` are the mechanism's
// flexible bodies by name (their nodes resolved here).
std::vector<AccelerationProbeEntry> read_acceleration_probes(const YamlValue& section,
                                                             const std::map<std::string, PlacedFlexibleBody>& flexible);

// The longest step of the probes' record, which the run promises before it starts: the probes
// are recorded at every integrator step (run_driver.h), so generalized-α's `step` (events and
// event windows only shorten it), IDA's `max_step`, or, for IDA without one, the sample
// interval, to which a run with probes caps IDA's step [s].
double probe_record_step(const integrate::IntegratorOptions& integrator, double sample_interval);

// The shock_spectrum section (nullptr: the defaults), checked against the band that a record
// with steps of at most `record_step` [s] supports (probe_record_step, results/shock_spectra.h):
// the error sits at the offending frequency, or at `probes` (the acceleration_probes section)
// for the defaults.
results::ShockSpectrumSettings read_shock_spectrum(const YamlValue* section, const YamlValue& probes,
                                                   double record_step);

}  // namespace limber::io
