#include "io/flexible_body_modes.h"

#include <chrono>
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
  if (!body.modes) {
    const auto start = std::chrono::steady_clock::now();
    body.modes = std::make_shared<const modal::ModalResult>(compute_body_modes(body));
    body.reduction_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
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
