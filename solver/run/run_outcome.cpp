#include "run/run_outcome.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "results/shock_spectra_file.h"

namespace limber::run {

std::string singular_start_message(const std::vector<std::string>& lost_equations) {
  return fmt::format(
      "the mechanism is assembled at a singular configuration: equation(s) {} depend on the "
      "others here but not next to it, so no choice of independent equations holds the "
      "mechanism together once it moves; start it slightly off this position (e.g. a driver's "
      "initial value, or a body's position, moved by 1e-3)",
      fmt::join(lost_equations, ", "));
}

void write_redundant_equations(const std::vector<RedundantEquationReport>& redundant,
                               results::ResultsWriter& writer) {
  std::vector<std::string> names, depends_on;
  for (const RedundantEquationReport& r : redundant) {
    names.push_back(r.name);
    depends_on.push_back(fmt::format("{}", fmt::join(r.depends_on, ", ")));
  }
  writer.set_redundant_equations(names, depends_on);
}

void warn_velocity_jumps(const multibody::Model& model, double t_end,
                         const std::function<void(const std::string&)>& warn) {
  for (const multibody::Driver& driver : model.drivers) {
    std::vector<double> jumps;
    for (const double t : driver.motion.slope_jumps()) {
      if (t > 0.0 && t < t_end) jumps.push_back(t);
    }
    if (jumps.empty()) continue;
    warn(fmt::format(
        "driver {}'s motion changes its rate abruptly at t = {} s (the kinks of its table): "
        "each is applied as an impulse (the integrators stop there and restart with the "
        "velocities after it), which the reaction and effort histories do not show; use "
        "`interpolation: cubic` and points that start and end at rest for a smooth motion",
        driver.name, fmt::join(jumps, ", ")));
  }
}

void add_model_warnings(RunSummary& summary) {
  // A body outside the linear range makes the linear floating-frame answer unphysical however
  // accurately it was integrated: the run is not "ok" either.
  for (const std::string& warning : summary.warnings) {
    summary.accuracy.warnings.push_back(warning + " (the linear modal body's answer is not the physical one there)");
  }
  // A change of branch at a singular passage is an impulse no force gave: not accurate.
  for (const SingularPassage& passage : summary.singular_passages) {
    if (passage.changed_branch()) summary.accuracy.warnings.push_back(passage.message());
  }
}

void record_shock_spectra(const multibody::Model& model, const io::RunSettings& settings,
                          const ProbeStepRecord& record, RunSummary& summary, results::ResultsWriter* writer) {
  summary.shock_spectra = probe_shock_spectra(model, settings, record.time(), record.histories(), summary.events);
  if (!writer) return;
  writer->set_shock_spectra(*summary.shock_spectra);
  // Beside results.h5; an in-memory file has no folder, and the spectra stay in the file.
  if (!writer->path().empty()) {
    results::write_shock_spectra_csv(writer->path().parent_path(), *summary.shock_spectra);
  }
}

std::string band_above_modes_warning(const multibody::Model& model, double max_frequency_hz) {
  double highest = 0.0;  // [Hz]
  std::string body;
  for (const multibody::Body& b : model.bodies) {
    if (b.kind != multibody::BodyKind::kFlexible || b.flexible->stiffness.size() == 0) continue;
    const double f = std::sqrt(std::max(0.0, b.flexible->stiffness.maxCoeff())) / (2.0 * std::numbers::pi);
    if (f > highest) {
      highest = f;
      body = b.name;
    }
  }
  if (highest == 0.0 || max_frequency_hz <= highest) return {};
  return fmt::format(
      "the shock spectra's band reaches {:.4g} Hz, above the highest mode the model retains ({:.4g} Hz, body {}): "
      "there the spectra follow the record's peak acceleration, and a structure's own response above its "
      "highest mode is not in the model (retain modes up to the band, or lower shock_spectrum.max_frequency)",
      max_frequency_hz, highest, body);
}

void write_run_tables(const RunSummary& summary, bool with_peaks, results::ResultsWriter& writer) {
  std::string warnings;
  for (const std::string& w : summary.accuracy.warnings) warnings += (warnings.empty() ? "" : "\n") + w;
  writer.set_accuracy(summary.accuracy.energy_relative, summary.accuracy.local_error,
                      summary.accuracy.drift_relative, warnings);
  std::vector<double> passage_time, passage_ratio, passage_jump;
  std::vector<std::string> passage_joints;
  for (const SingularPassage& passage : summary.singular_passages) {
    passage_time.push_back(passage.t);
    passage_ratio.push_back(passage.ratio);
    passage_joints.push_back(fmt::format("{}", fmt::join(passage.names, ", ")));
    passage_jump.push_back(passage.velocity_jump);
  }
  writer.set_singular_passages(passage_time, passage_ratio, passage_joints, passage_jump);
  if (with_peaks) writer.set_event_peaks(summary.peaks);
}

}  // namespace limber::run
