#include "io/formulation_override.h"

#include <algorithm>
#include <variant>

#include <fmt/format.h>

#include "core/error.h"

namespace limber::io {

namespace {

const FlexibleBodyCase& component_of(const Case& input, const FlexibleBodyEntry& body) {
  const auto found = std::find_if(input.flexible_bodies.begin(), input.flexible_bodies.end(),
                                  [&](const FlexibleBodyCase& c) { return c.name == body.component; });
  LIMBER_DEMAND(found != input.flexible_bodies.end());
  return *found;
}

// Rayleigh damping (any α, β) or none: what a nonlinear body can take.
bool rayleigh_or_undamped(const multibody::ModalDamping& damping) {
  if (damping.kind == multibody::ModalDamping::Kind::kRayleigh) return true;
  return (damping.ratios.array() == 0.0).all();
}

// The refusals of `formulation: nonlinear` (flexible_mechanism_body.cpp), on the read entry.
void check_can_be_nonlinear(const Case& input, const FlexibleBodyEntry& body, const std::string& option) {
  const auto fail = [&](const std::string& what) {
    throw InputError(fmt::format("{}: body '{}': expected {}", option, body.name, what), body.where);
  };
  const fe::FeModel& model = component_of(input, body).model;
  if (!model.shells.empty() || !model.triangles.empty()) {
    fail(fmt::format("beams only, got {} shell element(s) in '{}' (nonlinear shells are not available)",
                     model.shells.size() + model.triangles.size(), body.component));
  }
  for (const PerModeValues* values : {&body.modal_coordinates, &body.modal_velocities}) {
    if (values->values.size() > 0) fail(fmt::format("no '{}' (a nonlinear body has no modes), got one", values->key));
  }
  if (!rayleigh_or_undamped(body.damping) || body.damping_ratios.values.size() > 0) {
    fail("'damping: 0' or 'damping: {rayleigh: [alpha, beta]}' (a nonlinear body has no modes to give damping "
         "ratios to; without the key a modal body has a ratio of 0.01), got damping ratios");
  }
}

}  // namespace

bool nonlinear_formulation_requested(const std::string& name, const std::string& option) {
  if (name == "nonlinear") return true;
  if (name.empty() || name == "modal") return false;
  throw InputError(fmt::format("{}: expected modal or nonlinear, got '{}'", option, name));
}

void make_flexible_bodies_nonlinear(Case& input, const std::string& option) {
  LIMBER_DEMAND(input.mechanism.has_value());
  MechanismCase& mechanism = *input.mechanism;
  for (BodyEntry& entry : mechanism.bodies) {
    auto* body = std::get_if<FlexibleBodyEntry>(&entry);
    if (!body || body->nonlinear) continue;
    check_can_be_nonlinear(input, *body, option);
    body->nonlinear = true;
    body->formulation_where = body->where;
    mechanism.flexible_components.erase(body->name);
  }
}

}  // namespace limber::io
