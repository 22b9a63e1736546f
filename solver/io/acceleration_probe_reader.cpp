#include "io/acceleration_probe_reader.h"

#include <optional>

#include "io/flexible_mechanism_body.h"

namespace limber::io {

namespace {

AccelerationProbeEntry read_probe(const std::string& name, const YamlValue& entry,
                                  const std::map<std::string, PlacedFlexibleBody>& flexible) {
  entry.allow_only({"marker", "body", "position", "node"});
  multibody::AccelerationProbeSpec spec;
  spec.name = name;
  // At a marker: nothing else.
  if (const auto marker = entry.find("marker")) {
    for (const char* key : {"body", "position", "node"}) {
      if (entry.find(key)) {
        entry.fail("expected either 'marker' or 'body' (with 'position' or 'node') for acceleration probe '" +
                   name + "', got both ('" + key + "')");
      }
    }
    spec.marker = marker->as_string();
    return {spec, marker->where()};
  }
  // On a body: an FE node of a flexible body, a point of a rigid one.
  const YamlValue body = entry.at("body");
  spec.body = body.as_string();
  if (const auto found = flexible.find(spec.body); found != flexible.end()) {
    if (const auto position = entry.find("position")) {
      position->fail("expected 'node' for acceleration probe '" + name + "' on flexible body '" + spec.body +
                     "' (its points are its FE nodes), got 'position'");
    }
    spec.node = read_node(entry.at("node"), *found->second.component);
  } else {
    if (const auto node = entry.find("node")) {
      node->fail("expected 'position' (body frame) for acceleration probe '" + name + "' on '" + spec.body +
                 "', which is not a flexible body, got 'node'");
    }
    if (const auto position = entry.find("position")) spec.p_B = position->as_vector3();
  }
  return {spec, body.where()};
}

}  // namespace

std::vector<AccelerationProbeEntry> read_acceleration_probes(const YamlValue& section,
                                                             const std::map<std::string, PlacedFlexibleBody>& flexible) {
  std::vector<AccelerationProbeEntry> probes;
  for (const auto& [name, entry] : section.entries()) probes.push_back(read_probe(name, entry, flexible));
  return probes;
}

double probe_record_step(const integrate::IntegratorOptions& integrator, double sample_interval) {
  if (integrator.method == integrate::Method::kGeneralizedAlpha) return integrator.step;
  return integrator.max_step > 0.0 ? integrator.max_step : sample_interval;
}

results::ShockSpectrumSettings read_shock_spectrum(const YamlValue* section, const YamlValue& probes,
                                                   double record_step) {
  results::ShockSpectrumSettings settings;
  std::optional<YamlValue> min, max;
  if (section) {
    section->allow_only({"min_frequency", "max_frequency", "q", "window"});
    min = section->find("min_frequency");
    max = section->find("max_frequency");
    if (min) settings.min_frequency_hz = min->as_positive();
    if (max) settings.max_frequency_hz = max->as_positive();
    if (const auto q = section->find("q")) settings.q = q->as_positive();
    if (const auto window = section->find("window")) settings.window_seconds = window->as_positive();
    if (min && max && settings.max_frequency_hz < settings.min_frequency_hz) {
      max->fail("expected max_frequency >= min_frequency for 'max_frequency', got '" + max->node().Scalar() + "'");
    }
  }
  // The band the run's steps support.
  try {
    results::shock_frequency_grid(settings, record_step);
  } catch (const InputError& e) {
    const double limit = results::srs_frequency_limit(record_step);
    const YamlValue& where = max && settings.max_frequency_hz > limit ? *max : min ? *min : probes;
    where.fail(e.message() + " (run: `step` for galpha, `max_step` for ida)");
  }
  return settings;
}

}  // namespace limber::io
