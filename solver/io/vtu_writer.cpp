#include "io/vtu_writer.h"

#include <fmt/format.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "core/error.h"
#include "io/modes_file.h"

namespace limber::io {

namespace {

static_assert(std::endian::native == std::endian::little,
              "the VTU writer emits the machine's bytes as LittleEndian");

constexpr std::uint8_t kVtkLine = 3;
constexpr std::uint8_t kVtkQuad = 9;

// Appends the raw bytes of `values`.
template <typename T>
void append_bytes(std::vector<unsigned char>& bytes, const std::vector<T>& values) {
  const std::size_t start = bytes.size();
  bytes.resize(start + values.size() * sizeof(T));
  if (!values.empty()) std::memcpy(bytes.data() + start, values.data(), values.size() * sizeof(T));
}

// One <DataArray> element holding `values` (row-major tuples of `components`).
template <typename T>
void write_data_array(std::ostream& out, const char* type, const std::string& name, int components,
                      const std::vector<T>& values, VtuEncoding encoding) {
  out << "        <DataArray type=\"" << type << "\"";
  if (!name.empty()) out << " Name=\"" << name << "\"";
  if (components > 1) out << " NumberOfComponents=\"" << components << "\"";
  out << " format=\"" << (encoding == VtuEncoding::kAscii ? "ascii" : "binary") << "\">\n";
  if (encoding == VtuEncoding::kAscii) {
    // Shortest text that reads back to the same value, one tuple per line.
    for (std::size_t i = 0; i < values.size(); ++i) {
      const bool line_start = i % components == 0;
      const bool line_end = (i + 1) % components == 0;
      out << (line_start ? "          " : " ");
      if constexpr (sizeof(T) == 1) {
        out << static_cast<int>(values[i]);
      } else {
        out << fmt::format("{}", values[i]);
      }
      if (line_end) out << "\n";
    }
  } else {
    // One base64 stream: UInt32 byte count, then the data.
    const auto byte_count = static_cast<std::uint32_t>(values.size() * sizeof(T));
    std::vector<unsigned char> bytes;
    append_bytes(bytes, std::vector<std::uint32_t>{byte_count});
    append_bytes(bytes, values);
    out << "          " << base64_encode(bytes) << "\n";
  }
  out << "        </DataArray>\n";
}

}  // namespace

std::string base64_encode(const std::vector<unsigned char>& bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  text.reserve((bytes.size() + 2) / 3 * 4);
  // Each 3 bytes become 4 characters of 6 bits; a short last group is padded with '='.
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t left = bytes.size() - i;
    std::uint32_t group = static_cast<std::uint32_t>(bytes[i]) << 16;
    if (left > 1) group |= static_cast<std::uint32_t>(bytes[i + 1]) << 8;
    if (left > 2) group |= bytes[i + 2];
    text += kAlphabet[(group >> 18) & 63];
    text += kAlphabet[(group >> 12) & 63];
    text += left > 1 ? kAlphabet[(group >> 6) & 63] : '=';
    text += left > 2 ? kAlphabet[group & 63] : '=';
  }
  return text;
}

void write_vtu(const std::string& path, const VtuMesh& mesh,
               const std::vector<VtuPointArray>& arrays, VtuEncoding encoding) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InputError("cannot create the VTU file '" + path + "'");
  const std::size_t np = mesh.points.size();
  const std::size_t nc = mesh.lines.size() + mesh.quads.size();

  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt32\">\n"
      << "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << np << "\" NumberOfCells=\"" << nc << "\">\n";

  // Point data: node ids, then the caller's arrays.
  out << "      <PointData>\n";
  if (!mesh.point_ids.empty()) {
    LIMBER_DEMAND(mesh.point_ids.size() == np);
    write_data_array(out, "Int32", "node_id", 1,
                     std::vector<std::int32_t>(mesh.point_ids.begin(), mesh.point_ids.end()),
                     encoding);
  }
  for (const VtuPointArray& array : arrays) {
    LIMBER_DEMAND(static_cast<std::size_t>(array.values.rows()) == np);
    LIMBER_DEMAND(array.values.cols() == 1 || array.values.cols() == 3);
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rows =
        array.values;
    write_data_array(out, "Float64", array.name, static_cast<int>(array.values.cols()),
                     std::vector<double>(rows.data(), rows.data() + rows.size()), encoding);
  }
  out << "      </PointData>\n";

  // Points.
  std::vector<double> coordinates;
  for (const Eigen::Vector3d& p : mesh.points)
    coordinates.insert(coordinates.end(), {p.x(), p.y(), p.z()});
  out << "      <Points>\n";
  write_data_array(out, "Float64", "Points", 3, coordinates, encoding);
  out << "      </Points>\n";

  // Cells: lines then quads, as connectivity / offsets / types.
  std::vector<std::int32_t> connectivity;
  std::vector<std::int32_t> offsets;
  std::vector<std::uint8_t> types;
  for (const auto& line : mesh.lines) {
    connectivity.insert(connectivity.end(), line.begin(), line.end());
    offsets.push_back(static_cast<std::int32_t>(connectivity.size()));
    types.push_back(kVtkLine);
  }
  for (const auto& quad : mesh.quads) {
    connectivity.insert(connectivity.end(), quad.begin(), quad.end());
    offsets.push_back(static_cast<std::int32_t>(connectivity.size()));
    types.push_back(kVtkQuad);
  }
  for (std::int32_t index : connectivity)
    LIMBER_DEMAND(index >= 0 && static_cast<std::size_t>(index) < np);
  out << "      <Cells>\n";
  write_data_array(out, "Int32", "connectivity", 1, connectivity, encoding);
  write_data_array(out, "Int32", "offsets", 1, offsets, encoding);
  write_data_array(out, "UInt8", "types", 1, types, encoding);
  out << "      </Cells>\n"
      << "    </Piece>\n"
      << "  </UnstructuredGrid>\n"
      << "</VTKFile>\n";
  if (!out) throw InputError("cannot write the VTU file '" + path + "'");
}

std::string mode_array_name(int index, const modal::ModeInfo& mode) {
  return fmt::format("mode_{:02d}_{}_{:.1f}Hz", index, modal::to_string(mode.kind),
                     mode.frequency_hz);
}

void write_modes_vtu(const std::string& path, const fe::FeModel& model,
                     const modal::ModeSet& mode_set, VtuEncoding encoding) {
  LIMBER_DEMAND(mode_set.shapes.rows() == model.dof_count());
  VtuMesh mesh;
  mesh.points = model.node_positions;
  mesh.point_ids = model.node_ids;
  for (const fe::BeamElement& beam : model.beams) mesh.lines.push_back(beam.nodes);
  for (const fe::ShellElement& shell : model.shells) mesh.quads.push_back(shell.nodes);
  // Triangles drawn as quads with the last node repeated (drawing only).
  for (const fe::ShellTriangle& t : model.triangles) {
    mesh.quads.push_back({t.nodes[0], t.nodes[1], t.nodes[2], t.nodes[2]});
  }
  // One displacement field per mode, in mode order.
  std::vector<VtuPointArray> arrays;
  for (int i = 0; i < static_cast<int>(mode_set.modes.size()); ++i) {
    arrays.push_back(
        {mode_array_name(i + 1, mode_set.modes[i]), mode_translations(mode_set.shapes, i)});
  }
  write_vtu(path, mesh, arrays, encoding);
}

}  // namespace limber::io
