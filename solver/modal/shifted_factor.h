// Cholesky factor of the shifted stiffness restricted to a DOF subset,
//   A = K(dofs, dofs) - sigma M(dofs, dofs) = L L^T,
// for the shift-invert Lanczos operator (K - sigma M)^-1 M (sparse_eigensolver.h).
// A's lower triangle is built directly from the full K and M (no copy of K_ff or M_ff,
// neither of the upper triangle) and freed once factorised. Factorisation: CHOLMOD's
// supernodal Cholesky (Chen, Davis, Hager & Rajamanickam, "Algorithm 887: CHOLMOD",
// ACM TOMS 35(3), 2008) with METIS nested-dissection ordering, the best known ordering for
// 2-D and shell meshes (George, "Nested dissection of a regular finite element mesh",
// SIAM J. Numer. Anal. 10, 1973), with fill-reducing permutation P: P A P^T = L L^T.
// Solves reuse CHOLMOD's workspace (cholmod_solve2), so the Lanczos loop allocates nothing.
#pragma once

#include <initializer_list>
#include <memory>
#include <vector>

#include <Eigen/SparseCore>

namespace limber::modal {

class ShiftedFactor {
 public:
  // Factorises A. K and M: n x n, both triangles stored, column-major with sorted row
  // indices. dofs: ascending, distinct, in [0, n). ok() is false when A is not positive
  // definite (e.g. sigma above the lowest eigenvalue, or a free body with sigma = 0).
  ShiftedFactor(const Eigen::SparseMatrix<double>& stiffness,
                const Eigen::SparseMatrix<double>& mass, const std::vector<int>& dofs,
                double sigma);
  ~ShiftedFactor();
  ShiftedFactor(const ShiftedFactor&) = delete;
  ShiftedFactor& operator=(const ShiftedFactor&) = delete;

  bool ok() const;
  // y = A^-1 x, both of size dofs.size(); x and y may alias. Precondition: ok().
  void solve(const double* x, double* y);
  // y = P^T L^-T x and y = L^-1 P x, the two halves of A^-1 = (P^T L^-T)(L^-1 P); same
  // sizes and precondition.
  void solve_transposed_factor(const double* x, double* y);
  void solve_factor(const double* x, double* y);

 private:
  struct Cholmod;
  // y = op(x) for the CHOLMOD systems `systems` applied in turn (CHOLMOD_A, _L, _P, ...).
  void apply(std::initializer_list<int> systems, const double* x, double* y);
  std::unique_ptr<Cholmod> cholmod_;
};

}  // namespace limber::modal
