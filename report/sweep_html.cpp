#include "sweep_html.h"

#include "html.h"

#include <fmt/format.h>

namespace limber::report {
namespace {

std::string percent(const std::optional<double>& fraction) {
  return fraction ? fmt::format("{:.3g}", 100.0 * *fraction) : "";
}

std::string value(const std::optional<double>& v, const char* format) {
  return v ? fmt::format(fmt::runtime(format), *v) : "";
}

}  // namespace

std::string sweep_table(const SweepData& sweep) {
  if (sweep.points.empty()) return "";
  std::string out =
      "<p>Each grid point of <code>limber sweep</code>: what its run cost and its errors against the "
      "reference (the largest over the compared quantities of the peak and of the rms difference, "
      "relative; docs/sweep.md). <span class=\"chosen-key\">The cheapest point meeting the target</span> "
      "is marked; a point whose own accuracy check failed (<em>ok_inaccurate</em>) is never chosen.</p>\n"
      "<table class=\"comparison\"><tr><th>point</th><th>status</th><th>wall [s]</th><th>steps</th>"
      "<th>rejected</th><th>Newton</th><th>Jacobians</th><th>memory [MiB]</th><th>rms error [%]</th>"
      "<th>peak error [%]</th><th>worst quantity</th><th>message</th></tr>\n";
  for (const SweepPointRow& r : sweep.points) {
    out += fmt::format(
        "<tr{}><td>{}</td><td>{}</td><td class=\"number\">{}</td><td class=\"number\">{}</td>"
        "<td class=\"number\">{}</td><td class=\"number\">{}</td><td class=\"number\">{}</td>"
        "<td class=\"number\">{}</td><td class=\"number\">{}</td><td class=\"number\">{}</td><td>{}</td>"
        "<td>{}</td></tr>\n",
        r.role == "chosen" ? " class=\"chosen\"" : "", markup_escape(r.point), markup_escape(r.status),
        value(r.wall_s, "{:.3g}"), r.steps, r.rejected_steps, r.newton_iterations, r.jacobian_evaluations,
        value(r.peak_rss_mib, "{:.1f}"), percent(r.error_rms), percent(r.error_peak), markup_escape(r.worst_quantity),
        markup_escape(r.message));
  }
  return out + "</table>\n";
}

}  // namespace limber::report
