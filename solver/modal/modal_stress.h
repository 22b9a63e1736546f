// Modal stresses of a flexible component: the stress resultants of every element per unit
// modal coordinate, computed once from the mode shapes (normal and static modes alike), and
// their superposition at a state η. The resultants are linear in the nodal displacements
// u = Φ η, so r(η) = R Φ η = S η with S = R Φ precomputed; the scalar stresses (a beam's
// extreme-fibre stress, a shell's von Mises stress) are not linear and are evaluated from the
// superposed resultants. Element maps and stress formulas: fe/element_stress.h; the method:
// docs/stress-recovery.md.
//
// Elements are numbered beams first (FeModel::beams order), then shells (FeModel::shells),
// 0-based: element e < nb is beam e, else shell e − nb.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "fe/fe_model.h"

namespace limber::modal {

struct ModalStress {
  int beam_count = 0;   // nb
  int shell_count = 0;  // ns
  // Resultants per unit η: rows 12 e + k for beam e (fe::kBeamResultants order), rows 6 s + k
  // for shell s (fe::kShellResultants order); nm columns.
  Eigen::MatrixXd beam_modal;   // (12 nb) x nm [N, N·m per kg^½ m]
  Eigen::MatrixXd shell_modal;  // (6 ns) x nm [N/m, N·m/m per kg^½ m]
  // What the scalar stresses need: each element's section or shell property.
  std::vector<fe::BeamSection> beam_sections;      // nb
  std::vector<fe::ShellProperty> shell_properties;  // ns

  int element_count() const { return beam_count + shell_count; }
};

// S = R Φ for every element of `model`; `shapes` is the FE-DOF x nm mode matrix (ModeSet::shapes).
// Precondition (DEMAND): shapes.rows() == model.dof_count(). Throws as the element maps (a
// degenerate element, which the FE model's assembly has already rejected).
ModalStress modal_stress(const fe::FeModel& model, const Eigen::MatrixXd& shapes);

// Stresses of the whole mesh at modal coordinates η (nm values).
struct ElementStresses {
  Eigen::VectorXd beam_resultants;   // 12 nb: S_beam η
  Eigen::VectorXd shell_resultants;  // 6 ns: S_shell η
  Eigen::VectorXd shell_von_mises;   // 2 ns: (top, bottom) per shell [Pa]
  // Per element (beams then shells): the beam's extreme-fibre stress, or the larger of the
  // shell's two surface von Mises stresses [Pa]: what "the stress" of an element means in the
  // results' peak and colour maps.
  Eigen::VectorXd equivalent;
};
ElementStresses recover_stresses(const ModalStress& stress, const Eigen::VectorXd& eta);

}  // namespace limber::modal
