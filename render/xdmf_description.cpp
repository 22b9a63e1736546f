#include "xdmf_description.h"

#include "core/markup_escape.h"
#include "xdmf_layout.h"

#include <fmt/core.h>

namespace limber::render {
namespace {

// A DataItem naming the whole float64 dataset `path` of scene.h5 with `dimensions`.
std::string real_item(const std::string& path, const std::string& dimensions) {
  return fmt::format(
      "<DataItem Dimensions=\"{}\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">{}:{}</DataItem>",
      dimensions, xdmf::kFileName, markup_escape(path));
}

std::string attribute(const char* name, bool vector, const char* center, const std::string& item) {
  return fmt::format("      <Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"{}\">{}</Attribute>\n",
                     name, vector ? "Vector" : "Scalar", center, item);
}

// One body at sample k.
std::string grid(const XdmfBody& body, long k) {
  const std::string sample = xdmf::at(xdmf::at(body.group, xdmf::body::kSamples), xdmf::sample_name(k));
  const std::string np3 = fmt::format("{} 3", body.points), np = std::to_string(body.points);
  std::string text = fmt::format("     <Grid Name=\"{}\" GridType=\"Uniform\">\n", markup_escape(body.name));
  text += fmt::format(
      "      <Topology TopologyType=\"Mixed\" NumberOfElements=\"{}\"><DataItem Dimensions=\"{}\" "
      "NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">{}:{}</DataItem></Topology>\n",
      body.cells, body.topology, xdmf::kFileName, markup_escape(xdmf::at(body.group, xdmf::body::kTopology)));
  text += "      <Geometry GeometryType=\"XYZ\">" + real_item(xdmf::at(sample, xdmf::sample::kPoints), np3) +
          "</Geometry>\n";
  // Rigid bodies share one dataset of zeros for every sample.
  const auto nodal = [&](const char* name, bool vector) {
    const std::string path = body.flexible ? xdmf::at(sample, name)
                                           : xdmf::at(body.group, vector ? xdmf::body::kZeroVectors
                                                                         : xdmf::body::kZeroScalars);
    return attribute(name, vector, "Node", real_item(path, vector ? np3 : np));
  };
  text += nodal(xdmf::sample::kDisplacement, true);
  text += nodal(xdmf::sample::kDisplacementMagnitude, false);
  text += nodal(xdmf::sample::kRelativeDeflection, true);
  text += nodal(xdmf::sample::kRelativeDeflectionMagnitude, false);
  const std::string nc = std::to_string(body.cells);
  text += attribute(xdmf::body::kBeamRadius, false, "Cell",
                    real_item(xdmf::at(body.group, xdmf::body::kBeamRadius), nc));
  if (body.stress) {
    text += attribute(xdmf::sample::kStress, false, "Cell", real_item(xdmf::at(sample, xdmf::sample::kStress), nc));
  }
  return text + "     </Grid>\n";
}

}  // namespace

std::string xdmf_description(const std::vector<XdmfBody>& bodies, const std::vector<double>& times) {
  std::string text =
      "<?xml version=\"1.0\" ?>\n"
      "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      "<Xdmf Version=\"2.0\">\n"
      " <Domain>\n"
      "  <Grid Name=\"scene\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t k = 0; k < times.size(); ++k) {
    // 17 significant digits: the times read back exactly.
    text += fmt::format("   <Grid Name=\"t{}\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
                        "    <Time Value=\"{:.17g}\"/>\n",
                        xdmf::sample_name(static_cast<long>(k)), times[k]);
    for (const XdmfBody& body : bodies) {
      if (body.points > 0) text += grid(body, static_cast<long>(k));
    }
    text += "   </Grid>\n";
  }
  return text + "  </Grid>\n </Domain>\n</Xdmf>\n";
}

}  // namespace limber::render
