#include "shock_plots.h"

#include "file_stem.h"
#include "results/shock_spectra.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>

namespace limber::report {

namespace {

constexpr std::array<const char*, 3> kAxisLabels{"a_x", "a_y", "a_z"};

// The acceleration history of one probe [m/s²], its three ground-axis components.
NamedPlot acceleration_plot(const RunData& run, const AccelerationProbeTrack& probe, const std::string& prefix) {
  const Eigen::VectorXd& t = run.results.time;
  std::vector<Curve> curves;
  for (int c = 0; c < 3; ++c) curves.push_back({kAxisLabels[static_cast<std::size_t>(c)], t, probe.acceleration.col(c)});
  const std::string where = probe.node >= 0 ? fmt::format("FE node {} of {}", probe.node, probe.body) : "a point of " + probe.body;
  return {PlotSection::kShock, prefix + "acceleration_" + render::file_stem(probe.name) + ".png",
          "Absolute acceleration of probe " + probe.name + " (" + where + ", case key acceleration_probes), "
          "components in the ground axes " + ground_axes_note(run) + "; inertial, gravity not subtracted.",
          {"Acceleration of " + probe.name, "time [s]", "acceleration [m/s^2]", curves, false}};
}

// The spectrum of one probe [g], one curve per window: the largest of the axes per frequency.
NamedPlot spectrum_plot(const ShockSpectraData& spectra, const ProbeSpectrumData& probe, const std::string& prefix) {
  std::vector<Curve> curves;
  for (std::size_t w = 0; w < probe.maximax.size(); ++w) {
    const std::array<Eigen::VectorXd, 3>& axes = probe.maximax[w];
    const Eigen::VectorXd envelope = axes[0].cwiseMax(axes[1]).cwiseMax(axes[2]) / results::kStandardGravity;
    // A logarithmic axis has no place for 0 (a window without motion).
    if (envelope.size() == 0 || envelope.minCoeff() <= 0.0) continue;
    curves.push_back({shock_window_label(spectra, w), spectra.frequency_hz, envelope});
  }
  PlotSpec spec{"Shock response spectrum of " + probe.name, "natural frequency [Hz]",
                "peak absolute acceleration [g]", curves, true};
  spec.log_x = true;
  return {PlotSection::kShock, prefix + "srs_" + render::file_stem(probe.name) + ".png",
          fmt::format("Maximax absolute-acceleration shock response spectrum of probe {} (Q = {:g}, 1/6-octave "
                      "natural frequencies, Smallwood's ramp-invariant filter; docs/shock-response-spectrum.md): "
                      "per window, the largest of the three ground axes at each frequency; event windows last "
                      "{:g} s or up to the next event. Per-axis values: srs_{}.csv in the run directory.",
                      probe.name, spectra.q, spectra.window_length, probe.name),
          spec};
}

}  // namespace

std::string shock_window_label(const ShockSpectraData& spectra, std::size_t w) {
  const std::string& name = spectra.window_names[w];
  const double start = spectra.window_start[w], end = spectra.window_end[w];
  const std::string span = fmt::format("({:.4g}-{:.4g} s)", start, end);
  return name.rfind("latch ", 0) == 0 ? fmt::format("{} at {:.4g} s {}", name, start, span) : name + " " + span;
}

std::vector<NamedPlot> shock_plots(const RunData& run, const std::string& prefix) {
  std::vector<NamedPlot> plots;
  for (const AccelerationProbeTrack& probe : run.acceleration_probes) {
    if (probe.acceleration.rows() != run.results.time.size() || probe.acceleration.rows() == 0) continue;
    plots.push_back(acceleration_plot(run, probe, prefix));
    if (!run.shock_spectra) continue;
    const auto found = std::find_if(run.shock_spectra->probes.begin(), run.shock_spectra->probes.end(),
                                    [&](const ProbeSpectrumData& p) { return p.name == probe.name; });
    if (found != run.shock_spectra->probes.end()) plots.push_back(spectrum_plot(*run.shock_spectra, *found, prefix));
  }
  return plots;
}

}  // namespace limber::report
