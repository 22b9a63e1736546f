#include "xdmf_description.h"

#include "xdmf_layout.h"

#include "core/markup_escape.h"

#include <fmt/core.h>

namespace limber::render {
namespace {

// A DataItem naming the whole dataset `path` of scene.h5 with `dimensions`.
std::string item(const std::string& path, const std::string& dimensions, bool integer = false) {
  return fmt::format("<DataItem Dimensions=\"{}\" NumberType=\"{}\" Precision=\"{}\" Format=\"HDF\">{}:{}</DataItem>",
                     dimensions, integer ? "Int" : "Float", integer ? 4 : 8, xdmf::kFileName, path);
}

std::string attribute(const char* name, bool vector, const char* center, const std::string& item) {
  return fmt::format("   <Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"{}\">{}</Attribute>\n", name,
                     vector ? "Vector" : "Scalar", center, item);
}

// The grid at sample k, time t.
std::string sample_grid(const XdmfGrid& grid, long k, double t) {
  const std::string np3 = fmt::format("{} 3", grid.points), np = std::to_string(grid.points);
  const std::string nc = std::to_string(grid.cells);
  // 17 significant digits: the times read back exactly.
  std::string text = fmt::format("  <Grid Name=\"t{}\" GridType=\"Uniform\">\n   <Time Value=\"{:.17g}\"/>\n",
                                 xdmf::sample_name(k), t);
  text += fmt::format("   <Topology TopologyType=\"Mixed\" NumberOfElements=\"{}\">{}</Topology>\n", grid.cells,
                      item(xdmf::kTopology, std::to_string(grid.topology), true));
  text += "   <Geometry GeometryType=\"XYZ\">" + item(xdmf::sample_path(k, xdmf::sample::kPoints), np3) +
          "</Geometry>\n";
  for (const char* name : {xdmf::sample::kDisplacement, xdmf::sample::kRelativeDeflection}) {
    text += attribute(name, true, "Node", item(xdmf::sample_path(k, name), np3));
  }
  for (const char* name : {xdmf::sample::kDisplacementMagnitude, xdmf::sample::kRelativeDeflectionMagnitude}) {
    text += attribute(name, false, "Node", item(xdmf::sample_path(k, name), np));
  }
  text += attribute("beam_radius", false, "Cell", item(xdmf::kBeamRadius, nc));
  text += attribute("body", false, "Cell", item(xdmf::kBody, nc, true));
  if (grid.stress) {
    text += attribute(xdmf::sample::kStress, false, "Cell", item(xdmf::sample_path(k, xdmf::sample::kStress), nc));
  }
  return text + "  </Grid>\n";
}

}  // namespace

std::string xdmf_description(const XdmfGrid& grid, const std::vector<double>& times) {
  std::string text =
      "<?xml version=\"1.0\" ?>\n"
      "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      "<Xdmf Version=\"2.0\">\n"
      "<Domain>\n";
  for (std::size_t b = 0; b < grid.body_names.size(); ++b) {
    text += fmt::format(" <Information Name=\"body {}\" Value=\"{}\"/>\n", b, markup_escape(grid.body_names[b]));
  }
  text += " <Grid Name=\"scene\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t k = 0; k < times.size() && grid.points > 0; ++k) {
    text += sample_grid(grid, static_cast<long>(k), times[k]);
  }
  return text + " </Grid>\n</Domain>\n</Xdmf>\n";
}

}  // namespace limber::render
