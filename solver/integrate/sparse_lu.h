// Sparse LU of a square unsymmetric matrix by KLU (SuiteSparse; Davis & Palamadai Natarajan,
// ACM TOMS 37(3), 2010): block triangular form, AMD ordering, left-looking LU with partial
// pivoting. Made for generalized-α's iteration matrix of a system with hundreds of small coupled
// bodies (a nonlinear body's node bodies: 6 x 6 element blocks, block-diagonal mass, a few
// constraint rows), a saddle-point matrix whose zero block needs pivoting across rows, which a
// Cholesky or an LDLᵀ without pivoting cannot factorise.
// The ordering is analysed once per sparsity pattern and reused while the pattern stays the
// same (the entries change every factorisation, the pattern rarely); on the same pattern the
// factors are first recomputed with the last pivot order (klu_refactor), and pivoted afresh
// when that order's condition estimate falls below a tenth of the last pivoted one's.
#pragma once

#include <memory>

#include <Eigen/SparseCore>

namespace limber::integrate {

class SparseLu {
 public:
  SparseLu();
  ~SparseLu();
  SparseLu(const SparseLu&) = delete;
  SparseLu& operator=(const SparseLu&) = delete;

  // Factorises A (square, compressed). Returns false when KLU meets a zero pivot (A is
  // structurally or numerically singular); then solve must not be called.
  bool factorize(const Eigen::SparseMatrix<double>& A);
  // KLU's crude reciprocal condition estimate of the last factorisation: min |u_ii| / max |u_ii|
  // of the row-scaled matrix's U (0 before one succeeded).
  double rcond() const;
  // x = A⁻¹ b with the last successful factorisation.
  Eigen::VectorXd solve(const Eigen::VectorXd& b);

 private:
  struct Factors;  // KLU's symbolic and numeric objects, its settings and the analysed pattern
  std::unique_ptr<Factors> factors_;
};

}  // namespace limber::integrate
