#include "modes_reader.h"

#include "results/h5_reader.h"
#include "results/link_name.h"
#include "results/modes_layout.h"

namespace limber::render {

namespace layout = results::layout;
namespace modes_layout = results::modes_layout;

ModeShapes read_mode_shapes(const std::filesystem::path& modes_file) {
  ModeShapes shapes;
  shapes.file = modes_file;
  const results::H5Reader r(modes_file, "modes file", " (run `limber modes` first)");

  // Root attributes; bodies in case-file order.
  const std::string format = r.string_attribute("/", layout::kFormatAttribute);
  if (format != modes_layout::kFormat) {
    r.fail(std::string("format '") + modes_layout::kFormat + "'", "'" + format + "'");
  }
  shapes.title = r.string_attribute("/", layout::kTitleAttribute, false);
  const std::string body_names = layout::at("", modes_layout::kBodyNames);
  for (const std::string& name : r.strings(body_names)) {
    // The names are text; each body's group is at its link name.
    if (name.empty()) r.fail("non-empty names in " + body_names, "\"\"");
    BodyModeShapes body;
    body.name = name;
    const std::string group =
        layout::at(layout::at("", modes_layout::kBodies), results::link_name(name));
    body.mesh = read_flexible_mesh(r, group);
    const std::string modes = layout::at(group, modes_layout::kModes);
    body.kinds = r.strings(layout::at(modes, modes_layout::modes::kKinds));
    body.labels = r.strings(layout::at(modes, modes_layout::modes::kLabels));
    const auto nm = static_cast<std::size_t>(body.mesh.mode_translations.cols());
    if (body.kinds.size() != nm || body.labels.size() != nm ||
        static_cast<std::size_t>(body.mesh.frequencies_hz.size()) != nm) {
      r.fail(std::to_string(nm) + " kinds, labels and frequencies in " + modes,
             "other counts");
    }
    shapes.bodies.push_back(std::move(body));
  }
  return shapes;
}

}  // namespace limber::render
