#include "fe/multipoint_constraints.h"

#include <algorithm>
#include <map>

#include "core/error.h"

namespace limber::fe {

namespace {

// Constraint index of every dependent DOF (-1: independent).
std::vector<int> dependent_owner(const FeModel& model) {
  std::vector<int> owner(static_cast<std::size_t>(model.dof_count()), -1);
  for (std::size_t c = 0; c < model.multipoint_constraints.size(); ++c) {
    const int dof = model.multipoint_constraints[c].dependent;
    LIMBER_DEMAND(dof >= 0 && dof < model.dof_count());
    LIMBER_DEMAND(owner[static_cast<std::size_t>(dof)] == -1);
    owner[static_cast<std::size_t>(dof)] = static_cast<int>(c);
  }
  return owner;
}

}  // namespace

std::optional<std::vector<int>> constraint_cycle(const FeModel& model) {
  const std::vector<int> owner = dependent_owner(model);
  const auto& constraints = model.multipoint_constraints;
  // Depth-first search over "constraint c uses a DOF that constraint d makes dependent".
  enum State { kNew, kOpen, kDone };
  std::vector<State> state(constraints.size(), kNew);
  std::vector<int> path;
  std::optional<std::vector<int>> cycle;
  const auto visit = [&](auto&& self, int c) -> void {
    state[static_cast<std::size_t>(c)] = kOpen;
    path.push_back(c);
    for (int dof : constraints[static_cast<std::size_t>(c)].independent) {
      LIMBER_DEMAND(dof >= 0 && dof < model.dof_count());
      const int d = owner[static_cast<std::size_t>(dof)];
      if (d < 0 || cycle) continue;
      if (state[static_cast<std::size_t>(d)] == kOpen) {
        // The cycle is the path from d on.
        const auto start = std::find(path.begin(), path.end(), d);
        cycle = std::vector<int>(start, path.end());
        return;
      }
      if (state[static_cast<std::size_t>(d)] == kNew) self(self, d);
    }
    path.pop_back();
    state[static_cast<std::size_t>(c)] = kDone;
  };
  for (std::size_t c = 0; c < constraints.size() && !cycle; ++c) {
    if (state[c] == kNew) visit(visit, static_cast<int>(c));
  }
  return cycle;
}

ConstraintTransformation constraint_transformation(const FeModel& model) {
  const int n = model.dof_count();
  const std::vector<int> owner = dependent_owner(model);
  ConstraintTransformation out;
  std::vector<int> column(static_cast<std::size_t>(n), -1);
  for (int dof = 0; dof < n; ++dof) {
    if (owner[static_cast<std::size_t>(dof)] >= 0) {
      out.dependent_dofs.push_back(dof);
    } else {
      column[static_cast<std::size_t>(dof)] = static_cast<int>(out.independent_dofs.size());
      out.independent_dofs.push_back(dof);
    }
  }

  // Each dependent DOF as a combination of independent DOFs, chains substituted (memoised).
  std::vector<std::map<int, double>> resolved(model.multipoint_constraints.size());
  std::vector<bool> done(model.multipoint_constraints.size(), false);
  const auto resolve = [&](auto&& self, int c) -> const std::map<int, double>& {
    if (done[static_cast<std::size_t>(c)]) return resolved[static_cast<std::size_t>(c)];
    const MultipointConstraint& constraint = model.multipoint_constraints[static_cast<std::size_t>(c)];
    std::map<int, double> terms;
    for (std::size_t k = 0; k < constraint.independent.size(); ++k) {
      const int dof = constraint.independent[k];
      const double coefficient = constraint.coefficients[k];
      const int d = owner[static_cast<std::size_t>(dof)];
      if (d < 0) {
        terms[dof] += coefficient;
        continue;
      }
      for (const auto& [independent, value] : self(self, d)) terms[independent] += coefficient * value;
    }
    resolved[static_cast<std::size_t>(c)] = std::move(terms);
    done[static_cast<std::size_t>(c)] = true;
    return resolved[static_cast<std::size_t>(c)];
  };

  // T: unit rows for independent DOFs, resolved rows for dependent ones.
  std::vector<Eigen::Triplet<double>> entries;
  for (int dof : out.independent_dofs) entries.emplace_back(dof, column[static_cast<std::size_t>(dof)], 1.0);
  for (int dof : out.dependent_dofs) {
    for (const auto& [independent, value] : resolve(resolve, owner[static_cast<std::size_t>(dof)])) {
      entries.emplace_back(dof, column[static_cast<std::size_t>(independent)], value);
    }
  }
  out.transformation.resize(n, static_cast<Eigen::Index>(out.independent_dofs.size()));
  out.transformation.setFromTriplets(entries.begin(), entries.end());
  return out;
}

Eigen::SparseMatrix<double> embed(const Eigen::SparseMatrix<double>& reduced,
                                  const std::vector<int>& independent_dofs, int n) {
  LIMBER_DEMAND(reduced.rows() == static_cast<Eigen::Index>(independent_dofs.size()));
  LIMBER_DEMAND(reduced.cols() == reduced.rows());
  // E (n x n_r) with E(independent_dofs[i], i) = 1; E A_r E^T.
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(reduced.nonZeros()));
  for (Eigen::Index j = 0; j < reduced.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(reduced, j); it; ++it) {
      entries.emplace_back(independent_dofs[static_cast<std::size_t>(it.row())],
                           independent_dofs[static_cast<std::size_t>(j)], it.value());
    }
  }
  Eigen::SparseMatrix<double> out(n, n);
  out.setFromTriplets(entries.begin(), entries.end());
  return out;
}

}  // namespace limber::fe
