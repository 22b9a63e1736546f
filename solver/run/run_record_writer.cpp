// The writer of the run record (run_record.h).
#include <fmt/format.h>

#include "core/json_text.h"
#include "results/results_layout.h"
#include "run/run_record.h"

namespace limber::run {

namespace {

std::string json_string_list(const std::vector<std::string>& values) {
  std::string text = "[";
  for (std::size_t k = 0; k < values.size(); ++k) text += (k ? ", " : "") + json_string(values[k]);
  return text + "]";
}

std::string json_vector(const Eigen::Vector3d& v) {
  return fmt::format("[{}, {}, {}]", json_number(v(0)), json_number(v(1)), json_number(v(2)));
}

std::string json_events(const multibody::Model& model, const std::vector<multibody::HingeEvent>& events) {
  std::string text = "[";
  for (std::size_t k = 0; k < events.size(); ++k) {
    const multibody::HingeEvent& e = events[k];
    const auto& limit = std::get<multibody::HingeLimit>(model.forces[e.force]);
    text += fmt::format("{}{{\"t\": {}, \"name\": {}, \"kind\": {}, \"joint\": {}, \"engaged\": {}, "
                        "\"angle\": {}, \"rate\": {}}}",
                        k ? ", " : "", json_number(e.t), json_string(limit.name),
                        json_string(multibody::to_string(limit.kind)),
                        json_string(model.joints[limit.joint].name), e.engaged ? "true" : "false",
                        json_number(e.angle), json_number(e.rate));
  }
  return text + "]";
}

// {"minimum", "time", "pair": [body_a, body_b]}, or null when no clearance was checked.
std::string json_clearance(const ClearanceMinimum& clearance) {
  if (!clearance.checked) return "null";
  return fmt::format("{{\"minimum\": {}, \"time\": {}, \"pair\": {}}}",
                     json_number(clearance.distance), json_number(clearance.time),
                     json_string_list({clearance.body_a, clearance.body_b}));
}

std::string json_accuracy(const AccuracyEstimate& a) {
  return fmt::format("{{\"energy_relative\": {}, \"energy_residual\": {}, \"energy_scale\": {}, "
                     "\"local_error\": {}, \"drift_relative\": {}, \"warnings\": {}}}",
                     json_number(a.energy_relative), json_number(a.energy_residual),
                     json_number(a.energy_scale), json_number(a.local_error),
                     json_number(a.drift_relative), json_string_list(a.warnings));
}

// {"iterations", "force_residual", "force_scale", "unstable_directions"} of the static start, or null.
std::string json_statics(const RunSummary& summary) {
  if (!summary.statics) return "null";
  const multibody::StaticsResult& s = *summary.statics;
  return fmt::format("{{\"iterations\": {}, \"force_residual\": {}, \"force_scale\": {}, "
                     "\"unstable_directions\": {}}}",
                     s.iterations, json_number(s.force_residual), json_number(s.force_scale),
                     s.unstable_directions);
}

// [{"t", "joints": [...]}] of the hold-downs released.
std::string json_releases(const RunSummary& summary) {
  std::string text = "[";
  for (std::size_t k = 0; k < summary.releases.size(); ++k) {
    text += fmt::format("{}{{\"t\": {}, \"joints\": {}}}", k ? ", " : "",
                        json_number(summary.releases[k].t), json_string_list(summary.releases[k].joints));
  }
  return text + "]";
}

// {"window": s, "windows": [{"label", "start", "end", "states", "joints": [{"joint", "force",
// "force_time", "torque", "torque_time", "force_component": [x, y, z], "force_component_time",
// "torque_component", "torque_component_time"}]}]}; times null where nothing was seen.
std::string json_event_peaks(const results::EventPeaks& peaks) {
  std::string windows;
  for (std::size_t w = 0; w < peaks.windows.size(); ++w) {
    const results::PeakWindow& window = peaks.windows[w];
    std::string joints;
    for (std::size_t j = 0; j < peaks.joints.size(); ++j) {
      const results::JointPeak& p = window.joints[j];
      joints += fmt::format(
          "{}{{\"joint\": {}, \"force\": {}, \"force_time\": {}, \"torque\": {}, \"torque_time\": {}, "
          "\"force_component\": {}, \"force_component_time\": {}, \"torque_component\": {}, "
          "\"torque_component_time\": {}}}",
          j ? ", " : "", json_string(peaks.joints[j]), json_number(p.force), json_number(p.force_time),
          json_number(p.torque), json_number(p.torque_time), json_vector(p.force_component),
          json_vector(p.force_component_time), json_vector(p.torque_component), json_vector(p.torque_component_time));
    }
    windows += fmt::format("{}{{\"label\": {}, \"start\": {}, \"end\": {}, \"states\": {}, \"joints\": [{}]}}",
                           w ? ", " : "", json_string(window.start.label), json_number(window.start.t),
                           json_number(window.end), window.states, joints);
  }
  return fmt::format("{{\"window\": {}, \"windows\": [{}]}}", json_number(peaks.window), windows);
}

}  // namespace

std::string run_record_json(const multibody::Model& model, const RunSummary& summary,
                            const std::string& results_path) {
  std::vector<std::string> names, details;
  for (const RedundantEquationReport& r : summary.redundant) {
    names.push_back(r.name);
    details.push_back(r.description);
  }
  const integrate::Statistics& s = summary.statistics;
  const char* status = !summary.ok             ? results::layout::status::kFailed
                       : summary.accurate() ? results::layout::status::kOk
                                            : results::layout::status::kInaccurate;
  return fmt::format(
      "{{\"status\": {}, \"message\": {}, \"integrator\": {}, \"t_end\": {}, \"t_reached\": {}, "
      "\"samples\": {}, \"steps\": {}, \"rejected_steps\": {}, \"newton_failures\": {}, "
      "\"newton_iterations\": {}, \"jacobian_evaluations\": {}, \"residual_evaluations\": {}, "
      "\"wall_s\": {}, \"max_constraint_violation\": {}, \"max_velocity_violation\": {}, "
      "\"redundant\": {}, \"redundant_details\": {}, \"events\": {}, \"statics\": {}, "
      "\"releases\": {}, \"clearance\": {}, \"accuracy\": {}, \"event_peaks\": {}, \"results\": {}}}",
      json_string(status), json_string(summary.message), json_string(summary.integrator),
      json_number(summary.t_end), json_number(summary.t_reached), summary.samples, s.steps, s.rejected_steps,
      s.newton_failures, s.newton_iterations, s.jacobian_evaluations, s.residual_evaluations,
      json_number(summary.wall_seconds), json_number(summary.max_position_violation),
      json_number(summary.max_velocity_violation), json_string_list(names), json_string_list(details),
      json_events(model, summary.events), json_statics(summary), json_releases(summary),
      json_clearance(summary.clearance), json_accuracy(summary.accuracy), json_event_peaks(summary.peaks),
      json_string(results_path));
}

}  // namespace limber::run
