#include "modes_reader.h"

#include "h5_reader.h"
#include "results/link_name.h"

namespace limber::render {

ModeShapes read_mode_shapes(const std::filesystem::path& modes_file) {
  ModeShapes shapes;
  shapes.file = modes_file;
  const H5Reader r(modes_file, "modes file", " (run `limber modes` first)");

  // Root attributes; bodies in case-file order.
  const std::string format = r.string_attribute("/", "format");
  if (format != "limber-modes") r.fail("format 'limber-modes'", "'" + format + "'");
  shapes.title = r.string_attribute("/", "title", false);
  for (const std::string& name : r.strings("/body_names")) {
    // The names are text; each body's group is at its link name.
    if (name.empty()) r.fail("non-empty names in /body_names", "\"\"");
    BodyModeShapes body;
    body.name = name;
    const std::string group = "/bodies/" + results::link_name(name);
    body.mesh = read_flexible_mesh(r, group);
    body.kinds = r.strings(group + "/modes/kinds");
    body.labels = r.strings(group + "/modes/labels");
    const auto nm = static_cast<std::size_t>(body.mesh.mode_translations.cols());
    if (body.kinds.size() != nm || body.labels.size() != nm ||
        static_cast<std::size_t>(body.mesh.frequencies_hz.size()) != nm) {
      r.fail(std::to_string(nm) + " kinds, labels and frequencies in " + group + "/modes",
             "other counts");
    }
    shapes.bodies.push_back(std::move(body));
  }
  return shapes;
}

}  // namespace limber::render
