#include "modal/component_modes.h"

#include <algorithm>
#include <optional>
#include <set>

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include "core/error.h"
#include "modal/constrained_matrices.h"
#include "modal/dof_selection.h"
#include "modal/modal_invariants.h"
#include "modal/normal_modes.h"
#include "modal/orthonormalise_modes.h"
#include "modal/rigid_body_modes.h"
#include "modal/static_modes.h"

namespace limber::modal {
namespace {

struct SiteDofs {
  std::vector<int> dofs;             // global DOF indices, request order
  std::vector<std::string> labels;  // "constraint uz at node 101"
};

// Validates the sites of one kind and lists their DOFs (InputError on bad input).
// `dependent`: DOFs made dependent by multipoint constraints (ascending), refused when
// `independent_only` (a constraint mode prescribes a DOF, which a dependent DOF cannot take).
SiteDofs site_dofs(const fe::FeModel& model, const std::vector<StaticModeSite>& sites,
                   const std::vector<int>& free_dofs, const std::vector<int>& dependent,
                   bool independent_only, const char* kind) {
  SiteDofs result;
  std::set<int> seen;
  for (const StaticModeSite& site : sites) {
    if (site.node < 0 || site.node >= model.node_count()) {
      throw InputError(fmt::format("{} mode site: expected a node index in [0, {}), got {}", kind,
                                   model.node_count(), site.node));
    }
    const int id = site.node < static_cast<int>(model.node_ids.size())
                       ? model.node_ids[static_cast<std::size_t>(site.node)]
                       : site.node;
    if (site.dofs.empty()) {
      throw InputError(fmt::format("{} mode site at node {}: expected at least one DOF, got none",
                                   kind, id));
    }
    for (fe::Dof dof : site.dofs) {
      const int index = fe::FeModel::dof_index(site.node, dof);
      if (!std::binary_search(free_dofs.begin(), free_dofs.end(), index)) {
        throw InputError(fmt::format(
            "{} mode site: expected a free DOF, got {} at node {}, which is fixed", kind,
            fe::dof_name(dof), id));
      }
      if (independent_only && std::binary_search(dependent.begin(), dependent.end(), index)) {
        throw InputError(fmt::format(
            "{} mode site: expected an independent DOF, got {} at node {}, which a rigid element "
            "makes dependent (ask for it at the element's independent grid, or ask for an "
            "attachment mode)",
            kind, fe::dof_name(dof), id));
      }
      if (!seen.insert(index).second) {
        throw InputError(fmt::format(
            "{} mode sites: expected each DOF once, got {} at node {} twice", kind, fe::dof_name(dof),
            id));
      }
      result.dofs.push_back(index);
      result.labels.push_back(fmt::format("{} {} at node {}", kind, fe::dof_name(dof), id));
    }
  }
  return result;
}

// The combinations N (r x r', orthonormal) of the rigid motions `psi_free` (n x r, full
// displacements) that the springs of the model (FeModel::dof_stiffnesses) do not resist: the
// null space of psi_free^T K_springs psi_free, columns normalised first, eigenvalues below
// 1e-9 of K's largest diagonal entry counted as zero (a spring softer than that is not a
// support, and a two-node spring's rigid energy is round-off far below it). A grounded spring
// restrains rigid motion as a fixed DOF does.
Eigen::MatrixXd unresisted_rigid_motion(const fe::FeModel& model, const fe::SparseMatrix& stiffness,
                                        const Eigen::MatrixXd& psi_free) {
  const Eigen::VectorXd norms = psi_free.colwise().norm();
  const Eigen::MatrixXd v = psi_free * norms.cwiseInverse().asDiagonal();
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(v.cols(), v.cols());
  for (const fe::DofMatrix& spring : model.dof_stiffnesses) {
    const Eigen::MatrixXd v_e = gather_rows(v, spring.dofs);
    g += v_e.transpose() * spring.values * v_e;
  }
  const double scale = stiffness.diagonal().cwiseAbs().maxCoeff();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(0.5 * (g + g.transpose()));
  std::vector<Eigen::Index> zero;
  for (Eigen::Index i = 0; i < g.rows(); ++i) {
    if (eigen.eigenvalues()(i) <= 1e-9 * scale) zero.push_back(i);
  }
  Eigen::MatrixXd n(g.rows(), static_cast<Eigen::Index>(zero.size()));
  for (std::size_t j = 0; j < zero.size(); ++j) {
    n.col(static_cast<Eigen::Index>(j)) = norms.cwiseInverse().asDiagonal() * eigen.eigenvectors().col(zero[j]);
  }
  // Back to unnormalised columns of psi_free, re-orthonormalised (Psi N must stay a basis).
  if (n.cols() > 0) n = Eigen::HouseholderQR<Eigen::MatrixXd>(n).householderQ() * Eigen::MatrixXd::Identity(n.rows(), n.cols());
  return n;
}

ModalResult failure(ModalStatus status, const std::string& what, const std::string& message,
                    std::vector<std::string> notices) {
  ModalResult result;
  result.status = status;
  result.message = fmt::format("{}: {}", what, message);
  result.notices = std::move(notices);
  return result;
}

}  // namespace

ModalResult compute_component_modes(const fe::FeModel& model, const ModeRequest& request) {
  return compute_component_modes(model, fe::assemble(model), request);
}

ModalResult compute_component_modes(const fe::FeModel& model,
                                    const fe::StructuralMatrices& matrices,
                                    const ModeRequest& request) {
  // Multipoint constraints eliminated (constrained_matrices.h): embedded T^T K T, T^T M T,
  // dependent DOFs out of the free set; shapes are expanded by T at the end.
  const Eigen::MatrixXd psi_full = rigid_body_modes(model);
  std::optional<ConstrainedMatrices> constrained;
  if (!model.multipoint_constraints.empty()) constrained = constrain(model, matrices, psi_full);
  const fe::SparseMatrix& k = constrained ? constrained->stiffness : matrices.stiffness;
  const fe::SparseMatrix& m = constrained ? constrained->mass : matrices.mass;
  const Eigen::MatrixXd& psi = constrained ? constrained->psi : psi_full;
  const std::vector<int> unheld_dofs = fe::free_dofs(model);
  const std::vector<int> free_dofs = constrained ? constrained->free_dofs : unheld_dofs;
  const std::vector<int> no_dofs;
  const std::vector<int>& dependent = constrained ? constrained->transformation.dependent_dofs : no_dofs;
  const int n_free = static_cast<int>(free_dofs.size());

  // Validate the request.
  const bool want_normal = request.normal_count > 0 || request.max_frequency_hz.has_value();
  if (!want_normal && request.constraint_sites.empty() && request.attachment_sites.empty()) {
    throw InputError(
        "mode request: expected normal modes (a count or a cut-off frequency) or static-mode "
        "sites, got none");
  }
  if (request.normal_count < 0) {
    throw InputError(fmt::format("mode request: expected a normal-mode count >= 0, got {}",
                                 request.normal_count));
  }
  if (request.max_frequency_hz && !(*request.max_frequency_hz > 0.0)) {
    throw InputError(fmt::format("mode request: expected a cut-off frequency > 0 Hz, got {}",
                                 *request.max_frequency_hz));
  }
  if (!(request.dependency_tolerance > 0.0 && request.dependency_tolerance < 1.0)) {
    throw InputError(fmt::format("mode request: expected a dependency tolerance in (0, 1), got {}",
                                 request.dependency_tolerance));
  }
  const SiteDofs constraint =
      site_dofs(model, request.constraint_sites, unheld_dofs, dependent, true, "constraint");
  const SiteDofs attachment =
      site_dofs(model, request.attachment_sites, unheld_dofs, dependent, false, "attachment");

  // The rigid motion the fixed DOFs leave free.
  const std::vector<int> fixed = set_difference(
      [&] {
        std::vector<int> all(static_cast<std::size_t>(model.dof_count()));
        for (int i = 0; i < model.dof_count(); ++i) all[static_cast<std::size_t>(i)] = i;
        return all;
      }(),
      unheld_dofs);
  Eigen::MatrixXd psi_free = unrestrained_rigid_motion(psi, fixed);
  if (!model.dof_stiffnesses.empty() && psi_free.cols() > 0) {
    const Eigen::MatrixXd full = constrained ? expand(*constrained, psi_free) : psi_free;
    const Eigen::MatrixXd unresisted = unresisted_rigid_motion(model, matrices.stiffness, full);
    // Static modes take the free rigid motion from the held DOFs alone (static_modes.h).
    if (unresisted.cols() < psi_free.cols() && (!constraint.dofs.empty() || !attachment.dofs.empty())) {
      throw InputError(fmt::format(
          "mode request: expected no constraint or attachment modes on a body whose grounded "
          "springs restrain rigid motion ({} of {} rigid motions), got static-mode sites (not "
          "supported: hold the DOFs with fixed DOFs instead)",
          psi_free.cols() - unresisted.cols(), psi_free.cols()));
    }
    psi_free = psi_free * unresisted;
  }
  const int rigid_count = static_cast<int>(psi_free.cols());
  if (request.normal_count + rigid_count > n_free) {
    throw InputError(fmt::format(
        "mode request: expected at most {} normal modes ({} free DOFs, {} rigid-body modes), "
        "got {}",
        n_free - rigid_count, n_free, rigid_count, request.normal_count));
  }
  const std::size_t static_count = constraint.dofs.size() + attachment.dofs.size();
  if (static_cast<int>(static_count) > n_free) {
    throw InputError(fmt::format("mode request: expected at most {} static modes, got {}", n_free,
                                 static_count));
  }

  std::vector<std::string> notices;
  std::vector<Eigen::MatrixXd> blocks;
  std::vector<ModeInfo> info;
  std::vector<ModeInfo> rigid_modes;

  // Normal modes (seed paper eq. 4-6).
  if (want_normal) {
    NormalModeRequest normal_request;
    normal_request.count = request.normal_count;
    normal_request.max_frequency_hz = request.max_frequency_hz;
    normal_request.rigid_count = rigid_count;
    NormalModes normal = compute_normal_modes(k, m, free_dofs, normal_request);
    notices.insert(notices.end(), normal.notices.begin(), normal.notices.end());
    if (normal.status != ModalStatus::kOk) {
      return failure(normal.status, "normal modes", normal.message, notices);
    }
    for (Eigen::Index i = 0; i < normal.rigid_eigenvalues.size(); ++i) {
      rigid_modes.push_back({ModeKind::kRigid, frequency_hz(normal.rigid_eigenvalues[i]),
                             fmt::format("rigid {}", i + 1)});
    }
    for (Eigen::Index i = 0; i < normal.eigenvalues.size(); ++i) {
      info.push_back({ModeKind::kNormal, frequency_hz(normal.eigenvalues[i]),
                      fmt::format("normal {}", i + 1)});
    }
    blocks.push_back(std::move(normal.shapes));
  }

  // Constraint modes (eq. 7-9) and attachment modes (eq. 10-11).
  const auto add_static = [&](const SiteDofs& sites, ModeKind kind, auto compute,
                              const char* what) -> std::optional<ModalResult> {
    if (sites.dofs.empty()) return std::nullopt;
    StaticModes modes = compute(k, m, psi, free_dofs, sites.dofs);
    if (modes.status != ModalStatus::kOk) return failure(modes.status, what, modes.message, notices);
    for (const std::string& label : sites.labels) info.push_back({kind, 0.0, label});
    blocks.push_back(std::move(modes.shapes));
    return std::nullopt;
  };
  if (auto failed = add_static(constraint, ModeKind::kConstraint, compute_constraint_modes,
                               "constraint modes")) {
    return *failed;
  }
  // With constraints, a unit force at a DOF loads the independent DOFs with T^T e.
  const auto constrained_attachment = [&](const fe::SparseMatrix& stiffness, const fe::SparseMatrix& mass,
                                          const Eigen::MatrixXd& rigid, const std::vector<int>& free,
                                          const std::vector<int>& chosen) {
    Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(model.dof_count(), static_cast<Eigen::Index>(chosen.size()));
    for (std::size_t j = 0; j < chosen.size(); ++j) unit(chosen[j], static_cast<Eigen::Index>(j)) = 1.0;
    return compute_static_responses(stiffness, mass, rigid, free, reduce_loads(*constrained, unit),
                                    "attachment modes");
  };
  if (constrained) {
    if (auto failed = add_static(attachment, ModeKind::kAttachment, constrained_attachment,
                                 "attachment modes")) {
      return *failed;
    }
  } else if (auto failed = add_static(attachment, ModeKind::kAttachment, compute_attachment_modes,
                                      "attachment modes")) {
    return *failed;
  }

  // Orthonormalise the combined set [normal | constraint | attachment].
  Eigen::MatrixXd candidates(model.dof_count(), static_cast<Eigen::Index>(info.size()));
  Eigen::Index column = 0;
  for (const Eigen::MatrixXd& block : blocks) {
    candidates.middleCols(column, block.cols()) = block;
    column += block.cols();
  }
  OrthonormalisedModes combined =
      orthonormalise_modes(k, m, candidates, info, psi_free, request.dependency_tolerance);
  notices.insert(notices.end(), combined.notices.begin(), combined.notices.end());
  if (combined.mode_set.shapes.cols() == 0) {
    std::string why;
    for (const std::string& notice : notices) why += "; " + notice;
    return failure(ModalStatus::kNoModes, "mode set",
                   "every candidate was dependent or a rigid-body motion" + why, notices);
  }

  // Invariants of the final set.
  ModalResult result;
  result.notices = std::move(notices);
  result.mode_set = std::move(combined.mode_set);
  result.mode_set.rigid_modes = std::move(rigid_modes);
  // Full displacements u = T u_r; Phi^T M Phi over the full model equals Phi_r^T M_r Phi_r.
  if (constrained) result.mode_set.shapes = expand(*constrained, result.mode_set.shapes);
  result.mode_set.invariants =
      compute_modal_invariants(matrices.mass, psi_full, result.mode_set.shapes);
  return result;
}

}  // namespace limber::modal
