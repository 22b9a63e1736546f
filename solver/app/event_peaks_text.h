// A run's event peaks (results/event_peaks.h) as text for the terminal and as JSON, shared by
// `limber run` and `limber select`.
#pragma once

#include <cstdio>
#include <string>

#include "results/event_peaks.h"

namespace limber::app {

// One line per window, then one per joint: |F| and |T| with their times.
void print_event_peaks(std::FILE* out, const results::EventPeaks& peaks);

// {"window": s, "windows": [{"label", "start", "end", "states", "joints": [{"joint", "force",
// "force_time", "torque", "torque_time", "force_component": [x, y, z], "force_component_time",
// "torque_component", "torque_component_time"}]}]}; times null where nothing was seen.
std::string json_event_peaks(const results::EventPeaks& peaks);

}  // namespace limber::app
