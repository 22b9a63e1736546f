// VTU files read back with an independent XML parser and base64 decoder.
#include "io/vtu_writer.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "mini_xml.h"

namespace limber::io {
namespace {

// A file name in the test scratch directory, unique to this process.
std::string scratch_path(const std::string& name) {
  return ::testing::TempDir() + "/" + std::to_string(getpid()) + "_" + name;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Values of a <DataArray> as doubles, whatever its encoding and type.
std::vector<double> values_of(const test::XmlElement& array) {
  const std::string& type = array.attribute("type");
  std::vector<double> values;
  if (array.attribute("format") == "ascii") {
    std::istringstream in(array.text);
    double value = 0.0;
    while (in >> value) values.push_back(value);
    return values;
  }
  // binary: base64 of [UInt32 byte count][data].
  const std::vector<unsigned char> bytes = test::base64_decode(array.text);
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data(), sizeof count);
  EXPECT_EQ(bytes.size(), sizeof count + count) << "header byte count";
  const unsigned char* data = bytes.data() + sizeof count;
  const std::size_t size = type == "Float64" ? 8 : type == "Int32" ? 4 : 1;
  for (std::size_t k = 0; k < count / size; ++k) {
    if (type == "Float64") {
      double v;
      std::memcpy(&v, data + 8 * k, 8);
      values.push_back(v);
    } else if (type == "Int32") {
      std::int32_t v;
      std::memcpy(&v, data + 4 * k, 4);
      values.push_back(v);
    } else {
      values.push_back(data[k]);
    }
  }
  return values;
}

const test::XmlElement* array_named(const test::XmlElement& parent, const std::string& name) {
  for (const test::XmlElement* array : parent.children_named("DataArray")) {
    if (array->attributes.count("Name") && array->attribute("Name") == name) return array;
  }
  return nullptr;
}

class VtuWriter : public ::testing::TestWithParam<VtuEncoding> {};

TEST_P(VtuWriter, FileReadsBackWithEveryValue) {
  // Two lines and a quad over 5 points; one vector and one scalar point array.
  VtuMesh mesh;
  mesh.points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1, 0}, {0.1, 1.0 / 3.0, -2e-300}};
  mesh.lines = {{0, 1}, {1, 2}};
  mesh.quads = {{0, 1, 3, 4}};
  mesh.point_ids = {10, 11, 12, 13, 14};
  Eigen::MatrixXd shape(5, 3);
  shape << 0.1, 0.2, 0.3, 1e-17, -4.0, 5.5, 6, 7, 8, 9, 10, 11, 1.0 / 7.0, 2.0 / 3.0, -1;
  Eigen::MatrixXd scalar(5, 1);
  scalar << 1, 2, 3, 4, 5;
  const std::string path = scratch_path("mesh.vtu");
  write_vtu(path, mesh, {{"mode_01_normal_12.5Hz", shape}, {"weight", scalar}}, GetParam());

  const test::XmlElement root = test::parse_xml(read_text(path));
  EXPECT_EQ(root.name, "VTKFile");
  EXPECT_EQ(root.attribute("type"), "UnstructuredGrid");
  EXPECT_EQ(root.attribute("byte_order"), "LittleEndian");
  const test::XmlElement& piece = root.child("UnstructuredGrid").child("Piece");
  EXPECT_EQ(piece.attribute("NumberOfPoints"), "5");
  EXPECT_EQ(piece.attribute("NumberOfCells"), "3");

  // Points and point data come back exactly (ASCII is written in round-trip form).
  const std::vector<double> points = values_of(piece.child("Points").child("DataArray"));
  ASSERT_EQ(points.size(), 15u);
  EXPECT_EQ(points[13], 1.0 / 3.0);
  EXPECT_EQ(points[14], -2e-300);
  const test::XmlElement& point_data = piece.child("PointData");
  const test::XmlElement* mode = array_named(point_data, "mode_01_normal_12.5Hz");
  ASSERT_NE(mode, nullptr);
  EXPECT_EQ(mode->attribute("NumberOfComponents"), "3");
  const std::vector<double> mode_values = values_of(*mode);
  ASSERT_EQ(mode_values.size(), 15u);
  for (int i = 0; i < 5; ++i) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(mode_values[3 * i + k], shape(i, k));
  }
  ASSERT_NE(array_named(point_data, "weight"), nullptr);
  EXPECT_EQ(values_of(*array_named(point_data, "weight")), (std::vector<double>{1, 2, 3, 4, 5}));
  EXPECT_EQ(values_of(*array_named(point_data, "node_id")),
            (std::vector<double>{10, 11, 12, 13, 14}));

  // Cells: VTK_LINE = 3, VTK_QUAD = 9, offsets are running ends.
  const test::XmlElement& cells = piece.child("Cells");
  EXPECT_EQ(values_of(*array_named(cells, "connectivity")),
            (std::vector<double>{0, 1, 1, 2, 0, 1, 3, 4}));
  EXPECT_EQ(values_of(*array_named(cells, "offsets")), (std::vector<double>{2, 4, 8}));
  EXPECT_EQ(values_of(*array_named(cells, "types")), (std::vector<double>{3, 3, 9}));
  std::filesystem::remove(path);
}

INSTANTIATE_TEST_SUITE_P(Encodings, VtuWriter,
                         ::testing::Values(VtuEncoding::kAscii, VtuEncoding::kBase64));

TEST(VtuNames, ModeArrayNames) {
  EXPECT_EQ(mode_array_name(1, {modal::ModeKind::kNormal, 123.44, "normal 1"}),
            "mode_01_normal_123.4Hz");
  EXPECT_EQ(mode_array_name(12, {modal::ModeKind::kConstraint, 2365.96, "c"}),
            "mode_12_constraint_2366.0Hz");
}

TEST(VtuNames, Base64MatchesRfc4648Vectors) {
  // RFC 4648 §10 test vectors.
  auto encode = [](const std::string& s) {
    return base64_encode(std::vector<unsigned char>(s.begin(), s.end()));
  };
  EXPECT_EQ(encode(""), "");
  EXPECT_EQ(encode("f"), "Zg==");
  EXPECT_EQ(encode("fo"), "Zm8=");
  EXPECT_EQ(encode("foo"), "Zm9v");
  EXPECT_EQ(encode("foob"), "Zm9vYg==");
  EXPECT_EQ(encode("fooba"), "Zm9vYmE=");
  EXPECT_EQ(encode("foobar"), "Zm9vYmFy");
}

}  // namespace
}  // namespace limber::io
