#include "nonlinear_beam/corotational_beam.h"

#include "core/error.h"
#include "nonlinear_beam/rotation.h"

namespace limber::nonlinear_beam {

namespace {

using Matrix3x12 = Eigen::Matrix<double, 3, 12>;
using Matrix12x3 = Eigen::Matrix<double, 12, 3>;
using Matrix7x12 = Eigen::Matrix<double, 7, 12>;

// Local DOFs of the 12x12 linear element that p_l = (u, theta_a, theta_b) stands for: axial
// displacement of node b (node a at the origin) and the rotations of both nodes.
constexpr std::array<int, 7> kLocalDofs = {6, 3, 4, 5, 9, 10, 11};

// Selects the spin of node a (columns 3-5) or b (9-11) of a 12-vector.
Matrix3x12 spin_selector(int node) {
  Matrix3x12 s = Matrix3x12::Zero();
  s.block<3, 3>(0, 6 * node + 3).setIdentity();
  return s;
}

// Element frame R_r (Battini & Pacoste 2002, eq. 12) from the chord direction r1 and the
// nodes' triads.
Eigen::Matrix3d element_frame(const Eigen::Vector3d& r1, const Eigen::Matrix3d& triad_a,
                              const Eigen::Matrix3d& triad_b) {
  const Eigen::Vector3d q = 0.5 * (triad_a.col(1) + triad_b.col(1));
  const Eigen::Vector3d r3_raw = r1.cross(q);
  LIMBER_DEMAND(r3_raw.norm() > 1e-8);
  const Eigen::Vector3d r3 = r3_raw.normalized();
  Eigen::Matrix3d frame;
  frame << r1, r3.cross(r1), r3;
  return frame;
}

}  // namespace

double corotational_beam_energy(const CorotationalBeam& element, const Eigen::Vector3d& x_a,
                                const Eigen::Vector3d& x_b, const Eigen::Matrix3d& rotation_a,
                                const Eigen::Matrix3d& rotation_b) {
  const Eigen::Vector3d chord = x_b - x_a;
  const double ln = chord.norm();
  LIMBER_DEMAND(ln > 0.0);
  const Eigen::Matrix3d triad_a = rotation_a * element.r_0;
  const Eigen::Matrix3d triad_b = rotation_b * element.r_0;
  const Eigen::Matrix3d frame = element_frame(chord / ln, triad_a, triad_b);
  Vector7d p_l;
  p_l << ln - element.length_0, log_so3(frame.transpose() * triad_a),
      log_so3(frame.transpose() * triad_b);
  return 0.5 * p_l.dot(element.local_stiffness * p_l);
}

CorotationalBeam make_corotational_beam(const fe::FeModel& model, const fe::BeamElement& beam) {
  const Eigen::Vector3d& p_a = model.node_positions[beam.nodes[0]];
  const Eigen::Vector3d& p_b = model.node_positions[beam.nodes[1]];
  const fe::BeamProperty& property = model.beam_properties[beam.property];
  CorotationalBeam out;
  out.nodes = beam.nodes;
  out.r_0 = fe::beam_local_axes(p_a, p_b, beam.orientation).transpose();
  out.length_0 = (p_b - p_a).norm();
  const fe::BeamElementMatrices local = fe::beam_local_matrices(out.length_0, property);
  // K_l: the linear element's stiffness on (u_b, rotations of a and b).
  for (int i = 0; i < 7; ++i) {
    for (int j = 0; j < 7; ++j) out.local_stiffness(i, j) = local.stiffness(kLocalDofs[i], kLocalDofs[j]);
  }
  out.local_mass = local.mass;
  return out;
}

ElementResponse corotational_beam_response(const CorotationalBeam& element,
                                           const Eigen::Vector3d& x_a,
                                           const Eigen::Vector3d& x_b,
                                           const Eigen::Matrix3d& rotation_a,
                                           const Eigen::Matrix3d& rotation_b,
                                           bool with_tangent,
                                           const DeformationRateDamping& damping) {
  // Chord: current length and direction r1.
  const Eigen::Vector3d chord = x_b - x_a;
  const double ln = chord.norm();
  LIMBER_DEMAND(ln > 0.0);
  const Eigen::Vector3d r1 = chord / ln;

  // Node triads and the mean of their local y axes.
  const Eigen::Matrix3d triad_a = rotation_a * element.r_0;
  const Eigen::Matrix3d triad_b = rotation_b * element.r_0;
  const Eigen::Vector3d q_a = triad_a.col(1);
  const Eigen::Vector3d q_b = triad_b.col(1);
  const Eigen::Vector3d q = 0.5 * (q_a + q_b);

  // Element frame R_r = [r1 r2 r3].
  const Eigen::Matrix3d frame = element_frame(r1, triad_a, triad_b);

  // Local deformations p_l and their elastic forces K_l p_l.
  const Eigen::Vector3d theta_a = log_so3(frame.transpose() * triad_a);
  const Eigen::Vector3d theta_b = log_so3(frame.transpose() * triad_b);
  Vector7d p_l;
  p_l << ln - element.length_0, theta_a, theta_b;
  Vector7d f_l = element.local_stiffness * p_l;

  // B_h = diag(1, Ts_a^-1, Ts_b^-1) maps the spin-based local variables p_a to p_l.
  const Eigen::Matrix3d ts_inv_a = inverse_left_jacobian(theta_a);
  const Eigen::Matrix3d ts_inv_b = inverse_left_jacobian(theta_b);
  Matrix7d b_h = Matrix7d::Zero();
  b_h(0, 0) = 1.0;
  b_h.block<3, 3>(1, 1) = ts_inv_a;
  b_h.block<3, 3>(4, 4) = ts_inv_b;

  // The mean vector's components in the element frame and the eta ratios.
  const Eigen::Vector3d ql = frame.transpose() * q;
  const Eigen::Vector3d qa_l = frame.transpose() * q_a;
  const Eigen::Vector3d qb_l = frame.transpose() * q_b;
  const double q2 = ql(1);
  const double eta = ql(0) / q2;
  const double eta11 = qa_l(0) / q2;
  const double eta12 = qa_l(1) / q2;
  const double eta21 = qb_l(0) / q2;
  const double eta22 = qb_l(1) / q2;

  // G^T: the frame's spin in its own axes, omega = G^T E^T delta p_g (Battini & Pacoste eq. 19).
  // All matrices below act on local components E^T delta p_g, E = diag(R_r, R_r, R_r, R_r).
  Matrix3x12 gt = Matrix3x12::Zero();
  gt(0, 2) = eta / ln;
  gt(0, 3) = 0.5 * eta12;
  gt(0, 4) = -0.5 * eta11;
  gt(0, 8) = -eta / ln;
  gt(0, 9) = 0.5 * eta22;
  gt(0, 10) = -0.5 * eta21;
  gt(1, 2) = 1.0 / ln;
  gt(1, 8) = -1.0 / ln;
  gt(2, 1) = -1.0 / ln;
  gt(2, 7) = 1.0 / ln;

  // P: local spins of the nodes relative to the frame; r: chord length variation.
  Eigen::Matrix<double, 6, 12> p;
  p.topRows<3>() = spin_selector(0) - gt;
  p.bottomRows<3>() = spin_selector(1) - gt;
  Eigen::Matrix<double, 1, 12> r = Eigen::Matrix<double, 1, 12>::Zero();
  r(0) = -1.0;
  r(6) = 1.0;
  Matrix7x12 b_a;
  b_a.row(0) = r;
  b_a.bottomRows<6>() = p;

  ElementResponse out;
  // Kelvin-Voigt damping: f_l += beta K_l p_l', p_l' = B_h B_a E^T v (zero for a rigid velocity).
  if (damping.beta > 0.0) {
    Vector12d v_local;
    for (int bi = 0; bi < 4; ++bi) v_local.segment<3>(3 * bi) = frame.transpose() * damping.velocity.segment<3>(3 * bi);
    const Matrix7x12 b_local = b_h * b_a;
    const Vector7d rate = b_local * v_local;
    const Vector7d f_damping = damping.beta * (element.local_stiffness * rate);
    f_l += f_damping;
    out.dissipation = rate.dot(f_damping);
    if (damping.with_matrix) {
      const Matrix12d c_local = damping.beta * b_local.transpose() * element.local_stiffness * b_local;
      for (int bi = 0; bi < 4; ++bi) {
        for (int bj = 0; bj < 4; ++bj) {
          out.damping.block<3, 3>(3 * bi, 3 * bj) = frame * c_local.block<3, 3>(3 * bi, 3 * bj) * frame.transpose();
        }
      }
    }
  }

  // Forces on the spin-based local variables p_a: f_a = B_h^T f_l.
  const double axial = f_l(0);
  const Eigen::Vector3d m_a = ts_inv_a.transpose() * f_l.segment<3>(1);
  const Eigen::Vector3d m_b = ts_inv_b.transpose() * f_l.segment<3>(4);

  // Internal force in local components: f = r^T N + P^T m.
  Vector7d f_a;
  f_a << axial, m_a, m_b;
  const Vector12d f_local = b_a.transpose() * f_a;
  out.frame = frame;
  out.local_forces = f_l;
  for (int bi = 0; bi < 4; ++bi) out.force.segment<3>(3 * bi) = frame * f_local.segment<3>(3 * bi);
  if (!with_tangent) return out;

  // K_a = B_h^T K_l B_h + K_h.
  Matrix7d k_a = b_h.transpose() * element.local_stiffness * b_h;
  k_a.block<3, 3>(1, 1) += moment_rotation_stiffness(theta_a, f_l.segment<3>(1));
  k_a.block<3, 3>(4, 4) += moment_rotation_stiffness(theta_b, f_l.segment<3>(4));

  // Material part B_a^T K_a B_a.
  Matrix12d k_local = b_a.transpose() * k_a * b_a;

  // Chord rotation under a fixed axial force: D N, D3 = (I - r1 r1^T) / ln in frame axes.
  Eigen::Matrix3d d3 = Eigen::Matrix3d::Zero();
  d3(1, 1) = d3(2, 2) = 1.0 / ln;
  k_local.block<3, 3>(0, 0) += axial * d3;
  k_local.block<3, 3>(0, 6) -= axial * d3;
  k_local.block<3, 3>(6, 0) -= axial * d3;
  k_local.block<3, 3>(6, 6) += axial * d3;

  // Rotation of the frame carrying n = P^T m: - Q G^T, Q = [S(n_1); ...; S(n_4)].
  const Vector12d n = p.transpose() * (Eigen::Matrix<double, 6, 1>() << m_a, m_b).finished();
  Matrix12x3 q_mat;
  for (int blk = 0; blk < 4; ++blk) q_mat.block<3, 3>(3 * blk, 0) = skew(n.segment<3>(3 * blk));
  k_local -= q_mat * gt;

  // Variation of G (through ln and the eta ratios) under fixed moments: - dh/dp with
  // h = G (m_a + m_b). First the variations of the frame components of q_a, q_b and q.
  const Eigen::Vector3d c = m_a + m_b;
  const Matrix3x12 dqa = skew(qa_l) * gt - skew(qa_l) * spin_selector(0);
  const Matrix3x12 dqb = skew(qb_l) * gt - skew(qb_l) * spin_selector(1);
  const Matrix3x12 dq = 0.5 * (dqa + dqb);
  const Eigen::Matrix<double, 1, 12> d_eta = (dq.row(0) - eta * dq.row(1)) / q2;
  const Eigen::Matrix<double, 1, 12> d_eta11 = (dqa.row(0) - eta11 * dq.row(1)) / q2;
  const Eigen::Matrix<double, 1, 12> d_eta12 = (dqa.row(1) - eta12 * dq.row(1)) / q2;
  const Eigen::Matrix<double, 1, 12> d_eta21 = (dqb.row(0) - eta21 * dq.row(1)) / q2;
  const Eigen::Matrix<double, 1, 12> d_eta22 = (dqb.row(1) - eta22 * dq.row(1)) / q2;
  const double ln2 = ln * ln;
  Matrix12d dh = Matrix12d::Zero();
  dh.row(1) = c(2) * r / ln2;
  dh.row(7) = -dh.row(1);
  dh.row(2) = c(0) * (d_eta / ln - eta * r / ln2) - c(1) * r / ln2;
  dh.row(8) = -dh.row(2);
  dh.row(3) = 0.5 * c(0) * d_eta12;
  dh.row(4) = -0.5 * c(0) * d_eta11;
  dh.row(9) = 0.5 * c(0) * d_eta22;
  dh.row(10) = -0.5 * c(0) * d_eta21;
  k_local -= dh;

  // Back to component axes block by block: K_g = E K E^T, E = diag(R_r x 4) (f_g = E f above).
  for (int bi = 0; bi < 4; ++bi) {
    for (int bj = 0; bj < 4; ++bj) {
      out.tangent.block<3, 3>(3 * bi, 3 * bj) =
          frame * k_local.block<3, 3>(3 * bi, 3 * bj) * frame.transpose();
    }
  }
  return out;
}

}  // namespace limber::nonlinear_beam
