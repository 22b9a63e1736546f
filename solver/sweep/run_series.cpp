#include "sweep/run_series.h"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "core/error.h"
#include "io/hdf5_file.h"
#include "results/link_name.h"
#include "results/results_layout.h"

namespace limber::sweep {

namespace {

namespace layout = results::layout;

constexpr const char* kAxisNames = "xyz";

// The text name of a group (attribute `name`), else its link name.
std::string display_name(const io::H5Group& group, const std::string& link) {
  try {
    return group.read_string_attribute(results::kNameAttribute);
  } catch (const InputError&) {
    return link;
  }
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
  const io::H5Group root = io::H5Group::open_file(file.string());
  RunSeries series;
  series.status = root.read_string_attribute(layout::kStatusAttribute);
  try {
    series.message = root.read_string_attribute(layout::kMessageAttribute);
  } catch (const InputError&) {
  }
  const std::vector<double> time = root.read_doubles(layout::kTime);
  // A killed run may leave datasets one row apart: take the fewest rows (docs/results-format.md).
  Eigen::Index ns = static_cast<Eigen::Index>(time.size());
  std::vector<std::pair<std::string, std::vector<double>>> blocks;  // name prefix, ns x 3 row-major
  std::vector<std::string> units;
  if (root.has(layout::kJoints)) {
    const io::H5Group joints = root.open_group(layout::kJoints);
    for (const std::string& link : joints.links()) {
      const io::H5Group joint = joints.open_group(link);
      const std::string name = display_name(joint, link);
      blocks.emplace_back(name + " force", joint.read_doubles(layout::joint::kForceJoint));
      units.push_back("N");
      blocks.emplace_back(name + " torque", joint.read_doubles(layout::joint::kTorqueJoint));
      units.push_back("N m");
    }
  }
  if (root.has(layout::kBodies)) {
    const io::H5Group bodies = root.open_group(layout::kBodies);
    for (const std::string& link : bodies.links()) {
      const io::H5Group body = bodies.open_group(link);
      if (!body.has(layout::body::kDeflection)) continue;
      blocks.emplace_back(display_name(body, link) + " deflection", body.read_doubles(layout::body::kDeflection));
      units.push_back("m");
    }
  }
  // Equations of the redundancy groups, as reaction components.
  if (root.has(layout::kConstraints)) {
    const io::H5Group constraints = root.open_group(layout::kConstraints);
    std::vector<std::string> equations;
    if (constraints.has(layout::constraints::kRedundant)) equations = constraints.read_strings(layout::constraints::kRedundant);
    if (constraints.has(layout::constraints::kRedundantWith)) {
      for (const std::string& list : constraints.read_strings(layout::constraints::kRedundantWith)) {
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
    return io::H5Group::open_file(file.string()).read_string_attribute(layout::kStatusAttribute);
  } catch (const InputError&) {
    return "";
  }
}

bool final_status(const std::string& status) {
  return status == "ok" || status == "ok_inaccurate" || status == "failed";
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
