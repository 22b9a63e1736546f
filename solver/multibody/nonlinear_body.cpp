#include "multibody/nonlinear_body.h"

#include <algorithm>
#include <array>

#include "core/error.h"

#include "multibody/rotation.h"
#include "nonlinear_beam/corotational_beam.h"

namespace limber::multibody {
namespace {

using nonlinear_beam::Matrix12d;
using nonlinear_beam::Vector12d;
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

Eigen::Matrix3d body_rotation(const Model& model, int body, const Eigen::VectorXd& q) {
  return rotation_matrix(q.segment<4>(model.bodies[static_cast<std::size_t>(body)].q_offset + 3));
}

// One element's force f_b = T_eᵀ f, stiffness T_eᵀ (∂f/∂(δx, δw)) T_e and damping T_eᵀ C T_e in
// the body velocities of its two node bodies (header), with T_e = diag(R_WCᵀ, R_a, R_WCᵀ, R_b).
struct ElementInBodies {
  Vector12d force;
  Matrix12d stiffness;
  Matrix12d damping;
  double dissipation = 0.0;  // [W]
};

// What element_in_bodies computes beyond the force.
struct ElementRequest {
  bool stiffness = false;
  bool damping_matrix = false;
  const std::vector<Vector6d>* node_velocities = nullptr;  // structure terms (ẋ, w) per node: damp
};

// T_eᵀ A T_e block by block (T_e is block diagonal).
Matrix12d to_bodies(const std::array<const Eigen::Matrix3d*, 4>& t_e, const Matrix12d& A) {
  Matrix12d out;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) out.block<3, 3>(3 * i, 3 * j) = t_e[i]->transpose() * A.block<3, 3>(3 * i, 3 * j) * *t_e[j];
  }
  return out;
}

ElementInBodies element_in_bodies(const NonlinearBody& body, const nonlinear_beam::CorotationalBeam& element,
                                  const nonlinear_beam::BeamState& state,
                                  const std::vector<Eigen::Matrix3d>& rotations, const ElementRequest& request) {
  const int a = element.nodes[0], b = element.nodes[1];
  const Eigen::Matrix3d R_CW = body.R_WC.transpose();
  nonlinear_beam::DeformationRateDamping damping;
  if (body.stiffness_damping > 0.0 && (request.node_velocities || request.damping_matrix)) {
    damping.beta = body.stiffness_damping;
    damping.with_matrix = request.damping_matrix;
    if (request.node_velocities) damping.velocity << (*request.node_velocities)[a], (*request.node_velocities)[b];
  }
  const nonlinear_beam::ElementResponse response = nonlinear_beam::corotational_beam_response(
      element, state.positions[a], state.positions[b], rotations[a], rotations[b], request.stiffness, damping);
  const std::array<const Eigen::Matrix3d*, 4> t_e = {&R_CW, &rotations[a], &R_CW, &rotations[b]};
  ElementInBodies out;
  for (int k = 0; k < 4; ++k) out.force.segment<3>(3 * k) = t_e[k]->transpose() * response.force.segment<3>(3 * k);
  if (request.stiffness) out.stiffness = to_bodies(t_e, response.tangent);
  if (damping.with_matrix) out.damping = to_bodies(t_e, response.damping);
  out.dissipation = response.dissipation;
  return out;
}

// The nodes' velocities in the structure's terms, T v per node: (R_WCᵀ ṙ_W, R_k ω_B).
std::vector<Vector6d> structure_velocities(const Model& model, const NonlinearBody& body,
                                           const std::vector<Eigen::Matrix3d>& rotations, const Eigen::VectorXd& v) {
  std::vector<Vector6d> out(body.node_bodies.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    const int offset = model.bodies[static_cast<std::size_t>(body.node_bodies[k])].v_offset;
    out[k] << body.R_WC.transpose() * v.segment<3>(offset), rotations[k] * v.segment<3>(offset + 3);
  }
  return out;
}

// The node rotations of the state as matrices, once per node.
std::vector<Eigen::Matrix3d> rotation_matrices(const nonlinear_beam::BeamState& state) {
  std::vector<Eigen::Matrix3d> out;
  out.reserve(state.rotations.size());
  for (const Eigen::Quaterniond& r : state.rotations) out.push_back(r.toRotationMatrix());
  return out;
}

const Body& node_body(const Model& model, const NonlinearBody& body, int node) {
  return model.bodies[static_cast<std::size_t>(body.node_bodies[static_cast<std::size_t>(node)])];
}

// Position of entry (row, col) in a compressed column-major matrix whose pattern holds it.
int slot_of(const Eigen::SparseMatrix<double>& A, int row, int col) {
  const int* begin = A.innerIndexPtr() + A.outerIndexPtr()[col];
  const int* end = A.innerIndexPtr() + A.outerIndexPtr()[col + 1];
  const int* at = std::lower_bound(begin, end, row);
  LIMBER_DEMAND(at != end && *at == row);
  return static_cast<int>(at - A.innerIndexPtr());
}

// Adds a dense 6 x 6 block at (row, col) of `A`'s pattern, column by column.
void add_block_in_place(Eigen::SparseMatrix<double>& A, int row, int col, const Eigen::Matrix<double, 6, 6>& block) {
  for (int j = 0; j < 6; ++j) {
    double* column = A.valuePtr() + slot_of(A, row, col + j);
    for (int i = 0; i < 6; ++i) column[i] += block(i, j);
  }
}

// A node body's mass matrix in its velocities (ṙ_W, ω_B): diag(m I, J_B), the node at its mass
// centre (nonlinear_body_builder.cpp).
Matrix6d node_mass(const Body& node) {
  Matrix6d M = Matrix6d::Zero();
  M.topLeftCorner<3, 3>().diagonal().setConstant(node.mass);
  M.bottomRightCorner<3, 3>() = node.inertia_com_B;
  return M;
}

// Q += −α M (v − v_r) on the body's node bodies, v_r = Ψ (Ψᵀ M Ψ)⁻¹ Ψᵀ M v the M-orthogonal
// projection of v on the body's six rigid velocities Ψ (about the nodes' mass centre c:
// ṙ_k = v_c − S(r_k − c) ω, ω_B,k = R_kᵀ ω). Ψᵀ of the force is zero: no net force or moment.
void add_relative_mass_damping(const Model& model, const NonlinearBody& body, const Eigen::VectorXd& q,
                               const Eigen::VectorXd& v, Eigen::VectorXd& Q, double* dissipation) {
  const std::size_t nodes = body.node_bodies.size();
  double mass = 0.0;
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();
  for (const int b : body.node_bodies) {
    const Body& node = model.bodies[static_cast<std::size_t>(b)];
    mass += node.mass;
    first_moment += node.mass * q.segment<3>(node.q_offset);
  }
  const Eigen::Vector3d centre = first_moment / mass;
  // Ψ_k and M_k per node; A = Σ Ψ_kᵀ M_k Ψ_k, b = Σ Ψ_kᵀ M_k v_k.
  std::vector<Matrix6d> psi(nodes), M(nodes);
  Matrix6d A = Matrix6d::Zero();
  Vector6d rhs = Vector6d::Zero();
  for (std::size_t k = 0; k < nodes; ++k) {
    const int b = body.node_bodies[k];
    const Body& node = model.bodies[static_cast<std::size_t>(b)];
    psi[k].setZero();
    psi[k].topLeftCorner<3, 3>().setIdentity();
    psi[k].topRightCorner<3, 3>() = -skew(q.segment<3>(node.q_offset) - centre);
    psi[k].bottomRightCorner<3, 3>() = body_rotation(model, b, q).transpose();
    M[k] = node_mass(node);
    const Matrix6d psi_t_M = psi[k].transpose() * M[k];
    A += psi_t_M * psi[k];
    rhs += psi_t_M * v.segment<6>(node.v_offset);
  }
  const Vector6d rigid = A.ldlt().solve(rhs);
  // The force on each node and the power it removes, (v − v_r)ᵀ α M (v − v_r).
  for (std::size_t k = 0; k < nodes; ++k) {
    const int offset = model.bodies[static_cast<std::size_t>(body.node_bodies[k])].v_offset;
    const Vector6d relative = v.segment<6>(offset) - psi[k] * rigid;
    const Vector6d force = body.mass_damping * (M[k] * relative);
    Q.segment<6>(offset) -= force;
    if (dissipation) *dissipation += relative.dot(force);
  }
}

// The pattern of nonlinear_body_stiffness: the node-pair blocks of every element.
void build_stiffness_pattern(const Model& model, Eigen::SparseMatrix<double>& K) {
  std::vector<Eigen::Triplet<double>> pattern;
  for (const NonlinearBody& body : model.nonlinear_bodies) {
    for (const nonlinear_beam::CorotationalBeam& element : body.structure->elements) {
      for (const int a : element.nodes) {
        for (const int b : element.nodes) {
          const int row = node_body(model, body, a).v_offset, col = node_body(model, body, b).v_offset;
          for (int j = 0; j < 6; ++j) {
            for (int i = 0; i < 6; ++i) pattern.emplace_back(row + i, col + j, 0.0);
          }
        }
      }
    }
  }
  K.resize(model.nv, model.nv);
  K.setFromTriplets(pattern.begin(), pattern.end());
  K.makeCompressed();
}

}  // namespace

nonlinear_beam::BeamState nonlinear_body_state(const Model& model, const NonlinearBody& body,
                                               const Eigen::VectorXd& q) {
  nonlinear_beam::BeamState state;
  state.positions.reserve(body.node_bodies.size());
  state.rotations.reserve(body.node_bodies.size());
  const Eigen::Matrix3d R_CW = body.R_WC.transpose();
  // Node rotations R_CW R_WB composed as quaternions: no matrix round trip per node.
  const Eigen::Quaterniond q_CW(R_CW);
  for (const int b : body.node_bodies) {
    const Body& node = model.bodies[static_cast<std::size_t>(b)];
    state.positions.push_back(R_CW * (q.segment<3>(node.q_offset) - body.p_WC));
    const Eigen::Vector4d p = q.segment<4>(node.q_offset + 3);  // Euler parameters (w, x, y, z)
    state.rotations.push_back((q_CW * Eigen::Quaterniond(p(0), p(1), p(2), p(3)).normalized()).normalized());
  }
  return state;
}

void add_nonlinear_body_forces(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                               Eigen::VectorXd& Q, double* dissipation) {
  for (const NonlinearBody& body : model.nonlinear_bodies) {
    const nonlinear_beam::BeamState state = nonlinear_body_state(model, body, q);
    const std::vector<Eigen::Matrix3d> rotations = rotation_matrices(state);
    // The elements' deformation rates only when they are damped (an undamped body: as before).
    std::vector<Vector6d> velocities;
    ElementRequest request;
    if (body.stiffness_damping > 0.0) {
      velocities = structure_velocities(model, body, rotations, v);
      request.node_velocities = &velocities;
    }
    for (const nonlinear_beam::CorotationalBeam& element : body.structure->elements) {
      const ElementInBodies e = element_in_bodies(body, element, state, rotations, request);
      for (int end = 0; end < 2; ++end) {
        const Body& node = model.bodies[static_cast<std::size_t>(body.node_bodies[element.nodes[end]])];
        Q.segment<6>(node.v_offset) -= e.force.segment<6>(6 * end);
      }
      if (dissipation) *dissipation += e.dissipation;
    }
    if (body.mass_damping > 0.0) add_relative_mass_damping(model, body, q, v, Q, dissipation);
  }
}

bool nonlinear_body_stiffness(const Model& model, const Eigen::VectorXd& q, Eigen::SparseMatrix<double>& K) {
  if (model.nonlinear_bodies.empty()) return false;
  if (K.rows() != model.nv || K.cols() != model.nv || K.nonZeros() == 0) build_stiffness_pattern(model, K);
  std::fill(K.valuePtr(), K.valuePtr() + K.nonZeros(), 0.0);
  for (const NonlinearBody& body : model.nonlinear_bodies) {
    const nonlinear_beam::BeamState state = nonlinear_body_state(model, body, q);
    const std::vector<Eigen::Matrix3d> rotations = rotation_matrices(state);
    // Material internal moment per node, for the turning of its axes.
    std::vector<Eigen::Vector3d> moments(body.node_bodies.size(), Eigen::Vector3d::Zero());
    for (const nonlinear_beam::CorotationalBeam& element : body.structure->elements) {
      const ElementInBodies e = element_in_bodies(body, element, state, rotations, ElementRequest{.stiffness = true});
      for (int i = 0; i < 2; ++i) {
        moments[static_cast<std::size_t>(element.nodes[i])] += e.force.segment<3>(6 * i + 3);
        const int row = node_body(model, body, element.nodes[i]).v_offset;
        for (int j = 0; j < 2; ++j) {
          add_block_in_place(K, row, node_body(model, body, element.nodes[j]).v_offset, e.stiffness.block<6, 6>(6 * i, 6 * j));
        }
      }
    }
    for (std::size_t k = 0; k < body.node_bodies.size(); ++k) {
      const int offset = node_body(model, body, static_cast<int>(k)).v_offset;
      Eigen::Matrix<double, 6, 6> block = Eigen::Matrix<double, 6, 6>::Zero();
      block.bottomRightCorner<3, 3>() = skew(moments[k]);
      add_block_in_place(K, offset, offset, block);
    }
  }
  return true;
}

bool nonlinear_body_damping(const Model& model, const Eigen::VectorXd& q, Eigen::SparseMatrix<double>& C) {
  const bool damped = std::any_of(model.nonlinear_bodies.begin(), model.nonlinear_bodies.end(),
                                  [](const NonlinearBody& body) { return body.mass_damping > 0.0 || body.stiffness_damping > 0.0; });
  if (!damped) return false;
  if (C.rows() != model.nv || C.cols() != model.nv || C.nonZeros() == 0) build_stiffness_pattern(model, C);
  std::fill(C.valuePtr(), C.valuePtr() + C.nonZeros(), 0.0);
  for (const NonlinearBody& body : model.nonlinear_bodies) {
    // β: the elements' Kelvin–Voigt damping, exact in v at this q.
    if (body.stiffness_damping > 0.0) {
      const nonlinear_beam::BeamState state = nonlinear_body_state(model, body, q);
      const std::vector<Eigen::Matrix3d> rotations = rotation_matrices(state);
      for (const nonlinear_beam::CorotationalBeam& element : body.structure->elements) {
        const ElementInBodies e = element_in_bodies(body, element, state, rotations, ElementRequest{.damping_matrix = true});
        for (int i = 0; i < 2; ++i) {
          const int row = node_body(model, body, element.nodes[i]).v_offset;
          for (int j = 0; j < 2; ++j) {
            add_block_in_place(C, row, node_body(model, body, element.nodes[j]).v_offset, e.damping.block<6, 6>(6 * i, 6 * j));
          }
        }
      }
    }
    // α: α M_k per node; the rank-6 rigid projection is left out (a Newton matrix, not the force).
    if (body.mass_damping > 0.0) {
      for (const int b : body.node_bodies) {
        const Body& node = model.bodies[static_cast<std::size_t>(b)];
        add_block_in_place(C, node.v_offset, node.v_offset, body.mass_damping * node_mass(node));
      }
    }
  }
  return true;
}

double nonlinear_body_strain_energy(const Model& model, const Eigen::VectorXd& q) {
  double energy = 0.0;
  for (const NonlinearBody& body : model.nonlinear_bodies) {
    energy += nonlinear_beam::strain_energy(*body.structure, nonlinear_body_state(model, body, q));
  }
  return energy;
}

Eigen::Vector3d nonlinear_probe_deflection(const Model& model, const NonlinearBody& body,
                                           const Eigen::VectorXd& q) {
  const DeflectionProbe& probe = *body.deflection_probe;
  const std::vector<Eigen::Vector3d>& X = body.structure->reference_positions;
  // The node's place along the undeformed chord, and its offset from it.
  const Eigen::Vector3d E = X[probe.chord_end] - X[probe.chord_start];
  const double s = (X[probe.node] - X[probe.chord_start]).dot(E) / E.squaredNorm();
  const Eigen::Vector3d offset_0 = X[probe.node] - (X[probe.chord_start] + s * E);
  // The same now, in axes turned with the chord.
  const nonlinear_beam::BeamState state = nonlinear_body_state(model, body, q);
  const std::vector<Eigen::Vector3d>& x = state.positions;
  const Eigen::Vector3d e = x[probe.chord_end] - x[probe.chord_start];
  const Eigen::Vector3d offset = x[probe.node] - (x[probe.chord_start] + s * e);
  const Eigen::Matrix3d R_chord = Eigen::Quaterniond::FromTwoVectors(E, e).toRotationMatrix();
  return R_chord.transpose() * offset - offset_0;
}

std::vector<int> nonlinear_body_of(const Model& model) {
  std::vector<int> owner(model.bodies.size(), -1);
  for (std::size_t k = 0; k < model.nonlinear_bodies.size(); ++k) {
    for (const int b : model.nonlinear_bodies[k].node_bodies) owner[static_cast<std::size_t>(b)] = static_cast<int>(k);
  }
  return owner;
}

Eigen::MatrixXd rigid_nonlinear_velocity_basis(const Model& model, const Eigen::VectorXd& q) {
  const std::vector<int> owner = nonlinear_body_of(model);
  // Columns: the own velocities of every other body, then 6 per nonlinear body.
  int columns = 6 * static_cast<int>(model.nonlinear_bodies.size());
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (owner[b] < 0) columns += model.bodies[b].nv;
  }
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(model.nv, columns);
  int column = 0;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (owner[b] >= 0) continue;
    const Body& body = model.bodies[b];
    B.block(body.v_offset, column, body.nv, body.nv).setIdentity();
    column += body.nv;
  }
  // Node k: ṙ_k = v_C + ω × (r_k − p_C) = v_C − S(r_k − p_C) ω, ω_B,k = R_WBᵀ ω.
  for (const NonlinearBody& nonlinear : model.nonlinear_bodies) {
    for (const int b : nonlinear.node_bodies) {
      const Body& node = model.bodies[static_cast<std::size_t>(b)];
      B.block<3, 3>(node.v_offset, column).setIdentity();
      B.block<3, 3>(node.v_offset, column + 3) = -skew(q.segment<3>(node.q_offset) - nonlinear.p_WC);
      B.block<3, 3>(node.v_offset + 3, column + 3) = body_rotation(model, b, q).transpose();
    }
    column += 6;
  }
  return B;
}

}  // namespace limber::multibody
