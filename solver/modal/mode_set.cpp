#include "modal/mode_set.h"

#include "modal/modal_status.h"

namespace limber::modal {

const char* to_string(ModeKind kind) {
  switch (kind) {
    case ModeKind::kRigid: return "rigid";
    case ModeKind::kNormal: return "normal";
    case ModeKind::kConstraint: return "constraint";
    case ModeKind::kAttachment: return "attachment";
  }
  return "unknown";
}

const char* to_string(ModalStatus status) {
  switch (status) {
    case ModalStatus::kOk: return "ok";
    case ModalStatus::kNotConverged: return "not converged";
    case ModalStatus::kSingular: return "singular factorisation";
    case ModalStatus::kNoModes: return "no mode left";
  }
  return "unknown";
}

}  // namespace limber::modal
