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

// What the force and the tangent share at one configuration: the chord, the element frame,
// the local rotations and the eta ratios of the mean vector (Battini & Pacoste 2002, sec. 3).
struct ElementKinematics {
  double ln = 0.0;                 // current chord length [m]
  Eigen::Matrix3d frame;           // R_r = [r1 r2 r3]
  Vector7d p_l;                    // (u, theta_a, theta_b)
  Eigen::Matrix3d ts_inv_a, ts_inv_b;  // T_s^-1 of theta_a, theta_b
  Eigen::Vector3d qa_l, qb_l;      // the nodes' local y axes in frame components
  double q2 = 0.0, eta = 0.0, eta11 = 0.0, eta12 = 0.0, eta21 = 0.0, eta22 = 0.0;
  Matrix3x12 gt;                   // G^T: the frame's spin in its axes, omega = G^T E^T delta p_g
};

ElementKinematics element_kinematics(const CorotationalBeam& element, const Eigen::Vector3d& x_a,
                                     const Eigen::Vector3d& x_b, const Eigen::Matrix3d& rotation_a,
                                     const Eigen::Matrix3d& rotation_b) {
  ElementKinematics k;
  // Chord: current length and direction r1; node triads; element frame.
  const Eigen::Vector3d chord = x_b - x_a;
  k.ln = chord.norm();
  LIMBER_DEMAND(k.ln > 0.0);
  const Eigen::Matrix3d triad_a = rotation_a * element.r_0;
  const Eigen::Matrix3d triad_b = rotation_b * element.r_0;
  k.frame = element_frame(chord / k.ln, triad_a, triad_b);

  // Local deformations and T_s^-1, which maps spins to variations of the local rotations.
  const Eigen::Vector3d theta_a = log_so3(k.frame.transpose() * triad_a);
  const Eigen::Vector3d theta_b = log_so3(k.frame.transpose() * triad_b);
  k.p_l << k.ln - element.length_0, theta_a, theta_b;
  k.ts_inv_a = inverse_left_jacobian(theta_a);
  k.ts_inv_b = inverse_left_jacobian(theta_b);

  // The mean vector's components in the element frame and the eta ratios.
  k.qa_l = k.frame.transpose() * triad_a.col(1);
  k.qb_l = k.frame.transpose() * triad_b.col(1);
  const Eigen::Vector3d ql = 0.5 * (k.qa_l + k.qb_l);
  k.q2 = ql(1);
  k.eta = ql(0) / k.q2;
  k.eta11 = k.qa_l(0) / k.q2;
  k.eta12 = k.qa_l(1) / k.q2;
  k.eta21 = k.qb_l(0) / k.q2;
  k.eta22 = k.qb_l(1) / k.q2;

  // G^T (Battini & Pacoste eq. 19), on local components E^T delta p_g, E = diag(R_r x 4).
  k.gt.setZero();
  k.gt(0, 2) = k.eta / k.ln;
  k.gt(0, 3) = 0.5 * k.eta12;
  k.gt(0, 4) = -0.5 * k.eta11;
  k.gt(0, 8) = -k.eta / k.ln;
  k.gt(0, 9) = 0.5 * k.eta22;
  k.gt(0, 10) = -0.5 * k.eta21;
  k.gt(1, 2) = 1.0 / k.ln;
  k.gt(1, 8) = -1.0 / k.ln;
  k.gt(2, 1) = -1.0 / k.ln;
  k.gt(2, 7) = 1.0 / k.ln;
  return k;
}

// r: the chord length's variation on local components.
Eigen::Matrix<double, 1, 12> chord_variation() {
  Eigen::Matrix<double, 1, 12> r = Eigen::Matrix<double, 1, 12>::Zero();
  r(0) = -1.0;
  r(6) = 1.0;
  return r;
}

// B_a = [r; P]: the spin-based local variables' variation, P the nodes' spins relative to the
// frame, (S_a - G^T; S_b - G^T).
Matrix7x12 spin_variation(const ElementKinematics& k) {
  Matrix7x12 b_a;
  b_a.row(0) = chord_variation();
  b_a.middleRows<3>(1) = spin_selector(0) - k.gt;
  b_a.bottomRows<3>() = spin_selector(1) - k.gt;
  return b_a;
}

// B_h = diag(1, T_s^-1(theta_a), T_s^-1(theta_b)): from spin-based variables to p_l.
Matrix7d rotation_variation(const ElementKinematics& k) {
  Matrix7d b_h = Matrix7d::Zero();
  b_h(0, 0) = 1.0;
  b_h.block<3, 3>(1, 1) = k.ts_inv_a;
  b_h.block<3, 3>(4, 4) = k.ts_inv_b;
  return b_h;
}

// E M E^T block by block for a 12 x 12 matrix M on local components.
Matrix12d to_component_axes(const Eigen::Matrix3d& frame, const Matrix12d& local) {
  Matrix12d out;
  for (int bi = 0; bi < 4; ++bi) {
    for (int bj = 0; bj < 4; ++bj) out.block<3, 3>(3 * bi, 3 * bj) = frame * local.block<3, 3>(3 * bi, 3 * bj) * frame.transpose();
  }
  return out;
}

// Kelvin-Voigt damping: f_l += beta K_l p_l', p_l' = B_h B_a E^T v (zero for a rigid velocity).
void add_deformation_rate_damping(const CorotationalBeam& element, const ElementKinematics& k,
                                  const DeformationRateDamping& damping, Vector7d& f_l, ElementResponse& out) {
  Vector12d v_local;
  for (int bi = 0; bi < 4; ++bi) v_local.segment<3>(3 * bi) = k.frame.transpose() * damping.velocity.segment<3>(3 * bi);
  const Matrix7x12 b_local = rotation_variation(k) * spin_variation(k);
  const Vector7d rate = b_local * v_local;
  const Vector7d f_damping = damping.beta * (element.local_stiffness * rate);
  f_l += f_damping;
  out.dissipation = rate.dot(f_damping);
  if (damping.with_matrix) {
    out.damping = to_component_axes(k.frame, damping.beta * b_local.transpose() * element.local_stiffness * b_local);
  }
}

// Internal force in component axes, f_g = E B_a^T f_a with f_a = (N, m_a, m_b) on spins:
// r^T N + S_a^T m_a + S_b^T m_b - G (m_a + m_b), written out (r, S_a, S_b are selections).
Vector12d internal_force(const ElementKinematics& k, double axial, const Eigen::Vector3d& m_a,
                         const Eigen::Vector3d& m_b) {
  Vector12d f_local = -k.gt.transpose() * (m_a + m_b);
  f_local(0) -= axial;
  f_local(6) += axial;
  f_local.segment<3>(3) += m_a;
  f_local.segment<3>(9) += m_b;
  Vector12d out;
  for (int bi = 0; bi < 4; ++bi) out.segment<3>(3 * bi) = k.frame * f_local.segment<3>(3 * bi);
  return out;
}

// Material and axial parts on local components: B_a^T (B_h^T K_l B_h + K_h) B_a + D N, with
// D3 = (I - r1 r1^T) / ln in frame axes (the chord turning under a fixed axial force).
Matrix12d material_tangent(const CorotationalBeam& element, const ElementKinematics& k, const Vector7d& f_l,
                           const Matrix7x12& b_a) {
  const Matrix7d b_h = rotation_variation(k);
  Matrix7d k_a = b_h.transpose() * element.local_stiffness * b_h;
  k_a.block<3, 3>(1, 1) += moment_rotation_stiffness(k.p_l.segment<3>(1), f_l.segment<3>(1));
  k_a.block<3, 3>(4, 4) += moment_rotation_stiffness(k.p_l.segment<3>(4), f_l.segment<3>(4));
  Matrix12d k_local = b_a.transpose() * k_a * b_a;
  Eigen::Matrix3d d3 = Eigen::Matrix3d::Zero();
  d3(1, 1) = d3(2, 2) = f_l(0) / k.ln;
  k_local.block<3, 3>(0, 0) += d3;
  k_local.block<3, 3>(0, 6) -= d3;
  k_local.block<3, 3>(6, 0) -= d3;
  k_local.block<3, 3>(6, 6) += d3;
  return k_local;
}

// The variation of B_a^T under fixed moments on local components: the frame carrying
// n = P^T m turns (- Q G^T, Q = [S(n_1); ...; S(n_4)]), and G changes through ln and the eta
// ratios (- dh/dp with h = G (m_a + m_b)).
Matrix12d frame_turning_tangent(const ElementKinematics& k, const Matrix7x12& b_a, const Eigen::Vector3d& m_a,
                                const Eigen::Vector3d& m_b) {
  const Vector12d n = b_a.bottomRows<6>().transpose() * (Eigen::Matrix<double, 6, 1>() << m_a, m_b).finished();
  Matrix12x3 q_mat;
  for (int blk = 0; blk < 4; ++blk) q_mat.block<3, 3>(3 * blk, 0) = skew(n.segment<3>(3 * blk));
  Matrix12d out = -q_mat * k.gt;

  // Variations of the frame components of q_a, q_b and q, then of the eta ratios.
  const Eigen::Vector3d c = m_a + m_b;
  const Matrix3x12 dqa = skew(k.qa_l) * k.gt - skew(k.qa_l) * spin_selector(0);
  const Matrix3x12 dqb = skew(k.qb_l) * k.gt - skew(k.qb_l) * spin_selector(1);
  const Matrix3x12 dq = 0.5 * (dqa + dqb);
  const Eigen::Matrix<double, 1, 12> d_eta = (dq.row(0) - k.eta * dq.row(1)) / k.q2;
  const Eigen::Matrix<double, 1, 12> d_eta11 = (dqa.row(0) - k.eta11 * dq.row(1)) / k.q2;
  const Eigen::Matrix<double, 1, 12> d_eta12 = (dqa.row(1) - k.eta12 * dq.row(1)) / k.q2;
  const Eigen::Matrix<double, 1, 12> d_eta21 = (dqb.row(0) - k.eta21 * dq.row(1)) / k.q2;
  const Eigen::Matrix<double, 1, 12> d_eta22 = (dqb.row(1) - k.eta22 * dq.row(1)) / k.q2;
  const Eigen::Matrix<double, 1, 12> r_over_ln2 = chord_variation() / (k.ln * k.ln);
  out.row(1) -= c(2) * r_over_ln2;
  out.row(7) += c(2) * r_over_ln2;
  const Eigen::Matrix<double, 1, 12> dh2 = c(0) * (d_eta / k.ln - k.eta * r_over_ln2) - c(1) * r_over_ln2;
  out.row(2) -= dh2;
  out.row(8) += dh2;
  out.row(3) -= 0.5 * c(0) * d_eta12;
  out.row(4) += 0.5 * c(0) * d_eta11;
  out.row(9) -= 0.5 * c(0) * d_eta22;
  out.row(10) += 0.5 * c(0) * d_eta21;
  return out;
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
  const ElementKinematics k = element_kinematics(element, x_a, x_b, rotation_a, rotation_b);
  ElementResponse out;
  out.frame = k.frame;

  // Local forces: elastic K_l p_l, plus the deformation-rate damping.
  Vector7d f_l = element.local_stiffness * k.p_l;
  if (damping.beta > 0.0) add_deformation_rate_damping(element, k, damping, f_l, out);
  out.local_forces = f_l;

  // Forces on the spin-based local variables, f_a = B_h^T f_l, and the internal force.
  const Eigen::Vector3d m_a = k.ts_inv_a.transpose() * f_l.segment<3>(1);
  const Eigen::Vector3d m_b = k.ts_inv_b.transpose() * f_l.segment<3>(4);
  out.force = internal_force(k, f_l(0), m_a, m_b);
  if (!with_tangent) return out;

  // Tangent: material and axial parts plus the frame's turning, then to component axes.
  const Matrix7x12 b_a = spin_variation(k);
  const Matrix12d k_local = material_tangent(element, k, f_l, b_a) + frame_turning_tangent(k, b_a, m_a, m_b);
  out.tangent = to_component_axes(k.frame, k_local);
  return out;
}

}  // namespace limber::nonlinear_beam
