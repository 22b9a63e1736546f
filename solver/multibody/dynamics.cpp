#include "multibody/dynamics.h"
#include "multibody/evaluated.h"

#include "multibody/body.h"
#include "multibody/constraints.h"
#include "multibody/nonlinear_body.h"
#include "multibody/flexible_body.h"
#include "multibody/flexible_dynamics.h"
#include "multibody/geometric_stiffening.h"
#include "multibody/hinge_limit.h"
#include "multibody/released_joints.h"

namespace limber::multibody {

namespace {

// The mode of force element k (State::engaged; hinge_limit.h's kLimit* values).
unsigned char mode_of(const State& state, size_t k) {
  return k < state.engaged.size() ? state.engaged[k] : kLimitFree;
}

// θ of an RSDA, unwrapped within ±π of its reference angle.
double rsda_angle(const Rsda& r, const RelativeAngle& angle) {
  return r.reference_angle + wrap_angle(angle.theta - r.reference_angle);
}

struct ForceVisitor {
  const State& state;
  Workspace& ws;
  PowerTerms* powers;
  std::vector<MarkerLoad>* loads = nullptr;  // when set, collects the loads instead of adding Q
  unsigned char mode = kLimitFree;           // mode of the element being visited

  // Force and torque (ground axes) at the origin of marker m.
  void apply(int m, const Eigen::Vector3d& f_W, const Eigen::Vector3d& tau_W) const {
    if (loads) {
      loads->push_back({m, f_W, tau_W});
    } else {
      add_frame_load(ws.markers[m], f_W, tau_W, ws.Q);
    }
  }

  void operator()(const Rsda& r) const {
    const FrameKinematics& mi = ws.markers[r.marker_i];
    const FrameKinematics& mj = ws.markers[r.marker_j];
    const RelativeAngle angle = relative_angle(mi, mj, Stage::kVelocity);
    const double theta = rsda_angle(r, angle);
    // Torque on body j about z_i: spring, damper, actuator of t or θ.
    const double a = r.actuator.evaluate(r.actuator_of_angle ? theta : state.t).value;
    const double tau = -r.stiffness * (theta - r.free_angle) - r.damping * angle.rate + a;
    apply(r.marker_j, Eigen::Vector3d::Zero(), tau * angle.u);
    apply(r.marker_i, Eigen::Vector3d::Zero(), -tau * angle.u);
    if (powers) {
      powers->dissipation += r.damping * angle.rate * angle.rate;
      powers->actuators += a * angle.rate;
    }
  }

  void operator()(const Tsda& s) const {
    const FrameKinematics& mi = ws.markers[s.marker_i];
    const FrameKinematics& mj = ws.markers[s.marker_j];
    const Eigen::Vector3d d = mj.p_W - mi.p_W;
    const double length = d.norm();
    // Coincident points: the line of action is undefined and the force has no direction.
    if (length == 0.0) return;
    const Eigen::Vector3d e = d / length;
    const double rate = e.dot(mj.v_W - mi.v_W);
    const double a = s.actuator.evaluate(state.t).value;
    const double f = -s.stiffness * (length - s.free_length) - s.damping * rate + a;
    apply(s.marker_j, f * e, Eigen::Vector3d::Zero());
    apply(s.marker_i, -f * e, Eigen::Vector3d::Zero());
    if (powers) {
      powers->dissipation += s.damping * rate * rate;
      powers->actuators += a * rate;
    }
  }

  void operator()(const PointLoad& p) const {
    const FrameKinematics& m = ws.markers[p.marker];
    const double scale = p.scale.evaluate(state.t).value;
    // Marker-axis loads turn with the marker.
    const Eigen::Matrix3d R = p.frame == LoadFrame::kMarker ? m.R_WF : Eigen::Matrix3d::Identity();
    const Eigen::Vector3d f_W = scale * R * p.force, tau_W = scale * R * p.torque;
    apply(p.marker, f_W, tau_W);
    if (powers) powers->loads += f_W.dot(m.v_W) + tau_W.dot(m.w_W);
  }

  void operator()(const HingeLimit& h) const {
    if (mode == kLimitFree) return;
    const FrameKinematics& mi = ws.markers[h.marker_i];
    const FrameKinematics& mj = ws.markers[h.marker_j];
    const RelativeAngle angle = relative_angle(mi, mj, Stage::kVelocity);
    const HingeLimitForce f = hinge_limit_force(h, hinge_limit_angle(h, angle), angle.rate, mode);
    apply(h.marker_j, Eigen::Vector3d::Zero(), f.torque * angle.u);
    apply(h.marker_i, Eigen::Vector3d::Zero(), -f.torque * angle.u);
    if (powers) powers->dissipation += f.dissipation;
  }
};

}  // namespace

void mass_matrix(const Model& model, const State& state, Workspace& ws) {
  ws.M.setZero(model.nv, model.nv);
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (body.nv > 0) ws.M.block(body.v_offset, body.v_offset, body.nv, body.nv) = body_mass_block(model, b, state.q);
  }
}

Eigen::VectorXd mass_times(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& a) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(model.nv);
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (body.nv > 0) out.segment(body.v_offset, body.nv) = body_mass_block(model, b, q) * a.segment(body.v_offset, body.nv);
  }
  return out;
}

void sparse_mass_matrix(const Model& model, const State& state, Eigen::SparseMatrix<double>& M) {
  // The pattern, once: every body's full diagonal block.
  if (M.rows() != model.nv || !M.isCompressed() || M.nonZeros() == 0) {
    std::vector<Eigen::Triplet<double>> pattern;
    for (const Body& body : model.bodies) {
      for (int j = 0; j < body.nv; ++j) {
        for (int i = 0; i < body.nv; ++i) pattern.emplace_back(body.v_offset + i, body.v_offset + j, 0.0);
      }
    }
    M.resize(model.nv, model.nv);
    M.setFromTriplets(pattern.begin(), pattern.end());
    M.makeCompressed();
  }
  // Column j of a block starting at row o holds rows o … o + nv − 1 in order.
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (body.nv == 0) continue;
    const Eigen::MatrixXd M_b = body_mass_block(model, b, state.q);
    for (int j = 0; j < body.nv; ++j) {
      double* column = M.valuePtr() + M.outerIndexPtr()[body.v_offset + j];
      for (int i = 0; i < body.nv; ++i) column[i] = M_b(i, j);
    }
  }
}

void force_element_loads(const Model& model, const State& state, Workspace& ws, std::vector<MarkerLoad>& loads) {
  loads.clear();
  if (model.forces.empty()) return;
  update_marker_kinematics(model, state, Stage::kVelocity, ws);
  ForceVisitor visitor{state, ws, nullptr, &loads};
  for (size_t k = 0; k < model.forces.size(); ++k) {
    visitor.mode = mode_of(state, k);
    std::visit(visitor, model.forces[k]);
  }
}

namespace {

// The forces between bodies: nonlinear bodies' beams, force elements (from ws.markers, updated
// at the velocity stage by the caller when there are force elements) and the geometric
// stiffening from joint loads and frame accelerations.
void add_interaction_forces(const Model& model, const State& state, Workspace& ws, PowerTerms* powers) {
  // The co-rotational beams of nonlinear bodies between their node bodies, and their damping.
  add_nonlinear_body_forces(model, state.q, state.v, ws.Q, powers ? &powers->dissipation : nullptr);
  if (!model.forces.empty()) {
    ForceVisitor visitor{state, ws, powers};
    for (size_t k = 0; k < model.forces.size(); ++k) {
      visitor.mode = mode_of(state, k);
      std::visit(visitor, model.forces[k]);
    }
  }
  add_load_geometric_stiffness(model, state, ws, powers ? &powers->geometric : nullptr);
}

}  // namespace

namespace {

// A flexible body's share of the powers: its modal damping and centrifugal geometric force.
void add_body_powers(const Body& body, const State& state, PowerTerms& powers) {
  if (body.kind != BodyKind::kFlexible) return;
  // Modal damping removes Σ c_i η̇_i² (flexible_dynamics.cpp applies Q_η = −c η̇).
  const int nm = body.flexible->mode_count();
  const auto eta_dot = state.v.segment(body.v_offset + 6, nm);
  powers.dissipation += eta_dot.dot(body.flexible->damping.cwiseProduct(eta_dot));
  // The centrifugal geometric force's power (flexible_dynamics.cpp adds the force).
  if (body.flexible->stiffening != GeometricStiffening::kOff) {
    powers.geometric -= eta_dot.dot(centrifugal_geometric_force(
        body.flexible->geometric, state.v.segment<3>(body.v_offset + 3), state.q.segment(body.q_offset + 7, nm)));
  }
}

}  // namespace

void generalized_forces(const Model& model, const State& state, Workspace& ws, PowerTerms* powers) {
  ws.Q.setZero(model.nv);
  if (powers) *powers = PowerTerms{};
  // Bodies: quadratic-velocity forces and gravity.
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    add_body_inertial_and_gravity_forces(model, b, state.q, state.v, ws.Q);
    if (powers) add_body_powers(model.bodies[b], state, *powers);
  }
  if (!model.forces.empty()) update_marker_kinematics(model, state, Stage::kVelocity, ws);
  add_interaction_forces(model, state, ws, powers);
}

PowerTerms power_terms(const Model& model, const State& state, const ReleasedJoints& released, Workspace& ws) {
  PowerTerms powers;
  // The load-dependent stiffening, without lagged loads, solves for them from the bodies' forces too.
  if (has_load_stiffening(model) && state.stiffening.empty()) {
    generalized_forces(model, state, ws, &powers);
    return powers;
  }
  ws.Q.setZero(model.nv);
  for (const Body& body : model.bodies) add_body_powers(body, state, powers);
  if (!model.forces.empty()) update_marker_kinematics(model, state, Stage::kVelocity, released, ws);
  add_interaction_forces(model, state, ws, &powers);
  return powers;
}

void mass_matrix_and_forces(const Model& model, const State& state, Workspace& ws) {
  mass_matrix_and_forces(model, state, ReleasedJoints{}, ws);
}

void mass_matrix_and_forces(const Model& model, const State& state, const ReleasedJoints& released, Workspace& ws) {
  ws.M.setZero(model.nv, model.nv);
  ws.Q.setZero(model.nv);
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (body.kind == BodyKind::kFlexible) {
      add_flexible_mass_matrix_and_forces(body, model.gravity_W, state.q, state.v, ws.M, ws.Q);
    } else {
      if (body.nv > 0) ws.M.block(body.v_offset, body.v_offset, body.nv, body.nv) = body_mass_block(model, b, state.q);
      add_body_inertial_and_gravity_forces(model, b, state.q, state.v, ws.Q);
    }
  }
  update_marker_kinematics(model, state, model.forces.empty() ? Stage::kPosition : Stage::kVelocity, released, ws);
  add_interaction_forces(model, state, ws, nullptr);
}

EnergyTerms energies(const Model& model, const State& state, Workspace& ws) {
  update_marker_kinematics(model, state, Stage::kPosition, ws);
  return energies_at_markers(model, state, ws);
}

EnergyTerms energies_at_markers(const Model& model, const State& state, const Workspace& ws) {
  EnergyTerms e;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    e.kinetic += body_kinetic_energy(model, b, state.q, state.v);
    e.gravity += body_gravity_potential(model, b, state.q);
    if (model.bodies[b].kind == BodyKind::kFlexible) e.strain += flexible_strain_energy(model.bodies[b], state.q);
  }
  e.strain += nonlinear_body_strain_energy(model, state.q);
  for (size_t k = 0; k < model.forces.size(); ++k) {
    const ForceElement& force = model.forces[k];
    if (const Rsda* r = std::get_if<Rsda>(&force)) {
      const double theta =
          rsda_angle(*r, relative_angle(ws.markers[r->marker_i], ws.markers[r->marker_j], Stage::kPosition));
      e.spring += 0.5 * r->stiffness * (theta - r->free_angle) * (theta - r->free_angle);
    } else if (const Tsda* s = std::get_if<Tsda>(&force)) {
      const double stretch = (ws.markers[s->marker_j].p_W - ws.markers[s->marker_i].p_W).norm() - s->free_length;
      e.spring += 0.5 * s->stiffness * stretch * stretch;
    } else if (const HingeLimit* h = std::get_if<HingeLimit>(&force)) {
      const RelativeAngle angle =
          relative_angle(ws.markers[h->marker_i], ws.markers[h->marker_j], Stage::kPosition);
      e.spring += hinge_limit_energy(*h, hinge_limit_angle(*h, angle), mode_of(state, k) != kLimitFree);
    }
  }
  return e;
}

}  // namespace limber::multibody
