// Co-rotational 3D beam element: internal force and consistent tangent stiffness of limber's
// linear 2-node beam (fe/beam_element.h) carried through arbitrarily large rigid motions.
//
// Formulation: Crisfield, "A consistent co-rotational formulation for non-linear,
// three-dimensional, beam-elements", CMAME 81 (1990) 131-150 and "Non-linear Finite Element
// Analysis of Solids and Structures" vol. 2 (1997) ch. 17; the element frame, local variables
// and tangent of Battini & Pacoste, "Co-rotational beam elements with warping effects in
// instability problems", CMAME 191 (2002) 1755-1789, section 3 (without warping):
//  - node triads t_i = R_i R_0 (R_i: nodal rotation from the undeformed state, R_0: the
//    element's undeformed local axes as columns, beam_local_axes transposed);
//  - element frame R_r = [r1 r2 r3]: r1 along the chord x_b - x_a, r3 = r1 × q / |r1 × q|,
//    r2 = r3 × r1 with q = (t_a e2 + t_b e2) / 2 (mean of the nodes' local y axes);
//  - local deformations p_l = (u, theta_a, theta_b): u = l - l0, theta_i = log(R_r^T t_i);
//  - local forces f_l = K_l p_l, K_l the 7x7 restriction of the linear element's stiffness
//    (Euler-Bernoulli or Timoshenko, per BeamProperty) to axial stretch and end rotations, all
//    other local displacements being zero in the chord frame by construction (small strain);
//  - global force f_g = B^T f_l and tangent K_g = B^T K_l B + K_h + K_m, where B maps global
//    variations (translations, spatial spins) to local ones, K_h comes from T_s^-1 of the
//    local rotations and K_m from the variation of B (frame rotation, chord length, and the
//    eta terms of the mean vector q, all kept: the tangent is the exact derivative of f_g).
//
// DOF order of the 12-vectors: (x_a, w_a, x_b, w_b), translations [m] and spatial spins [rad]
// in component axes, the order of FeModel. Units: forces [N], moments [N m].
#pragma once

#include <Eigen/Core>
#include <array>

#include "fe/beam_element.h"
#include "fe/fe_model.h"

namespace limber::nonlinear_beam {

using Matrix7d = Eigen::Matrix<double, 7, 7>;
using Vector7d = Eigen::Matrix<double, 7, 1>;
using Vector12d = Eigen::Matrix<double, 12, 1>;
using fe::Matrix12d;

// Constant data of one element (set up once from the FE model).
struct CorotationalBeam {
  std::array<int, 2> nodes{};                         // node indices (a, b)
  Eigen::Matrix3d r_0 = Eigen::Matrix3d::Identity();  // undeformed local axes as columns
  double length_0 = 0.0;                              // undeformed length [m]
  Matrix7d local_stiffness = Matrix7d::Zero();        // K_l on (u, theta_a, theta_b)
  Matrix12d local_mass = Matrix12d::Zero();           // the linear element's consistent mass,
                                                      // local axes (fe::beam_local_matrices)
};

// The element of FE beam `beam` of `model`. Throws InputError as fe::beam_local_axes.
CorotationalBeam make_corotational_beam(const fe::FeModel& model, const fe::BeamElement& beam);

// Kelvin-Voigt damping of the local deformations (docs/nonlinear-beams.md, "Rayleigh damping in
// a mechanism"): f_l = K_l (p_l + beta p_l'), p_l' = B_h B_a E^T v, v the nodes' velocities
// (x_a', w_a, x_b', w_b: translation rates [m/s] and spatial angular velocities [rad/s],
// component axes). Objective: B annihilates rigid velocities, so rigid motion is not damped.
struct DeformationRateDamping {
  double beta = 0.0;                       // [s]; 0: undamped (the force is then unchanged)
  Vector12d velocity = Vector12d::Zero();  // v above
  bool with_matrix = false;                // fill ElementResponse::damping
};

struct ElementResponse {
  Vector12d force;         // internal force f_g (what the element exerts on its nodes, negated),
                           // with the damping force when DeformationRateDamping::beta > 0
  Matrix12d tangent;       // d f_g / d(x_a, w_a, x_b, w_b), exact without damping; not symmetric
                           // off equilibrium
  Eigen::Matrix3d frame;   // element frame R_r (columns r1, r2, r3)
  Vector7d local_forces;   // f_l = (N, m_a, m_b) conjugate to p_l
  double dissipation = 0.0;  // beta p_l'^T K_l p_l' [W]: the power the damping removes
  Matrix12d damping;         // d f_g / d v = beta (B_h B_a E^T)^T K_l (B_h B_a E^T), with_matrix only
};

// Strain energy 1/2 p_l^T K_l p_l [J] of the element in the same configuration; f_g is its
// gradient along (translations, spatial spins).
double corotational_beam_energy(const CorotationalBeam& element, const Eigen::Vector3d& x_a,
                                const Eigen::Vector3d& x_b, const Eigen::Matrix3d& rotation_a,
                                const Eigen::Matrix3d& rotation_b);

// Response at node positions x_a, x_b [m] and nodal rotations rotation_a, rotation_b (from the
// undeformed state, component axes). Precondition (LIMBER_DEMAND): the nodes do not coincide
// and the mean y axis q is not parallel to the chord (a relative rotation of the two node
// triads near pi, outside any beam's small-strain range). Without `with_tangent` the tangent
// is left unset: a residual needs only the force, and the tangent is three quarters of the cost.
// With `damping` (beta > 0) the force carries the deformation-rate damping; the tangent then
// leaves out the change of the damping force with the configuration (a Newton matrix term).
ElementResponse corotational_beam_response(const CorotationalBeam& element,
                                           const Eigen::Vector3d& x_a,
                                           const Eigen::Vector3d& x_b,
                                           const Eigen::Matrix3d& rotation_a,
                                           const Eigen::Matrix3d& rotation_b,
                                           bool with_tangent = true,
                                           const DeformationRateDamping& damping = {});

}  // namespace limber::nonlinear_beam
