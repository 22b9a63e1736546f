#include "multibody/nonlinear_body_stress.h"

#include "core/error.h"
#include "fe/element_stress.h"
#include "nonlinear_beam/corotational_beam.h"

namespace limber::multibody {

Eigen::VectorXd nonlinear_beam_resultants(const nonlinear_beam::BeamStructure& structure,
                                          const nonlinear_beam::BeamState& state) {
  const auto ne = static_cast<Eigen::Index>(structure.elements.size());
  Eigen::VectorXd resultants(fe::kBeamResultants * ne);
  for (Eigen::Index e = 0; e < ne; ++e) {
    const nonlinear_beam::CorotationalBeam& element = structure.elements[static_cast<std::size_t>(e)];
    const auto a = static_cast<std::size_t>(element.nodes[0]);
    const auto b = static_cast<std::size_t>(element.nodes[1]);
    // The local forces (N, m_a, m_b) in the element's current frame; the force alone.
    const nonlinear_beam::ElementResponse response = nonlinear_beam::corotational_beam_response(
        element, state.positions[a], state.positions[b], state.rotations[a].toRotationMatrix(),
        state.rotations[b].toRotationMatrix(), false);
    const Eigen::Vector3d m_a = response.local_forces.segment<3>(1);
    const Eigen::Vector3d m_b = response.local_forces.segment<3>(4);
    // The node-b force that balances the end moments over the current chord.
    const double l = (state.positions[b] - state.positions[a]).norm();
    const Eigen::Vector3d F_b(response.local_forces(0), -(m_a.z() + m_b.z()) / l, (m_a.y() + m_b.y()) / l);
    auto r = resultants.segment<fe::kBeamResultants>(fe::kBeamResultants * e);
    r << F_b, -m_a, F_b, m_b;
  }
  return resultants;
}

Eigen::VectorXd nonlinear_beam_fibre_stresses(const Eigen::VectorXd& resultants,
                                              const std::vector<fe::BeamSection>& sections) {
  const auto ne = static_cast<Eigen::Index>(sections.size());
  LIMBER_DEMAND(resultants.size() == fe::kBeamResultants * ne);
  Eigen::VectorXd stress(ne);
  for (Eigen::Index e = 0; e < ne; ++e) {
    stress(e) = fe::beam_extreme_fibre_stress(resultants.segment<fe::kBeamResultants>(fe::kBeamResultants * e),
                                              sections[static_cast<std::size_t>(e)]);
  }
  return stress;
}

std::vector<fe::BeamSection> beam_sections_of(const fe::FeModel& model) {
  std::vector<fe::BeamSection> sections;
  for (const fe::BeamElement& beam : model.beams) {
    sections.push_back(model.beam_properties[static_cast<std::size_t>(beam.property)].section);
  }
  return sections;
}

}  // namespace limber::multibody
