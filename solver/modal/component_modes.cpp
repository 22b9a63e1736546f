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

// The eigenproblem the modes are computed on: with multipoint constraints, the embedded
// T^T K T, T^T M T and Psi with the dependent DOFs out of the free set (constrained_matrices.h);
// without, the model's own matrices.
struct ReductionSpace {
  const fe::StructuralMatrices& matrices;
  Eigen::MatrixXd psi_full;                        // rigid-body modes of the whole model
  std::optional<ConstrainedMatrices> constrained;  // set when the model has MPCs
  std::vector<int> unheld_dofs;                    // not fixed (fe::free_dofs)

  const fe::SparseMatrix& k() const {
    return constrained ? constrained->stiffness : matrices.stiffness;
  }
  const fe::SparseMatrix& m() const { return constrained ? constrained->mass : matrices.mass; }
  const Eigen::MatrixXd& psi() const { return constrained ? constrained->psi : psi_full; }
  const std::vector<int>& free_dofs() const {
    return constrained ? constrained->free_dofs : unheld_dofs;
  }
  const std::vector<int>& dependent_dofs() const {
    static const std::vector<int> kNone;
    return constrained ? constrained->transformation.dependent_dofs : kNone;
  }
};

ReductionSpace reduction_space(const fe::FeModel& model, const fe::StructuralMatrices& matrices) {
  ReductionSpace space{matrices, rigid_body_modes(model), std::nullopt, fe::free_dofs(model)};
  if (!model.multipoint_constraints.empty()) {
    space.constrained = constrain(model, matrices, space.psi_full);
  }
  return space;
}

// The request's own numbers, before any site is looked at (InputError on bad input).
void check_request_values(const ModeRequest& request) {
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
}

// The rigid motion (columns of Psi combined) that neither the fixed DOFs nor grounded springs
// resist. Static modes take the free rigid motion from the held DOFs alone (static_modes.h),
// so springs that restrain rigid motion refuse static-mode sites (InputError).
Eigen::MatrixXd free_rigid_motion(const fe::FeModel& model, const ReductionSpace& space,
                                  bool has_static_sites) {
  std::vector<int> all(static_cast<std::size_t>(model.dof_count()));
  for (int i = 0; i < model.dof_count(); ++i) all[static_cast<std::size_t>(i)] = i;
  const std::vector<int> fixed = set_difference(all, space.unheld_dofs);
  Eigen::MatrixXd psi_free = unrestrained_rigid_motion(space.psi(), fixed);
  if (model.dof_stiffnesses.empty() || psi_free.cols() == 0) return psi_free;
  const Eigen::MatrixXd full = space.constrained ? expand(*space.constrained, psi_free) : psi_free;
  const Eigen::MatrixXd unresisted = unresisted_rigid_motion(model, space.matrices.stiffness, full);
  if (unresisted.cols() < psi_free.cols() && has_static_sites) {
    throw InputError(fmt::format(
        "mode request: expected no constraint or attachment modes on a body whose grounded "
        "springs restrain rigid motion ({} of {} rigid motions), got static-mode sites (not "
        "supported: hold the DOFs with fixed DOFs instead)",
        psi_free.cols() - unresisted.cols(), psi_free.cols()));
  }
  return psi_free * unresisted;
}

// The counts the free DOFs can hold (InputError when the request asks for more).
void check_mode_counts(const ModeRequest& request, int rigid_count, int n_free,
                       std::size_t static_count) {
  if (request.normal_count + rigid_count > n_free) {
    throw InputError(fmt::format(
        "mode request: expected at most {} normal modes ({} free DOFs, {} rigid-body modes), "
        "got {}",
        n_free - rigid_count, n_free, rigid_count, request.normal_count));
  }
  if (static_cast<int>(static_count) > n_free) {
    throw InputError(fmt::format("mode request: expected at most {} static modes, got {}", n_free,
                                 static_count));
  }
}

// The candidate vectors gathered before orthonormalisation, block by block.
struct Candidates {
  std::vector<std::string> notices;
  std::vector<Eigen::MatrixXd> blocks;  // [normal | constraint | attachment]
  std::vector<ModeInfo> info;           // one per column of the blocks
  std::vector<ModeInfo> rigid_modes;    // the rigid eigenpairs set aside
};

// Normal modes (seed paper eq. 4-6); a failure result when the eigensolver fails.
std::optional<ModalResult> add_normal_modes(const ReductionSpace& space, const ModeRequest& request,
                                            int rigid_count, Candidates& candidates) {
  NormalModeRequest normal_request;
  normal_request.count = request.normal_count;
  normal_request.max_frequency_hz = request.max_frequency_hz;
  normal_request.rigid_count = rigid_count;
  NormalModes normal =
      compute_normal_modes(space.k(), space.m(), space.free_dofs(), normal_request);
  candidates.notices.insert(candidates.notices.end(), normal.notices.begin(), normal.notices.end());
  if (normal.status != ModalStatus::kOk) {
    return failure(normal.status, "normal modes", normal.message, candidates.notices);
  }
  for (Eigen::Index i = 0; i < normal.rigid_eigenvalues.size(); ++i) {
    candidates.rigid_modes.push_back({ModeKind::kRigid, frequency_hz(normal.rigid_eigenvalues[i]),
                                      fmt::format("rigid {}", i + 1)});
  }
  for (Eigen::Index i = 0; i < normal.eigenvalues.size(); ++i) {
    candidates.info.push_back({ModeKind::kNormal, frequency_hz(normal.eigenvalues[i]),
                               fmt::format("normal {}", i + 1)});
  }
  candidates.blocks.push_back(std::move(normal.shapes));
  return std::nullopt;
}

// One block of static modes from `modes` labelled by its sites; a failure result when the
// factorisation failed.
std::optional<ModalResult> add_static_block(StaticModes modes, const SiteDofs& sites,
                                             ModeKind kind, const char* what,
                                             Candidates& candidates) {
  if (modes.status != ModalStatus::kOk) {
    return failure(modes.status, what, modes.message, candidates.notices);
  }
  for (const std::string& label : sites.labels) candidates.info.push_back({kind, 0.0, label});
  candidates.blocks.push_back(std::move(modes.shapes));
  return std::nullopt;
}

// Constraint modes (eq. 7-9) and attachment modes (eq. 10-11). With multipoint constraints a
// unit force at a DOF loads the independent DOFs with T^T e.
std::optional<ModalResult> add_static_modes(const fe::FeModel& model, const ReductionSpace& space,
                                            const SiteDofs& constraint, const SiteDofs& attachment,
                                            Candidates& candidates) {
  const fe::SparseMatrix& k = space.k();
  const fe::SparseMatrix& m = space.m();
  if (!constraint.dofs.empty()) {
    StaticModes modes =
        compute_constraint_modes(k, m, space.psi(), space.free_dofs(), constraint.dofs);
    if (auto failed = add_static_block(std::move(modes), constraint, ModeKind::kConstraint,
                                       "constraint modes", candidates)) {
      return failed;
    }
  }
  if (attachment.dofs.empty()) return std::nullopt;
  StaticModes modes;
  if (space.constrained) {
    const std::vector<int>& chosen = attachment.dofs;
    Eigen::MatrixXd unit =
        Eigen::MatrixXd::Zero(model.dof_count(), static_cast<Eigen::Index>(chosen.size()));
    for (std::size_t j = 0; j < chosen.size(); ++j) {
      unit(chosen[j], static_cast<Eigen::Index>(j)) = 1.0;
    }
    modes = compute_static_responses(k, m, space.psi(), space.free_dofs(),
                                     reduce_loads(*space.constrained, unit), "attachment modes");
  } else {
    modes = compute_attachment_modes(k, m, space.psi(), space.free_dofs(), attachment.dofs);
  }
  return add_static_block(std::move(modes), attachment, ModeKind::kAttachment, "attachment modes",
                          candidates);
}

// Orthonormalises the combined set [normal | constraint | attachment] against the free rigid
// motion and takes the invariants of the final set over the full model.
ModalResult orthonormalised_result(const fe::FeModel& model, const ReductionSpace& space,
                                   const ModeRequest& request, const Eigen::MatrixXd& psi_free,
                                   Candidates candidates) {
  Eigen::MatrixXd shapes(model.dof_count(), static_cast<Eigen::Index>(candidates.info.size()));
  Eigen::Index column = 0;
  for (const Eigen::MatrixXd& block : candidates.blocks) {
    shapes.middleCols(column, block.cols()) = block;
    column += block.cols();
  }
  std::vector<std::string>& notices = candidates.notices;
  OrthonormalisedModes combined = orthonormalise_modes(
      space.k(), space.m(), shapes, candidates.info, psi_free, request.dependency_tolerance);
  notices.insert(notices.end(), combined.notices.begin(), combined.notices.end());
  if (combined.mode_set.shapes.cols() == 0) {
    std::string why;
    for (const std::string& notice : notices) why += "; " + notice;
    return failure(ModalStatus::kNoModes, "mode set",
                   "every candidate was dependent or a rigid-body motion" + why, notices);
  }
  ModalResult result;
  result.notices = std::move(notices);
  result.mode_set = std::move(combined.mode_set);
  result.mode_set.rigid_modes = std::move(candidates.rigid_modes);
  // Full displacements u = T u_r; Phi^T M Phi over the full model equals Phi_r^T M_r Phi_r.
  if (space.constrained) {
    result.mode_set.shapes = expand(*space.constrained, result.mode_set.shapes);
  }
  result.mode_set.invariants =
      compute_modal_invariants(space.matrices.mass, space.psi_full, result.mode_set.shapes);
  return result;
}

}  // namespace

ModalResult compute_component_modes(const fe::FeModel& model, const ModeRequest& request) {
  return compute_component_modes(model, fe::assemble(model), request);
}

ModalResult compute_component_modes(const fe::FeModel& model,
                                    const fe::StructuralMatrices& matrices,
                                    const ModeRequest& request) {
  // Multipoint constraints eliminated; shapes are expanded by T at the end.
  const ReductionSpace space = reduction_space(model, matrices);

  // Validate the request, then the sites, then the counts the free DOFs can hold.
  check_request_values(request);
  const SiteDofs constraint = site_dofs(model, request.constraint_sites, space.unheld_dofs,
                                        space.dependent_dofs(), true, "constraint");
  const SiteDofs attachment = site_dofs(model, request.attachment_sites, space.unheld_dofs,
                                        space.dependent_dofs(), false, "attachment");
  const std::size_t static_count = constraint.dofs.size() + attachment.dofs.size();
  const Eigen::MatrixXd psi_free = free_rigid_motion(model, space, static_count > 0);
  const int rigid_count = static_cast<int>(psi_free.cols());
  check_mode_counts(request, rigid_count, static_cast<int>(space.free_dofs().size()), static_count);

  // The candidates: normal, constraint and attachment modes.
  Candidates candidates;
  if (request.normal_count > 0 || request.max_frequency_hz.has_value()) {
    if (auto failed = add_normal_modes(space, request, rigid_count, candidates)) return *failed;
  }
  if (auto failed = add_static_modes(model, space, constraint, attachment, candidates)) {
    return *failed;
  }
  return orthonormalised_result(model, space, request, psi_free, std::move(candidates));
}

}  // namespace limber::modal
