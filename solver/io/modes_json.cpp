#include "io/modes_json.h"

#include "core/json_text.h"
#include "fe/fe_model.h"
#include "modal/mode_set.h"

namespace limber::io {

std::string modes_json(const std::vector<BodyModesRef>& bodies, const std::vector<std::string>& failures) {
  std::string text = "{\"bodies\": {";
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const BodyModesRef& body = bodies[b];
    text += (b ? ", " : "") + json_string(body.name) + ": {\"dofs\": " + std::to_string(body.model->dof_count()) +
            ", \"modes\": [";
    bool first = true;
    auto add_modes = [&](const std::vector<modal::ModeInfo>& modes) {
      for (const modal::ModeInfo& mode : modes) {
        text += std::string(first ? "" : ", ") + "{\"kind\": " + json_string(modal::to_string(mode.kind)) +
                ", \"frequency_hz\": " + json_number(mode.frequency_hz) + ", \"label\": " + json_string(mode.label) +
                "}";
        first = false;
      }
    };
    add_modes(body.mode_set->rigid_modes);
    add_modes(body.mode_set->modes);
    text += "]}";
  }
  text += "}";
  // Bodies whose computation failed (only present after a numerical failure).
  if (!failures.empty()) {
    text += ", \"failures\": [";
    for (std::size_t i = 0; i < failures.size(); ++i) text += (i ? ", " : "") + json_string(failures[i]);
    text += "]";
  }
  return text + "}";
}

}  // namespace limber::io
