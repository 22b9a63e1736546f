#include "io/flexible_body_modes.h"

#include <memory>

#include "core/error.h"

namespace limber::io {

modal::ModalResult compute_body_modes(const FlexibleBodyCase& body) {
  try {
    return modal::compute_component_modes(body.model, body.request);
  } catch (const InputError& error) {
    if (error.where().known()) throw;
    throw InputError("body '" + body.name + "': " + error.message(), body.modes_where);
  }
}

const modal::ModeSet& body_mode_set(FlexibleBodyCase& body) {
  if (!body.modes) body.modes = std::make_shared<const modal::ModalResult>(compute_body_modes(body));
  if (body.modes->status != modal::ModalStatus::kOk) {
    throw NumericalError("modes of flexible body '" + body.name + "' (" +
                         body.modes_where.to_string() + "): " +
                         (body.modes->status == modal::ModalStatus::kSingular
                              ? "singular matrix: "
                              : "eigen-solver did not converge: ") +
                         body.modes->message);
  }
  return body.modes->mode_set;
}

}  // namespace limber::io
