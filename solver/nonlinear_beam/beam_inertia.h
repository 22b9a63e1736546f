// Inertia of a co-rotational beam structure (beam_structure.h): lumped nodal masses and rotary
// inertias, the nodal velocities that go with them, and the inertial force, its tangent, the
// kinetic energy and the momenta.
//
// Formulation: lumped (nodal) inertia. Each element gives each of its nodes half its mass,
// rho A l0 / 2 [kg], and a rotary inertia about the element's local axes (x along the beam)
//   diag(rho (Iy + Iz) l0/2,  rho Iy l0/2 + rho A l0^3/78,  rho Iz l0/2 + rho A l0^3/78)
// [kg m^2]: half the section's rotary inertia (the two bending terms dropped when
// BeamProperty::rotary_inertia is false, as the linear element does), plus on the two bending
// rotations the HRZ diagonal lumping of the consistent Euler-Bernoulli mass (Hinton, Rock &
// Zienkiewicz, Earthquake Eng. Struct. Dyn. 4 (1976) 245-249: the consistent diagonal
// 4 l0^2 rho A l0/420 scaled by 420/312 so that the translations carry the exact mass). The
// HRZ term vanishes as l0^2 under refinement and keeps the bending rotations from being
// nearly massless (their frequencies, and so the response to a suddenly applied moment, stay
// within reach of the time step). FeModel point masses add their mass and inertia at their
// node. The nodal inertia J_i is constant in the node's material frame (the frame R_i carries
// from the undeformed component axes), so with the material angular velocity W_i (R_i' = R_i S(W_i)) the inertial
// force of a node is exact and has no element-frame terms:
//   translations  m_i a_i                       (a_i = x_i'', component axes) [N]
//   rotations     J_i W_i' + W_i × J_i W_i        (material axes: Euler's equations) [N m]
// Lumped nodal inertia is the simple alternative of the co-rotational dynamics literature
// (Crisfield, Galvanetto & Jelenić, "Dynamics of 3-D co-rotational beams", Comput. Mech. 20
// (1997) 507-519; Le, Battini & Hjiaj, "A consistent 3D corotational beam element for
// nonlinear dynamic analysis of flexible structures", CMAME 269 (2014) 538-565, who derive the
// consistent co-rotational mass and compare it with lumped forms; neither re-read in this
// session). Chosen over the consistent co-rotational mass because its inertial force is
// exactly that of the nodal rigid bodies: the translational mass is constant, the only
// velocity term is the gyroscopic one above, energy and momentum follow in closed form, and
// the tangent is a 3x3 block per node. The price is the lumped mass's discretisation error on
// the frequencies, which falls as 1/n^2 with the element count n (the consistent linear mass, corotational_mass in
// beam_structure.h, stays available for modal checks): measured in
// tests/nonlinear_beam/test_dynamics.cpp and docs/nonlinear-beams.md.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "fe/fe_model.h"
#include "nonlinear_beam/beam_structure.h"

namespace limber::nonlinear_beam {

// Nodal inertia of the structure, frozen after lumped_inertia.
struct NodalInertia {
  std::vector<double> mass;              // m_i [kg]
  std::vector<Eigen::Matrix3d> inertia;  // J_i about the node, material axes [kg m^2]
};

// The lumped inertia of `model`'s beams and point masses (above). Throws InputError as
// build_beam_structure does for models this step does not treat, and when the model has DOF
// mass matrices (general masses), which have no nodal rigid-body form.
NodalInertia lumped_inertia(const fe::FeModel& model);

// Velocities of a structure: translational velocities x_i' [m/s] in component axes and
// material angular velocities W_i [rad/s] (R_i' = R_i S(W_i)).
struct BeamVelocity {
  std::vector<Eigen::Vector3d> linear;
  std::vector<Eigen::Vector3d> angular;
};

// Zero velocities for `node_count` nodes.
BeamVelocity zero_velocity(int node_count);

// The velocity of a rigid motion with linear velocity `v_0` [m/s] of the point `p_0` [m] and
// angular velocity `w` [rad/s] (both component axes) at the configuration `state`:
// x_i' = v_0 + w × (x_i - p_0), W_i = R_i^T w.
BeamVelocity rigid_velocity(const BeamState& state, const Eigen::Vector3d& p_0,
                            const Eigen::Vector3d& v_0, const Eigen::Vector3d& w);

// Kinetic energy sum 1/2 m_i |x_i'|^2 + 1/2 W_i^T J_i W_i [J].
double kinetic_energy(const NodalInertia& inertia, const BeamVelocity& velocity);

// Linear momentum sum m_i x_i' [kg m/s], component axes.
Eigen::Vector3d linear_momentum(const NodalInertia& inertia, const BeamVelocity& velocity);

// Angular momentum about the origin, sum (x_i × m_i x_i' + R_i J_i W_i) [kg m^2/s], component
// axes.
Eigen::Vector3d angular_momentum(const NodalInertia& inertia, const BeamState& state,
                                 const BeamVelocity& velocity);

// Gyroscopic moment W × J W [N m] of one node and its derivative in W, S(W) J - S(J W).
Eigen::Vector3d gyroscopic_moment(const Eigen::Matrix3d& j, const Eigen::Vector3d& w);
Eigen::Matrix3d gyroscopic_tangent(const Eigen::Matrix3d& j, const Eigen::Vector3d& w);

}  // namespace limber::nonlinear_beam
