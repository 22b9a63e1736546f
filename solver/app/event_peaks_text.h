// A run's event peaks (results/event_peaks.h) as text for the terminal (in JSON: the run
// record, run/run_record.h).
#pragma once

#include <cstdio>

#include "results/event_peaks.h"

namespace limber::app {

// One line per window, then one per joint: |F| and |T| with their times.
void print_event_peaks(std::FILE* out, const results::EventPeaks& peaks);

}  // namespace limber::app
