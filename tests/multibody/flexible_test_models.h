// Flexible bodies shared by the multibody tests: the seed paper's steel rod section as FE
// beams (a straight rod, and a bent space frame whose every invariant term is non-zero),
// their component modes, and the FlexibleBodySpec that puts them into a model.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/error.h"
#include "fe/beam_section.h"
#include "fe/fe_model_builder.h"
#include "modal/component_modes.h"
#include "multibody/model_builder.h"

namespace limber::multibody::testing {

// Steel 0.01 m (local y) x 0.02 m (local z) beams of the seed rod (docs/seed-paper.md, example 1).
inline fe::BeamProperty seed_rod_property() {
  fe::BeamProperty property;
  property.name = "rod";
  property.material = {"steel", 206.8e9, 0.3, 7820.0};
  property.section = fe::rectangle_section(0.01, 0.02);
  return property;
}

// A polyline of beams through `corners` (body frame), `elements` per segment, nodes shared
// at the corners; `clamped` node indices get all 6 DOFs fixed (for constrained modes).
inline fe::FeModel beam_polyline(const std::vector<Eigen::Vector3d>& corners, int elements,
                                 const std::vector<int>& clamped = {}) {
  fe::FeModelBuilder builder;
  const int property = builder.add_beam_property(seed_rod_property());
  int previous = builder.add_node(1, corners[0]);
  for (size_t s = 0; s + 1 < corners.size(); ++s) {
    const Eigen::Vector3d a = corners[s], b = corners[s + 1], axis = (b - a).normalized();
    // Local y: the ground axis least aligned with the segment.
    Eigen::Index least = 0;
    axis.cwiseAbs().minCoeff(&least);
    const Eigen::Vector3d orientation = Eigen::Vector3d::Unit(least);
    for (int e = 1; e <= elements; ++e) {
      const int node = builder.add_node(builder.peek().node_count() + 1, a + (b - a) * e / double(elements));
      builder.add_beam(fe::BeamElement{{previous, node}, orientation, property});
      previous = node;
    }
  }
  for (int node : clamped) {
    for (int d = 0; d < fe::kDofsPerNode; ++d) builder.fix(node, static_cast<fe::Dof>(d));
  }
  return std::move(builder).build();
}

// Straight rod from the origin along +x.
inline fe::FeModel straight_rod(double length, int elements, const std::vector<int>& clamped = {}) {
  return beam_polyline({Eigen::Vector3d::Zero(), Eigen::Vector3d(length, 0, 0)}, elements, clamped);
}

// Bent frame 0.4 m along x, 0.3 m along y, 0.2 m along z: no symmetry, so every
// frame-mode coupling and first/second-order inertia term is non-zero.
inline fe::FeModel space_frame(int elements_per_segment, const std::vector<int>& clamped = {}) {
  return beam_polyline({Eigen::Vector3d::Zero(), Eigen::Vector3d(0.4, 0, 0), Eigen::Vector3d(0.4, 0.3, 0),
                        Eigen::Vector3d(0.4, 0.3, 0.2)},
                       elements_per_segment, clamped);
}

// The `count` lowest elastic normal modes (free-free when nothing is clamped) and, when
// given, inertia-relief / restrained attachment modes at `attachments`.
inline modal::ModeSet normal_modes(const fe::FeModel& model, int count,
                                   const std::vector<modal::StaticModeSite>& attachments = {}) {
  modal::ModeRequest request;
  request.normal_count = count;
  request.attachment_sites = attachments;
  modal::ModalResult result = modal::compute_component_modes(model, request);
  LIMBER_DEMAND(result.status == modal::ModalStatus::kOk);
  return std::move(result.mode_set);
}

inline FlexibleBodySpec flexible_spec(const std::string& name, const fe::FeModel& model, const modal::ModeSet& modes,
                                      const ModalDamping& damping) {
  FlexibleBodySpec spec;
  spec.name = name;
  spec.modes = modes;
  spec.node_positions_B = model.node_positions;
  spec.damping = damping;
  return spec;
}

}  // namespace limber::multibody::testing
