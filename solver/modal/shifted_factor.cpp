#include "modal/shifted_factor.h"

#include <algorithm>
#include <cstring>

#include <cholmod.h>

#include "core/error.h"

namespace limber::modal {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// Lower triangle of K(dofs, dofs) - sigma M(dofs, dofs) as a CHOLMOD matrix (stype -1):
// the two sorted columns are merged, entries outside `dofs` or above the diagonal skipped.
cholmod_sparse* shifted_lower(const SparseMatrix& k, const SparseMatrix& m,
                              const std::vector<int>& dofs, double sigma, cholmod_common* c) {
  const int n = static_cast<int>(k.rows());
  const int n_dofs = static_cast<int>(dofs.size());
  std::vector<int> position(static_cast<std::size_t>(n), -1);
  for (int j = 0; j < n_dofs; ++j) position[static_cast<std::size_t>(dofs[j])] = j;

  // Visits the merged entries (restricted row, value) of restricted column j, row >= j.
  const auto for_each_entry = [&](int j, auto&& visit) {
    const int g = dofs[static_cast<std::size_t>(j)];
    SparseMatrix::InnerIterator ik(k, g);
    SparseMatrix::InnerIterator im(m, g);
    while (ik || im) {
      const Eigen::Index row = !im ? ik.row() : !ik ? im.row() : std::min(ik.row(), im.row());
      double value = 0.0;
      if (ik && ik.row() == row) {
        value += ik.value();
        ++ik;
      }
      if (im && im.row() == row) {
        value -= sigma * im.value();
        ++im;
      }
      const int i = position[static_cast<std::size_t>(row)];
      if (i >= j) visit(i, value);
    }
  };

  std::size_t nonzeros = 0;
  for (int j = 0; j < n_dofs; ++j) for_each_entry(j, [&](int, double) { ++nonzeros; });
  cholmod_sparse* a = cholmod_allocate_sparse(static_cast<std::size_t>(n_dofs),
                                              static_cast<std::size_t>(n_dofs), nonzeros, 1, 1,
                                              -1, CHOLMOD_REAL, c);
  if (!a) return nullptr;
  int* column_start = static_cast<int*>(a->p);
  int* rows = static_cast<int*>(a->i);
  double* values = static_cast<double*>(a->x);
  int next = 0;
  for (int j = 0; j < n_dofs; ++j) {
    column_start[j] = next;
    for_each_entry(j, [&](int i, double value) {
      rows[next] = i;
      values[next] = value;
      ++next;
    });
  }
  column_start[n_dofs] = next;
  return a;
}

}  // namespace

struct ShiftedFactor::Cholmod {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;
  cholmod_dense* x = nullptr;  // solution, reused by cholmod_solve2
  cholmod_dense* y = nullptr;  // workspace of cholmod_solve2
  cholmod_dense* e = nullptr;  // workspace of cholmod_solve2
  std::vector<double> rhs;     // right-hand side, owned here
  bool ok = false;
};

ShiftedFactor::ShiftedFactor(const SparseMatrix& stiffness, const SparseMatrix& mass,
                             const std::vector<int>& dofs, double sigma)
    : cholmod_(std::make_unique<Cholmod>()) {
  LIMBER_DEMAND(stiffness.rows() == stiffness.cols() && mass.rows() == stiffness.rows() &&
                mass.cols() == stiffness.cols());
  LIMBER_DEMAND(std::is_sorted(dofs.begin(), dofs.end()) && !dofs.empty() && dofs.front() >= 0 &&
                dofs.back() < stiffness.rows());
  cholmod_common* c = &cholmod_->common;
  cholmod_start(c);
  // Supernodal LL^T with METIS ordering alone (the default would also try AMD and keep the
  // sparser factor, at the cost of a second ordering).
  c->supernodal = CHOLMOD_SUPERNODAL;
  c->nmethods = 1;
  c->method[0].ordering = CHOLMOD_METIS;
  c->postorder = 1;
  c->final_ll = 1;
  c->print = 0;

  cholmod_sparse* a = shifted_lower(stiffness, mass, dofs, sigma, c);
  if (!a) return;
  cholmod_->factor = cholmod_analyze(a, c);
  if (cholmod_->factor) cholmod_factorize(a, cholmod_->factor, c);
  cholmod_free_sparse(&a, c);
  cholmod_->ok = cholmod_->factor && c->status == CHOLMOD_OK &&
                 cholmod_->factor->minor == cholmod_->factor->n;
  cholmod_->rhs.resize(dofs.size());
}

ShiftedFactor::~ShiftedFactor() {
  cholmod_common* c = &cholmod_->common;
  cholmod_free_dense(&cholmod_->x, c);
  cholmod_free_dense(&cholmod_->y, c);
  cholmod_free_dense(&cholmod_->e, c);
  cholmod_free_factor(&cholmod_->factor, c);
  cholmod_finish(c);
}

bool ShiftedFactor::ok() const { return cholmod_->ok; }

void ShiftedFactor::solve(const double* x, double* y) { apply({CHOLMOD_A}, x, y); }

void ShiftedFactor::solve_transposed_factor(const double* x, double* y) {
  apply({CHOLMOD_Lt, CHOLMOD_Pt}, x, y);
}

void ShiftedFactor::solve_factor(const double* x, double* y) {
  apply({CHOLMOD_P, CHOLMOD_L}, x, y);
}

void ShiftedFactor::apply(std::initializer_list<int> systems, const double* x, double* y) {
  LIMBER_DEMAND(cholmod_->ok);
  const std::size_t n = cholmod_->rhs.size();
  // A dense header over our own right-hand side (copied: x may alias y).
  std::memcpy(cholmod_->rhs.data(), x, n * sizeof(double));
  cholmod_dense b{};
  b.nrow = n;
  b.ncol = 1;
  b.nzmax = n;
  b.d = n;
  b.x = cholmod_->rhs.data();
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  for (const int system : systems) {
    const int solved = cholmod_solve2(system, cholmod_->factor, &b, nullptr, &cholmod_->x,
                                      nullptr, &cholmod_->y, &cholmod_->e, &cholmod_->common);
    LIMBER_DEMAND(solved);
    // The result is the next system's right-hand side.
    std::memcpy(cholmod_->rhs.data(), cholmod_->x->x, n * sizeof(double));
  }
  std::memcpy(y, cholmod_->rhs.data(), n * sizeof(double));
}

}  // namespace limber::modal
