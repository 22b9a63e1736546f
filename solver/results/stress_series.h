// /bodies/<body>/stress of results.h5 (results_writer.h, docs/results-format.md): a flexible
// body's stress peak at every sample, its history at every `every`-th, and the running peak of
// the run, written as attributes at finish.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <memory>

#include "results/h5_handle.h"
#include "results/results_writer.h"
#include "results/sample_series.h"

namespace limber::results {

// A body's stress group and its series.
struct StressSeries {
  H5Handle group;
  Series peak, peak_element, time, equivalent, beam_resultants, shell_resultants;
  std::int64_t rows = 0;          // history rows in the file
  std::int64_t pending_rows = 0;  // history rows waiting in the series' buffers
  hsize_t elements = 0, beam_width = 0, shell_width = 0;
  double max_value = -1.0, max_time = 0.0;
  int max_element = -1;
};

// The stress group of a flexible body under `body_group`: element list, `every`, and its series.
std::unique_ptr<StressSeries> create_stress_series(hid_t body_group, const FlexibleBodySpec& body);

// The peak of this sample (buffered with the sample), and a history row when the sample
// carries one (written with the next block).
void append_stress(StressSeries& stress, const BodySample& body, double time);

// Writes a body's buffered stress rows: the per-sample peaks at `first_sample`, then the
// history, time last.
void write_stress_block(StressSeries& stress, std::int64_t first_sample, std::int64_t samples);

}  // namespace limber::results
