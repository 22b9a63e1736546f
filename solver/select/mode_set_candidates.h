// Step 4 of the seed paper's procedure (its Fig. 2, compared as its Fig. 6 does): the mode sets
// a selection runs, built from the case's own normal-mode count and the kept reaction
// components (docs/select.md):
//   normal       the case's normal modes only (the ranking run)
//   normal+R3.Fz one kept component's static modes added, for each kept component
//   kept         every kept component's static modes added: the procedure's answer
//   more_normal  as many normal modes as `kept` has modes in all (like for like)
//   reference    many more normal modes plus every kept static mode: the richest set, against
//                which the others are measured
// A static mode is a unit load (attachment mode, with inertia relief on a free-free body) or a
// unit displacement (constraint mode) at the joint's FE node along the component's body axis.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "select/reaction_ranking.h"

namespace limber::select {

// Attachment modes stay elastic on a free-free body (inertia relief makes them M-orthogonal to
// the rigid motions the floating frame carries); a constraint mode at a node of a free-free body
// is a rigid motion and is dropped (docs/select.md).
enum class StaticModeKind { kAttachment, kConstraint };

struct ModeSetCandidate {
  std::string name;         // "normal", "normal+R3.Fz", "kept", "more_normal", "reference"
  std::string description;  // what it holds, in words
  io::ModeOverrides requests;  // per `flexible_bodies` entry
  bool reference = false;
  // Every flexible body nonlinear, unreduced (`--reference nonlinear`; io/formulation_override.h):
  // no modes, `requests` empty.
  bool nonlinear = false;
};

// One-component sets run when a selection has a target and its request does not say: each can
// be the answer then. Without a target the answer is `kept`, and they would only explain it, at
// 38 % of the satellite selection's CPU time (docs/select.md, "Which sets run"): none run unless
// asked for.
inline constexpr int kMaxSingle = 6;

struct CandidateOptions {
  StaticModeKind static_kind = StaticModeKind::kAttachment;
  // At most this many one-component sets (the largest kept first); empty: kMaxSingle with a
  // target, none without (run_selection; mode_set_candidates alone takes kMaxSingle).
  std::optional<int> max_single;
  int reference_normal = 0;  // normal modes per body in the reference; 0: 4 × the case's
};

// The case's requests with the static modes removed: the normal-mode run. Throws InputError
// when a flexible body asks for no normal modes (the procedure starts from them).
io::ModeOverrides normal_only(const io::Case& input);

// The sets above for the kept components of `ranking` (which must keep at least one), in the
// order listed. `input` must hold a mechanism; `normal` is the normal-mode run's reduction
// (its mode counts set those of the other sets).
std::vector<ModeSetCandidate> mode_set_candidates(const io::Case& input, const io::CaseReduction& normal,
                                                  const std::vector<RankedComponent>& ranking,
                                                  const CandidateOptions& options);

// The static modes of the sets, as a `modes` entry of a case file (docs/case-format.md), e.g.
// "normal: 5\nattachment: [{nodes: [101], dofs: [ux, uz]}]" (one line each, no indent).
std::string modes_yaml(const modal::ModeRequest& request, const std::vector<int>& node_ids);

}  // namespace limber::select
