#include "run_summary.h"

#include "hinge_summary.h"
#include "html.h"
#include "model_description.h"
#include "results/results_layout.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <numbers>

namespace limber::report {
namespace {

// The value of a solver attribute, "" when absent.
std::string attribute(const RunData& run, const std::string& name) {
  for (const auto& [key, value] : run.solver_attributes) {
    if (key == name) return value;
  }
  return "";
}

// Index of the largest |row| of an ns x 3 matrix, and its norm; (−1, 0) when empty.
std::pair<Eigen::Index, double> largest_row(const RowMatrix3d& values) {
  if (values.rows() == 0) return {-1, 0.0};
  Eigen::Index k = 0;
  const double peak = values.rowwise().norm().maxCoeff(&k);
  return {k, peak};
}

// First sample of the all-zero tail of an ns x 3 matrix: ns when its last row is not 0, 0 when
// every row is.
Eigen::Index zero_tail(const RowMatrix3d& values) {
  Eigen::Index k = values.rows();
  while (k > 0 && (values.row(k - 1).array() == 0.0).all()) --k;
  return k;
}

std::string number(double value) { return fmt::format("{:.3g}", value); }

// Loads at or below this fraction of the run's largest are rounding, shown "≈ 0" (as in the
// loads for sizing, sizing_loads.cpp).
constexpr double kRoundingFraction = 1e-6;

// "0.00196 of the allowed 0.01" and whether it passed.
std::string measure_text(const AccuracyMeasure& m) {
  return fmt::format("<span class=\"{}\">{} {} of the allowed {:g}</span>", m.passed() ? "pass" : "fail",
                     markup_escape(m.name), number(m.value), m.threshold);
}

// The status badge: green ok, amber ok_inaccurate or unfinished, red failed.
std::string badge(const std::string& status) {
  const char* kind = status == results::layout::status::kOk           ? "ok"
                     : status == results::layout::status::kInaccurate ? "inaccurate"
                     : status == results::layout::status::kFailed     ? "failed"
                                                                       : "inaccurate";
  return fmt::format("<span class=\"badge {}\">{}</span>", kind, markup_escape(status));
}

// The flexible bodies by mode table: "panel_R1, panel_R2 (component panel): 8 modes"; then
// the nonlinear ones: "rod: nonlinear, 100 beam elements (101 nodes)".
std::string flexible_text(const RunData& run) {
  std::string out;
  for (const ModeTable& table : run.mode_tables) {
    std::string bodies;
    for (const std::string& b : table.bodies) bodies += (bodies.empty() ? "" : ", ") + markup_escape(b);
    const std::string component =
        table.component.empty() || (table.bodies.size() == 1 && table.bodies[0] == table.component)
            ? ""
            : " (component " + markup_escape(table.component) + ")";
    out += fmt::format("{}{}{}: {} modes", out.empty() ? "" : "; ", bodies, component, table.modes.size());
  }
  for (const render::BodyTrack& body : run.results.bodies) {
    if (!is_nonlinear(body)) continue;
    out += fmt::format("{}{}: {}", out.empty() ? "" : "; ", markup_escape(body.name), nonlinear_description(body));
  }
  return out;
}

// Each body's mass, centre of mass and inertia about it, folded below the model line.
std::string mass_table(const RunData& run) {
  if (run.body_masses.empty()) return "";
  std::string rows;
  for (const BodyMass& b : run.body_masses) {
    const Eigen::Matrix3d& J = b.inertia_com_B;
    rows += fmt::format("<tr><td>{}</td><td class=\"number\">{:.4g}</td><td class=\"number\">{:.4g}, {:.4g}, "
                        "{:.4g}</td><td class=\"number\">{:.4g}, {:.4g}, {:.4g}</td><td class=\"number\">{:.3g}, "
                        "{:.3g}, {:.3g}</td></tr>\n",
                        markup_escape(b.body), b.mass, b.com_B.x(), b.com_B.y(), b.com_B.z(), J(0, 0), J(1, 1),
                        J(2, 2), J(0, 1), J(0, 2), J(1, 2));
  }
  return fmt::format("<details><summary>masses and inertias of the {} bodies (flexible: undeformed)</summary>\n"
                     "<table class=\"compact\"><tr><th>body</th><th>mass [kg]</th><th>centre of mass, body "
                     "frame [m]</th><th>J<sub>xx</sub>, J<sub>yy</sub>, J<sub>zz</sub> [kg m²]</th><th>J<sub>xy"
                     "</sub>, J<sub>xz</sub>, J<sub>yz</sub> [kg m²]</th></tr>\n{}</table>\n</details>\n",
                     run.body_masses.size(), rows);
}

// The model in one line (bodies, the flexible ones by component with their mode counts,
// joints, total mass), then the bodies' masses, folded.
std::string model_line(const RunData& run, const RunDigest& d) {
  const std::string flexible = flexible_text(run);
  // A file without every body's mass (older files: nonlinear bodies had none): the total would be short.
  const std::string mass = d.total_mass              ? fmt::format(", {:.4g} kg in all", *d.total_mass)
                           : run.body_masses.empty() ? std::string(" (masses not in this results.h5)")
                                                     : fmt::format(" (masses of {} of them stored)", run.body_masses.size());
  return fmt::format("<p class=\"model\">Model: {} bodies{}, {} rigid and {} flexible{}; {} joints.</p>\n{}",
                     run.results.bodies.size(), mass, d.rigid_bodies, d.flexible_bodies.size(),
                     flexible.empty() ? "" : " (" + flexible + ")", d.joints, mass_table(run));
}

// Latch and stop switches, then joints released.
std::string events_table(const RunData& run, const RunDigest& d) {
  constexpr double kDegrees = 180.0 / std::numbers::pi;
  std::string rows;
  for (const HingeEventRow& e : run.events) {
    const HingeLimitTrack& limit = run.hinge_limits[static_cast<std::size_t>(e.limit)];
    const char* what = limit.kind == "latch" ? "locks" : (e.engaged ? "contact" : "contact ends");
    rows += fmt::format("<tr><td class=\"number\">{:.4f}</td><td>{} {}</td><td class=\"number\">{:.1f}</td></tr>\n",
                        e.time, markup_escape(limit.name), what, e.rate * kDegrees);
  }
  for (const ReleaseRow& r : d.releases) {
    std::string names;
    for (std::size_t k = 0; k < r.joints.size() && k < 4; ++k) names += (k > 0 ? ", " : "") + markup_escape(r.joints[k]);
    if (r.joints.size() > 4) names += fmt::format(" and {} more", r.joints.size() - 4);
    rows += fmt::format("<tr><td class=\"number\">≤ {:.4f}</td><td>released: {} (reaction 0 from then on)</td>"
                        "<td></td></tr>\n",
                        r.time, names);
  }
  if (rows.empty()) return "<p class=\"note\">No events (latches, stops, releases).</p>\n";
  return "<table class=\"compact\"><tr><th>t [s]</th><th>event</th><th>rate [deg/s]</th></tr>\n" + rows +
         "</table>\n";
}

// A value at or below `floor` is rounding: "≈ 0" and no time (as the loads for sizing).
std::string peak_cells(double value, double time, double floor) {
  if (value <= floor) return "<td class=\"number\">≈ 0</td><td></td>";
  return fmt::format("<td class=\"number\">{:.4g}</td><td class=\"number\">{:.4f}</td>", value, time);
}

std::string peak_row(const JointPeakRow& p, double floor) {
  return fmt::format("<tr><td>{}</td><td>{}</td>{}{}</tr>\n", markup_escape(p.joint), markup_escape(p.type),
                     peak_cells(p.force, p.force_time, floor), peak_cells(p.torque, p.torque_time, floor));
}

// The largest kSummaryPeakRows reactions, the rest folded.
std::string peaks_table(const RunDigest& d) {
  if (d.peaks.empty()) return "<p class=\"note\">No joint reactions in the results.</p>\n";
  const std::string head =
      "<tr><th>joint</th><th>type</th><th>peak |F| [N]</th><th>at t [s]</th><th>peak |T| [N m]</th>"
      "<th>at t [s]</th></tr>\n";
  // Below a millionth of the largest load is rounding (a revolute's torque about its free axis).
  double largest = 0.0;
  for (const JointPeakRow& p : d.peaks) largest = std::max({largest, p.force, p.torque});
  const double floor = kRoundingFraction * largest;
  std::string out = "<table class=\"compact peaks\">\n" + head;
  for (std::size_t k = 0; k < d.peaks.size() && k < kSummaryPeakRows; ++k) out += peak_row(d.peaks[k], floor);
  out += "</table>\n";
  if (d.peaks.size() > kSummaryPeakRows) {
    out += fmt::format("<details><summary>the other {} joints</summary>\n<table class=\"compact peaks\">\n{}",
                       d.peaks.size() - kSummaryPeakRows, head);
    for (std::size_t k = kSummaryPeakRows; k < d.peaks.size(); ++k) out += peak_row(d.peaks[k], floor);
    out += "</table>\n</details>\n";
  }
  return out;
}

// Peak deflection, stress and energy closure on one line.
std::string peaks_line(const RunDigest& d) {
  std::vector<std::string> parts;
  if (d.deflection) {
    parts.push_back(fmt::format("peak deflection {:.3g} mm ({}, t = {:.3f} s)", *d.deflection * 1e3,
                                markup_escape(d.deflection_body), d.deflection_time));
  }
  if (d.stress) {
    parts.push_back(fmt::format("peak stress {:.4g} MPa ({}, {}, t = {:.3f} s)", d.stress->value / 1e6,
                                markup_escape(d.stress->body), markup_escape(d.stress->element_name),
                                d.stress->time));
  }
  if (d.acceleration_g) {
    parts.push_back(fmt::format("peak acceleration {:.3g} g (probe {}, t = {:.3f} s)", *d.acceleration_g,
                                markup_escape(d.acceleration_probe), d.acceleration_time));
  }
  if (d.energy_residual) {
    parts.push_back(d.peak_kinetic > 0.0
                        ? fmt::format("energy balance closes to {:.3g} J ({:.2g} of the peak kinetic "
                                      "energy, {:.3g} J)",
                                      *d.energy_residual, *d.energy_residual / d.peak_kinetic, d.peak_kinetic)
                        : fmt::format("energy balance closes to {:.3g} J", *d.energy_residual));
  }
  if (const std::optional<MomentumDrift>& m = d.momentum) {
    parts.push_back(fmt::format("free-floating: momentum drifts by {:.3g} kg m/s ({:.2g} relative) and "
                                "{:.3g} kg m²/s ({:.2g} relative) from the first to the last sample",
                                m->linear, m->linear_relative(), m->angular, m->angular_relative()));
  }
  if (parts.empty()) return "";
  std::string out = "<p class=\"peaks-line\">";
  for (std::size_t k = 0; k < parts.size(); ++k) out += (k > 0 ? " · " : "") + parts[k];
  return out + ".</p>\n";
}

// The <figure> id of a written plot (report_html.cpp writes "fig-<png stem>").
std::string figure_id(const WrittenPlot& plot) {
  const std::string& file = plot.plot.file;
  return "fig-" + file.substr(0, file.rfind('.'));
}

// The run's first reaction force plot of `joint` (its first frame), or nullptr.
const WrittenPlot* reaction_plot(const RunSection& s, const std::string& joint) {
  for (const WrittenPlot& p : s.plots) {
    if (p.plot.kind == PlotKind::kReaction && p.plot.subject == joint &&
        p.plot.file.find("_force") != std::string::npos) {
      return &p;
    }
  }
  return nullptr;
}

// The comparison of `joint`'s component whose file tag ends in `axis` ("x", "z", "Fx"...).
const WrittenPlot* comparison_plot(const ReportContent& content, const std::string& joint,
                                   const std::vector<std::string>& tags) {
  for (const std::string& tag : tags) {
    const std::string file = "compare_" + file_stem(joint) + "_" + tag + ".png";
    for (const WrittenPlot& p : content.comparisons) {
      if (p.plot.file == file) return &p;
    }
  }
  return nullptr;
}

bool case_is(const RunSection& s, const std::string& stem) {
  const std::string name = std::filesystem::path(s.run->results.case_file).filename().string();
  return name.rfind(stem, 0) == 0;
}

// Each joint's peak reaction, largest first, and the joints released (reaction exactly 0 from
// some sample to the end), grouped by that sample's time.
void add_joint_peaks(const RunData& run, RunDigest& d) {
  for (const JointReactions& joint : run.joints) {
    const RowMatrix3d& force = joint.force_ground.rows() > 0 ? joint.force_ground : joint.force_joint;
    const RowMatrix3d& torque = joint.torque_ground.rows() > 0 ? joint.torque_ground : joint.torque_joint;
    const auto [kf, f] = largest_row(force);
    if (kf < 0) continue;
    JointPeakRow row;
    row.joint = joint.name;
    const auto track = std::find_if(run.results.joints.begin(), run.results.joints.end(),
                                    [&](const render::JointTrack& j) { return j.name == joint.name; });
    if (track != run.results.joints.end()) row.type = track->type;
    row.force = f;
    row.force_time = run.results.time(kf);
    const auto [kt, t] = largest_row(torque);
    if (kt >= 0) {
      row.torque = t;
      row.torque_time = run.results.time(kt);
    }
    d.peaks.push_back(row);
    // Released: force and torque exactly 0 from a sample to the end, loaded before it.
    const Eigen::Index released = zero_tail(force);
    if (released > 0 && released < force.rows() && (torque.rows() == 0 || zero_tail(torque) <= released)) {
      const double at = run.results.time(released);
      auto same = std::find_if(d.releases.begin(), d.releases.end(),
                               [&](const ReleaseRow& rr) { return rr.time == at; });
      if (same == d.releases.end()) same = d.releases.insert(d.releases.end(), ReleaseRow{at, {}});
      same->joints.push_back(joint.name);
    }
  }
  std::stable_sort(d.peaks.begin(), d.peaks.end(),
                   [](const JointPeakRow& a, const JointPeakRow& b) { return a.force > b.force; });
  std::sort(d.releases.begin(), d.releases.end(),
            [](const ReleaseRow& a, const ReleaseRow& b) { return a.time < b.time; });
}

}  // namespace

RunDigest digest_run(const RunData& run) {
  RunDigest d;
  const render::Results& r = run.results;
  d.status = r.status;
  d.message = r.message;

  // Accuracy measures as the run stored them, each against its threshold.
  const std::pair<const char*, std::pair<const char*, double>> measures[] = {
      {"accuracy_energy_relative", {"energy balance", kEnergyThreshold}},
      {"accuracy_local_error", {"local error", kLocalErrorThreshold}},
      {"accuracy_drift_relative", {"constraint drift", kDriftThreshold}}};
  // IDA controls its local error to rtol and keeps no second estimate (stored as 0): no row.
  const bool ida = attribute(run, "integrator") == "ida";
  for (const auto& [key, what] : measures) {
    const std::string text = attribute(run, key);
    if (text.empty() || (ida && std::string(key) == "accuracy_local_error")) continue;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (end == text.c_str()) continue;
    d.accuracy.push_back({what.first, value, what.second});
  }
  d.accuracy_warnings = attribute(run, "accuracy_warnings");

  // The model.
  for (const render::BodyTrack& b : r.bodies) {
    if (b.flexible) {
      d.flexible_bodies.emplace_back(b.name, static_cast<int>(b.mesh.mode_translations.cols()));
    } else {
      ++d.rigid_bodies;
    }
  }
  d.joints = static_cast<int>(r.joints.size());
  if (!run.body_masses.empty() && run.body_masses.size() == r.bodies.size()) {
    d.total_mass = 0.0;
    for (const BodyMass& b : run.body_masses) *d.total_mass += b.mass;
  }
  d.momentum = momentum_drift(run);

  add_joint_peaks(run, d);

  // Peak relative deflection over the flexible bodies.
  for (const render::BodyTrack& b : r.bodies) {
    if (!b.flexible || r.sample_count() == 0) continue;
    const Eigen::VectorXd u = max_relative_deflection(r, b);
    if (u.size() == 0) continue;
    Eigen::Index k = 0;
    const double peak = u.maxCoeff(&k);
    if (!d.deflection || peak > *d.deflection) {
      d.deflection = peak;
      d.deflection_time = r.time(k);
      d.deflection_body = b.name;
    }
  }

  // Peak stress over the bodies.
  for (const StressPeak& p : stress_peaks(run)) {
    if (!d.stress || p.value > d.stress->value) d.stress = p;
  }

  // Peak probe acceleration, in g.
  constexpr double kStandardGravity = 9.80665;  // [m/s²]
  for (const AccelerationProbeTrack& probe : run.acceleration_probes) {
    if (probe.acceleration.rows() == 0) continue;
    Eigen::Index k = 0;
    const double peak = probe.acceleration.rowwise().norm().maxCoeff(&k) / kStandardGravity;
    if (!d.acceleration_g || peak > *d.acceleration_g) {
      d.acceleration_g = peak;
      d.acceleration_time = k < r.time.size() ? r.time(k) : 0.0;
      d.acceleration_probe = probe.name;
    }
  }

  // Energy closure.
  if (const std::optional<Series> residual = energy_residual(run); residual && residual->values.size() > 0) {
    d.energy_residual = residual->values.cwiseAbs().maxCoeff();
    for (const Series& s : run.energies) {
      if (s.name == "kinetic" && s.values.size() > 0) d.peak_kinetic = s.values.cwiseAbs().maxCoeff();
    }
  }
  return d;
}

std::vector<SeedFigureLink> seed_figure_links(const ReportContent& content) {
  std::vector<SeedFigureLink> links;
  // Slider-crank (seed Figs. 3–6): the pins' reactions in ground axes, the mode sets' R3 force.
  for (const RunSection& s : content.runs) {
    if (!case_is(s, "slider_crank")) continue;
    for (const char* joint : {"R2", "R3"}) {
      if (const WrittenPlot* p = reaction_plot(s, joint)) {
        links.push_back({"Figs. 4–5", std::string(joint) + " reaction, " + s.label, figure_id(*p)});
      }
    }
    break;
  }
  bool fig6 = false;
  for (const RunSection& s : content.runs) {
    if (fig6 || !case_is(s, "slider_crank")) continue;
    for (const WrittenPlot& p : s.plots) {
      if (p.plot.section != PlotSection::kSelection) continue;
      links.push_back({"Fig. 6", "mode sets' " + p.plot.spec.title.substr(p.plot.spec.title.find(':') + 2),
                       figure_id(p)});
      fig6 = true;
      break;
    }
  }
  const bool slider_crank = std::any_of(content.runs.begin(), content.runs.end(),
                                        [](const RunSection& s) { return case_is(s, "slider_crank"); });
  if (!fig6 && slider_crank) {
    if (const WrittenPlot* p = comparison_plot(content, "R3", {"ground_z", "Fz"})) {
      links.push_back({"Fig. 6", "R3 Z over the runs", figure_id(*p)});
    }
  }
  // Satellite (seed Figs. 7–10): R1's reaction with normal modes, its X with static modes added.
  for (const RunSection& s : content.runs) {
    if (!case_is(s, "satellite_deployment")) continue;
    if (const WrittenPlot* p = reaction_plot(s, "R1")) {
      links.push_back({"Fig. 9", "R1 reaction, " + s.label, figure_id(*p)});
    }
    break;
  }
  const bool satellite = std::any_of(content.runs.begin(), content.runs.end(),
                                     [](const RunSection& s) { return case_is(s, "satellite_deployment"); });
  if (satellite) {
    // The paper's "X" is its own axis; here the overlay of R1's dominant component (the largest
    // peak over the runs).
    const WrittenPlot* dominant = nullptr;
    double largest = -1.0;
    const std::string prefix = "compare_" + file_stem("R1") + "_";
    for (const WrittenPlot& p : content.comparisons) {
      if (p.plot.file.rfind(prefix, 0) != 0) continue;
      double peak = 0.0;
      for (const Curve& c : p.plot.spec.curves) {
        if (c.y.size() > 0) peak = std::max(peak, c.y.cwiseAbs().maxCoeff());
      }
      if (peak > largest) {
        largest = peak;
        dominant = &p;
      }
    }
    if (dominant != nullptr) {
      links.push_back({"Fig. 10", "R1's dominant component over the runs: " + dominant->plot.spec.title,
                       figure_id(*dominant)});
    }
  }
  return links;
}

std::string summary_section(const ReportContent& content) {
  std::string out = "<section id=\"summary\">\n<h2>Summary</h2>\n";
  for (const RunSection& s : content.runs) {
    const RunData& run = *s.run;
    const RunDigest d = digest_run(run);
    out += fmt::format("<div class=\"run-summary\">\n<h3>{} <a href=\"#{}\">{}</a></h3>\n", badge(d.status),
                       s.anchor, markup_escape(s.label));
    // What the status rests on: each accuracy measure against its threshold.
    std::string accuracy;
    for (const AccuracyMeasure& m : d.accuracy) accuracy += (accuracy.empty() ? "" : " · ") + measure_text(m);
    if (!accuracy.empty()) {
      out += "<p class=\"accuracy\">Accuracy (relative; docs/integrators.md): " + accuracy + ".";
      if (!d.accuracy_warnings.empty()) out += " <span class=\"fail\">" + markup_escape(d.accuracy_warnings) + "</span>";
      out += "</p>\n";
    }
    if (d.status == results::layout::status::kFailed && !d.message.empty()) {
      out += "<p class=\"fail\">" + markup_escape(d.message) + "</p>\n";
    }
    out += model_line(run, d);
    out += "<div class=\"summary-grid\">\n<div>" + events_table(run, d) +
           "</div>\n<div>" + peaks_table(d) + "</div>\n</div>\n";
    out += peaks_line(d);
    out += "</div>\n";
  }
  const std::vector<SeedFigureLink> links = seed_figure_links(content);
  if (!links.empty()) {
    out += "<p class=\"seed-figures\">The seed paper's figures: ";
    for (std::size_t k = 0; k < links.size(); ++k) {
      out += fmt::format("{}<a href=\"#{}\">seed {}</a> ({})", k > 0 ? " · " : "", links[k].target,
                         markup_escape(links[k].figure), markup_escape(links[k].what));
    }
    out += ".</p>\n";
  }
  return out + "</section>\n";
}

}  // namespace limber::report
