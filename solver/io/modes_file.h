// `modes.h5`: the mode sets of a case's flexible bodies, with their meshes, DOF layout
// and floating-frame invariants (layout in docs/modes-format.md). Written here by
// `limber modes`; read by the one reader of the file, results/modes_reader.h.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "fe/fe_model.h"
#include "modal/mode_set.h"

namespace limber::io {

// One body to write: references must outlive the call.
struct BodyModesRef {
  std::string name;
  const fe::FeModel* model = nullptr;
  const modal::ModeSet* mode_set = nullptr;
};

// Writes `path` (truncating it). Throws InputError when the file cannot be written.
void write_modes_file(const std::string& path, const std::string& title,
                      const std::string& case_file, const std::vector<BodyModesRef>& bodies);

// Translations of every node in mode `mode` of `shapes` (n_dof x nm): nn x 3.
Eigen::MatrixX3d mode_translations(const Eigen::MatrixXd& shapes, int mode);

}  // namespace limber::io
