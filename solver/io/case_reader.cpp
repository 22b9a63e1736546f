#include "io/case_reader.h"

#include <filesystem>
#include <string_view>

#include "io/case_library.h"
#include "io/flexible_body_reader.h"
#include "io/mechanism_reader.h"
#include "io/yaml_reader.h"

namespace limber::io {

namespace {

// The top-level sections a case file may hold (extend here, with a reader below).
// The mechanism sections are those of kMechanismSections (mechanism_reader.h).
const std::initializer_list<std::string_view> kCaseSections = {
    "title",  "materials", "sections", "flexible_bodies", "gravity", "bodies",
    "markers", "joints",   "drivers",  "forces",          "assembly", "run"};

Case read_case(const YamlDocument& document) {
  const YamlValue root = document.root();
  if (root.is_null()) root.fail("expected a case (a map of sections), got an empty file");
  root.allow_only(kCaseSections);

  Case result;
  result.file = document.file();
  result.title = std::filesystem::path(document.file()).stem().string();
  if (auto title = root.find("title")) result.title = title->as_string();

  // Shared definitions first, whatever their place in the file, then what refers to them.
  const CaseLibrary library = CaseLibrary::read(root);
  if (auto bodies = root.find("flexible_bodies")) {
    for (const auto& [name, entry] : bodies->entries()) {
      result.flexible_bodies.push_back(read_flexible_body(name, entry, library));
    }
  }
  if (has_mechanism(root)) result.mechanism = read_mechanism(root, result.flexible_bodies);
  return result;
}

}  // namespace

Case read_case_file(const std::string& path) { return read_case(YamlDocument::load_file(path)); }

Case read_case_text(const std::string& text, const std::string& file) {
  return read_case(YamlDocument::load_text(text, file));
}

}  // namespace limber::io
