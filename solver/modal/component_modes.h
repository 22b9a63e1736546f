// Component mode synthesis for one flexible component (seed paper eq. 4-11):
// normal modes + constraint modes + attachment modes -> one M-orthonormal,
// K-diagonal mode set with labels, plus the floating-frame modal invariants.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fe/fe_model.h"
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
  // Vectors whose M-norm falls below this fraction of the largest after projection on
  // the others are dropped as dependent (see orthonormalise_modes).
  double dependency_tolerance = 1e-8;
};

// Outcome of a modal computation. `status` is not kOk when the eigen-solver did not
// converge; `message` then says what and where, and `mode_set` holds nothing.
enum class ModalStatus { kOk, kNotConverged, kSingular };

struct ModalResult {
  ModalStatus status = ModalStatus::kOk;
  std::string message;               // failure explanation, or empty
  std::vector<std::string> notices;  // e.g. "dropped constraint rz at node 101: dependent"
  ModeSet mode_set;
};

// Runs the whole reduction. Throws InputError for impossible requests (more modes than
// DOFs, static-mode sites on fixed DOFs, no modes requested).
ModalResult compute_component_modes(const fe::FeModel& model, const ModeRequest& request);

}  // namespace limber::modal
