// linear.h5 of `limber linearize` (layout: results/linear_layout.h, docs/linearize.md): the
// tangent matrices, the null-space basis, the system modes, the mass properties and the
// cantilevered modes of a LinearizeSummary.
#pragma once

#include <filesystem>
#include <string>

#include "multibody/model.h"
#include "run/linearize_run.h"

namespace limber::run {

// Writes DIR/linear.h5 (replacing it) and returns its path. Throws std::runtime_error naming the
// file and the object when HDF5 fails.
std::filesystem::path write_linear_h5(const multibody::Model& model, const LinearizeSummary& summary,
                                      const std::filesystem::path& directory, const std::string& title,
                                      const std::string& case_file);

}  // namespace limber::run
