// Outcome of a modal computation (house style §11: numerical failure is a returned
// status, never an exception).
#pragma once

namespace limber::modal {

//  kOk            everything requested was computed;
//  kNotConverged  ARPACK stopped before all requested eigenpairs converged;
//  kSingular      a sparse Cholesky factorisation failed (matrix not positive definite,
//                 e.g. a mechanism left unrestrained or a shift above an eigenvalue);
//  kNoModes       no mode was left: every candidate was dependent or a rigid-body motion.
enum class ModalStatus { kOk, kNotConverged, kSingular, kNoModes };

const char* to_string(ModalStatus status);

}  // namespace limber::modal
