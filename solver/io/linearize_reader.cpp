#include "io/linearize_reader.h"

#include <algorithm>
#include <iterator>
#include <optional>
#include <string_view>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/names.h"

namespace limber::io {

namespace {

using multibody::LinearInputKind;
using multibody::LinearOutputKind;

constexpr std::pair<std::string_view, LinearInputKind> kInputKeys[] = {
    {"force", LinearInputKind::kForce},
    {"torque", LinearInputKind::kTorque},
    {"rsda", LinearInputKind::kRsdaTorque},
    {"driver", LinearInputKind::kDriverEffort}};
constexpr std::pair<std::string_view, LinearOutputKind> kOutputKeys[] = {
    {"position", LinearOutputKind::kPosition},
    {"velocity", LinearOutputKind::kVelocity},
    {"acceleration", LinearOutputKind::kAcceleration},
    {"rotation", LinearOutputKind::kRotation},
    {"angular_velocity", LinearOutputKind::kAngularVelocity},
    {"angular_acceleration", LinearOutputKind::kAngularAcceleration},
    {"reaction_force", LinearOutputKind::kReactionForce},
    {"reaction_torque", LinearOutputKind::kReactionTorque}};

bool is_reaction(LinearOutputKind kind) {
  return kind == LinearOutputKind::kReactionForce || kind == LinearOutputKind::kReactionTorque;
}

// The one quantity key of `entry` among `keys`: its kind and value.
template <typename Kind, std::size_t N>
std::pair<Kind, YamlValue> quantity(const std::string& what, const std::string& name, const YamlValue& entry,
                                    const std::pair<std::string_view, Kind> (&keys)[N]) {
  std::optional<std::pair<Kind, YamlValue>> found;
  std::vector<std::string_view> names;
  for (const auto& key : keys) names.push_back(key.first);
  // In file order: the second quantity is the error.
  for (const auto& [key, value] : entry.entries()) {
    const std::string_view wanted = key;  // a structured binding cannot be captured before C++20
    const auto* known =
        std::find_if(std::begin(keys), std::end(keys), [wanted](const auto& k) { return k.first == wanted; });
    if (known == std::end(keys)) continue;
    if (found) {
      value.fail(fmt::format("expected one quantity for {} '{}', got a second ('{}')", what, name, key));
    }
    found.emplace(known->second, value);
  }
  if (!found) entry.fail(fmt::format("expected one of {} for {} '{}', got none", fmt::join(names, ", "), what, name));
  return *found;
}

// `axes: ground | <local>` (default ground): local is "marker" for a marker's channels and
// "joint" for a joint's reaction (its marker j's axes).
multibody::ChannelAxes read_axes(const YamlValue& entry, const std::string& local = "marker") {
  const auto axes = entry.find("axes");
  if (!axes) return multibody::ChannelAxes::kGround;
  return axes->as_choice({"ground", local}) == local ? multibody::ChannelAxes::kMarker
                                                     : multibody::ChannelAxes::kGround;
}

// The name in `value`, which must be one of `names` (listed in the message).
std::string known_name(const YamlValue& value, const std::vector<std::string>& names, const std::string& what) {
  const std::string name = value.as_string();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    value.fail(fmt::format("expected {} of the case ({}), got '{}'", what,
                           names.empty() ? std::string("there are none") : fmt::format("{}", fmt::join(names, ", ")),
                           name));
  }
  return name;
}

LinearInputEntry read_input(const std::string& name, const YamlValue& entry, const LinearizeTargets& targets) {
  entry.allow_only({"force", "torque", "rsda", "driver", "axes"});
  const auto [kind, value] = quantity("linearize input", name, entry, kInputKeys);
  LinearInputEntry input;
  input.spec.name = name;
  input.spec.kind = kind;
  input.where = value.where();
  // One channel along a coordinate: no axes to choose.
  if (kind == LinearInputKind::kRsdaTorque || kind == LinearInputKind::kDriverEffort) {
    const bool rsda = kind == LinearInputKind::kRsdaTorque;
    if (const auto axes = entry.find("axes")) {
      axes->fail(rsda ? "expected no 'axes' for the RSDA torque '" + name + "' (it acts about the RSDA's axis), got one"
                      : "expected no 'axes' for the driver effort '" + name + "' (it acts along the driver's coordinate), got one");
    }
    input.target = rsda ? known_name(value, targets.rsdas, "an rsda force") : known_name(value, targets.drivers, "a driver");
    return input;
  }
  input.spec.axes = read_axes(entry);
  input.target = known_name(value, targets.markers, "a marker");
  return input;
}

LinearOutputEntry read_output(const std::string& name, const YamlValue& entry, const LinearizeTargets& targets) {
  entry.allow_only({"position", "velocity", "acceleration", "rotation", "angular_velocity", "angular_acceleration",
                    "reaction_force", "reaction_torque", "axes"});
  const auto [kind, value] = quantity("linearize output", name, entry, kOutputKeys);
  LinearOutputEntry output;
  output.spec.name = name;
  output.spec.kind = kind;
  output.where = value.where();
  if (is_reaction(kind)) {
    output.spec.axes = read_axes(entry, "joint");
    output.target = known_name(value, targets.joints, "a joint");
    return output;
  }
  output.spec.axes = read_axes(entry);
  output.target = known_name(value, targets.markers, "a marker");
  return output;
}

int marker_index(const multibody::Model& model, const std::string& name, const SourceLocation& where) {
  for (std::size_t m = 0; m < model.markers.size(); ++m) {
    if (model.markers[m].name == name) return static_cast<int>(m);
  }
  throw InputError(fmt::format("expected a marker of the model, got '{}'", name), where);
}

}  // namespace

LinearizeCase read_linearize(const YamlValue& section, const LinearizeTargets& targets) {
  section.allow_only({"inputs", "outputs"});
  LinearizeCase result;
  if (const auto inputs = section.find("inputs")) {
    for (const auto& [name, entry] : inputs->entries()) {
      check_name_text("linearize input", name, entry.key_where());
      result.inputs.push_back(read_input(name, entry, targets));
    }
  }
  if (const auto outputs = section.find("outputs")) {
    for (const auto& [name, entry] : outputs->entries()) {
      check_name_text("linearize output", name, entry.key_where());
      result.outputs.push_back(read_output(name, entry, targets));
    }
  }
  return result;
}

std::vector<multibody::LinearInput> linear_inputs(const LinearizeCase& section, const multibody::Model& model) {
  std::vector<multibody::LinearInput> inputs;
  for (const LinearInputEntry& entry : section.inputs) {
    multibody::LinearInput input = entry.spec;
    if (input.kind == LinearInputKind::kRsdaTorque) {
      for (std::size_t k = 0; k < model.forces.size(); ++k) {
        if (std::holds_alternative<multibody::Rsda>(model.forces[k]) && multibody::force_name(model.forces[k]) == entry.target) {
          input.force = static_cast<int>(k);
        }
      }
      if (input.force < 0) throw InputError("expected an rsda force of the model, got '" + entry.target + "'", entry.where);
    } else if (input.kind == LinearInputKind::kDriverEffort) {
      input.driver = model.find_driver(entry.target);
      if (input.driver < 0) throw InputError("expected a driver of the model, got '" + entry.target + "'", entry.where);
    } else {
      input.marker = marker_index(model, entry.target, entry.where);
    }
    inputs.push_back(input);
  }
  return inputs;
}

std::vector<multibody::LinearOutput> linear_outputs(const LinearizeCase& section, const multibody::Model& model) {
  std::vector<multibody::LinearOutput> outputs;
  for (const LinearOutputEntry& entry : section.outputs) {
    multibody::LinearOutput output = entry.spec;
    if (is_reaction(output.kind)) {
      for (std::size_t k = 0; k < model.joints.size(); ++k) {
        if (model.joints[k].name == entry.target) output.joint = static_cast<int>(k);
      }
      if (output.joint < 0) throw InputError("expected a joint of the model, got '" + entry.target + "'", entry.where);
    } else {
      output.marker = marker_index(model, entry.target, entry.where);
    }
    outputs.push_back(output);
  }
  return outputs;
}

}  // namespace limber::io
