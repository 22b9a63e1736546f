#include "multibody/flexible_body.h"

#include <cmath>

#include "core/error.h"

namespace limber::multibody {

const char* to_string(GeometricStiffening stiffening) {
  switch (stiffening) {
    case GeometricStiffening::kOff: return "off";
    case GeometricStiffening::kInertia: return "inertia_only";
    case GeometricStiffening::kFull: return "full";
  }
  return "?";
}

ModalDamping ModalDamping::ratio(double zeta) {
  ModalDamping d;
  d.ratios = Eigen::VectorXd::Constant(1, zeta);
  return d;
}

ModalDamping ModalDamping::per_mode(const Eigen::VectorXd& zeta) {
  ModalDamping d;
  d.ratios = zeta;
  return d;
}

ModalDamping ModalDamping::rayleigh(double alpha, double beta) {
  ModalDamping d;
  d.kind = Kind::kRayleigh;
  d.alpha = alpha;
  d.beta = beta;
  return d;
}

Eigen::VectorXd modal_damping_coefficients(const ModalDamping& damping, const Eigen::VectorXd& stiffness) {
  const Eigen::Index nm = stiffness.size();
  // Rayleigh: ΦᵀDΦ = α I + β diag(ω²).
  if (damping.kind == ModalDamping::Kind::kRayleigh) {
    return (damping.alpha + damping.beta * stiffness.array()).matrix();
  }
  // Ratio of critical: 2 ζ_i ω_i.
  LIMBER_DEMAND(damping.ratios.size() == 1 || damping.ratios.size() == nm);
  Eigen::VectorXd c(nm);
  for (Eigen::Index i = 0; i < nm; ++i) {
    const double zeta = damping.ratios.size() == 1 ? damping.ratios(0) : damping.ratios(i);
    c(i) = 2.0 * zeta * std::sqrt(std::max(stiffness(i), 0.0));
  }
  return c;
}

Eigen::Vector3d probe_deflection(const FlexibleBody& body, const DeflectionProbe& probe,
                                 const Eigen::VectorXd& eta) {
  const Eigen::Vector3d a = body.node_positions.col(probe.chord_start);
  const Eigen::Vector3d chord = body.node_positions.col(probe.chord_end) - a;
  const double s = (body.node_positions.col(probe.node) - a).dot(chord) / chord.squaredNorm();
  const auto u = [&](int node) -> Eigen::Vector3d { return body.translation_shapes(node) * eta; };
  return u(probe.node) - ((1.0 - s) * u(probe.chord_start) + s * u(probe.chord_end));
}

}  // namespace limber::multibody
