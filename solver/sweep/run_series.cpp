#include "sweep/run_series.h"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "core/error.h"
#include "results/h5_reader.h"
#include "results/link_name.h"
#include "results/results_layout.h"

namespace limber::sweep {

namespace {

namespace layout = results::layout;

constexpr const char* kAxisNames = "xyz";

// Every row of a dataset, row-major.
std::vector<double> all_rows(const results::H5Reader& file, const std::string& path) {
  const std::vector<hsize_t> dims = file.dims(path);
  return file.read<double>(path, H5T_NATIVE_DOUBLE, dims.empty() ? 1 : dims[0]);
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
  const results::H5Reader root(file, "results file", "");
  RunSeries series;
  series.status = root.string_attribute("/", layout::kStatusAttribute);
  series.message = root.string_attribute("/", layout::kMessageAttribute, false);
  const std::vector<double> time = all_rows(root, layout::kTime);
  // A killed run may leave datasets one row apart: take the fewest rows (docs/results-format.md).
  Eigen::Index ns = static_cast<Eigen::Index>(time.size());
  std::vector<std::pair<std::string, std::vector<double>>> blocks;  // name prefix, ns x 3 row-major
  std::vector<std::string> units;
  // Groups are listed by link name and shown by name (the link in files older than names).
  for (const std::string& link : root.members(layout::kJoints)) {
    const std::string joint = layout::at(layout::kJoints, link);
    const std::string name = root.string_attribute(joint, results::kNameAttribute, false, link);
    blocks.emplace_back(name + " force", all_rows(root, layout::at(joint, layout::joint::kForceJoint)));
    units.push_back("N");
    blocks.emplace_back(name + " torque", all_rows(root, layout::at(joint, layout::joint::kTorqueJoint)));
    units.push_back("N m");
  }
  for (const std::string& link : root.members(layout::kBodies)) {
    const std::string body = layout::at(layout::kBodies, link);
    const std::string frequencies = layout::at(layout::at(body, layout::body::kModes), layout::modes::kFrequenciesHz);
    if (root.exists(frequencies)) {
      for (const double f : all_rows(root, frequencies)) series.f_max_hz = std::max(series.f_max_hz, f);
    }
    const std::string deflection = layout::at(body, layout::body::kDeflection);
    if (!root.exists(deflection)) continue;
    const std::string name = root.string_attribute(body, results::kNameAttribute, false, link);
    blocks.emplace_back(name + " deflection", all_rows(root, deflection));
    units.push_back("m");
  }
  // Equations of the redundancy groups, as reaction components.
  {
    const std::string redundant = layout::at(layout::kConstraints, layout::constraints::kRedundant);
    const std::string with = layout::at(layout::kConstraints, layout::constraints::kRedundantWith);
    std::vector<std::string> equations;
    if (root.exists(redundant)) equations = root.strings(redundant);
    if (root.exists(with)) {
      for (const std::string& list : root.strings(with)) {
        std::size_t start = 0;
        while (start < list.size()) {
          const std::size_t end = std::min(list.find(", ", start), list.size());
          equations.push_back(list.substr(start, end - start));
          start = end + 2;
        }
      }
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
  }
  for (const auto& block : blocks) ns = std::min(ns, static_cast<Eigen::Index>(block.second.size() / 3));
  series.time = Eigen::Map<const Eigen::VectorXd>(time.data(), ns);
  series.values.resize(ns, 3 * static_cast<Eigen::Index>(blocks.size()));
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    for (int axis = 0; axis < 3; ++axis) {
      series.names.push_back(fmt::format("{} {} [{}]", blocks[b].first, kAxisNames[axis], units[b]));
      for (Eigen::Index k = 0; k < ns; ++k) {
        const std::size_t at = 3 * static_cast<std::size_t>(k) + static_cast<std::size_t>(axis);
        series.values(k, 3 * static_cast<Eigen::Index>(b) + axis) = blocks[b].second[at];
      }
    }
  }
  return series;
}

std::string read_run_status(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) return "";
  try {
    return results::H5Reader(file, "results file", "").string_attribute("/", layout::kStatusAttribute);
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
