#include "select/half_step_runs.h"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "results/file_names.h"
#include "run/window_restart.h"
#include "select/selection_procedure.h"

namespace limber::select {

namespace {

// A stretch's folder under runs/<reference>_half_step: "1_start", "2_latch_latch_R3".
std::string stretch_folder(const std::string& reference, std::size_t k, const TwinStretch& stretch) {
  return folder_name(reference) + "_half_step/" + folder_name(fmt::format("{}_{}", k + 1, stretch.windows.front()));
}

bool same_stretch(const TwinStretch& a, const TwinStretch& b) {
  return a.t_start() == b.t_start() && a.t_end == b.t_end && a.windows == b.windows;
}

// The reference's windows so far, as twin_stretches reads them: the start's and each reported
// one's, `window` s long.
results::EventPeaks windows_so_far(const std::vector<run::WindowRestart>& restarts, double window) {
  results::EventPeaks peaks;
  peaks.window = window;
  peaks.windows.push_back({{0.0, "start"}, window, 0, {}});
  for (const run::WindowRestart& restart : restarts) {
    peaks.windows.push_back({restart.window, restart.window.t + window, 0, {}});
  }
  return peaks;
}

}  // namespace

std::string folder_name(const std::string& name) {
  std::string folder;
  for (char c : name) {
    const bool plain = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-' || c == '_';
    folder += plain ? c : '_';
  }
  return folder;
}

bool stretch_settled(const TwinStretch& stretch, double t_reached, double window) {
  return t_reached >= stretch.t_end + window;
}

HalfStepRuns::HalfStepRuns(const SelectionRequest& request, const SelectionHooks& hooks, std::size_t first_number,
                           std::size_t sets)
    : request_(request), hooks_(hooks), first_number_(first_number), sets_(sets) {}

bool HalfStepRuns::starts_early(const CandidateRun& reference) {
  return !reference.candidate.nonlinear && run::restart_points_supported(reference.mechanism.model);
}

void HalfStepRuns::run_reference(const std::shared_ptr<const io::Case>& input, const ModeSetCandidate& candidate,
                                 JobQueue& queue, std::optional<CandidateRun>& slot) {
  CandidateRun& run =
      slot.emplace(prepare_candidate(input, candidate, request_.root / results::kRunsFolder / folder_name(candidate.name)));
  const io::RunSettings settings = candidate_settings(run.mechanism, request_.adjust, request_.policy, run.step);
  const bool early = starts_early(run);
  run_mechanism_recorded(*input, run.mechanism, settings, candidate.name, nullptr,
                         [&](const integrate::Sample& sample) {
                           if (hooks_.on_sample) hooks_.on_sample(sample, request_.jobs <= 1);
                           if (early) on_reference_progress(queue, run, settings, sample.t);
                         },
                         run);
}

void HalfStepRuns::on_reference_progress(JobQueue& queue, const CandidateRun& reference,
                                         const io::RunSettings& settings, double t_reached) {
  const double window = settings.peak_window;
  if (window <= 0.0) return;
  const std::vector<TwinStretch> known =
      twin_stretches(windows_so_far(reference.window_restarts, window), reference.window_restarts, settings.t_end);
  const std::lock_guard guard(lock_);
  for (const TwinStretch& stretch : known) {
    if (!stretch_settled(stretch, t_reached, window)) break;  // nor can any later one be
    const bool started = std::any_of(launched_.begin(), launched_.end(),
                                     [&](const TwinStretch& s) { return same_stretch(s, stretch); });
    if (started) continue;
    std::size_t k = 0;
    queue.push_front(stretch_job(reference, stretch, nullptr, k));
  }
}

void HalfStepRuns::on_reference_done(JobQueue& queue, const CandidateRun& reference,
                                     const multibody::Model* columns) {
  stretches = twin_stretches(reference.summary.peaks,
                             columns ? std::vector<run::WindowRestart>{} : reference.window_restarts,
                             reference.summary.t_end);
  const std::lock_guard guard(lock_);
  const std::size_t early = launched_.size();
  std::vector<std::size_t> late;
  slots_.clear();
  for (const TwinStretch& stretch : stretches) {
    const auto found = std::find_if(launched_.begin(), launched_.begin() + static_cast<std::ptrdiff_t>(early),
                                    [&](const TwinStretch& s) { return same_stretch(s, stretch); });
    slots_.push_back(static_cast<std::size_t>(found - launched_.begin()));
    if (slots_.back() < early) {
      ++started_early;
    } else {
      late.push_back(slots_.size() - 1);
    }
  }
  // The others at the front of the queue, numbered in order, the first to run first.
  std::vector<JobQueue::Job> jobs;
  for (const std::size_t k : late) jobs.push_back(stretch_job(reference, stretches[k], columns, slots_[k]));
  for (std::size_t k = jobs.size(); k-- > 0;) queue.push_front(std::move(jobs[k]));
}

void HalfStepRuns::collect() {
  runs.clear();
  for (const std::size_t slot : slots_) runs.push_back(std::move(*launched_runs_[slot]));
}

JobQueue::Job HalfStepRuns::stretch_job(const CandidateRun& reference, const TwinStretch& stretch,
                                        const multibody::Model* columns, std::size_t& k) {
  k = launched_.size();
  launched_.push_back(stretch);
  std::optional<CandidateRun>* slot = &launched_runs_.emplace_back();
  const CandidateRun* ran = &reference;
  return [this, ran, stretch, k, slot, columns](JobQueue&) { *slot = run_stretch(*ran, stretch, k, columns); };
}

CandidateRun HalfStepRuns::run_stretch(const CandidateRun& reference, const TwinStretch& stretch, std::size_t k,
                                       const multibody::Model* columns) const {
  const std::string folder = stretch_folder(reference.candidate.name, k, stretch);
  const std::string description = fmt::format("{}, windows {} re-run from t = {:.6g} s", reference.candidate.description,
                                              fmt::join(stretch.windows, ", "), stretch.t_start());
  if (hooks_.on_set_start) hooks_.on_set_start({first_number_ + k, sets_ + k + 1, folder, description, 0.5});
  StepPolicy policy = request_.policy;
  policy.scale = 0.5;
  CandidateRun run;
  run.candidate = reference.candidate;
  run.input = reference.input;
  run.modes = reference.modes;
  run.directory = request_.root / results::kRunsFolder / folder;
  io::RunSettings settings = candidate_settings(reference.mechanism, request_.adjust, policy, run.step);
  settings.t_end = stretch.t_end;
  run_mechanism_recorded(*reference.input, reference.mechanism, settings, reference.candidate.name + " at half its step",
                         stretch.restart ? &*stretch.restart : nullptr,
                         [&](const integrate::Sample& sample) {
                           if (hooks_.on_sample) hooks_.on_sample(sample, request_.jobs <= 1);
                         },
                         run, columns);
  if (hooks_.on_set_done) hooks_.on_set_done(run, folder);
  return run;
}

}  // namespace limber::select
