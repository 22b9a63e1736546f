#include "select/selection_json.h"

#include <fmt/format.h>

#include "core/json_text.h"

namespace limber::select {

namespace {

std::string json_ranking(const std::vector<RankedComponent>& ranking) {
  std::string text = "[";
  for (std::size_t k = 0; k < ranking.size(); ++k) {
    const RankedComponent& c = ranking[k];
    text += fmt::format(
        "{}{{\"component\": {}, \"body\": {}, \"joint\": {}, \"node\": {}, \"quantity\": {}, \"axis\": {}, "
        "\"peak\": {}, \"rms\": {}, \"relative\": {}, \"kept\": {}, \"indeterminate\": {}}}",
        k ? ", " : "", json_string(c.label()), json_string(c.body), json_string(c.joint), c.node_id,
        json_string(c.load == Load::kForce ? "force" : "torque"), json_string(std::string(1, "xyz"[c.axis])),
        json_number(c.peak), json_number(c.rms), json_number(c.relative), c.kept ? "true" : "false",
        c.indeterminate ? "true" : "false");
  }
  return text + "]";
}

// A set's event peaks against the reference's, one object per window and joint.
std::string json_peak_rows(const PeakComparison& peaks) {
  std::string text = "[";
  for (std::size_t k = 0; k < peaks.rows.size(); ++k) {
    const PeakDifference& r = peaks.rows[k];
    text += fmt::format("{}{{\"window\": {}, \"joint\": {}, \"start\": {}, \"reference_start\": {}, \"force\": {}, "
                        "\"reference_force\": {}, \"force_error\": {}, \"torque\": {}, \"reference_torque\": {}, "
                        "\"torque_error\": {}}}",
                        k ? ", " : "", json_string(r.window), json_string(r.joint), json_number(r.start),
                        json_number(r.reference_start), json_number(r.force), json_number(r.reference_force),
                        json_number(r.force_error), json_number(r.torque), json_number(r.reference_torque),
                        json_number(r.torque_error));
  }
  return text + "]";
}

std::string json_comparison(const std::vector<CandidateRun>& runs, const std::filesystem::path& root) {
  std::string text = "[";
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const CandidateRun& run = runs[k];
    text += fmt::format(
        "{}{{\"set\": {}, \"description\": {}, \"modes\": {}, \"reduction_s\": {}, \"run_s\": {}, "
        "\"status\": {}, \"message\": {}, \"f_max_hz\": {}, \"step\": {}, \"event_window\": {}, "
        "\"step_between_windows\": {}, \"steps_per_period\": {}, "
        "\"resolved\": {}, \"error_event\": {}, \"worst_event\": {}, \"error_peak\": {}, \"error_rms\": {}, "
        "\"worst_quantity\": {}, \"event_peaks\": {}, \"directory\": {}}}",
        k ? ", " : "", json_string(run.candidate.name), json_string(run.candidate.description), run.modes,
        json_number(run.reduction_seconds), json_number(run.summary.wall_seconds),
        json_string(run.status().substr(0, run.status().find(':'))), json_string(run.summary.message),
        json_number(run.step.f_max), json_number(run.step.step), json_number(run.step.window),
        json_number(run.step.window > 0.0 ? run.step.outside_step : run.step.step),
        json_number(run.step.steps_per_period),
        run.step.resolved ? "true" : "false", json_number(run.peaks.error), json_string(run.peaks.worst),
        json_number(run.error_peak), json_number(run.error_rms), json_string(run.worst_quantity),
        json_peak_rows(run.peaks), json_string(run.directory.lexically_relative(root).generic_string()));
  }
  return text + "]";
}

std::string json_reference_check(const ReferenceCheck& check) {
  return fmt::format("{{\"step\": {}, \"half_step\": {}, \"half_step_status\": {}, \"windows_rerun\": {}, "
                     "\"peak_change\": {}, \"worst\": {}, \"threshold\": {}, \"converged\": {}}}",
                     json_number(check.step), json_number(check.half_step),
                     json_string(check.half_step_status.substr(0, check.half_step_status.find(':'))),
                     check.windows_rerun,
                     json_number(check.change.error), json_string(check.change.worst), json_number(kConvergedChange),
                     check.converged ? "true" : "false");
}

}  // namespace

std::string selection_json(const Selection& selection, const SelectionRequest& request) {
  const std::vector<CandidateRun>& runs = selection.runs;
  return fmt::format("{{\"status\": \"ok\", \"reference\": {}, \"ranking\": {}, \"comparison\": {}, "
                     "\"reference_check\": {}, "
                     "\"chosen\": {}, \"target\": {}, \"target_met\": {}, \"norm\": {}, "
                     "\"steps_per_period_needed\": {}, \"fragment\": {}, \"directory\": {}}}",
                     json_string(request.nonlinear_reference ? "nonlinear" : "modal"), json_ranking(selection.ranking),
                     json_comparison(runs, request.root),
                     json_reference_check(selection.check),
                     selection.chosen ? json_string(runs[*selection.chosen].candidate.name) : std::string("null"),
                     request.target ? json_number(*request.target) : std::string("null"),
                     selection.chosen ? "true" : "false", json_string(to_string(request.norm)), kStepsPerPeriod,
                     json_string(selection.fragment), json_string(request.root.string()));
}

}  // namespace limber::select
