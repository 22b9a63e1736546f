// The second stage of the pipeline read (case_reader.h) -> reduce -> build
// (mechanism_builder.h): the modal reduction of a case's flexible bodies
// (modal::compute_component_modes on each body's FE model and mode request, seed paper
// eq. 4-11), returned as a value; the Case is not changed.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "io/case_reader.h"
#include "modal/component_modes.h"

namespace limber::io {

// Mode requests that replace those of the case file, by `flexible_bodies` entry name: how
// `limber select` runs one mechanism with several mode sets (the FE models stay as read).
using ModeOverrides = std::map<std::string, modal::ModeRequest>;

// One body's reduction: the mode set, or the numerical failure in result.status.
struct BodyReduction {
  std::string name;            // the `flexible_bodies` entry
  modal::ModalResult result;   // status, message, mode set, notices
  double seconds = 0.0;        // wall time [s]
};

struct CaseReduction {
  std::vector<BodyReduction> bodies;  // in `flexible_bodies` order, those reduced

  // The reduction of entry `name`, or null when it was not reduced.
  const BodyReduction* find(const std::string& name) const;
  // Sum of the bodies' wall times [s].
  double seconds() const;
};

// Which bodies to reduce: every `flexible_bodies` entry (`limber modes`), or those the
// mechanism uses (`limber run`, `limber select`; none without a mechanism).
enum class ReductionScope { kAllBodies, kMechanismBodies };

// Reduces the bodies of `scope`, with the requests of `overrides` in place of the case's.
// Throws InputError when an override names no `flexible_bodies` entry, or when a request
// cannot be met (at the body's `modes` entry). A numerical failure (singular matrix, no
// convergence) is not thrown: it is the body's result.status, with the others still computed.
CaseReduction reduce_case(const Case& input, ReductionScope scope,
                          const ModeOverrides& overrides = {});

}  // namespace limber::io
