// The one-file ParaView scene (scene.h5 + scene.xmf) against the test scene's closed forms, the
// same the VTU series is checked against (vtk_export_test.cpp), read with limber_results'
// reader at the paths of render/xdmf_layout.h.
#include "xdmf_export.h"

#include "body_pose.h"

#include "results/h5_reader.h"
#include "results/link_name.h"
#include "test_dir.h"
#include "test_results.h"
#include "xdmf_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace limber::render {
namespace {

using testing::TestScene;

std::vector<double> reals(const results::H5Reader& file, const std::string& path) {
  return file.read<double>(path, H5T_NATIVE_DOUBLE, file.dims(path).at(0));
}

int int_attribute(const results::H5Reader& file, const std::string& body, const char* name) {
  return static_cast<int>(file.doubles_attribute(xdmf::at(xdmf::kBodies, results::link_name(body)), name, 1).at(0));
}

// The rows of `body` in the scene's dataset `name` of sample k (`width` values a row: 3 for
// vectors, 1 for scalars), or in a constant per-cell dataset when k < 0.
std::vector<double> body_rows(const results::H5Reader& file, const std::string& body, int k, const char* name,
                              int width = 3, bool cells = false) {
  const std::vector<double> all = reals(file, k < 0 ? std::string(name) : xdmf::sample_path(k, name));
  const int first = int_attribute(file, body, cells ? xdmf::body::kFirstCellAttribute : xdmf::body::kFirstPointAttribute);
  const int count = int_attribute(file, body, cells ? xdmf::body::kCellCountAttribute : xdmf::body::kPointCountAttribute);
  return {all.begin() + width * first, all.begin() + width * (first + count)};
}

// `sequence` appears in `values`.
bool holds(const std::vector<int>& values, const std::vector<int>& sequence) {
  return std::search(values.begin(), values.end(), sequence.begin(), sequence.end()) != values.end();
}

std::vector<int> ints(const results::H5Reader& file, const std::string& path) {
  return file.read<int>(path, H5T_NATIVE_INT, file.dims(path).at(0));
}

TEST(XdmfExport, SceneMatchesTheClosedForms) {
  const auto dir = testing::fresh_directory("xdmf");
  const TestScene scene;
  testing::write_test_results(dir, scene);
  const XdmfSceneSummary summary = write_xdmf_scene(read_results(dir), dir / "vtk", 0.0, 1.0, false);
  EXPECT_EQ(summary.samples, scene.samples);
  EXPECT_EQ(summary.grids, 3 * scene.samples);
  const results::H5Reader file(dir / "vtk" / xdmf::kFileName, "ParaView scene", "");

  EXPECT_EQ(file.string_attribute("/", xdmf::kFormatAttribute), xdmf::kFormat);
  EXPECT_EQ(file.string_attribute(xdmf::at(xdmf::kBodies, "plate0"), results::kNameAttribute), "plate0");

  // Times t_k = k T / (ns - 1), exactly as results.h5 holds them.
  const std::vector<double> times = reals(file, xdmf::kTime);
  ASSERT_EQ(times.size(), static_cast<std::size_t>(scene.samples));
  for (int k = 0; k < scene.samples; ++k) EXPECT_EQ(times[k], scene.duration * k / (scene.samples - 1));

  // Plate at sample k: points = origin + X0; displacement, its magnitude and (no joints on the
  // plate: the fit is empty) the relative deflection = the closed form.
  // Tolerance 1e-14 m: same products, summed in another order, on values <= 0.1 m.
  const int np = (scene.nx + 1) * (scene.ny + 1);
  for (int k : {0, 3, 7}) {
    const double t = scene.duration * k / (scene.samples - 1);
    const std::vector<double> x = body_rows(file, "plate0", k, xdmf::sample::kPoints);
    const std::vector<double> u = body_rows(file, "plate0", k, xdmf::sample::kDisplacement);
    const std::vector<double> u_norm = body_rows(file, "plate0", k, xdmf::sample::kDisplacementMagnitude, 1);
    const std::vector<double> u_rel = body_rows(file, "plate0", k, xdmf::sample::kRelativeDeflection);
    const std::vector<double> u_rel_norm = body_rows(file, "plate0", k, xdmf::sample::kRelativeDeflectionMagnitude, 1);
    ASSERT_EQ(x.size(), 3u * np);
    ASSERT_EQ(u_norm.size(), static_cast<std::size_t>(np));
    for (int n = 0; n < np; ++n) {
      const int i = n % (scene.nx + 1), j = n / (scene.nx + 1);
      const double px = scene.lx * i / scene.nx, py = scene.ly * j / scene.ny;
      const Eigen::Vector3d expected = testing::plate_displacement(scene, px, py, t);
      EXPECT_NEAR(x[3 * n], px, 1e-14);
      EXPECT_NEAR(x[3 * n + 1], py, 1e-14);
      EXPECT_NEAR(x[3 * n + 2], testing::plate_origin(0).z(), 1e-14);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(u[3 * n + c], expected(c), 1e-14);
        EXPECT_NEAR(u_rel[3 * n + c], expected(c), 1e-14);
      }
      EXPECT_NEAR(u_norm[n], expected.norm(), 1e-14);
      EXPECT_NEAR(u_rel_norm[n], expected.norm(), 1e-14);
    }
  }

  // The bodies one after the other, without gaps, in results.h5's order; the cell data `body`
  // holds each cell's body index.
  const std::vector<int> body = ints(file, xdmf::kBody);
  int points = 0, cells = 0;
  for (int index = 0; index < 3; ++index) {
    for (const char* name : {"plate0", "beam", "box"}) {
      if (int_attribute(file, name, xdmf::body::kIndexAttribute) != index) continue;
      EXPECT_EQ(int_attribute(file, name, xdmf::body::kFirstPointAttribute), points) << name;
      EXPECT_EQ(int_attribute(file, name, xdmf::body::kFirstCellAttribute), cells) << name;
      const int count = int_attribute(file, name, xdmf::body::kCellCountAttribute);
      ASSERT_LE(static_cast<std::size_t>(cells + count), body.size());
      EXPECT_EQ(std::count(body.begin() + cells, body.begin() + cells + count, index), count) << name;
      points += int_attribute(file, name, xdmf::body::kPointCountAttribute);
      cells += count;
    }
  }
  EXPECT_EQ(static_cast<std::size_t>(cells), body.size());
  EXPECT_EQ(int_attribute(file, "plate0", xdmf::body::kCellCountAttribute), scene.nx * scene.ny);

  // Plate topology: its first quad (code 5 and four node indices) is (0, 1, nx + 2, nx + 1)
  // counter-clockwise, point indices moved by the plate's first point; no beam radius on quads.
  const std::vector<int> topology = ints(file, xdmf::kTopology);
  const int p0 = int_attribute(file, "plate0", xdmf::body::kFirstPointAttribute);
  EXPECT_TRUE(holds(topology, {xdmf::kQuadrilateral, p0, p0 + 1, p0 + scene.nx + 2, p0 + scene.nx + 1}));
  EXPECT_EQ(body_rows(file, "plate0", -1, xdmf::kBeamRadius, 1, true), std::vector<double>(scene.nx * scene.ny, 0.0));

  // Beam: 21 points on 20 polylines of 2 points (moved by its first point), each carrying the
  // tube radius 0.02 m; tip displacement (0, B sin, B cos) at t = 0.3 s.
  const int b0 = int_attribute(file, "beam", xdmf::body::kFirstPointAttribute);
  EXPECT_EQ(int_attribute(file, "beam", xdmf::body::kPointCountAttribute), testing::kBeamNodes);
  EXPECT_TRUE(holds(topology, {xdmf::kPolyline, 2, b0, b0 + 1}));
  EXPECT_EQ(body_rows(file, "beam", -1, xdmf::kBeamRadius, 1, true), std::vector<double>(testing::kBeamNodes - 1, 0.02));
  const std::vector<double> beam_u = body_rows(file, "beam", 3, xdmf::sample::kDisplacement);
  const Eigen::Vector3d tip = testing::beam_displacement(scene, testing::kBeamLength, 0.3);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(beam_u[3 * (testing::kBeamNodes - 1) + c], tip(c), 1e-14);

  // Box: its surface centred on the box position (+-0.1 m around it), zero displacements.
  const std::vector<double> box = body_rows(file, "box", 5, xdmf::sample::kPoints);
  ASSERT_FALSE(box.empty());
  const Eigen::Vector3d centre = testing::box_position(0.5);
  for (int c = 0; c < 3; ++c) {
    double lo = 1e300, hi = -1e300;
    for (std::size_t n = c; n < box.size(); n += 3) {
      lo = std::min(lo, box[n]);
      hi = std::max(hi, box[n]);
    }
    EXPECT_NEAR(lo, centre(c) - 0.1, 1e-6);  // vtkCubeSource makes float points
    EXPECT_NEAR(hi, centre(c) + 0.1, 1e-6);
  }
  EXPECT_EQ(body_rows(file, "box", 5, xdmf::sample::kDisplacement), std::vector<double>(box.size(), 0.0));

  // The description names one grid per sample, with its time.
  std::ifstream in(dir / "vtk" / xdmf::kDescriptionName);
  std::stringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  std::size_t grids = 0;
  for (std::size_t at = xml.find("GridType=\"Uniform\""); at != std::string::npos;
       at = xml.find("GridType=\"Uniform\"", at + 1)) {
    ++grids;
  }
  EXPECT_EQ(grids, static_cast<std::size_t>(scene.samples));
  EXPECT_NE(xml.find("<Time Value=\"0.10000000000000001\"/>"), std::string::npos);
  EXPECT_NE(xml.find("scene.h5:/samples/00010/points"), std::string::npos);
}

// A joint at the beam's mid node: the relative deflection is u(x) - u(L/2) (a one-node rigid fit
// is the translation u(L/2)), in ground axes (the beam frame is not rotated); the displacement
// stays u. Tolerance 1e-14 m: differences of values <= 0.05 m.
TEST(XdmfExport, RelativeDeflectionIsMeasuredFromTheJointNode) {
  const auto dir = testing::fresh_directory("xdmf_relative");
  TestScene scene;
  scene.beam_mid_joint = true;
  testing::write_test_results(dir, scene);
  write_xdmf_scene(read_results(dir), dir / "vtk", 0.0, 1.0, false);
  const results::H5Reader file(dir / "vtk" / xdmf::kFileName, "ParaView scene", "");
  for (int k : {2, 3, 9}) {
    const double t = scene.duration * k / (scene.samples - 1);
    const std::vector<double> u = body_rows(file, "beam", k, xdmf::sample::kDisplacement);
    const std::vector<double> u_rel = body_rows(file, "beam", k, xdmf::sample::kRelativeDeflection);
    const std::vector<double> u_rel_norm = body_rows(file, "beam", k, xdmf::sample::kRelativeDeflectionMagnitude, 1);
    ASSERT_EQ(u_rel.size(), 3u * testing::kBeamNodes);
    const Eigen::Vector3d u_mid = testing::beam_displacement(scene, 0.5 * testing::kBeamLength, t);
    for (int n = 0; n < testing::kBeamNodes; ++n) {
      const double x = testing::kBeamLength * n / (testing::kBeamNodes - 1);
      const Eigen::Vector3d expected_u = testing::beam_displacement(scene, x, t);
      const Eigen::Vector3d expected = expected_u - u_mid;
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(u[3 * n + c], expected_u(c), 1e-14);
        EXPECT_NEAR(u_rel[3 * n + c], expected(c), 1e-14) << "node " << n << " t " << t;
      }
      EXPECT_NEAR(u_rel_norm[n], expected.norm(), 1e-14);
    }
  }
}

// A beam stored node by node (a nonlinear body's layout, docs/results-format.md) exports as the
// same beam stored as modes, every dataset of every sample: the second method is the modal sum
// Φη against the stored displacements, both the closed form beam_displacement. With the tube
// section (swept-surface points follow their nodes) and the mid joint (the relative deflection's
// rigid fit). Tolerance 1e-15 m: the same products on values <= 1.1 m (the modal sum adds
// exact zeros).
TEST(XdmfExport, NodeDisplacementsExportAsTheModalBeam) {
  TestScene scene;
  scene.beam_tube_section = true;
  scene.beam_mid_joint = true;
  const auto modal_dir = testing::fresh_directory("xdmf_beam_modal");
  testing::write_test_results(modal_dir, scene);
  scene.beam_node_displacements = true;
  const auto nodes_dir = testing::fresh_directory("xdmf_beam_nodes");
  testing::write_test_results(nodes_dir, scene);
  const Results stored = read_results(nodes_dir);
  const auto found = std::find_if(stored.bodies.begin(), stored.bodies.end(),
                                  [](const BodyTrack& body) { return body.name == "beam"; });
  ASSERT_NE(found, stored.bodies.end());
  const BodyTrack& beam = *found;
  EXPECT_EQ(beam.modal_coordinates.cols(), 0);
  ASSERT_EQ(beam.node_displacements.rows(), scene.samples);
  ASSERT_EQ(beam.node_displacements.cols(), 3 * testing::kBeamNodes);
  // Between samples the displacements interpolate linearly, as modal coordinates do.
  const RowMatrix3d u_mid = elastic_displacements(beam.mesh, body_state(beam, {2, 0.5}));
  const Eigen::Vector3d tip_2 = testing::beam_displacement(scene, testing::kBeamLength, 0.2);
  const Eigen::Vector3d tip_3 = testing::beam_displacement(scene, testing::kBeamLength, 0.3);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(u_mid(testing::kBeamNodes - 1, c), 0.5 * (tip_2(c) + tip_3(c)), 1e-15);

  write_xdmf_scene(read_results(modal_dir), modal_dir / "vtk", 0.0, 1.0, false);
  write_xdmf_scene(stored, nodes_dir / "vtk", 0.0, 1.0, false);
  const results::H5Reader modal(modal_dir / "vtk" / xdmf::kFileName, "ParaView scene", "");
  const results::H5Reader nodes(nodes_dir / "vtk" / xdmf::kFileName, "ParaView scene", "");
  for (int k = 0; k < scene.samples; ++k) {
    for (const char* name : {xdmf::sample::kPoints, xdmf::sample::kDisplacement, xdmf::sample::kRelativeDeflection,
                             xdmf::sample::kRelativeDeflectionMagnitude}) {
      const std::vector<double> expected = reals(modal, xdmf::sample_path(k, name));
      const std::vector<double> got = reals(nodes, xdmf::sample_path(k, name));
      ASSERT_EQ(got.size(), expected.size()) << name;
      ASSERT_GT(got.size(), static_cast<std::size_t>(testing::kBeamNodes)) << "the swept surface's points follow the nodes";
      for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], expected[i], 1e-15) << name << " " << i;
    }
  }
}

TEST(XdmfExport, TimeRangeSelectsSamples) {
  const auto dir = testing::fresh_directory("xdmf_range");
  testing::write_test_results(dir, TestScene{});
  // Samples at 0.0, 0.1, ..., 1.0 s: [0.25, 0.55] holds 0.3, 0.4, 0.5 (rows 3, 4, 5).
  const XdmfSceneSummary summary = write_xdmf_scene(read_results(dir), dir / "vtk", 0.25, 0.55, false);
  EXPECT_EQ(summary.samples, 3);
  const results::H5Reader file(dir / "vtk" / xdmf::kFileName, "ParaView scene", "");
  EXPECT_EQ(file.read<int>(xdmf::kSampleRows, H5T_NATIVE_INT, 3), (std::vector<int>{3, 4, 5}));
}

}  // namespace
}  // namespace limber::render
