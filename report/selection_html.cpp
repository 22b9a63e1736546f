#include "selection_html.h"

#include "html.h"
#include "plot_set.h"
#include "results/results_layout.h"

#include <fmt/format.h>

namespace limber::report {
namespace {

std::string number(double value) { return fmt::format("{:.6g}", value); }

// A fraction as a percentage with two decimals; "" when not available.
std::string percent(const std::optional<double>& fraction) {
  return fraction ? fmt::format("{:.2f}", 100.0 * *fraction) : "";
}

std::string seconds(const std::optional<double>& value) {
  return value ? fmt::format("{:.3g}", *value) : "";
}

// A ranking row's reaction component is minimum-norm: decided from the run's redundancy in the
// body's axes (the joints table's decision) when the row names an axis, else as the CSV says.
bool minimum_norm(const RunData& run, const RankingRow& r) {
  const std::size_t axis = std::string("xyz").find(r.axis);
  if (r.axis.size() != 1 || axis == std::string::npos) return r.indeterminate;
  return is_indeterminate_component(run, r.joint, r.body, r.quantity == "torque", static_cast<int>(axis));
}

std::string ranking_table(const RunData& run, const SelectionData& selection) {
  if (selection.ranking.empty()) return "";
  std::string out =
      "<h4>Ranking of the reactions on flexible bodies</h4>\n"
      "<p>Every reaction component acting on a flexible body, in the body's own axes, by its peak "
      "relative to the body's largest. <span class=\"kept-key\">Highlighted rows</span> are kept "
      "as boundary conditions of static modes; <em>minimum-norm</em> marks the reaction of a "
      "redundant joint, which the equations leave indeterminate (the smallest one is shown).</p>\n"
      "<table class=\"ranking\"><tr><th>#</th><th>body</th><th>joint</th><th>node</th>"
      "<th>reaction</th><th>peak</th><th>rms</th><th>unit</th><th>relative [%]</th>"
      "<th>kept</th><th>indeterminate</th></tr>\n";
  for (std::size_t k = 0; k < selection.ranking.size(); ++k) {
    const RankingRow& r = selection.ranking[k];
    const char* unit = r.quantity == "torque" ? "N m" : r.quantity == "force" ? "N" : "";
    out += fmt::format(
        "<tr{}><td class=\"number\">{}</td><td>{}</td><td>{}</td><td class=\"number\">{}</td>"
        "<td>{} {}</td><td class=\"number\">{}</td><td class=\"number\">{}</td><td>{}</td>"
        "<td class=\"number\">{:.1f}</td><td>{}</td><td>{}</td></tr>\n",
        r.kept ? " class=\"kept\"" : "", k + 1, markup_escape(r.body), markup_escape(r.joint), r.node,
        markup_escape(r.quantity), markup_escape(r.axis), number(r.peak), number(r.rms), unit,
        100.0 * r.relative, r.kept ? "kept" : "",
        minimum_norm(run, r) ? "<em class=\"indeterminate\">minimum-norm</em>" : "");
  }
  return out + "</table>\n";
}

std::string comparison_table(const SelectionData& selection) {
  if (selection.comparison.empty()) return "";
  std::string out =
      "<h4>Mode sets compared</h4>\n"
      "<p>Each mode set run, with its errors relative to the reference run: the largest error of "
      "a key quantity's peak and of its rms, and the quantity with the worst. "
      "<span class=\"chosen-key\">The chosen set</span> and <span class=\"reference-key\">the "
      "reference</span> are marked.</p>\n"
      "<table class=\"comparison\"><tr><th>set</th><th>description</th><th>modes</th>"
      "<th>reduction [s]</th><th>run [s]</th><th>status</th><th>peak error [%]</th>"
      "<th>rms error [%]</th><th>worst quantity</th><th>directory</th><th>role</th></tr>\n";
  for (const ComparisonRow& r : selection.comparison) {
    const std::string row_class =
        r.role == "chosen" || r.role == "reference" ? " class=\"" + r.role + "\"" : "";
    out += fmt::format(
        "<tr{}><td>{}</td><td>{}</td><td class=\"number\">{}</td><td class=\"number\">{}</td>"
        "<td class=\"number\">{}</td><td{}>{}</td><td class=\"number\">{}</td>"
        "<td class=\"number\">{}</td><td>{}</td><td><code>{}</code></td><td>{}</td></tr>\n",
        row_class, markup_escape(r.set), markup_escape(r.description), r.modes, seconds(r.reduction_s),
        seconds(r.run_s), r.status == results::layout::status::kOk ? "" : " class=\"failed\"", markup_escape(r.status),
        percent(r.error_peak), percent(r.error_rms), markup_escape(r.worst_quantity),
        markup_escape(r.directory), markup_escape(r.role));
  }
  return out + "</table>\n";
}

}  // namespace

std::string selection_tables(const RunData& run) {
  if (!run.selection) return "";
  return ranking_table(run, *run.selection) + comparison_table(*run.selection);
}

}  // namespace limber::report
