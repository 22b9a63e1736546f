#include "run/redundant_row_watch.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace limber::run {

RedundantRowWatch::RedundantRowWatch(const multibody::Model& model,
                                     const multibody::ConstraintPartition& partition,
                                     std::vector<DeformationRedundancy> known)
    : model_(model), partition_(partition), known_(std::move(known)) {}

integrate::Status RedundantRowWatch::check(double t, const Eigen::VectorXd& g, double size) const {
  if (partition_.redundant.empty()) return integrate::Status::success(t);
  double held = 0.0;
  for (int row : partition_.independent) held = std::max(held, std::abs(g(row)));
  for (const multibody::RedundantEquation& r : partition_.redundant) {
    const double residual = std::abs(g(r.row));
    const bool length = model_.equations[static_cast<std::size_t>(r.row)].kind == multibody::EquationKind::kDot2;
    const double limit = std::max(kLooseRedundantRow * (length ? size : 1.0), kLooseOverHeld * held);
    if (residual > limit) {
      return {integrate::StatusCode::kRedundantViolated, t, message(r.row, residual, held, t)};
    }
  }
  return integrate::Status::success(t);
}

std::string RedundantRowWatch::message(int row, double residual, double held, double t) const {
  const multibody::ConstraintEquation& eq = model_.equations[static_cast<std::size_t>(row)];
  const char* unit = eq.kind == multibody::EquationKind::kDot2 ? "m" : "rad";
  std::string text = fmt::format(
      "at t = {:.6g} s: the redundant equation {}, which the run does not hold, is off by {:.3g} {} "
      "(the held ones by {:.2g}): the mechanism has a freedom there that the model does not",
      t, eq.name, residual, unit, held);
  // The start's diagnosis of its dependency (a reselection may have dropped another row of it).
  const auto known = std::find_if(known_.begin(), known_.end(), [&](const DeformationRedundancy& d) {
    return std::find(d.group.begin(), d.group.end(), row) != d.group.end();
  });
  if (known != known_.end()) {
    const std::string instead =
        known->row == row ? "" : fmt::format(" (dropped in place of {}, its dependency at the start)",
                                             model_.equations[static_cast<std::size_t>(known->row)].name);
    return text + fmt::format("{}; {}. Remedy: {}", instead, known->description(model_), known->remedy(model_));
  }
  return text + "; it depends on the held equations only in the configurations the run started "
                "from: start the mechanism away from such a position, or free the motion the "
                "equation holds in its joint";
}

}  // namespace limber::run
