#include "io/case_reduction.h"

#include <algorithm>
#include <chrono>

#include "core/error.h"

namespace limber::io {

namespace {

// Runs one body's reduction; an impossible request is an InputError at its `modes` entry.
BodyReduction reduce_body(const FlexibleBodyCase& body, const modal::ModeRequest& request) {
  const auto start = std::chrono::steady_clock::now();
  BodyReduction reduction{body.name, {}, 0.0};
  try {
    reduction.result = modal::compute_component_modes(body.model, request);
  } catch (const InputError& error) {
    if (error.where().known()) throw;
    throw InputError("body '" + body.name + "': " + error.message(), body.modes_where);
  }
  reduction.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return reduction;
}

}  // namespace

const BodyReduction* CaseReduction::find(const std::string& name) const {
  const auto found = std::find_if(bodies.begin(), bodies.end(),
                                  [&](const BodyReduction& b) { return b.name == name; });
  return found == bodies.end() ? nullptr : &*found;
}

double CaseReduction::seconds() const {
  double total = 0.0;
  for (const BodyReduction& body : bodies) total += body.seconds;
  return total;
}

CaseReduction reduce_case(const Case& input, ReductionScope scope, const ModeOverrides& overrides) {
  // Every override must name an entry.
  for (const auto& override_entry : overrides) {
    // A named reference, not a structured binding: clang 14 cannot capture those in a lambda.
    const std::string& name = override_entry.first;
    const bool known = std::any_of(input.flexible_bodies.begin(), input.flexible_bodies.end(),
                                   [&](const FlexibleBodyCase& b) { return b.name == name; });
    if (!known) {
      throw InputError("expected an entry of 'flexible_bodies' named '" + name +
                           "' for a mode set, got none",
                       SourceLocation{input.file, 0, 0});
    }
  }
  // The bodies in scope, each once (several mechanism bodies may share an entry).
  CaseReduction reduction;
  for (const FlexibleBodyCase& body : input.flexible_bodies) {
    if (scope == ReductionScope::kMechanismBodies) {
      if (!input.mechanism) continue;
      const auto& used = input.mechanism->flexible_components;
      const bool in_use = std::any_of(used.begin(), used.end(),
                                      [&](const auto& entry) { return entry.second == body.name; });
      if (!in_use) continue;
    }
    const auto replaced = overrides.find(body.name);
    reduction.bodies.push_back(
        reduce_body(body, replaced == overrides.end() ? body.request : replaced->second));
  }
  return reduction;
}

}  // namespace limber::io
