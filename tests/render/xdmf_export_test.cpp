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

std::string sample_path(const std::string& body, int k, const char* name) {
  return xdmf::at(xdmf::at(xdmf::at(xdmf::at(xdmf::kBodies, results::link_name(body)), xdmf::body::kSamples),
                           xdmf::sample_name(k)),
                  name);
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
    const std::vector<double> x = reals(file, sample_path("plate0", k, xdmf::sample::kPoints));
    const std::vector<double> u = reals(file, sample_path("plate0", k, xdmf::sample::kDisplacement));
    const std::vector<double> u_norm = reals(file, sample_path("plate0", k, xdmf::sample::kDisplacementMagnitude));
    const std::vector<double> u_rel = reals(file, sample_path("plate0", k, xdmf::sample::kRelativeDeflection));
    const std::vector<double> u_rel_norm =
        reals(file, sample_path("plate0", k, xdmf::sample::kRelativeDeflectionMagnitude));
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

  // Plate topology: nx ny quads (code 5 and four node indices), the first one (0, 1, nx + 2, nx + 1)
  // counter-clockwise; no beam radius on quads.
  const std::string plate = xdmf::at(xdmf::kBodies, "plate0");
  const std::vector<int> topology = file.read<int>(xdmf::at(plate, xdmf::body::kTopology), H5T_NATIVE_INT,
                                                   file.dims(xdmf::at(plate, xdmf::body::kTopology)).at(0));
  ASSERT_EQ(topology.size(), 5u * scene.nx * scene.ny);
  EXPECT_EQ(topology[0], xdmf::kQuadrilateral);
  EXPECT_EQ(reals(file, xdmf::at(plate, xdmf::body::kBeamRadius)), std::vector<double>(scene.nx * scene.ny, 0.0));

  // Beam: 21 points on 20 polylines of 2 points, each carrying the tube radius 0.02 m; tip
  // displacement (0, B sin, B cos) at t = 0.3 s.
  const std::string beam = xdmf::at(xdmf::kBodies, "beam");
  const std::vector<int> lines = file.read<int>(xdmf::at(beam, xdmf::body::kTopology), H5T_NATIVE_INT,
                                                file.dims(xdmf::at(beam, xdmf::body::kTopology)).at(0));
  ASSERT_EQ(lines.size(), 4u * (testing::kBeamNodes - 1));
  EXPECT_EQ((std::vector<int>(lines.begin(), lines.begin() + 4)), (std::vector<int>{xdmf::kPolyline, 2, 0, 1}));
  EXPECT_EQ(reals(file, xdmf::at(beam, xdmf::body::kBeamRadius)), std::vector<double>(testing::kBeamNodes - 1, 0.02));
  const std::vector<double> beam_u = reals(file, sample_path("beam", 3, xdmf::sample::kDisplacement));
  const Eigen::Vector3d tip = testing::beam_displacement(scene, testing::kBeamLength, 0.3);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(beam_u[3 * (testing::kBeamNodes - 1) + c], tip(c), 1e-14);

  // Box: its surface centred on the box position (+-0.1 m around it), zero displacements.
  const std::vector<double> box = reals(file, sample_path("box", 5, xdmf::sample::kPoints));
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
  const std::vector<double> zeros = reals(file, xdmf::at(xdmf::at(xdmf::kBodies, "box"), xdmf::body::kZeroVectors));
  EXPECT_EQ(zeros, std::vector<double>(box.size(), 0.0));

  // The description names every body's grid at every sample, with its time.
  std::ifstream in(dir / "vtk" / xdmf::kDescriptionName);
  std::stringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  std::size_t grids = 0;
  for (std::size_t at = xml.find("GridType=\"Uniform\""); at != std::string::npos;
       at = xml.find("GridType=\"Uniform\"", at + 1)) {
    ++grids;
  }
  EXPECT_EQ(grids, 3u * scene.samples);
  EXPECT_NE(xml.find("<Time Value=\"0.10000000000000001\"/>"), std::string::npos);
  EXPECT_NE(xml.find("<Grid Name=\"plate0\" GridType=\"Uniform\">"), std::string::npos);
  EXPECT_NE(xml.find("scene.h5:/bodies/plate0/samples/00010/points"), std::string::npos);
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
    const std::vector<double> u = reals(file, sample_path("beam", k, xdmf::sample::kDisplacement));
    const std::vector<double> u_rel = reals(file, sample_path("beam", k, xdmf::sample::kRelativeDeflection));
    const std::vector<double> u_rel_norm =
        reals(file, sample_path("beam", k, xdmf::sample::kRelativeDeflectionMagnitude));
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
      const std::vector<double> expected = reals(modal, sample_path("beam", k, name));
      const std::vector<double> got = reals(nodes, sample_path("beam", k, name));
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
