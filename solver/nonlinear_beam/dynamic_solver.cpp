#include "nonlinear_beam/dynamic_solver.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.h"
#include "nonlinear_beam/rotation.h"

namespace limber::nonlinear_beam {

namespace {

using Matrix12d = Eigen::Matrix<double, 12, 12>;

// Right Jacobian of exp: R exp(ξ + δξ) = R exp(ξ) exp(T(ξ) δξ) to first order,
// T(ξ) = I − (1 − cos t)/t² S(ξ) + (t − sin t)/t³ S(ξ)², t = |ξ| (series below 1e-4).
Eigen::Matrix3d right_jacobian(const Eigen::Vector3d& xi) {
  const double t = xi.norm();
  double c1, c2;
  if (t < 1e-4) {
    c1 = 0.5 - t * t / 24.0;
    c2 = 1.0 / 6.0 - t * t / 120.0;
  } else {
    c1 = (1.0 - std::cos(t)) / (t * t);
    c2 = (t - std::sin(t)) / (t * t * t);
  }
  const Eigen::Matrix3d s = skew(xi);
  return Eigen::Matrix3d::Identity() - c1 * s + c2 * s * s;
}

// Slot of entry (row, col) in a compressed column-major matrix.
int slot_of(const SparseMatrix& m, int row, int col) {
  const int* begin = m.innerIndexPtr() + m.outerIndexPtr()[col];
  const int* end = m.innerIndexPtr() + m.outerIndexPtr()[col + 1];
  const int* found = std::lower_bound(begin, end, row);
  LIMBER_DEMAND(found != end && *found == row);
  return static_cast<int>(found - m.innerIndexPtr());
}

}  // namespace

PrescribedNode hub_rotation(const BeamStructure& structure, int node, const Eigen::Vector3d& point,
                            const Eigen::Vector3d& axis,
                            std::function<Eigen::Vector3d(double t)> angle) {
  LIMBER_DEMAND(node >= 0 && node < structure.node_count());
  const Eigen::Vector3d n = axis.normalized();
  const Eigen::Vector3d arm_0 = structure.reference_positions[node] - point;
  PrescribedNode out;
  out.node = node;
  out.motion = [n, arm_0, point, angle = std::move(angle)](double t) {
    const Eigen::Vector3d th = angle(t);  // θ, θ', θ''
    NodeMotion m;
    m.rotation = exp_so3(th(0) * n);
    const Eigen::Vector3d arm = m.rotation * arm_0;
    m.position = point + arm;
    // Rigid rotation about a fixed axis: v = θ' n × r, a = θ'' n × r + θ'² n × (n × r).
    m.velocity = th(1) * n.cross(arm);
    m.acceleration = th(2) * n.cross(arm) + th(1) * th(1) * n.cross(n.cross(arm));
    // The axis is fixed in both the spatial and the material axes: W = θ' n, W' = θ'' n.
    m.angular_velocity = th(1) * n;
    m.angular_acceleration = th(2) * n;
    return m;
  };
  return out;
}

BeamGeneralizedAlpha::BeamGeneralizedAlpha(const BeamStructure& structure,
                                           const NodalInertia& inertia, DynamicOptions options)
    : structure_(structure), inertia_(inertia), options_(std::move(options)) {
  LIMBER_DEMAND(options_.step > 0.0 && options_.rho_inf >= 0.0 && options_.rho_inf <= 1.0);
  LIMBER_DEMAND(options_.max_iterations >= 1);
  LIMBER_DEMAND(static_cast<int>(inertia_.mass.size()) == structure_.node_count());
  const int nn = structure_.node_count();
  const int n = structure_.dof_count();

  // Chung & Hulbert 1993 coefficients.
  const double rho = options_.rho_inf;
  alpha_m_ = (2.0 * rho - 1.0) / (rho + 1.0);
  alpha_f_ = rho / (rho + 1.0);
  gamma_ = 0.5 + alpha_f_ - alpha_m_;
  beta_ = 0.25 * (gamma_ + 0.5) * (gamma_ + 0.5);

  // Held DOFs: fixed ones (rotations all or none per node), then prescribed nodes.
  held_.assign(n, true);
  for (int i : structure_.free_dofs) held_[i] = false;
  for (int node = 0; node < nn; ++node) {
    const int fixed_rotations = held_[6 * node + 3] + held_[6 * node + 4] + held_[6 * node + 5];
    if (fixed_rotations == 1 || fixed_rotations == 2) {
      throw InputError(fmt::format(
          "nonlinear beam dynamics: expected all three rotations of node {} fixed or none, got "
          "{} fixed",
          node, fixed_rotations));
    }
  }
  prescribed_of_.assign(nn, -1);
  for (std::size_t p = 0; p < options_.prescribed.size(); ++p) {
    const int node = options_.prescribed[p].node;
    LIMBER_DEMAND(node >= 0 && node < nn && options_.prescribed[p].motion);
    prescribed_of_[node] = static_cast<int>(p);
    for (int d = 0; d < 6; ++d) held_[6 * node + d] = true;
  }

  // Dead loads at factor 1.
  f_ext_ = Eigen::VectorXd::Zero(n);
  for (const NodalLoad& load : options_.loads) {
    LIMBER_DEMAND(load.node >= 0 && load.node < nn);
    f_ext_.segment<3>(6 * load.node) += load.force;
    f_ext_.segment<3>(6 * load.node + 3) += load.moment;
  }

  // Pattern of S: every element's four node blocks and every node's diagonal block.
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(144 * structure_.elements.size() + 36 * nn);
  const auto add_block = [&](int a, int b) {
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) triplets.emplace_back(6 * a + i, 6 * b + j, 0.0);
    }
  };
  for (const CorotationalBeam& e : structure_.elements) {
    for (int a : e.nodes) {
      for (int b : e.nodes) add_block(a, b);
    }
  }
  for (int node = 0; node < nn; ++node) add_block(node, node);
  s_.resize(n, n);
  s_.setFromTriplets(triplets.begin(), triplets.end());
  s_.makeCompressed();
  element_slots_.resize(structure_.elements.size());
  for (std::size_t e = 0; e < structure_.elements.size(); ++e) {
    const std::array<int, 2>& nodes = structure_.elements[e].nodes;
    for (int i = 0; i < 12; ++i) {
      for (int j = 0; j < 12; ++j) {
        element_slots_[e][12 * i + j] =
            slot_of(s_, 6 * nodes[i / 6] + i % 6, 6 * nodes[j / 6] + j % 6);
      }
    }
  }
  node_slots_.resize(nn);
  for (int node = 0; node < nn; ++node) {
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) node_slots_[node][6 * i + j] = slot_of(s_, 6 * node + i, 6 * node + j);
    }
  }
  r_ = Eigen::VectorXd::Zero(n);
}

BeamVelocity BeamGeneralizedAlpha::velocity() const {
  BeamVelocity out = zero_velocity(structure_.node_count());
  for (int i = 0; i < structure_.node_count(); ++i) {
    out.linear[i] = v_.segment<3>(6 * i);
    out.angular[i] = v_.segment<3>(6 * i + 3);
  }
  return out;
}

BeamVelocity BeamGeneralizedAlpha::acceleration() const {
  BeamVelocity out = zero_velocity(structure_.node_count());
  for (int i = 0; i < structure_.node_count(); ++i) {
    out.linear[i] = vdot_.segment<3>(6 * i);
    out.angular[i] = vdot_.segment<3>(6 * i + 3);
  }
  return out;
}

void BeamGeneralizedAlpha::hold(double t, const BeamState& q0, Eigen::VectorXd& xi,
                                Eigen::VectorXd& v, Eigen::VectorXd& vdot,
                                Eigen::VectorXd& a) const {
  for (int i = 0; i < structure_.dof_count(); ++i) {
    if (held_[i] && prescribed_of_[i / 6] < 0) xi(i) = v(i) = vdot(i) = a(i) = 0.0;
  }
  for (const PrescribedNode& p : options_.prescribed) {
    const NodeMotion m = p.motion(t);
    const int k = 6 * p.node;
    xi.segment<3>(k) = m.position - q0.positions[p.node];
    xi.segment<3>(k + 3) = log_so3(q0.rotations[p.node].toRotationMatrix().transpose() * m.rotation);
    v.segment<3>(k) = m.velocity;
    v.segment<3>(k + 3) = m.angular_velocity;
    vdot.segment<3>(k) = a.segment<3>(k) = m.acceleration;
    vdot.segment<3>(k + 3) = a.segment<3>(k + 3) = m.angular_acceleration;
  }
}

void BeamGeneralizedAlpha::assemble(double t, const BeamState& q, const Eigen::VectorXd& v,
                                    const Eigen::VectorXd& vdot, const Eigen::VectorXd& xi,
                                    double c_m, double c_v, bool with_matrix) {
  const double alpha = options_.rayleigh_mass;
  const double beta_k = options_.rayleigh_stiffness;
  const double factor = options_.load_factor ? options_.load_factor(t) : 1.0;
  r_.setZero();
  double* values = s_.valuePtr();
  if (with_matrix) std::fill(values, values + s_.nonZeros(), 0.0);
  const int nn = structure_.node_count();

  // Node rotations and the increment map T(ξ), once per node.
  std::vector<Eigen::Matrix3d> rot(nn), t_xi(nn);
  for (int i = 0; i < nn; ++i) {
    rot[i] = q.rotations[i].toRotationMatrix();
    t_xi[i] = with_matrix ? right_jacobian(xi.segment<3>(6 * i + 3)) : Eigen::Matrix3d::Identity();
  }

  // Elements: internal force and stiffness in material-increment variables, stiffness damping.
  for (std::size_t e = 0; e < structure_.elements.size(); ++e) {
    const CorotationalBeam& element = structure_.elements[e];
    const int a = element.nodes[0];
    const int b = element.nodes[1];
    const ElementResponse resp =
        corotational_beam_response(element, q.positions[a], q.positions[b], rot[a], rot[b]);
    // T_e = diag(I, R_a, I, R_b) maps material spins to spatial ones.
    Matrix12d t_e = Matrix12d::Identity();
    t_e.block<3, 3>(3, 3) = rot[a];
    t_e.block<3, 3>(9, 9) = rot[b];
    const Vector12d f_b = t_e.transpose() * resp.force;
    const Matrix12d k_b = t_e.transpose() * resp.tangent * t_e;
    Vector12d v_e;
    v_e << v.segment<6>(6 * a), v.segment<6>(6 * b);
    const Vector12d r_e = f_b + beta_k * (k_b * v_e);
    r_.segment<6>(6 * a) += r_e.head<6>();
    r_.segment<6>(6 * b) += r_e.tail<6>();
    if (!with_matrix) continue;
    // S_e = K_b T(ξ) + γ/(βh) β_k K_b.
    Matrix12d s_e = (1.0 + c_v * beta_k) * k_b;
    s_e.block<12, 3>(0, 3) = k_b.block<12, 3>(0, 3) * t_xi[a] + c_v * beta_k * k_b.block<12, 3>(0, 3);
    s_e.block<12, 3>(0, 9) = k_b.block<12, 3>(0, 9) * t_xi[b] + c_v * beta_k * k_b.block<12, 3>(0, 9);
    const std::array<int, 144>& slots = element_slots_[e];
    for (int i = 0; i < 144; ++i) values[slots[i]] += s_e(i / 12, i % 12);
  }

  // Nodes: inertia, gyroscopic and mass damping forces, loads, turning of the material axes.
  for (int i = 0; i < nn; ++i) {
    const double m = inertia_.mass[i];
    const Eigen::Matrix3d& j = inertia_.inertia[i];
    const Eigen::Vector3d w = v.segment<3>(6 * i + 3);
    const Eigen::Vector3d moment_ext = factor * (rot[i].transpose() * f_ext_.segment<3>(6 * i + 3));
    // Material moment of the internal forces (before the inertia is added).
    const Eigen::Vector3d moment_int = r_.segment<3>(6 * i + 3);
    r_.segment<3>(6 * i) += m * (vdot.segment<3>(6 * i) + alpha * v.segment<3>(6 * i)) -
                            factor * f_ext_.segment<3>(6 * i);
    r_.segment<3>(6 * i + 3) += j * (vdot.segment<3>(6 * i + 3) + alpha * w) +
                                gyroscopic_moment(j, w) - moment_ext;
    if (!with_matrix) continue;
    Eigen::Matrix<double, 6, 6> s_n = Eigen::Matrix<double, 6, 6>::Zero();
    s_n.topLeftCorner<3, 3>().diagonal().setConstant((c_m + c_v * alpha) * m);
    s_n.bottomRightCorner<3, 3>() = (c_m + c_v * alpha) * j + c_v * gyroscopic_tangent(j, w) +
                                    skew(moment_int - moment_ext) * t_xi[i];
    const std::array<int, 36>& slots = node_slots_[i];
    for (int k = 0; k < 36; ++k) values[slots[k]] += s_n(k / 6, k % 6);
  }
}

DynamicReport BeamGeneralizedAlpha::fail(DynamicStatus status, const std::string& why) const {
  DynamicReport out;
  out.status = status;
  out.t = t_;
  out.message = fmt::format("nonlinear beam dynamics: at t = {:.9g} s: {}", t_, why);
  return out;
}

DynamicReport BeamGeneralizedAlpha::init(double t0, const BeamState& state,
                                         const BeamVelocity& velocity) {
  const int nn = structure_.node_count();
  LIMBER_DEMAND(static_cast<int>(state.positions.size()) == nn &&
                static_cast<int>(velocity.linear.size()) == nn);
  t_ = t0;
  state_ = state;
  const int n = structure_.dof_count();
  v_.resize(n);
  for (int i = 0; i < nn; ++i) {
    v_.segment<3>(6 * i) = velocity.linear[i];
    v_.segment<3>(6 * i + 3) = velocity.angular[i];
  }
  vdot_ = Eigen::VectorXd::Zero(n);
  a_ = Eigen::VectorXd::Zero(n);

  // Held DOFs at t0: fixed ones at rest, prescribed nodes on their motion.
  for (const PrescribedNode& p : options_.prescribed) {
    const NodeMotion m = p.motion(t0);
    state_.positions[p.node] = m.position;
    state_.rotations[p.node] = Eigen::Quaterniond(m.rotation).normalized();
  }
  Eigen::VectorXd xi = Eigen::VectorXd::Zero(n);
  hold(t0, state_, xi, v_, vdot_, a_);

  // v̇_0 = −M⁻¹ r(q, v, 0) node by node (pseudo-inverse of a rank-deficient J: no inertia,
  // no acceleration).
  assemble(t0, state_, v_, Eigen::VectorXd::Zero(n), xi, 0.0, 0.0, false);
  if (!r_.allFinite()) return fail(DynamicStatus::kNotFinite, "non-finite forces in the initial state");
  for (int i = 0; i < nn; ++i) {
    for (int d = 0; d < 3; ++d) {
      if (!held_[6 * i + d] && inertia_.mass[i] > 0.0) vdot_(6 * i + d) = -r_(6 * i + d) / inertia_.mass[i];
    }
    if (!held_[6 * i + 3]) {
      const Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix3d> j(inertia_.inertia[i]);
      vdot_.segment<3>(6 * i + 3) = -j.solve(Eigen::Vector3d(r_.segment<3>(6 * i + 3)));
    }
  }
  a_ = vdot_;
  return {};
}

DynamicReport BeamGeneralizedAlpha::step() { return take_step(options_.step); }

DynamicReport BeamGeneralizedAlpha::advance_to(double t_end) {
  const double h = options_.step;
  while (t_end - t_ > 1e-9 * h) {
    const double step = std::min(h, t_end - t_);
    const DynamicReport r = take_step(step);
    if (r.status != DynamicStatus::kOk) return r;
  }
  DynamicReport ok;
  ok.t = t_;
  return ok;
}

void BeamGeneralizedAlpha::end_of_step(double h, Eigen::VectorXd& xi, StepEnd& end) const {
  const int nn = structure_.node_count();
  // a from the Newmark position formula, then v, v̇ and q (held DOFs from their prescription).
  end.a = (xi / (h * h) - v_ / h - (0.5 - beta_) * a_) / beta_;
  end.v = v_ + h * (1.0 - gamma_) * a_ + h * gamma_ * end.a;
  end.vdot = ((1.0 - alpha_m_) * end.a + alpha_m_ * a_ - alpha_f_ * vdot_) / (1.0 - alpha_f_);
  hold(t_ + h, state_, xi, end.v, end.vdot, end.a);
  end.q = state_;
  for (int i = 0; i < nn; ++i) {
    end.q.positions[i] = state_.positions[i] + xi.segment<3>(6 * i);
    end.q.rotations[i] = (state_.rotations[i] * exp_quaternion(xi.segment<3>(6 * i + 3))).normalized();
  }
}

void BeamGeneralizedAlpha::evaluate_step(double h, const Eigen::VectorXd& xi, const StepEnd& end,
                                         bool with_matrix) {
  const double c_m = (1.0 - alpha_m_) / ((1.0 - alpha_f_) * beta_ * h * h);
  const double c_v = gamma_ / (beta_ * h);
  assemble(t_ + h, end.q, end.v, end.vdot, xi, c_m, c_v, with_matrix);
  // Held rows (and columns) replaced by the identity's.
  for (int i = 0; i < structure_.dof_count(); ++i) {
    if (held_[i]) r_(i) = 0.0;
  }
  if (!with_matrix) return;
  for (int col = 0; col < structure_.dof_count(); ++col) {
    for (SparseMatrix::InnerIterator e(s_, col); e; ++e) {
      if (held_[e.row()] || held_[col]) e.valueRef() = e.row() == col ? 1.0 : 0.0;
    }
  }
}

Eigen::VectorXd BeamGeneralizedAlpha::step_residual(double h, const Eigen::VectorXd& xi) {
  Eigen::VectorXd x = xi;
  StepEnd end;
  end_of_step(h, x, end);
  evaluate_step(h, x, end, false);
  return r_;
}

SparseMatrix BeamGeneralizedAlpha::step_matrix(double h, const Eigen::VectorXd& xi) {
  Eigen::VectorXd x = xi;
  StepEnd end;
  end_of_step(h, x, end);
  evaluate_step(h, x, end, true);
  return s_;
}

DynamicReport BeamGeneralizedAlpha::take_step(double h) {
  // Predictor: v̇_{n+1} = v̇_n, a from the α relation, ξ from the Newmark formula.
  const Eigen::VectorXd a_pred = (vdot_ - alpha_m_ * a_) / (1.0 - alpha_m_);
  const Eigen::VectorXd newmark = h * v_ + h * h * (0.5 - beta_) * a_ + beta_ * h * h * a_pred;
  const DynamicReport first = attempt_step(h, newmark);
  if (first.status == DynamicStatus::kOk || first.status == DynamicStatus::kSingularMatrix) return first;
  // Retry once from constant velocity, ξ = h v_n: the Newmark predictor carries a_n, which on
  // nearly massless or stiff DOFs (a suddenly applied load on one node of a fine mesh; fast
  // components left by a sudden event) can put nodes far outside Newton's basin.
  const DynamicReport second = attempt_step(h, h * v_);
  if (second.status == DynamicStatus::kOk) return second;
  DynamicReport out = second;
  out.message += " (from constant velocity; from the Newmark predictor it failed too)";
  return out;
}

DynamicReport BeamGeneralizedAlpha::attempt_step(double h, const Eigen::VectorXd& predictor) {
  const int n = structure_.dof_count();
  const int nn = structure_.node_count();
  const double t1 = t_ + h;
  Eigen::VectorXd xi = predictor;
  Eigen::VectorXd delta(n);
  StepEnd end;
  end_of_step(h, xi, end);

  for (int it = 0; it < options_.max_iterations; ++it) {
    // Residual and iteration matrix.
    evaluate_step(h, xi, end, true);
    if (!r_.allFinite() || !Eigen::Map<const Eigen::VectorXd>(s_.valuePtr(), s_.nonZeros()).allFinite()) {
      return fail(DynamicStatus::kNotFinite,
                  fmt::format("non-finite residual or iteration matrix in Newton iteration {} of "
                              "the step to {:.9g} s",
                              it + 1, t1));
    }

    // Newton increment.
    if (!pattern_analysed_) {
      lu_.analyzePattern(s_);
      pattern_analysed_ = true;
    }
    lu_.factorize(s_);
    if (lu_.info() != Eigen::Success) {
      return fail(DynamicStatus::kSingularMatrix,
                  fmt::format("singular iteration matrix in the step to {:.9g} s", t1));
    }
    delta = lu_.solve(-r_);
    if (!delta.allFinite()) {
      return fail(DynamicStatus::kNotFinite,
                  fmt::format("non-finite Newton increment in the step to {:.9g} s", t1));
    }
    xi += delta;
    end_of_step(h, xi, end);
    ++stats_.newton_iterations;

    // Increment test: translations against the structure size, rotations in rad.
    double du = 0.0, dw = 0.0;
    for (int i = 0; i < nn; ++i) {
      du = std::max(du, delta.segment<3>(6 * i).cwiseAbs().maxCoeff());
      dw = std::max(dw, delta.segment<3>(6 * i + 3).cwiseAbs().maxCoeff());
    }
    if (du <= options_.increment_tolerance * structure_.size &&
        dw <= options_.increment_tolerance) {
      // Accept the step.
      t_ = t1;
      state_ = std::move(end.q);
      v_ = std::move(end.v);
      vdot_ = std::move(end.vdot);
      a_ = std::move(end.a);
      ++stats_.steps;
      DynamicReport ok;
      ok.t = t_;
      return ok;
    }
  }
  return fail(DynamicStatus::kNotConverged,
              fmt::format("Newton did not converge in {} iterations in the step to {:.9g} s "
                          "(h = {:.3g} s)",
                          options_.max_iterations, t1, h));
}

}  // namespace limber::nonlinear_beam
