#include "decimate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace limber::report {
namespace {

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

bool same_abscissa(const std::vector<Curve>& curves) {
  for (const Curve& c : curves) {
    if (c.x.size() != curves.front().x.size() || c.x != curves.front().x) return false;
  }
  return true;
}

// The samples a curve contributes: all, or its M4 selection.
std::vector<Eigen::Index> kept(const Curve& c, int buckets) {
  const Eigen::Index n = std::min(c.x.size(), c.y.size());
  if (buckets <= 0) {
    std::vector<Eigen::Index> all(static_cast<std::size_t>(n));
    for (Eigen::Index k = 0; k < n; ++k) all[static_cast<std::size_t>(k)] = k;
    return all;
  }
  return m4_indices(c.x.head(n), c.y.head(n), buckets);
}

}  // namespace

std::vector<Eigen::Index> m4_indices(const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                                     int buckets) {
  const Eigen::Index n = x.size();
  std::vector<Eigen::Index> out;
  if (n <= 4 * static_cast<Eigen::Index>(buckets) || n < 2) {
    for (Eigen::Index k = 0; k < n; ++k) out.push_back(k);
    return out;
  }
  const double x0 = x(0), span = x(n - 1) - x(0);
  // Column of each sample; a zero span puts everything in one column.
  auto column = [&](Eigen::Index k) {
    if (!(span > 0.0)) return 0;
    const int b = static_cast<int>(std::floor((x(k) - x0) / span * buckets));
    return std::clamp(b, 0, buckets - 1);
  };
  Eigen::Index first = 0;
  while (first < n) {
    // One column: [first, last].
    const int b = column(first);
    Eigen::Index last = first;
    while (last + 1 < n && column(last + 1) == b) ++last;
    Eigen::Index lo = -1, hi = -1;
    for (Eigen::Index k = first; k <= last; ++k) {
      if (!std::isfinite(y(k))) {
        out.push_back(k);  // a gap or a blow-up stays visible
        continue;
      }
      if (lo < 0 || y(k) < y(lo)) lo = k;
      if (hi < 0 || y(k) > y(hi)) hi = k;
    }
    out.push_back(first);
    out.push_back(last);
    if (lo >= 0) out.push_back(lo);
    if (hi >= 0) out.push_back(hi);
    first = last + 1;
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

CurveTable curve_table(const std::vector<Curve>& curves, int buckets) {
  CurveTable table;
  for (const Curve& c : curves) {
    table.labels.push_back(c.label);
    table.samples = std::max(table.samples, std::min(c.x.size(), c.y.size()));
  }
  if (curves.empty()) return table;

  if (same_abscissa(curves)) {
    // One abscissa: the union of every curve's kept rows.
    std::vector<Eigen::Index> rows;
    for (const Curve& c : curves) {
      const std::vector<Eigen::Index> k = kept(c, buckets);
      rows.insert(rows.end(), k.begin(), k.end());
    }
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    for (Eigen::Index r : rows) table.x.push_back(curves.front().x(r));
    for (const Curve& c : curves) {
      std::vector<double>& column = table.columns.emplace_back();
      for (Eigen::Index r : rows) column.push_back(r < c.y.size() ? c.y(r) : kMissing);
    }
    return table;
  }

  // Different abscissae (several runs): merge on equal values, gaps where a curve lacks one.
  std::map<double, std::vector<double>> merged;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    for (Eigen::Index k : kept(curves[i], buckets)) {
      merged.try_emplace(curves[i].x(k), curves.size(), kMissing).first->second[i] = curves[i].y(k);
    }
  }
  table.columns.assign(curves.size(), {});
  for (const auto& [x, values] : merged) {
    table.x.push_back(x);
    for (std::size_t i = 0; i < curves.size(); ++i) table.columns[i].push_back(values[i]);
  }
  return table;
}

}  // namespace limber::report
