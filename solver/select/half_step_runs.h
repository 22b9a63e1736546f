// The reference's convergence check at half its step, run beside the reference (docs/select.md,
// "Reference check"): its event windows re-run in stretches (windowed_twin.h), each started on
// the job queue as soon as the reference has run far enough past it that no later window can
// join it, instead of all of them after the reference. On the satellite all three of the
// check's stretches (21 CPU s) are queued while the reference runs, the last at 4.8 s of its 6 s,
// and the second core takes them between the other sets (docs/benchmarks.md, "`limber select`
// on the satellite: the sets the answer needs").
//
// The stretches of the reference's final windows decide: a stretch started early is used when it
// is one of them (same windows, start and end), and any other runs once the queue is done. So
// the check is the one twin_stretches gives, whatever was started early; a reference whose
// restart points are not kept (run::restart_points_supported, a nonlinear reference) starts none
// early.
#pragma once

#include <cstddef>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "select/job_queue.h"
#include "select/selection_study.h"
#include "select/windowed_twin.h"

namespace limber::select {

struct SelectionRequest;
struct SelectionHooks;

// A mode set's name as a folder name: letters, digits, '.', '+', '-', '_' kept, others '_'.
std::string folder_name(const std::string& name);

// Whether no window the reference opens once it has reached `t_reached` [s] can join `stretch`
// (twin_stretches merges a window whose start lies before a stretch's end): a later window's
// restart point lies a step or two before its event, and its event after t_reached, so a
// window's length `window` [s] past the stretch's end is room enough.
bool stretch_settled(const TwinStretch& stretch, double t_reached, double window);

class HalfStepRuns {
 public:
  // `first_number` and `sets` number the stretches for the hooks ([first_number + k / sets + k + 1]).
  HalfStepRuns(const SelectionRequest& request, const SelectionHooks& hooks, std::size_t first_number,
               std::size_t sets);

  // Whether the reference `reference` (prepared, not yet run) gets stretches started early.
  static bool starts_early(const CandidateRun& reference);

  // Runs the modal reference `candidate` of `input` into `slot`, in place (its stretches read it
  // while it runs), into DIR/runs/<its folder>, each stretch that starts early going to `queue`
  // as soon as the reference has run past it (on_reference_progress). Throws as run_candidate.
  void run_reference(const std::shared_ptr<const io::Case>& input, const ModeSetCandidate& candidate, JobQueue& queue,
                     std::optional<CandidateRun>& slot);

  // The reference's progress, on its thread during its run with `settings`: its windows so far
  // (the start's and reference.window_restarts') and the time reached [s]. Each stretch settled
  // by then that has not been started goes to the front of `queue`. `reference` must stay in
  // place until the queue has run.
  void on_reference_progress(JobQueue& queue, const CandidateRun& reference, const io::RunSettings& settings,
                             double t_reached);

  // The reference has run and passed its own accuracy check (on its thread): the stretches of
  // its final windows; those not started early go to the front of `queue`, the first to run
  // first (`columns` as run_candidate's: the nonlinear reference's, whose windows all re-run
  // from t = 0, its restart points not being kept).
  void on_reference_done(JobQueue& queue, const CandidateRun& reference, const multibody::Model* columns);

  // After the queue has run: `runs` in the order of `stretches`.
  void collect();

  std::vector<TwinStretch> stretches;  // the stretches of the reference's final windows
  std::vector<CandidateRun> runs;      // their runs, in the same order (after collect)
  std::size_t started_early = 0;       // of them, how many were started while the reference ran

 private:
  // The job that runs `stretch` into a new slot, whose number goes to `k` (lock_ held).
  JobQueue::Job stretch_job(const CandidateRun& reference, const TwinStretch& stretch,
                            const multibody::Model* columns, std::size_t& k);
  // Stretch number `k` of the reference re-run at half its step from its restart point.
  CandidateRun run_stretch(const CandidateRun& reference, const TwinStretch& stretch, std::size_t k,
                           const multibody::Model* columns) const;

  const SelectionRequest& request_;
  const SelectionHooks& hooks_;
  std::size_t first_number_ = 0, sets_ = 0;
  std::mutex lock_;                                // guards launched_ and early_ (growing)
  std::vector<TwinStretch> launched_;                 // started, in order
  std::deque<std::optional<CandidateRun>> launched_runs_;  // their runs (a deque: slots stay in place)
  std::vector<std::size_t> slots_;                    // per final stretch, its slot in launched_
};

}  // namespace limber::select
