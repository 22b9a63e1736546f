// Rigid-body modes Psi of an FE component about its frame origin (PITFALLS.md:
// rotational DOFs carry inertia, so they are part of Psi).
//
// For node p at undeformed position x_p (component frame, metres):
//   translation k (k = x, y, z):  u_p = e_k,        theta_p = 0
//   small rotation k:             u_p = e_k × x_p,  theta_p = e_k
// i.e. Psi = [Psi_t  Psi_r] with node blocks [I  -[x_p]×; 0  I] (n x 6, n = 6 nodes).
// Psi^T M Psi is the exact rigid mass matrix of the consistent-mass FE model.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "fe/fe_model.h"

namespace limber::modal {

// Psi, n x 6: columns ux, uy, uz (unit translations) then rx, ry, rz (unit small
// rotations about the component frame axes through the origin).
Eigen::MatrixXd rigid_body_modes(const fe::FeModel& model);

// The same for explicit node positions (used to rebuild Psi at deformed positions).
Eigen::MatrixXd rigid_body_modes(const std::vector<Eigen::Vector3d>& node_positions);

// The nodes' extent L [m], read from Psi's rotation columns: the largest distance of a node from
// the nodes' centre (1 m for a single node). Nodes with a zeroed translation row (a DOF made
// dependent by a multipoint constraint) are skipped.
double rigid_length_scale(const Eigen::MatrixXd& psi);

// Rigid motions that the held DOFs do not prevent: Psi N, with N a basis (6 x r) of the null
// space of Psi(held, :). r = 6 - rank(Psi(held, :)), numerical rank with relative tolerance
// kRankTolerance on the singular values, decided on an orthonormal basis of Psi with its
// translational rows divided by L (rigid_length_scale): free of units, of the model's size and of
// its distance from the frame origin. r = 0 for a restrained component; Psi itself when nothing
// is held.
Eigen::MatrixXd unrestrained_rigid_motion(const Eigen::MatrixXd& psi,
                                          const std::vector<int>& held_dofs);

inline constexpr double kRankTolerance = 1e-9;

// A statically determinate temporary support for the rigid motions `psi_free` (n x r,
// full DOF vectors): r DOFs chosen among `candidates` such that psi_free(support, :) is
// nonsingular, picked by column-pivoted QR of the candidates' rows of an orthonormal basis of
// psi_free with its translational rows divided by `length` (rigid_length_scale of the Psi that
// psi_free came from), which favours far-apart nodes (largest remaining rigid displacement) and
// so a well-conditioned support. Translational candidates are tried first, all candidates if
// those do not suffice. Returns the DOFs ascending; DEMANDs that r independent DOFs exist.
std::vector<int> determinate_support(const Eigen::MatrixXd& psi_free,
                                     const std::vector<int>& candidates, double length);

}  // namespace limber::modal
