#include "sweep/run_series.h"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "core/error.h"
#include "results/results_layout.h"
#include "results/run_records.h"

namespace limber::sweep {

namespace {

namespace layout = results::layout;

constexpr const char* kAxisNames = "xyz";

// The items of a ", "-separated list ("R1.z, R3.z").
std::vector<std::string> split_list(const std::string& with) {
  std::vector<std::string> equations;
  std::size_t start = 0;
  while (start < with.size()) {
    const std::size_t end = std::min(with.find(", ", start), with.size());
    equations.push_back(with.substr(start, end - start));
    start = end + 2;
  }
  return equations;
}

// The unit and kind of a quantity name: "[N]" force, "[N m]" torque, "[m]" deflection.
std::string kind_of(const std::string& name) {
  if (name.find(" force ") != std::string::npos) return "force";
  if (name.find(" torque ") != std::string::npos) return "torque";
  return name.substr(0, name.rfind(" deflection "));  // per body
}

std::string without_unit(const std::string& name) { return name.substr(0, name.rfind(" [")); }

}  // namespace

RunSeries read_run_series(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) throw InputError("expected a results file, got none at '" + file.string() + "'");
  // Poses and series cut to the samples complete in all (a killed run may leave datasets one
  // row apart: docs/results-format.md).
  results::Results run = results::read_results_file(file);
  const results::RunRecords records = results::read_run_records(run);
  RunSeries series;
  series.status = run.status;
  series.message = run.message;
  series.time = run.time;
  const Eigen::Index ns = run.sample_count();
  // Blocks of three columns: each joint's force and torque (joint frame), each body's deflection.
  std::vector<std::pair<std::string, const results::RowMatrix3d*>> blocks;
  std::vector<std::string> units;
  for (const results::JointReactions& joint : records.joints) {
    blocks.emplace_back(joint.name + " force", &joint.force_joint);
    units.push_back("N");
    blocks.emplace_back(joint.name + " torque", &joint.torque_joint);
    units.push_back("N m");
  }
  for (const results::DeflectionProbe& probe : records.deflections) {
    blocks.emplace_back(probe.body + " deflection", &probe.values);
    units.push_back("m");
  }
  for (const results::BodyTrack& body : run.bodies) {
    for (const double f : body.mesh.frequencies_hz) series.f_max_hz = std::max(series.f_max_hz, f);
  }
  // Equations of the redundancy groups, as reaction components: the redundant ones, then those
  // they combine.
  std::vector<std::string> equations;
  for (const auto& pair : records.redundant_equations) equations.push_back(pair.first);
  for (const auto& pair : records.redundant_equations) {
    const std::vector<std::string> with = split_list(pair.second);
    equations.insert(equations.end(), with.begin(), with.end());
  }
  for (const std::string& equation : equations) {
    const std::size_t dot = equation.rfind('.');
    if (dot == std::string::npos) continue;
    const std::string joint = equation.substr(0, dot), component = equation.substr(dot + 1);
    const bool rotation = component.rfind("rot_", 0) == 0;
    const std::string axis = rotation ? component.substr(4) : component;
    series.indeterminate.push_back(fmt::format("{} {} {} [{}]", joint, rotation ? "torque" : "force", axis,
                                               rotation ? "N m" : "N"));
  }
  series.values.resize(ns, 3 * static_cast<Eigen::Index>(blocks.size()));
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    for (int axis = 0; axis < 3; ++axis) {
      series.names.push_back(fmt::format("{} {} [{}]", blocks[b].first, kAxisNames[axis], units[b]));
    }
    series.values.middleCols(3 * static_cast<Eigen::Index>(b), 3) = *blocks[b].second;
  }
  return series;
}

std::string read_run_status(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) return "";
  try {
    return results::read_run_attributes(file).status;
  } catch (const InputError&) {
    return "";
  }
}

bool final_status(const std::string& status) {
  return status == results::layout::status::kOk || status == results::layout::status::kInaccurate || status == results::layout::status::kFailed;
}

std::vector<std::string> default_quantities(const RunSeries& reference) {
  std::map<std::string, double> largest;  // by kind
  std::vector<double> peaks;
  for (std::size_t q = 0; q < reference.names.size(); ++q) {
    if (std::find(reference.indeterminate.begin(), reference.indeterminate.end(), reference.names[q]) !=
        reference.indeterminate.end()) {
      peaks.push_back(0.0);
      continue;
    }
    const auto column = reference.values.col(static_cast<Eigen::Index>(q));
    const double peak = column.size() > 0 ? column.cwiseAbs().maxCoeff() : 0.0;
    peaks.push_back(peak);
    double& most = largest[kind_of(reference.names[q])];
    most = std::max(most, peak);
  }
  // Round-off floor of the reactions: 1e-6 of the largest reaction component (forces in N and
  // torques in N m compared directly). Below it is motion that round-off seeds, e.g. the
  // out-of-plane torques of a planar slider-crank, ~3e-9 of its 2 kN forces.
  const double floor = 1e-6 * std::max(largest["force"], largest["torque"]);
  std::vector<std::string> names;
  for (std::size_t q = 0; q < reference.names.size(); ++q) {
    const std::string kind = kind_of(reference.names[q]);
    if ((kind == "force" || kind == "torque") && peaks[q] < floor) continue;
    const bool indeterminate = std::find(reference.indeterminate.begin(), reference.indeterminate.end(),
                                         reference.names[q]) != reference.indeterminate.end();
    if (!indeterminate && peaks[q] > 0.0 && peaks[q] >= 0.01 * largest[kind_of(reference.names[q])]) {
      names.push_back(reference.names[q]);
    }
  }
  return names;
}

std::vector<std::string> named_quantities(const RunSeries& reference, const std::vector<std::string>& requested) {
  std::vector<std::string> names;
  for (const std::string& wanted : requested) {
    const auto found = std::find_if(reference.names.begin(), reference.names.end(), [&](const std::string& name) {
      return name == wanted || without_unit(name) == wanted;
    });
    if (found == reference.names.end()) {
      throw InputError(fmt::format("--quantities: expected a quantity of the reference run ({}), got '{}'",
                                   fmt::join(reference.names, "; "), wanted));
    }
    names.push_back(*found);
  }
  return names;
}

int quantity_column(const RunSeries& series, const std::string& name) {
  const auto found = std::find(series.names.begin(), series.names.end(), name);
  return found == series.names.end() ? -1 : static_cast<int>(found - series.names.begin());
}

}  // namespace limber::sweep
