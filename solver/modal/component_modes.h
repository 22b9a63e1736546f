// Component mode synthesis for one flexible component (seed paper eq. 4-11):
// normal modes + constraint modes + attachment modes -> one M-orthonormal,
// K-diagonal mode set with labels, plus the floating-frame modal invariants.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fe/assembly.h"
#include "fe/fe_model.h"
#include "modal/modal_status.h"
#include "modal/mode_set.h"

namespace limber::modal {

// DOFs of one node at which static modes are requested.
struct StaticModeSite {
  int node = 0;                 // node index
  std::vector<fe::Dof> dofs;    // e.g. {kUx, kUz}
};

struct ModeRequest {
  // Normal modes: the lowest `normal_count` elastic modes, or all elastic modes up to
  // `max_frequency_hz` when set (then normal_count is an upper bound, 0 = no bound).
  int normal_count = 0;
  std::optional<double> max_frequency_hz;
  std::vector<StaticModeSite> constraint_sites;  // eq. 7-9: unit displacement, others held
  std::vector<StaticModeSite> attachment_sites;  // eq. 10-11: unit force
  // A candidate vector whose M-norm, after projection on the vectors before it, falls
  // below this fraction of its own M-norm is dropped as dependent (orthonormalise_modes.h).
  double dependency_tolerance = 1e-8;
};

// Outcome of a modal computation. `status` is not kOk when the eigen-solver did not
// converge or a factorisation failed (modal_status.h); `message` then says what and
// where, and `mode_set` holds nothing.
struct ModalResult {
  ModalStatus status = ModalStatus::kOk;
  std::string message;               // failure explanation, or empty
  std::vector<std::string> notices;  // e.g. "dropped constraint rz at node 101: dependent"
  ModeSet mode_set;
};

// Runs the whole reduction: assemble K, M (fe::assemble); multipoint constraints (RBE2,
// RBE3) eliminated by u = T u_r (constrained_matrices.h), the shapes returned as full
// displacements T u_r; normal modes on the free DOFs
// (normal_modes.h, rigid modes set aside for free components); constraint and attachment
// modes (static_modes.h); orthonormalisation of [normal | constraint | attachment]
// (orthonormalise_modes.h); invariants (modal_invariants.h).
// Throws InputError (expected/got) for impossible requests: no modes requested, more
// normal modes than free DOFs (after the rigid ones), a site on an unknown node, with no
// DOFs, naming a DOF twice or on a fixed DOF, a constraint mode on a DOF a rigid element makes
// dependent, constraints that a rigid motion violates, a dependency tolerance outside (0, 1),
// a non-positive cut-off frequency.
ModalResult compute_component_modes(const fe::FeModel& model, const ModeRequest& request);

// The same with K and M already assembled for `model` (fixed DOFs not removed).
ModalResult compute_component_modes(const fe::FeModel& model,
                                    const fe::StructuralMatrices& matrices,
                                    const ModeRequest& request);

}  // namespace limber::modal
