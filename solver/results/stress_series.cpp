#include "results/stress_series.h"

#include <algorithm>

#include "core/error.h"
#include "results/results_layout.h"
#include "results/writer_attributes.h"

namespace limber::results {

std::unique_ptr<StressSeries> create_stress_series(hid_t body_group, const FlexibleBodySpec& body) {
  const auto lines = static_cast<int>(body.lines.rows());
  const auto elements = static_cast<int>(body.lines.rows() + body.quads.rows());
  LIMBER_DEMAND(body.stress_every >= 1);
  LIMBER_DEMAND(std::is_sorted(body.stress_elements.begin(), body.stress_elements.end()));
  auto stress = std::make_unique<StressSeries>();
  stress->group = create_group(body_group, layout::body::kStress);
  write_int_attribute(stress->group.get(), layout::stress::kEveryAttribute, body.stress_every);
  const hid_t g = stress->group.get();
  write_dataset(g, layout::stress::kElements, H5T_STD_I32LE, H5T_NATIVE_INT, {body.stress_elements.size()},
                body.stress_elements.data());
  hsize_t beams = 0, shells = 0;
  for (int e : body.stress_elements) {
    LIMBER_DEMAND(e >= 0 && e < elements);
    (e < lines ? beams : shells) += 1;
  }
  stress->elements = body.stress_elements.size();
  stress->beam_width = 12 * beams;
  stress->shell_width = 8 * shells;
  stress->peak = create_series(g, layout::stress::kPeak, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0);
  stress->peak_element = create_series(g, layout::stress::kPeakElement, H5T_STD_I32LE, H5T_NATIVE_INT, 0);
  stress->time = create_series(g, layout::stress::kTime, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0);
  stress->equivalent = create_series(g, layout::stress::kEquivalent, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, stress->elements);
  LIMBER_DEMAND(stress->elements > 0);
  // Resultants of the kinds of element declared (a width of 0 would make a [ns] series).
  if (beams > 0) {
    stress->beam_resultants =
        create_series(g, layout::stress::kBeamResultants, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, stress->beam_width);
  }
  if (shells > 0) {
    stress->shell_resultants =
        create_series(g, layout::stress::kShellResultants, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, stress->shell_width);
  }
  return stress;
}

void append_stress(StressSeries& stress, const BodySample& body, double time) {
  append_row(stress.peak, &body.stress_peak);
  append_row(stress.peak_element, &body.stress_peak_element);
  if (body.stress_peak > stress.max_value) {
    stress.max_value = body.stress_peak;
    stress.max_element = body.stress_peak_element;
    stress.max_time = time;
  }
  if (!body.stress_recorded) return;
  LIMBER_DEMAND(static_cast<hsize_t>(body.stress_equivalent.size()) == stress.elements);
  LIMBER_DEMAND(static_cast<hsize_t>(body.stress_beam_resultants.size()) == stress.beam_width);
  LIMBER_DEMAND(static_cast<hsize_t>(body.stress_shell_resultants.size()) == stress.shell_width);
  append_row(stress.equivalent, body.stress_equivalent.data());
  if (stress.beam_width > 0) append_row(stress.beam_resultants, body.stress_beam_resultants.data());
  if (stress.shell_width > 0) append_row(stress.shell_resultants, body.stress_shell_resultants.data());
  append_row(stress.time, &time);
  ++stress.pending_rows;
}

void write_stress_block(StressSeries& stress, std::int64_t first_sample, std::int64_t samples) {
  write_pending(stress.peak, first_sample, samples);
  write_pending(stress.peak_element, first_sample, samples);
  write_pending(stress.equivalent, stress.rows, stress.pending_rows);
  if (stress.beam_width > 0) write_pending(stress.beam_resultants, stress.rows, stress.pending_rows);
  if (stress.shell_width > 0) write_pending(stress.shell_resultants, stress.rows, stress.pending_rows);
  write_pending(stress.time, stress.rows, stress.pending_rows);
  stress.rows += stress.pending_rows;
  stress.pending_rows = 0;
}

}  // namespace limber::results
