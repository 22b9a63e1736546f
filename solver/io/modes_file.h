// `modes.h5`: the mode sets of a case's flexible bodies, with their meshes, DOF layout
// and floating-frame invariants (layout in docs/modes-format.md). Written by
// `limber modes`, read back by tests and later analyses.
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

// One body as read back.
struct BodyModes {
  std::string name;
  std::vector<Eigen::Vector3d> nodes;  // undeformed, body frame [m]
  std::vector<int> node_ids;
  std::vector<std::array<int, 2>> lines;  // beam elements (node indices)
  std::vector<std::array<int, 4>> quads;  // shell elements (node indices)
  std::vector<fe::FixedDof> fixed_dofs;
  modal::ModeSet mode_set;
  // Translational part of each mode shape, nm entries of nn x 3 [m per unit modal coordinate].
  std::vector<Eigen::MatrixX3d> translations;
  // Modal stresses (modal/modal_stress.h, ModalStress::beam_modal and shell_modal): element
  // resultants per unit modal coordinate, (12 beams) x nm and (6 shells) x nm; empty when the
  // file predates them.
  Eigen::MatrixXd beam_stress_modal, shell_stress_modal;
};

struct ModesFile {
  std::string title;
  std::string case_file;
  std::vector<BodyModes> bodies;  // in the order written
};

// Writes `path` (truncating it). Throws InputError when the file cannot be written.
void write_modes_file(const std::string& path, const std::string& title,
                      const std::string& case_file, const std::vector<BodyModesRef>& bodies);

// Reads a file written by write_modes_file. Throws InputError when it is missing,
// is not a limber modes file, or lacks a dataset.
ModesFile read_modes_file(const std::string& path);

// Translations of every node in mode `mode` of `shapes` (n_dof x nm): nn x 3.
Eigen::MatrixX3d mode_translations(const Eigen::MatrixXd& shapes, int mode);

}  // namespace limber::io
