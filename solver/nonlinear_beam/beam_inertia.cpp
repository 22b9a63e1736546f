#include "nonlinear_beam/beam_inertia.h"

#include <fmt/format.h>

#include "core/error.h"
#include "fe/beam_element.h"
#include "nonlinear_beam/rotation.h"

namespace limber::nonlinear_beam {

NodalInertia lumped_inertia(const fe::FeModel& model) {
  if (!model.dof_masses.empty()) {
    throw InputError(fmt::format(
        "nonlinear beams: expected nodal masses only, got {} DOF mass matrices (general masses)",
        model.dof_masses.size()));
  }
  // The same element set as the stiffness (throws for shells, springs, ...).
  const BeamStructure structure = build_beam_structure(model);

  NodalInertia out;
  out.mass.assign(structure.node_count(), 0.0);
  out.inertia.assign(structure.node_count(), Eigen::Matrix3d::Zero());

  // Half of each element's mass to each of its nodes, and the rotary inertia above.
  for (std::size_t e = 0; e < model.beams.size(); ++e) {
    const fe::BeamElement& beam = model.beams[e];
    const CorotationalBeam& element = structure.elements[e];
    const fe::BeamProperty& property = model.beam_properties[beam.property];
    const double rho = property.material.density;
    const fe::BeamSection& section = property.section;
    const double half = 0.5 * element.length_0;
    const double iy = property.rotary_inertia ? section.inertia_y : 0.0;
    const double iz = property.rotary_inertia ? section.inertia_z : 0.0;
    // Section rotary inertia (half the element's), plus the HRZ diagonal of the consistent
    // Euler-Bernoulli translational mass on the two bending rotations, rho A l0^3 / 78.
    const double l3 = element.length_0 * element.length_0 * element.length_0;
    const double hrz = rho * section.area * l3 / 78.0;
    const Eigen::Vector3d local(half * rho * (section.inertia_y + section.inertia_z),
                                half * rho * iy + hrz, half * rho * iz + hrz);
    const Eigen::Matrix3d j_node = element.r_0 * local.asDiagonal() * element.r_0.transpose();
    for (int node : element.nodes) {
      out.mass[node] += half * rho * section.area;
      out.inertia[node] += j_node;
    }
  }

  // Point masses at their nodes.
  for (const fe::PointMass& p : model.point_masses) {
    out.mass[p.node] += p.mass;
    out.inertia[p.node] += p.inertia;
  }
  return out;
}

BeamVelocity zero_velocity(int node_count) {
  BeamVelocity v;
  v.linear.assign(node_count, Eigen::Vector3d::Zero());
  v.angular.assign(node_count, Eigen::Vector3d::Zero());
  return v;
}

BeamVelocity rigid_velocity(const BeamState& state, const Eigen::Vector3d& p_0,
                            const Eigen::Vector3d& v_0, const Eigen::Vector3d& w) {
  const int n = static_cast<int>(state.positions.size());
  BeamVelocity v = zero_velocity(n);
  for (int i = 0; i < n; ++i) {
    v.linear[i] = v_0 + w.cross(state.positions[i] - p_0);
    v.angular[i] = state.rotations[i].toRotationMatrix().transpose() * w;
  }
  return v;
}

double kinetic_energy(const NodalInertia& inertia, const BeamVelocity& velocity) {
  double t = 0.0;
  for (std::size_t i = 0; i < inertia.mass.size(); ++i) {
    t += 0.5 * inertia.mass[i] * velocity.linear[i].squaredNorm() +
         0.5 * velocity.angular[i].dot(inertia.inertia[i] * velocity.angular[i]);
  }
  return t;
}

Eigen::Vector3d linear_momentum(const NodalInertia& inertia, const BeamVelocity& velocity) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < inertia.mass.size(); ++i) p += inertia.mass[i] * velocity.linear[i];
  return p;
}

Eigen::Vector3d angular_momentum(const NodalInertia& inertia, const BeamState& state,
                                 const BeamVelocity& velocity) {
  Eigen::Vector3d h = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < inertia.mass.size(); ++i) {
    h += state.positions[i].cross(inertia.mass[i] * velocity.linear[i]) +
         state.rotations[i].toRotationMatrix() * (inertia.inertia[i] * velocity.angular[i]);
  }
  return h;
}

Eigen::Vector3d gyroscopic_moment(const Eigen::Matrix3d& j, const Eigen::Vector3d& w) {
  return w.cross(j * w);
}

Eigen::Matrix3d gyroscopic_tangent(const Eigen::Matrix3d& j, const Eigen::Vector3d& w) {
  return skew(w) * j - skew(j * w);
}

}  // namespace limber::nonlinear_beam
