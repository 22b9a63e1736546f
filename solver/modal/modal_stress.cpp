#include "modal/modal_stress.h"

#include "core/error.h"
#include "fe/element_stress.h"

namespace limber::modal {

namespace {

// Rows of the element's DOFs in the full FE vector, node-major.
template <int kNodes>
Eigen::Matrix<int, 6 * kNodes, 1> element_dofs(const std::array<int, kNodes>& nodes) {
  Eigen::Matrix<int, 6 * kNodes, 1> rows;
  for (int a = 0; a < kNodes; ++a) {
    for (int d = 0; d < 6; ++d) rows(6 * a + d) = 6 * nodes[a] + d;
  }
  return rows;
}

}  // namespace

ModalStress modal_stress(const fe::FeModel& model, const Eigen::MatrixXd& shapes) {
  LIMBER_DEMAND(shapes.rows() == model.dof_count());
  const Eigen::Index nm = shapes.cols();
  ModalStress out;
  out.beam_count = static_cast<int>(model.beams.size());
  out.shell_count = static_cast<int>(model.shells.size());
  out.beam_modal.resize(fe::kBeamResultants * out.beam_count, nm);
  out.shell_modal.resize(fe::kShellResultants * out.shell_count, nm);

  // Beams: R (12 x 12) times the element's rows of Φ.
  for (int e = 0; e < out.beam_count; ++e) {
    const fe::BeamElement& beam = model.beams[e];
    const fe::BeamProperty& property = model.beam_properties[beam.property];
    const fe::BeamResultantOperator r = fe::beam_resultant_operator(
        model.node_positions[beam.nodes[0]], model.node_positions[beam.nodes[1]], beam.orientation,
        property);
    out.beam_modal.middleRows(fe::kBeamResultants * e, fe::kBeamResultants) =
        r * shapes(element_dofs<2>(beam.nodes), Eigen::all);
    out.beam_sections.push_back(property.section);
  }
  // Shells: R (6 x 24) times the element's rows of Φ.
  for (int e = 0; e < out.shell_count; ++e) {
    const fe::ShellElement& shell = model.shells[e];
    const fe::ShellProperty& property = model.shell_properties[shell.property];
    std::array<Eigen::Vector3d, 4> corners;
    for (int k = 0; k < 4; ++k) corners[k] = model.node_positions[shell.nodes[k]];
    const fe::ShellResultantOperator r = fe::shell_resultant_operator(corners, property);
    out.shell_modal.middleRows(fe::kShellResultants * e, fe::kShellResultants) =
        r * shapes(element_dofs<4>(shell.nodes), Eigen::all);
    out.shell_properties.push_back(property);
  }
  return out;
}

ElementStresses recover_stresses(const ModalStress& stress, const Eigen::VectorXd& eta) {
  LIMBER_DEMAND(eta.size() == stress.beam_modal.cols() && eta.size() == stress.shell_modal.cols());
  ElementStresses out;
  // Superpose the resultants (linear), then the scalar stresses (not linear).
  out.beam_resultants = stress.beam_modal * eta;
  out.shell_resultants = stress.shell_modal * eta;
  out.shell_von_mises.resize(2 * stress.shell_count);
  out.equivalent.resize(stress.element_count());
  for (int e = 0; e < stress.beam_count; ++e) {
    out.equivalent(e) = fe::beam_extreme_fibre_stress(
        out.beam_resultants.segment<fe::kBeamResultants>(fe::kBeamResultants * e),
        stress.beam_sections[e]);
  }
  for (int s = 0; s < stress.shell_count; ++s) {
    const Eigen::Vector2d vm = fe::shell_von_mises(
        out.shell_resultants.segment<fe::kShellResultants>(fe::kShellResultants * s),
        stress.shell_properties[s]);
    out.shell_von_mises.segment<2>(2 * s) = vm;
    out.equivalent(stress.beam_count + s) = vm.maxCoeff();
  }
  return out;
}

}  // namespace limber::modal
