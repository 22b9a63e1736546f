#include "run/settings_overrides.h"

#include <fmt/format.h>

#include "core/error.h"

namespace limber::run {

io::RunSettings SettingsOverrides::apply(io::RunSettings settings) const {
  integrate::IntegratorOptions& options = settings.integrator;
  if (integrator == "ida") {
    options.method = integrate::Method::kIda;
  } else if (integrator == "galpha") {
    options.method = integrate::Method::kGeneralizedAlpha;
  } else if (!integrator.empty()) {
    throw InputError(fmt::format("expected integrator ida or galpha, got '{}'", integrator));
  }
  if (rtol) options.rtol = *rtol;
  if (atol) options.atol = *atol;
  if (step) options.step = *step;
  if (t_end) settings.t_end = *t_end;
  if (max_wall) options.max_wall_seconds = *max_wall;
  if (start == "assembly") {
    settings.start = io::StartKind::kAssembly;
  } else if (start == "statics") {
    settings.start = io::StartKind::kStatics;
  } else if (!start.empty()) {
    throw InputError(fmt::format("expected start assembly or statics, got '{}'", start));
  }
  if (peak_window) settings.peak_window = *peak_window;
  return settings;
}

io::ModeOverrides normal_mode_overrides(const io::Case& input, std::optional<int> modes) {
  io::ModeOverrides overrides;
  if (!modes) return overrides;
  if (*modes < 0) throw InputError(fmt::format("expected --modes >= 0, got {}", *modes));
  for (const io::FlexibleBodyCase& body : input.flexible_bodies) {
    modal::ModeRequest request = body.request;
    request.normal_count = *modes;
    request.max_frequency_hz.reset();
    overrides[body.name] = request;
  }
  return overrides;
}

}  // namespace limber::run
