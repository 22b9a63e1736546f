#include "multibody/multibody_system.h"

#include <algorithm>

#include <Eigen/QR>

#include "multibody/body.h"
#include "multibody/constraints.h"
#include "multibody/dynamics.h"
#include "multibody/geometric_stiffening.h"
#include "multibody/nonlinear_body.h"
#include "multibody/reactions.h"

namespace limber::multibody {

MultibodySystem::MultibodySystem(const Model& model, ConstraintPartition partition)
    : model_(model), partition_(std::move(partition)), event_releases_(model), workspace_(model) {
  for (const Body& b : model_.bodies) {
    if (b.kind != BodyKind::kGround) ++num_moving_bodies_;
  }
  for (size_t k = 0; k < model_.forces.size(); ++k) {
    if (std::holds_alternative<HingeLimit>(model_.forces[k])) limits_.push_back(static_cast<int>(k));
  }
  engaged_.assign(model_.forces.size(), 0);
  state_.engaged = engaged_;
}

void MultibodySystem::kinematic_matrix(const Eigen::VectorXd& q, Eigen::MatrixXd& N) const {
  N.setZero(model_.nq, model_.nv);
  for (size_t b = 0; b < model_.bodies.size(); ++b) set_body_kinematic_matrix(model_, b, q, N);
}

void MultibodySystem::integrate_coordinates(const Eigen::VectorXd& q, const Eigen::VectorXd& dv,
                                            Eigen::VectorXd& q_out) const {
  q_out.resize(model_.nq);
  for (size_t b = 0; b < model_.bodies.size(); ++b) integrate_body_coordinates(model_, b, q, dv, q_out);
}

void MultibodySystem::coordinate_invariants(const Eigen::VectorXd& q, Eigen::VectorXd& h,
                                            Eigen::MatrixXd& h_q) const {
  // h = |p|² − 1 per moving body (rigid or flexible frame), ∂h/∂p = 2 pᵀ.
  h.setZero(num_moving_bodies_);
  h_q.setZero(num_moving_bodies_, model_.nq);
  int k = 0;
  for (const Body& b : model_.bodies) {
    if (b.kind == BodyKind::kGround) continue;
    const Eigen::Vector4d p = q.segment<4>(b.q_offset + 3);
    h(k) = p.squaredNorm() - 1.0;
    h_q.block<1, 4>(k, b.q_offset + 3) = 2.0 * p.transpose();
    ++k;
  }
}

void MultibodySystem::mass_matrix(double t, const Eigen::VectorXd& q, Eigen::MatrixXd& M) {
  state_.t = t;
  state_.q = q;
  multibody::mass_matrix(model_, state_, workspace_);
  M = workspace_.M;
}

void MultibodySystem::generalized_forces(double t, const Eigen::VectorXd& q,
                                         const Eigen::VectorXd& v, Eigen::VectorXd& Q) {
  state_.t = t;
  state_.q = q;
  state_.v = v;
  multibody::generalized_forces(model_, state_, workspace_);
  add_fading_loads(fading_, t, workspace_);
  Q = workspace_.Q;
}

bool MultibodySystem::coupled_damping(double /*t*/, const Eigen::VectorXd& q, Eigen::SparseMatrix<double>& C) const {
  return nonlinear_body_damping(model_, q, C);
}

void MultibodySystem::evaluate(double t, const Eigen::VectorXd& q, const Eigen::VectorXd* v) {
  state_.t = t;
  state_.q = q;
  if (v) state_.v = *v;
  evaluate_constraints(model_, state_, v ? Stage::kVelocity : Stage::kPosition, released_, workspace_);
}

void MultibodySystem::select_rows(const Eigen::VectorXd& full, Eigen::VectorXd& out) const {
  out.resize(nc());
  for (int k = 0; k < nc(); ++k) out(k) = full(partition_.independent[k]);
}

void MultibodySystem::select_rows(const Eigen::MatrixXd& full, Eigen::MatrixXd& out) const {
  // Column by column (the matrices are column-major): a nonlinear body's hundreds of columns
  // made the strided row copies a tenth of a run's CPU.
  out.resize(nc(), full.cols());
  const std::vector<int>& rows = partition_.independent;
  for (Eigen::Index j = 0; j < full.cols(); ++j) {
    const double* from = full.col(j).data();
    double* to = out.col(j).data();
    for (int k = 0; k < nc(); ++k) to[k] = from[rows[static_cast<std::size_t>(k)]];
  }
}

void MultibodySystem::map_to_q(const Eigen::VectorXd& q, const Eigen::MatrixXd& G,
                               Eigen::MatrixXd& g_q) const {
  g_q.setZero(nc(), model_.nq);
  for (size_t b = 0; b < model_.bodies.size(); ++b) map_body_jacobian_to_q(model_, b, q, G, g_q);
}

void MultibodySystem::constraints(double t, const Eigen::VectorXd& q, Eigen::VectorXd& g) {
  evaluate(t, q, nullptr);
  select_rows(workspace_.g, g);
}

void MultibodySystem::constraint_jacobian_v(double t, const Eigen::VectorXd& q,
                                            Eigen::MatrixXd& G) {
  evaluate(t, q, nullptr);
  select_rows(workspace_.G, G);
}

void MultibodySystem::constraint_jacobian_q(double t, const Eigen::VectorXd& q,
                                            Eigen::MatrixXd& g_q) {
  evaluate(t, q, nullptr);
  select_rows(workspace_.G, scratch_G_);
  map_to_q(q, scratch_G_, g_q);
}

bool MultibodySystem::diagonal_stiffness_damping(Eigen::VectorXd& k, Eigen::VectorXd& c) const {
  k.setZero(model_.nv);
  c.setZero(model_.nv);
  for (const Body& b : model_.bodies) {
    if (b.kind != BodyKind::kFlexible) continue;
    const int nm = b.flexible->mode_count();
    k.segment(b.v_offset + 6, nm) = b.flexible->stiffness;
    c.segment(b.v_offset + 6, nm) = b.flexible->damping;
  }
  return true;
}

bool MultibodySystem::coupled_stiffness(double /*t*/, const Eigen::VectorXd& q,
                                        Eigen::SparseMatrix<double>& K) const {
  return nonlinear_body_stiffness(model_, q, K);
}

void MultibodySystem::evaluate(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                               bool with_g_q, SystemEvaluation& out) {
  state_.t = t;
  state_.q = q;
  state_.v = v;
  if (sparse()) {
    out.M.resize(0, 0);
    sparse_mass_matrix(model_, state_, out.M_sparse);
    multibody::generalized_forces(model_, state_, workspace_);
    evaluate_constraints(model_, state_, Stage::kPosition, released_, workspace_);
  } else {
    multibody::mass_matrix_and_forces(model_, state_, released_, workspace_);
    evaluate_constraint_rows(model_, state_, Stage::kPosition, released_, workspace_);
    out.M = workspace_.M;
  }
  add_fading_loads(fading_, t, workspace_);
  out.Q = workspace_.Q;
  select_rows(workspace_.g, out.g);
  select_rows(workspace_.G, out.G);
  select_rows(workspace_.g_t, out.g_t);
  if (with_g_q) map_to_q(q, out.G, out.g_q);
}

void MultibodySystem::constraint_time_derivative(double t, const Eigen::VectorXd& q,
                                                 Eigen::VectorXd& g_t) {
  evaluate(t, q, nullptr);
  select_rows(workspace_.g_t, g_t);
}

void MultibodySystem::acceleration_rhs(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                       Eigen::VectorXd& gamma) {
  evaluate(t, q, &v);
  select_rows(workspace_.gamma, gamma);
}

double MultibodySystem::smallest_pivot(const std::vector<int>& rows, const Workspace& ws) const {
  if (rows.empty()) return 1.0;
  Eigen::MatrixXd G_rows(rows.size(), model_.nv);
  for (size_t k = 0; k < rows.size(); ++k) G_rows.row(k) = ws.G.row(rows[k]);
  // Pivoted QR as in analyse_redundancy: |R_kk| decrease, the last one measures the rank.
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(unit_rows(G_rows).transpose());
  return std::abs(qr.matrixR()(rows.size() - 1, rows.size() - 1));
}

MultibodySystem::RowProposal MultibodySystem::propose_rows(double t, const Eigen::VectorXd& q, State& state,
                                                          Workspace& ws) const {
  RowProposal proposal;
  // Without redundant rows the choice is all rows, nothing to reselect.
  if (partition_.redundant.empty()) return proposal;
  state.t = t;
  state.q = q;
  evaluate_constraints(model_, state, Stage::kPosition, released_, ws);
  const double current = smallest_pivot(partition_.independent, ws);
  proposal.current_pivot = current;
  // The first measurement becomes the reference (reselect_constraints keeps it).
  const double chosen = chosen_pivot_ < 0.0 ? current : chosen_pivot_;
  // Hysteresis: a tenth of the pivot at selection before re-analysing, twice better to switch.
  if (current >= 0.1 * chosen) return proposal;
  proposal.degraded = true;
  // The joints whose dropped rows lost their weight in the dependency are measured in frames
  // that turn with the motion (a crank's), and so are their other rows: keep them all, so the
  // redundancy falls on rows whose weight stays (without this, R2.rot_x and R2.rot_y of the
  // flexible slider-crank took turns every quarter turn, 50 000 rejected IDA steps at rtol 1e-8).
  proposal.kept_rows = kept_rows_;
  for (const RedundantEquation& r : partition_.redundant) {
    const int joint = model_.equations[r.row].joint;
    for (int row = 0; row < model_.num_equations(); ++row) {
      if (joint >= 0 && model_.equations[row].joint == joint) proposal.kept_rows.push_back(row);
    }
  }
  ConstraintPartition fresh = analyse_redundancy(model_, state, ws, partition_.relative_threshold,
                                                 proposal.kept_rows, partition_.row_released);
  if (fresh.independent.size() != partition_.independent.size() ||
      fresh.independent == partition_.independent) {
    return proposal;
  }
  const double better = smallest_pivot(fresh.independent, ws);
  if (better < 2.0 * current) return proposal;
  proposal.fresh = std::move(fresh);
  proposal.fresh_pivot = better;
  return proposal;
}

bool MultibodySystem::reselect_constraints(double t, const Eigen::VectorXd& q) {
  RowProposal proposal = propose_rows(t, q, state_, workspace_);
  if (proposal.current_pivot && chosen_pivot_ < 0.0) chosen_pivot_ = *proposal.current_pivot;
  // A degraded choice keeps its joints' rows from now on, whether or not it switches.
  if (proposal.degraded) kept_rows_ = std::move(proposal.kept_rows);
  if (!proposal.fresh) return false;
  partition_ = std::move(*proposal.fresh);
  chosen_pivot_ = proposal.fresh_pivot;
  return true;
}

bool MultibodySystem::reselection_candidate(double t, const Eigen::VectorXd& q, Eigen::MatrixXd& G) const {
  // A state and workspace of its own: the system's stay as they are.
  State state = state_;
  Workspace ws(model_);
  const RowProposal proposal = propose_rows(t, q, state, ws);
  if (!proposal.fresh) return false;
  // G of the rows it would hold, as constraint_jacobian_v gives it once they are held.
  evaluate_constraints(model_, state, Stage::kPosition, released_, ws);
  const std::vector<int>& rows = proposal.fresh->independent;
  G.resize(static_cast<Eigen::Index>(rows.size()), model_.nv);
  for (std::size_t k = 0; k < rows.size(); ++k) G.row(static_cast<Eigen::Index>(k)) = ws.G.row(rows[k]);
  return true;
}

std::vector<int> MultibodySystem::release_joints(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                                 const Eigen::VectorXd& lambda) {
  state_.t = t;
  state_.q = q;
  state_.v = v;
  // Timed releases up to t, and those of events: the ones due now and the ones before.
  std::vector<bool> released = rows_released_by(model_, t);
  event_releases_.take_due();
  const std::vector<bool> before = partition_.row_released;
  std::vector<int> now;
  for (std::size_t j = 0; j < model_.joints.size(); ++j) {
    const Joint& joint = model_.joints[j];
    const auto first = static_cast<std::size_t>(joint.first_row);
    if (joint.rows == 0) continue;
    if (event_releases_.released_at()[j] <= t) {
      released.resize(static_cast<std::size_t>(model_.num_equations()), false);
      std::fill_n(released.begin() + joint.first_row, joint.rows, true);
    }
    const bool was = first < before.size() && before[first];
    if (first < released.size() && released[first] && !was) now.push_back(static_cast<int>(j));
  }
  // Releases that take time: the reactions just before, as loads that fade (fading_loads.h).
  const bool fading = std::any_of(now.begin(), now.end(), [&](int j) {
    return model_.joints[static_cast<std::size_t>(j)].release_duration > 0.0;
  });
  if (fading) {
    const Reactions before_release = reactions_from_multipliers(model_, state_, lambda, partition_, workspace_);
    for (const int j : now) {
      if (model_.joints[static_cast<std::size_t>(j)].release_duration <= 0.0) continue;
      fading_.push_back(fading_load(model_, j, before_release.joints[static_cast<std::size_t>(j)], t));
    }
  }
  partition_ = analyse_redundancy(model_, state_, workspace_, partition_.relative_threshold, kept_rows_, released);
  // Their rows and markers are no longer evaluated, but for the markers of fading loads.
  released_ = released_joints(model_, released);
  for (const FadingLoad& load : fading_) {
    if (released_.markers.empty()) break;
    released_.markers[static_cast<std::size_t>(load.marker_i)] = false;
    released_.markers[static_cast<std::size_t>(load.marker_j)] = false;
  }
  chosen_pivot_ = -1.0;
  return now;
}

std::vector<double> MultibodySystem::velocity_breakpoints() const {
  std::vector<double> times;
  for (const Driver& driver : model_.drivers) {
    const std::vector<double> jumps = driver.motion.slope_jumps();
    times.insert(times.end(), jumps.begin(), jumps.end());
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

void MultibodySystem::event_functions(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                      Eigen::VectorXd& e) {
  state_.t = t;
  state_.q = q;
  state_.v = v;
  hinge_limit_events(model_, limits_, state_, workspace_, e);
  // The delayed releases after them.
  const auto nl = static_cast<Eigen::Index>(limits_.size());
  e.conservativeResize(nl + event_releases_.num_events());
  auto tail = e.tail(event_releases_.num_events());
  event_releases_.event_functions(t, tail);
}

void MultibodySystem::apply_event(int k, double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  // A delayed release: its joint is due, and the integrator hands back control here.
  if (k >= static_cast<int>(limits_.size())) {
    event_releases_.on_release_event(k - static_cast<int>(limits_.size()), t);
    return;
  }
  const int force = limits_.at(static_cast<size_t>(k));
  const auto& limit = std::get<HingeLimit>(model_.forces[force]);
  state_.t = t;
  state_.q = q;
  state_.v = v;
  update_marker_kinematics(model_, state_, Stage::kVelocity, workspace_);
  const RelativeAngle angle = hinge_limit_state(limit, workspace_);
  // A latch locks for good (and is seated later); a stop toggles between free and in contact.
  unsigned char& mode = engaged_[force];
  mode = hinge_limit_next_mode(limit, mode);
  state_.engaged = engaged_;
  event_releases_.on_limit_switch(force, mode == kLimitEngaged, t);
  // A latch's seating changes only its damping's share: not a switch a user sees.
  if (mode == kLatchSeated) return;
  events_.push_back(HingeEvent{force, t, angle.theta, angle.rate, mode != kLimitFree});
}

void MultibodySystem::step_accepted(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                    const Eigen::VectorXd& v_dot, const Eigen::VectorXd& lambda) {
  if (!has_load_stiffening(model_)) return;
  state_.t = t;
  state_.q = q;
  state_.v = v;
  // G and the marker kinematics at the step, then the loads from its v̇ and λ (no solve).
  evaluate_constraints(model_, state_, Stage::kVelocity, released_, workspace_);
  state_.stiffening = accepted_step_stiffening_loads(model_, state_, v_dot, partition_.independent, lambda, workspace_);
}

}  // namespace limber::multibody
