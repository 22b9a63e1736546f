#include "curve_styles.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace limber::report {
namespace {

// Largest minus smallest finite y over every curve (the largest |y| when that is 0).
double plot_range(const PlotSpec& plot) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, largest = 0.0;
  for (const Curve& curve : plot.curves) {
    for (Eigen::Index k = 0; k < curve.y.size(); ++k) {
      const double y = curve.y(k);
      if (!std::isfinite(y)) continue;
      lo = std::min(lo, y);
      hi = std::max(hi, y);
      largest = std::max(largest, std::abs(y));
    }
  }
  if (!(hi >= lo)) return 0.0;
  return hi > lo ? hi - lo : largest;
}

// max |a − b| over the samples when a and b share their abscissae and non-finite places,
// else infinity.
double curve_distance(const Curve& a, const Curve& b) {
  const double apart = std::numeric_limits<double>::infinity();
  if (a.x.size() != b.x.size() || a.y.size() != b.y.size() || a.x.size() != a.y.size()) return apart;
  if (a.y.size() == 0) return apart;
  double worst = 0.0;
  for (Eigen::Index k = 0; k < a.y.size(); ++k) {
    if (a.x(k) != b.x(k)) return apart;
    const bool fa = std::isfinite(a.y(k)), fb = std::isfinite(b.y(k));
    if (fa != fb) return apart;
    if (fa) worst = std::max(worst, std::abs(a.y(k) - b.y(k)));
  }
  return worst;
}

// "1e-9" (not printf's "1e-09").
std::string tolerance_text(double tolerance) {
  std::string text = fmt::format("{:g}", tolerance);
  for (const char* padded : {"e-0", "e+0"}) {
    const std::size_t at = text.find(padded);
    if (at != std::string::npos) text.erase(at + 2, 1);
  }
  return text;
}

}  // namespace

std::vector<Coincidence> coinciding_curves(const PlotSpec& plot, double tolerance) {
  std::vector<Coincidence> pairs;
  const double limit = tolerance * plot_range(plot);
  for (std::size_t i = 0; i < plot.curves.size(); ++i) {
    for (std::size_t j = i + 1; j < plot.curves.size(); ++j) {
      const double d = curve_distance(plot.curves[i], plot.curves[j]);
      if (d <= limit) pairs.push_back({i, j, d});
    }
  }
  return pairs;
}

std::string distinguish_coinciding_curves(PlotSpec& plot, double tolerance, double visual) {
  const std::vector<Coincidence> pairs = coinciding_curves(plot, std::max(tolerance, visual));
  if (pairs.empty()) return "";
  const double range = plot_range(plot);
  // Groups of curves on one another: each curve joins the group of the first curve it lies on.
  const std::size_t n = plot.curves.size();
  std::vector<std::size_t> group(n);
  std::vector<double> distance(n, 0.0);  // to the group's first curve
  for (std::size_t i = 0; i < n; ++i) group[i] = i;
  for (const Coincidence& c : pairs) {
    if (group[c.later] != c.later || group[c.first] != c.first) continue;
    group[c.later] = c.first;
    distance[c.later] = c.max_difference;
  }
  // Styles in each group's order, the first curve solid; the note lists each group, the curves
  // within `tolerance` of the first after "≡", those only within `visual` after "≈".
  constexpr LineStyle kStyles[] = {LineStyle::kDashed, LineStyle::kDotted, LineStyle::kDashDot};
  std::string note;
  bool near_only = false;  // some curve only within `visual`
  for (std::size_t head = 0; head < n; ++head) {
    if (group[head] != head) continue;
    std::string same, near;
    std::size_t members = 0;
    for (std::size_t k = head + 1; k < n; ++k) {
      if (group[k] != head) continue;
      Curve& curve = plot.curves[k];
      if (curve.style == LineStyle::kSolid) curve.style = kStyles[members % std::size(kStyles)];
      (distance[k] <= tolerance * range ? same : near) += (distance[k] <= tolerance * range ? " ≡ " : " ≈ ") + curve.label;
      ++members;
    }
    if (members == 0) continue;
    near_only = near_only || !near.empty();
    // Curves at 0 throughout (modes the motion does not excite) say so.
    const Eigen::ArrayXd y = plot.curves[head].y.array().abs();
    const std::string zero = y.size() == 0                          ? ""
                             : near.empty() && (y <= tolerance * range).all() ? " ≡ 0"
                             : (y <= visual * range).all()                    ? " ≈ 0"
                                                                              : "";
    note += (note.empty() ? "" : "; ") + plot.curves[head].label + same + near + zero;
  }
  note += near_only ? fmt::format(" (≡ to {}, ≈ to {} of the plot's range: under a pixel)",
                                  tolerance_text(tolerance), tolerance_text(visual))
                    : fmt::format(" (to {})", tolerance_text(tolerance));
  return note;
}

}  // namespace limber::report
