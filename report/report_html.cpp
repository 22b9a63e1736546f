#include "report_html.h"

#include "hinge_summary.h"
#include "run_summary.h"
#include "html.h"
#include "mode_origins.h"
#include "model_description.h"
#include "selection_html.h"
#include "sizing_loads.h"
#include "stress_summary.h"
#include "sweep_html.h"
#include "results/results_layout.h"

#include <fmt/format.h>

#include <algorithm>
#include <numbers>

namespace limber::report {
namespace {

// Print-friendly, system fonts only (nothing fetched).
constexpr const char* kStyle = R"(
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; margin: 2em auto;
       max-width: 1250px; padding: 0 1em; color: #1a1a1a; line-height: 1.4; }
h1 { border-bottom: 3px solid #1f77b4; padding-bottom: .2em; }
h2 { border-bottom: 1px solid #bbb; margin-top: 2em; }
nav ul { columns: 2; }
table { border-collapse: collapse; margin: .5em 0 1em; }
th, td { border: 1px solid #ccc; padding: .2em .6em; text-align: left; }
th { background: #eef2f7; }
td.number { text-align: right; font-variant-numeric: tabular-nums; }
figure { margin: 1em 0 2em; page-break-inside: avoid; }
figure img { max-width: 100%; height: auto; border: 1px solid #ddd; }
figcaption { font-size: .95em; color: #444; }
.banner { padding: .8em 1em; margin: 1em 0; border-radius: 4px; font-weight: bold; }
.banner.failed { background: #fde2e1; border: 2px solid #c62828; color: #8e0000; }
.banner.running { background: #fff4d6; border: 2px solid #e09b00; color: #6d4c00; }
.note { color: #555; font-style: italic; }
.coincide { font-weight: bold; color: #333; }
.strip { display: flex; gap: 6px; flex-wrap: wrap; }
.strip figure { margin: 0; flex: 1 1 180px; }
.modes { display: grid; grid-template-columns: repeat(auto-fill, minmax(300px, 1fr)); gap: 8px; }
.modes figure { margin: 0; }
tr.kept td, .kept-key, tr.chosen td, .chosen-key { background: #e3f2e1; }
tr.kept td { font-weight: bold; }
tr.reference td, .reference-key { background: #eef2f7; font-style: italic; }
.indeterminate { color: #8a5a00; }
.plot-warning { background: #fff4d6; border-left: 4px solid #e09b00; padding: .4em .8em;
                margin: .3em 0; color: #6d4c00; }
td.failed { color: #8e0000; font-weight: bold; }
#summary h3 { margin: .6em 0 .2em; }
.badge { display: inline-block; padding: .1em .6em; border-radius: 4px; color: #fff; font-size: .9em; }
.badge.ok { background: #2e7d32; }
.badge.inaccurate { background: #b26a00; }
.badge.failed { background: #c62828; }
.accuracy, .model, .peaks-line, .seed-figures { margin: .2em 0; }
span.pass { color: #1b5e20; }
span.fail, p.fail { color: #8e0000; font-weight: bold; }
.summary-grid { display: grid; grid-template-columns: minmax(0, 2fr) minmax(0, 3fr); gap: 1em; align-items: start; }
table.compact { margin: .2em 0 .4em; font-size: .92em; }
table.compact td, table.compact th { padding: .1em .45em; }
details > summary { cursor: pointer; color: #1f4e79; }
@media print { nav { display: none; } h2 { page-break-before: always; }
               details::details-content { content-visibility: visible; display: block; } }
)";

std::string number(double value) { return fmt::format("{:.6g}", value); }

// The file name without its extension (made of [A-Za-z0-9_~-]: an HTML id as it is).
std::string stem_of(const std::string& file) { return file.substr(0, file.rfind('.')); }

// One plot: the interactive chart (when its JSON is there), the PNG (for print, and on screen
// without scripts), the caption with the link to the CSV of every sample.
std::string figure(const WrittenPlot& written, const std::string& run_anchor) {
  const NamedPlot& plot = written.plot;
  const std::string caption = markup_escape(plot.caption);
  const std::string id = stem_of(plot.file);
  std::string out = fmt::format("<figure class=\"plot\" id=\"fig-{}\">\n", id);
  if (!written.interactive_json.empty()) {
    out += fmt::format(
        "<div class=\"dygraph-plot\" id=\"plot-{0}\" data-source=\"json-{0}\" "
        "data-legend=\"legend-{0}\" data-run=\"{1}\"></div><div class=\"plot-legend\" "
        "id=\"legend-{0}\"></div>\n",
        id, run_anchor);
  }
  if (!plot.warning.empty()) {
    out += "<p class=\"plot-warning\" role=\"note\">" + markup_escape(plot.warning) + "</p>\n";
  }
  out += fmt::format("<img class=\"static\" src=\"{}/{}\" alt=\"{}\">\n<figcaption>", kImageFolder,
                     plot.file, caption);
  // Curves lying on each other are dashed; say which, before the caption.
  if (!plot.coincidence.empty()) {
    out += "<span class=\"coincide\">Coinciding curves (the later dashed): " +
           markup_escape(plot.coincidence) + ".</span> ";
  }
  out += caption;
  if (!written.csv_file.empty()) {
    out += fmt::format(" <a class=\"csv\" href=\"{}/{}\">Data (CSV)</a>", kDataFolder, written.csv_file);
  }
  if (!written.interactive_json.empty()) {
    std::size_t samples = 0;
    for (const Curve& c : plot.spec.curves) samples = std::max<std::size_t>(samples, c.x.size());
    if (written.interactive_rows < samples) {
      out += fmt::format(
          " <span class=\"note decimated\">Interactive view: {} of {} samples, the first, last, "
          "smallest and largest of each pixel column (peaks exact); the CSV holds all.</span>",
          written.interactive_rows, samples);
    }
  }
  out += "</figcaption>\n";
  if (!written.interactive_json.empty()) {
    out += fmt::format("<script type=\"application/json\" id=\"json-{}\">{}</script>\n", id,
                       written.interactive_json);
  }
  return out + "</figure>\n";
}

// The first figure open, the others folded: a long section (24 joints' reactions) reads as
// its first plot and a line saying how many follow.
std::string folded_figures(const std::vector<const WrittenPlot*>& plots, const std::string& anchor) {
  if (plots.empty()) return "";
  std::string out = figure(*plots.front(), anchor);
  if (plots.size() == 1) return out;
  out += fmt::format("<details class=\"more-figures\"><summary>{} more figure{}</summary>\n", plots.size() - 1,
                     plots.size() > 2 ? "s" : "");
  for (std::size_t k = 1; k < plots.size(); ++k) out += figure(*plots[k], anchor);
  return out + "</details>\n";
}

std::string plots_of(const RunSection& section, PlotSection kind) {
  std::vector<const WrittenPlot*> plots;
  for (const WrittenPlot& plot : section.plots) {
    if (plot.plot.section == kind) plots.push_back(&plot);
  }
  return folded_figures(plots, section.anchor);
}

// A red (failed) or amber (did not finish, or finished inaccurate) banner; nothing for a run
// that finished ok.
std::string status_banner(const RunData& run) {
  const render::Results& r = run.results;
  if (r.status == results::layout::status::kOk) return "";
  const std::string shown =
      r.sample_count() > 0
          ? fmt::format("The report shows the {} samples written, up to t = {} s.", r.sample_count(),
                        number(r.time(r.sample_count() - 1)))
          : std::string("No sample was written.");
  if (r.status == results::layout::status::kInaccurate) {
    // The run's own accuracy warnings (results.h5 root attribute accuracy_warnings).
    std::string warnings;
    for (const auto& [name, value] : run.solver_attributes) {
      if (name == "accuracy_warnings") warnings = value;
    }
    return fmt::format(
        "<div class=\"banner running\" role=\"alert\">This run finished, but its own accuracy "
        "estimate says the answer is off: {}</div>\n",
        markup_escape(warnings.empty() ? "(no warning recorded)" : warnings));
  }
  if (r.status == results::layout::status::kFailed) {
    return fmt::format("<div class=\"banner failed\" role=\"alert\">This run failed: {} {}</div>\n",
                       markup_escape(r.message.empty() ? "(no message)" : r.message), shown);
  }
  return fmt::format(
      "<div class=\"banner running\" role=\"alert\">This run did not finish (status \"{}\": "
      "killed, crashed or still running). {}</div>\n",
      markup_escape(r.status), shown);
}

std::string summary_table(const RunData& run) {
  const render::Results& r = run.results;
  std::string rows;
  auto row = [&rows](const std::string& key, const std::string& value) {
    rows += fmt::format("<tr><th>{}</th><td>{}</td></tr>\n", key, value);
  };
  row("directory", markup_escape(run.directory.string()));
  row("case title", markup_escape(r.title));
  row("case file", markup_escape(r.case_file));
  row("status", markup_escape(r.status) + (r.message.empty() ? "" : ": " + markup_escape(r.message)));
  row("samples", std::to_string(r.sample_count()));
  if (r.sample_count() > 0) {
    row("time span", fmt::format("{} … {} s", number(r.time(0)), number(r.time(r.sample_count() - 1))));
  }
  if (run.steps) row("accepted steps", std::to_string(*run.steps));
  if (run.position_violation && run.sample_count() > 0) {
    row("largest position violation", number(run.position_violation->values.cwiseAbs().maxCoeff()));
  }
  if (run.velocity_violation && run.sample_count() > 0) {
    row("largest velocity violation", number(run.velocity_violation->values.cwiseAbs().maxCoeff()));
  }
  for (const auto& [key, value] : run.solver_attributes) row(markup_escape(key), markup_escape(value));
  return "<table class=\"summary\">\n" + rows + "</table>\n";
}

std::string bodies_table(const RunData& run) {
  std::string out =
      "<table><tr><th>body</th><th>kind</th><th>nodes</th><th>beam elements</th>"
      "<th>shell elements</th><th>modes</th></tr>\n";
  for (const render::BodyTrack& b : run.results.bodies) {
    if (b.flexible) {
      // A nonlinear body: its beams unreduced, no modes.
      const bool nonlinear = is_nonlinear(b);
      out += fmt::format(
          "<tr><td>{}</td><td>{}</td><td class=\"number\">{}</td><td class=\"number\">{}</td>"
          "<td class=\"number\">{}</td><td class=\"number\">{}</td></tr>\n",
          markup_escape(b.name), nonlinear ? "flexible, nonlinear" : "flexible", b.mesh.nodes.rows(),
          b.mesh.lines.rows(), b.mesh.quads.rows(),
          nonlinear ? std::string("none (unreduced)") : std::to_string(b.mesh.mode_translations.cols()));
    } else {
      out += fmt::format("<tr><td>{}</td><td>rigid</td><td></td><td></td><td></td><td></td></tr>\n",
                         markup_escape(b.name));
    }
  }
  return out + "</table>\n";
}

std::string joints_table(const RunData& run) {
  if (run.results.joints.empty()) return "<p class=\"note\">No joints in the results.</p>\n";
  std::string out =
      "<table><tr><th>joint</th><th>type</th><th>body i</th><th>body j</th><th>reaction</th></tr>\n";
  for (const render::JointTrack& j : run.results.joints) {
    const auto reactions = std::find_if(run.joints.begin(), run.joints.end(),
                                        [&](const JointReactions& r) { return r.name == j.name; });
    const Indeterminacy which =
        reactions != run.joints.end() ? indeterminacy(run, *reactions) : Indeterminacy{};
    const std::string what =
        reactions != run.joints.end() ? indeterminate_summary(run, *reactions) : "determined";
    out += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td{}>{}</td></tr>\n",
                       markup_escape(j.name), markup_escape(j.type), markup_escape(j.body_i),
                       markup_escape(j.body_j),
                       which.force || which.torque ? " class=\"indeterminate\"" : "", markup_escape(what));
  }
  return out + "</table>\n";
}

// The joints of a comparison (held by two or more runs, as comparison_plots.h overlays them):
// per run, what of each reaction is minimum-norm, since redundancy may differ between runs.
std::string comparison_joints_table(const std::vector<RunSection>& sections) {
  std::vector<std::string> names;
  for (const RunSection& s : sections) {
    for (const JointReactions& joint : s.run->joints) {
      if (std::find(names.begin(), names.end(), joint.name) != names.end()) continue;
      int holders = 0;
      for (const RunSection& other : sections) {
        holders += std::any_of(other.run->joints.begin(), other.run->joints.end(),
                               [&](const JointReactions& j) { return j.name == joint.name; });
      }
      if (holders >= 2) names.push_back(joint.name);
    }
  }
  if (names.empty()) return "";
  std::string out = "<h3>Joints compared</h3>\n<table class=\"joints-compared\"><tr><th>joint</th>";
  for (const RunSection& s : sections) out += "<th>" + markup_escape(s.label) + "</th>";
  out += "</tr>\n";
  for (const std::string& name : names) {
    out += "<tr><td>" + markup_escape(name) + "</td>";
    for (const RunSection& s : sections) {
      const auto joint = std::find_if(s.run->joints.begin(), s.run->joints.end(),
                                      [&](const JointReactions& j) { return j.name == name; });
      if (joint == s.run->joints.end()) {
        out += "<td class=\"note\">not in this run</td>";
        continue;
      }
      const Indeterminacy which = indeterminacy(*s.run, *joint);
      out += fmt::format("<td{}>{}</td>", which.force || which.torque ? " class=\"indeterminate\"" : "",
                         markup_escape(indeterminate_summary(*s.run, *joint)));
    }
    out += "</tr>\n";
  }
  return out + "</table>\n";
}

std::string redundancy_table(const RunData& run) {
  if (run.redundant_equations.empty()) return "";
  std::string out =
      "<h4>Redundant constraints</h4>\n<table><tr><th>equation</th><th>combination of</th></tr>\n";
  for (const auto& [name, with] : run.redundant_equations) {
    out += fmt::format("<tr><td>{}</td><td>{}</td></tr>\n", markup_escape(name), markup_escape(with));
  }
  return out + "</table>\n";
}

std::string notes(const RunData& run) {
  std::string out;
  for (const std::string& note : run.notes) out += "<p class=\"note\">" + markup_escape(note) + "</p>\n";
  return out;
}

// "Modes of plate0" for one body; for bodies sharing a component, that they share it.
std::string mode_table_heading(const ModeTable& table) {
  const std::string source = "from " + markup_escape(table.source);
  if (table.bodies.size() == 1) {
    return fmt::format("<h4>Modes of {} <span class=\"note\">({}{})</span></h4>\n", markup_escape(table.bodies[0]),
                       table.component.empty() || table.component == table.bodies[0]
                           ? ""
                           : "component " + markup_escape(table.component) + ", ",
                       source);
  }
  std::string bodies;
  for (std::size_t k = 0; k < table.bodies.size(); ++k) {
    bodies += (k == 0 ? "" : k + 1 == table.bodies.size() ? " and " : ", ") + markup_escape(table.bodies[k]);
  }
  return fmt::format("<h4>Modes of component {} <span class=\"note\">({} share component {}; {})</span></h4>\n",
                     markup_escape(table.component), bodies, markup_escape(table.component), source);
}

// One table per distinct component: frequency, kind, and the label with the joints at a
// static mode's node.
std::string mode_tables(const RunData& run) {
  std::string out;
  for (const ModeTable& table : run.mode_tables) {
    out += mode_table_heading(table);
    if (table.modes.empty()) {
      out += "<p class=\"note\">No modes.</p>\n";
      continue;
    }
    out += "<table><tr><th>#</th><th>frequency [Hz]</th><th>kind</th><th>label</th></tr>\n";
    for (std::size_t i = 0; i < table.modes.size(); ++i) {
      const ModeRow& m = table.modes[i];
      const std::string joints = mode_origin_joints(run, table, m.label);
      out += fmt::format(
          "<tr><td class=\"number\">{}</td><td class=\"number\">{}</td><td>{}</td><td>{}{}</td></tr>\n",
          i + 1, number(m.frequency_hz), markup_escape(m.kind), markup_escape(m.label),
          joints.empty() ? "" : ": " + markup_escape(joints));
    }
    out += "</table>\n";
  }
  // Nonlinear bodies have no modes: what they are instead.
  for (const render::BodyTrack& body : run.results.bodies) {
    if (!is_nonlinear(body)) continue;
    out += fmt::format("<h4>{}</h4>\n<p class=\"note\">No modes: {}, integrated unreduced.</p>\n",
                       markup_escape(body.name), markup_escape(nonlinear_description(body)));
  }
  return out;
}

std::string media(const RunSection& section) {
  std::string out;
  if (!section.stills.empty()) {
    out += "<div class=\"strip\">\n";
    for (std::size_t k = 0; k < section.stills.size(); ++k) {
      out += fmt::format("<figure><img src=\"{}/{}\" alt=\"animation still {}\"></figure>\n",
                         kImageFolder, section.stills[k], k + 1);
    }
    out += "</div>\n";
  }
  if (!section.video_url.empty()) {
    out += fmt::format(
        "<p><video controls preload=\"none\" width=\"640\" src=\"{0}\"></video><br>"
        "<a href=\"{0}\">the video (MP4)</a></p>\n",
        section.video_url);
  }
  if (out.empty()) {
    out = "<p class=\"note\">No frames or video: run <code>limber render</code> on this directory "
          "to add them.</p>\n";
  }
  return out;
}

std::string mode_images(const RunSection& section) {
  std::string out = "<div class=\"modes\">\n";
  for (const ModeImage& m : section.mode_images) {
    const std::string caption = markup_escape(fmt::format("{} mode {}: {} Hz{}", m.body, m.mode + 1,
                                                          number(m.frequency_hz),
                                                          m.label.empty() ? "" : ", " + m.label));
    out += fmt::format("<figure><img src=\"{}/{}\" alt=\"{}\"><figcaption>{}</figcaption></figure>\n",
                       kImageFolder, m.file, caption, caption);
  }
  return out + "</div>\n";
}

// Located latch and stop switches, and the peaks after each latch-up.
std::string hinge_tables(const RunData& run) {
  if (run.events.empty()) return "";
  constexpr double kDegrees = 180.0 / std::numbers::pi;
  std::string out =
      "<h4>Events</h4>\n<table><tr><th>time [s]</th><th>limit</th><th>kind</th><th>joint</th>"
      "<th>what</th><th>angle [deg]</th><th>rate [deg/s]</th></tr>\n";
  for (const HingeEventRow& e : run.events) {
    const HingeLimitTrack& limit = run.hinge_limits[static_cast<std::size_t>(e.limit)];
    const char* what = limit.kind == "latch" ? "locked" : (e.engaged ? "contact begins" : "contact ends");
    out += fmt::format("<tr><td class=\"number\">{:.6f}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td>"
                       "<td class=\"number\">{:.3f}</td><td class=\"number\">{:.2f}</td></tr>\n",
                       e.time, markup_escape(limit.name), markup_escape(limit.kind), markup_escape(limit.joint),
                       what, e.angle * kDegrees, e.rate * kDegrees);
  }
  out += "</table>\n";
  const std::vector<LatchUpPeaks> peaks = latch_up_peaks(run);
  if (peaks.empty()) return out;
  out += fmt::format(
      "<h4>Latch-up peaks</h4>\n<p>Within {:g} s after each latch locked: the largest reaction "
      "force (magnitude, ground axes) at the latched joint, its largest components in the "
      "joint frame (on body j), the largest latch torque, and the largest reaction magnitude "
      "of any joint. Peaks are read at the output samples.</p>\n"
      "<table><tr><th>latch</th><th>locked at [s]</th><th>joint</th><th>peak |F| [N]</th>"
      "<th>at [s]</th><th>peak |F<sub>x</sub>|, |F<sub>y</sub>|, |F<sub>z</sub>| joint frame [N]</th>"
      "<th>peak latch torque [N m]</th><th>largest |F| of any joint [N]</th>"
      "<th>joint</th><th>at [s]</th></tr>\n",
      kLatchUpWindow);
  for (const LatchUpPeaks& p : peaks) {
    const HingeEventRow& e = run.events[static_cast<std::size_t>(p.event)];
    const HingeLimitTrack& limit = run.hinge_limits[static_cast<std::size_t>(e.limit)];
    out += fmt::format("<tr><td>{}</td><td class=\"number\">{:.6f}</td><td>{}</td>"
                       "<td class=\"number\">{}</td><td class=\"number\">{:.4f}</td>"
                       "<td class=\"number\">{}, {}, {}</td>"
                       "<td class=\"number\">{}</td><td class=\"number\">{}</td><td>{}</td>"
                       "<td class=\"number\">{:.4f}</td></tr>\n",
                       markup_escape(limit.name), e.time, markup_escape(limit.joint), number(p.latched_force),
                       p.latched_force_time, number(p.latched_force_joint.x()),
                       number(p.latched_force_joint.y()), number(p.latched_force_joint.z()),
                       number(p.latch_torque), number(p.largest_force),
                       markup_escape(p.largest_joint), p.largest_force_time);
  }
  return out + "</table>\n";
}

// Each body's peak stress: value, element, where and when.
std::string stress_table(const RunData& run) {
  const std::vector<StressPeak> peaks = stress_peaks(run);
  if (peaks.empty()) return "";
  std::string out =
      "<p>Largest equivalent stress of each body over its mesh and the run, read at the output "
      "samples (docs/stress-recovery.md): shells' von Mises stress on their top or bottom "
      "surface, beams' extreme-fibre axial stress.</p>\n"
      "<table><tr><th>body</th><th>peak [MPa]</th><th>at t [s]</th><th>element</th>"
      "<th>element centre, body frame [m]</th><th>after</th></tr>\n";
  for (const StressPeak& p : peaks) {
    out += fmt::format("<tr><td>{}</td><td class=\"number\">{:.4g}</td><td class=\"number\">{:.4f}</td>"
                       "<td>{}</td><td class=\"number\">({:.3f}, {:.3f}, {:.3f})</td><td>{}</td></tr>\n",
                       markup_escape(p.body), p.value / 1e6, p.time, markup_escape(p.element_name),
                       p.centre_B.x(), p.centre_B.y(), p.centre_B.z(), markup_escape(p.after));
  }
  return out + "</table>\n";
}

// The energy balance's worst residual against the largest kinetic energy.
std::string energy_note(const RunData& run) {
  const std::optional<Series> residual = energy_residual(run);
  if (!residual) return "";
  double kinetic = 0.0;
  for (const Series& s : run.energies) {
    if (s.name == "kinetic" && s.values.size() > 0) kinetic = s.values.cwiseAbs().maxCoeff();
  }
  const double worst = residual->values.cwiseAbs().maxCoeff();
  if (kinetic <= 0.0) return fmt::format("<p>Energy balance residual at most {} J.</p>\n", number(worst));
  return fmt::format("<p>The energy balance closes to {} J, {:.2g} of the peak kinetic energy "
                     "({} J).</p>\n",
                     number(worst), worst / kinetic, number(kinetic));
}

// The smallest clearance over the run, with a warning when bodies interfere.
std::string clearance_note(const RunData& run) {
  if (!run.clearance || run.clearance->values.size() == 0) return "";
  Eigen::Index k = 0;
  const double minimum = run.clearance->values.minCoeff(&k);
  const int pair = run.clearance_pair[static_cast<std::size_t>(k)];
  const std::string pair_name =
      pair >= 0 && pair < static_cast<int>(run.clearance_pairs.size()) ? run.clearance_pairs[pair] : "?";
  const std::string text = fmt::format("Smallest clearance over the run: {} m, between {} at t = {:.4f} s.",
                                       number(minimum), markup_escape(pair_name), run.results.time(k));
  if (minimum < 0.0) return "<div class=\"banner failed\" role=\"alert\">Interference. " + text + "</div>\n";
  return "<p>" + text + "</p>\n";
}

// One <h3> subsection when it has content.
std::string subsection(const RunSection& s, const std::string& id, const std::string& heading,
                       const std::string& body) {
  if (body.empty()) return "";
  return fmt::format("<h3 id=\"{}-{}\">{}</h3>\n{}", s.anchor, id, heading, body);
}

std::string run_section(const RunSection& s, bool interactive) {
  const RunData& run = *s.run;
  std::string out = fmt::format("<section id=\"{}\">\n<h2>{}</h2>\n", s.anchor, markup_escape(s.label));
  out += status_banner(run);
  // The case's details, folded: the summary at the top holds what a reviewer reads first.
  out += subsection(s, "summary", "Case summary",
                    notes(run) +
                        fmt::format("<details><summary>case file, solver settings and accuracy "
                                    "attributes, {} bodies, {} joints{}, mode tables</summary>\n",
                                    run.results.bodies.size(), run.results.joints.size(),
                                    run.redundant_equations.empty() ? "" : ", redundant constraints") +
                        summary_table(run) + "<h4>Bodies</h4>\n" + bodies_table(run) + "<h4>Joints</h4>\n" +
                        joints_table(run) + redundancy_table(run) + mode_tables(run) + "</details>\n");
  if (interactive && !s.plots.empty()) out += time_window_form(s.anchor);
  out += subsection(s, "reactions", "Reaction forces", plots_of(s, PlotSection::kReactions));
  if (run.selection) {
    std::string body = selection_tables(run) + plots_of(s, PlotSection::kSelection);
    if (body.empty()) {
      body = "<p class=\"note\">The selection folder holds nothing usable (see the notes in the "
             "case summary).</p>\n";
    }
    out += subsection(s, "selection", "Mode selection", body);
  }
  if (run.sweep) {
    std::string body = plots_of(s, PlotSection::kSweep) + sweep_table(*run.sweep);
    if (body.empty()) {
      body = "<p class=\"note\">The sweep folder holds nothing usable (see the notes in the case "
             "summary).</p>\n";
    }
    out += subsection(s, "sweep", "Work-precision sweep", body);
  }
  out += subsection(s, "drivers", "Drivers", plots_of(s, PlotSection::kDrivers));
  out += subsection(s, "energy", "Energy", energy_note(run) + plots_of(s, PlotSection::kEnergy));
  out += subsection(s, "hinges", "Hinges and latches", hinge_tables(run) + plots_of(s, PlotSection::kHinges));
  out += subsection(s, "clearance", "Clearance", clearance_note(run) + plots_of(s, PlotSection::kClearance));
  out += subsection(s, "deflection", "Deflection", plots_of(s, PlotSection::kDeflection));
  out += subsection(s, "stress", "Stress", stress_table(run) + plots_of(s, PlotSection::kStress));
  out += subsection(s, "shock", "Acceleration probes and shock response spectra", plots_of(s, PlotSection::kShock));
  out += subsection(s, "violation", "Constraint violation", plots_of(s, PlotSection::kViolation));
  out += subsection(s, "animation", "Animation", media(s));
  if (!s.mode_images.empty()) {
    out += subsection(s, "mode-shapes", "Mode shapes",
                      fmt::format("<details><summary>{} mode-shape images</summary>\n{}</details>\n",
                                  s.mode_images.size(), mode_images(s)));
  }
  return out + "</section>\n";
}

}  // namespace

std::string report_html(const ReportContent& content) {
  std::string out = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<title>{0}</title>\n<style>{1}{2}{3}</style>\n</head>\n<body>\n<h1>{0}</h1>\n",
      markup_escape(content.title), kStyle, interactive_style(),
      content.interactive ? content.interactive->style : std::string());
  if (!content.interactive) {
    out += "<p class=\"banner running\" role=\"note\">" + markup_escape(content.interactive_note) +
           "</p>\n";
  }

  // The summary first: status, model, events, peaks, the seed's figures.
  out += summary_section(content);

  // Contents.
  out += "<nav><ul>\n<li><a href=\"#summary\">Summary</a></li>\n";
  for (const RunSection& s : content.runs) {
    out += fmt::format("<li><a href=\"#{}\">{}</a>{}</li>\n", s.anchor, markup_escape(s.label),
                       s.run->finished_ok() ? "" : " (" + markup_escape(s.run->results.status) + ")");
  }
  if (!content.comparisons.empty()) out += "<li><a href=\"#comparison\">Comparison</a></li>\n";
  out += "</ul></nav>\n";

  // What a structures engineer sizes from, before the runs' details.
  out += sizing_loads_section(content.runs);
  for (const RunSection& s : content.runs) out += run_section(s, content.interactive.has_value());

  // Several runs: one reaction component overlaid (seed paper Figs. 6 and 10).
  if (!content.comparisons.empty()) {
    out += "<section id=\"comparison\">\n<h2>Comparison of runs</h2>\n";
    out += comparison_joints_table(content.runs);
    if (content.interactive) out += time_window_form("comparison");
    std::vector<const WrittenPlot*> plots;
    for (const WrittenPlot& plot : content.comparisons) plots.push_back(&plot);
    out += folded_figures(plots, "comparison");
    out += "</section>\n";
  }
  out += "<footer class=\"note\">Generated by limber report.</footer>\n";
  if (content.interactive) out += interactive_scripts(*content.interactive);
  return out + "</body>\n</html>\n";
}

}  // namespace limber::report
