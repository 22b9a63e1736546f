#include "model_description.h"

#include <fmt/format.h>

namespace limber::report {

bool is_nonlinear(const render::BodyTrack& body) {
  return body.flexible && body.node_displacements.cols() > 0;
}

std::string nonlinear_description(const render::BodyTrack& body) {
  return fmt::format("nonlinear, {} beam elements ({} nodes)", body.mesh.lines.rows(), body.mesh.nodes.rows());
}

}  // namespace limber::report
