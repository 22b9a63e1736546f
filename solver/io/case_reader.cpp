#include "io/case_reader.h"

#include <algorithm>
#include <filesystem>
#include <string_view>

#include "core/input_file.h"
#include "io/case_library.h"
#include "io/flexible_body_reader.h"
#include "io/mechanism_builder.h"
#include "io/mechanism_reader.h"
#include "io/yaml_reader.h"

namespace limber::io {

namespace {

// The top-level sections a case file may hold (extend here, with a reader below).
// The mechanism sections are those of kMechanismSections (mechanism_reader.h).
const std::initializer_list<std::string_view> kCaseSections = {
    "title",  "materials", "sections", "flexible_bodies", "gravity", "bodies",
    "markers", "joints",   "drivers",  "forces",          "acceleration_probes", "shock_spectrum",
    "linearize", "assembly", "run", "axis_names"};
// A case may also name a `base` case whose sections it takes where it has none: a variant
// (another mode set, other settings) without copying the mechanism.
const std::initializer_list<std::string_view> kCaseSectionsAndBase = {
    "title",  "materials", "sections", "flexible_bodies", "gravity", "bodies",
    "markers", "joints",   "drivers",  "forces",          "acceleration_probes", "shock_spectrum",
    "linearize", "assembly", "run", "base", "axis_names"};

// A case's `base`: the file (relative to the case's folder) whose sections this case takes
// where it has none of its own. One level only: a base has no base.
YamlValue with_base_case(const YamlValue& root) {
  const auto base = root.find("base");
  if (!base) return root;
  const std::filesystem::path path = base->as_existing_file("a case file for 'base'");
  const YamlValue base_root = YamlDocument::load_file(path.string()).root();
  if (!base_root.is_map()) base_root.fail("expected a case (a map of sections) as a base");
  base_root.allow_only(kCaseSections);
  return root.with_base(base_root);
}

// `title`: text of at most 1024 bytes (results.h5 and modes.h5 keep it in an HDF5 attribute,
// which holds at most 64 KiB in their 1.8 file format; reports show it as a heading).
std::string read_title(const YamlValue& value) {
  constexpr std::size_t kMaxTitleBytes = 1024;
  std::string title = value.as_string();
  if (title.size() > kMaxTitleBytes) {
    value.fail("expected a title of at most " + std::to_string(kMaxTitleBytes) + " bytes, got '" +
               abbreviated(title) + "'");
  }
  return title;
}

// `axis_names`: three distinct short names of the ground axes x, y, z (reports name the
// ground-axes components with them).
std::vector<std::string> read_axis_names(const YamlValue& value) {
  const std::vector<YamlValue> items = value.items();
  if (items.size() != 3) {
    value.fail("expected three names for 'axis_names' (ground x, y, z), got " +
               std::to_string(items.size()));
  }
  std::vector<std::string> names;
  for (const YamlValue& item : items) {
    const std::string name = item.as_string();
    if (name.size() > 24 || name.find(',') != std::string::npos ||
        std::find(names.begin(), names.end(), name) != names.end()) {
      item.fail("expected a distinct name of at most 24 characters without a comma, got '" +
                name + "'");
    }
    names.push_back(name);
  }
  return names;
}

Case read_case(const YamlDocument& document) {
  if (document.root().is_null()) {
    document.root().fail("expected a case (a map of sections), got an empty file");
  }
  document.root().allow_only(kCaseSectionsAndBase);
  const YamlValue root = with_base_case(document.root());

  Case result;
  result.file = document.file();
  result.title = std::filesystem::path(document.file()).stem().string();
  if (auto title = root.find("title")) result.title = read_title(*title);
  if (auto axes = root.find("axis_names")) result.axis_names = read_axis_names(*axes);

  // Shared definitions first, whatever their place in the file, then what refers to them.
  const CaseLibrary library = CaseLibrary::read(root);
  if (auto bodies = root.find("flexible_bodies")) {
    for (const auto& [name, entry] : bodies->entries()) {
      result.flexible_bodies.push_back(read_flexible_body(name, entry, library));
    }
  }
  // The mechanism as data, then its references checked (no modes needed).
  if (has_mechanism(root)) {
    result.mechanism = read_mechanism(root, result.flexible_bodies);
    check_mechanism(*result.mechanism, result.flexible_bodies);
  }
  return result;
}

}  // namespace

Case read_case_file(const std::string& path) { return read_case(YamlDocument::load_file(path)); }

Case read_case_text(const std::string& text, const std::string& file) {
  return read_case(YamlDocument::load_text(text, file));
}

}  // namespace limber::io
