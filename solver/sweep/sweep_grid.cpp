#include "sweep/sweep_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

#include <fmt/format.h>

#include "core/error.h"
#include "run/run_driver.h"

namespace limber::sweep {

namespace {

constexpr const char* kAxes = "integrator, rtol, step, modes";
// A tight IDA reference stays a decade above the tightest rtol `limber run` accepts.
constexpr double kTightestReferenceRtol = 10.0 * run::kMinimumRtol;

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end - start));
    if (end == std::string::npos) return parts;
    start = end + 1;
  }
}

[[noreturn]] void bad(const std::string& argument, const std::string& expected, const std::string& got) {
  throw InputError(fmt::format("--over '{}': expected {}, got {}", argument, expected, got));
}

double parse_double(const std::string& argument, const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value)) {
    bad(argument, "a number", "'" + text + "'");
  }
  return value;
}

int parse_int(const std::string& argument, const std::string& text) {
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || end != text.c_str() + text.size() || value < 0 || value > 100000) {
    bad(argument, "a whole number of modes >= 0", "'" + text + "'");
  }
  return static_cast<int>(value);
}

std::string method_name(integrate::Method method) {
  return method == integrate::Method::kIda ? "ida" : "galpha";
}

}  // namespace

GridSpec parse_over(const std::vector<std::string>& arguments, const CaseDefaults& defaults) {
  GridSpec spec;
  std::set<std::string> seen;
  const auto axis = [&](const std::string& argument, const std::string& name, const std::vector<std::string>& values) {
    if (name == "mesh") {
      bad(argument, std::string("an axis among ") + kAxes,
          "'mesh' (mesh density is not a variable of a case yet: run the case files of each mesh)");
    }
    if (name != "integrator" && name != "rtol" && name != "step" && name != "modes") {
      bad(argument, std::string("an axis among ") + kAxes, "'" + name + "'");
    }
    if (!seen.insert(name).second) bad(argument, "each axis once", "'" + name + "' again");
    if (name == "modes" && defaults.normal_modes == 0) {
      bad(argument, "a case with flexible bodies for the modes axis", "a case without one");
    }
    if (values.empty()) {
      // Default values.
      if (name == "integrator") spec.integrators = {"ida", "galpha"};
      if (name == "rtol") spec.rtols = {1e-3, 1e-4, 1e-5, 1e-6};
      if (name == "step") {
        for (double factor : {4.0, 2.0, 1.0, 0.5}) spec.steps.push_back(factor * defaults.step);
      }
      if (name == "modes") {
        const int n = defaults.normal_modes;
        spec.modes = {std::max(1, (n + 1) / 2), n, 2 * n};
        spec.modes.erase(std::unique(spec.modes.begin(), spec.modes.end()), spec.modes.end());
      }
      return;
    }
    for (const std::string& value : values) {
      if (name == "integrator") {
        if (value != "ida" && value != "galpha") bad(argument, "integrator ida or galpha", "'" + value + "'");
        spec.integrators.push_back(value);
      } else if (name == "rtol") {
        const double rtol = parse_double(argument, value);
        if (!(rtol >= run::kMinimumRtol && rtol < 1.0)) {
          bad(argument, fmt::format("rtol in [{:g}, 1)", run::kMinimumRtol), "'" + value + "'");
        }
        spec.rtols.push_back(rtol);
      } else if (name == "step") {
        const double step = parse_double(argument, value);
        if (!(step > 0.0)) bad(argument, "step > 0 [s]", "'" + value + "'");
        spec.steps.push_back(step);
      } else {
        spec.modes.push_back(parse_int(argument, value));
      }
    }
  };
  if (arguments.empty()) throw InputError(fmt::format("expected --over with at least one axis among {}", kAxes));
  for (const std::string& argument : arguments) {
    const std::size_t equals = argument.find('=');
    if (equals == std::string::npos) {
      for (const std::string& name : split(argument, ',')) axis(argument, name, {});
      continue;
    }
    const std::vector<std::string> values = split(argument.substr(equals + 1), ',');
    for (const std::string& value : values) {
      if (value.empty()) bad(argument, "a comma-separated list of values", "an empty value");
    }
    axis(argument, argument.substr(0, equals), values);
  }
  // A tolerance or step axis must have points that use it.
  const std::vector<std::string> integrators =
      spec.integrators.empty() ? std::vector<std::string>{method_name(defaults.method)} : spec.integrators;
  const auto uses = [&](const char* name) {
    return std::find(integrators.begin(), integrators.end(), name) != integrators.end();
  };
  if (!spec.rtols.empty() && !uses("ida")) {
    throw InputError("--over: expected integrator ida in the grid for the rtol axis (IDA's tolerance), got " +
                     fmt::format("{}", fmt::join(integrators, ", ")));
  }
  if (!spec.steps.empty() && !uses("galpha")) {
    throw InputError("--over: expected integrator galpha in the grid for the step axis (generalized-alpha's "
                     "step), got " + fmt::format("{}", fmt::join(integrators, ", ")));
  }
  return spec;
}

std::string SweepPoint::name() const {
  std::string text = nonlinear ? "nonlinear_" + integrator : integrator;
  if (rtol) text += fmt::format("_rtol{:g}", *rtol);
  if (atol) text += fmt::format("_atol{:g}", *atol);
  if (step) text += fmt::format("_step{:g}", *step);
  if (modes) text += fmt::format("_m{}", *modes);
  return text;
}

std::string SweepPoint::curve() const {
  return modes ? fmt::format("{}, {} modes", integrator, *modes) : integrator;
}

std::vector<std::string> SweepPoint::run_options() const {
  std::vector<std::string> options;
  if (nonlinear) options = {"--formulation", "nonlinear"};
  options.insert(options.end(), {"--integrator", integrator});
  // Shortest text that reads back exactly: the child runs exactly this setting.
  if (rtol) options.insert(options.end(), {"--rtol", fmt::format("{}", *rtol)});
  if (atol) options.insert(options.end(), {"--atol", fmt::format("{}", *atol)});
  if (step) options.insert(options.end(), {"--step", fmt::format("{}", *step)});
  if (modes) options.insert(options.end(), {"--modes", std::to_string(*modes)});
  return options;
}

std::vector<SweepPoint> expand_grid(const GridSpec& spec, const CaseDefaults& defaults) {
  const std::vector<std::string> integrators =
      spec.integrators.empty() ? std::vector<std::string>{method_name(defaults.method)} : spec.integrators;
  std::vector<std::optional<int>> modes;
  for (int m : spec.modes) modes.emplace_back(m);
  if (modes.empty()) modes.emplace_back();
  std::vector<SweepPoint> points;
  std::set<std::string> names;
  for (const std::string& integrator : integrators) {
    const bool ida = integrator == "ida";
    const std::vector<double>& values = ida ? spec.rtols : spec.steps;
    const std::vector<double> settings =
        values.empty() ? std::vector<double>{ida ? defaults.rtol : defaults.step} : values;
    for (double setting : settings) {
      for (const std::optional<int>& m : modes) {
        SweepPoint point;
        point.integrator = integrator;
        (ida ? point.rtol : point.step) = setting;
        point.modes = m;
        // A value listed twice is one point.
        if (names.insert(point.name()).second) points.push_back(point);
      }
    }
  }
  return points;
}

SweepPoint tight_reference(const std::vector<SweepPoint>& points, const CaseDefaults& defaults, double case_atol) {
  SweepPoint reference;
  std::optional<double> smallest_step, smallest_rtol;
  for (const SweepPoint& point : points) {
    if (point.step) smallest_step = std::min(smallest_step.value_or(*point.step), *point.step);
    if (point.rtol) smallest_rtol = std::min(smallest_rtol.value_or(*point.rtol), *point.rtol);
    if (point.modes) reference.modes = std::max(reference.modes.value_or(0), *point.modes);
  }
  if (smallest_step || !smallest_rtol) {
    reference.integrator = "galpha";
    reference.step = smallest_step.value_or(defaults.step) / 8.0;
  } else {
    reference.integrator = "ida";
    reference.rtol = std::max(*smallest_rtol / 100.0, kTightestReferenceRtol);
    reference.atol = std::max(case_atol / 100.0, run::kMinimumAtol);
  }
  return reference;
}

SweepPoint nonlinear_reference(const std::vector<SweepPoint>& points, const CaseDefaults& defaults) {
  SweepPoint reference;
  reference.nonlinear = true;
  reference.integrator = "galpha";
  reference.step = defaults.step;
  for (const SweepPoint& point : points) {
    if (point.step) reference.step = std::min(*reference.step, *point.step);
  }
  return reference;
}

}  // namespace limber::sweep
