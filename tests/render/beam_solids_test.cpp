// Beams as swept solids (render/beam_solids.h): the cap triangulation covers the outline
// exactly; the swept surface is closed, faces outward and encloses the outline's area times the
// beam's length (divergence theorem, exact for these polyhedra); the outline turns with the
// beam's y axis; and in pixels, a 40 x 5 mm rectangular bar looks 8 times thinner seen along
// its width than along its height, while a file without sections still draws the round tube.
#include "beam_solids.h"

#include "frame_renderer.h"
#include "scene.h"
#include "test_dir.h"
#include "vtk_export.h"

#include "core/error.h"
#include "fe/section_outline.h"
#include "results/results_writer.h"

#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <utility>

namespace limber::render {
namespace {

// Twice the signed area of a triangle.
double turn(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

// The file's form of one outline (results/beam_sections.h) for every line of `mesh`.
void set_sections(FlexibleMesh& mesh, const fe::SectionOutline& outline, const Eigen::Vector3d& y_axis) {
  results::BeamSections& s = mesh.beam_sections;
  s.y_axes = RowMatrix3d(mesh.lines.rows(), 3);
  s.y_axes.rowwise() = y_axis.transpose();
  s.outline.assign(static_cast<std::size_t>(mesh.lines.rows()), 0);
  s.points.resize(static_cast<Eigen::Index>(outline.points.size()), 2);
  for (std::size_t k = 0; k < outline.points.size(); ++k) {
    s.points.row(static_cast<Eigen::Index>(k)) = outline.points[k].transpose();
  }
  s.offsets = {0, static_cast<int>(outline.points.size())};
  s.hollow = {static_cast<std::int8_t>(outline.hollow)};
  s.equivalent = {0};
}

// A straight mesh of `n` beams from (0, 0, 0) to `end`.
FlexibleMesh straight_mesh(int n, const Eigen::Vector3d& end) {
  FlexibleMesh mesh;
  mesh.nodes.resize(n + 1, 3);
  mesh.lines.resize(n, 2);
  for (int k = 0; k <= n; ++k) mesh.nodes.row(k) = (end * k / n).transpose();
  for (int k = 0; k < n; ++k) mesh.lines.row(k) << k, k + 1;
  return mesh;
}

// I-beam 300 mm high (y), flanges 150 and 80 mm wide, web 8 mm, flanges 12 and 9 mm thick.
fe::SectionOutline i_outline() {
  const double h = 0.3, bottom = 0.15, top = 0.08, web = 0.008, tb = 0.012, tt = 0.009;
  return fe::centred_polygon(
      {{0.0, -0.5 * bottom}, {0.0, 0.5 * bottom}, {tb, 0.5 * bottom}, {tb, 0.5 * web},
       {h - tt, 0.5 * web}, {h - tt, 0.5 * top}, {h, 0.5 * top}, {h, -0.5 * top},
       {h - tt, -0.5 * top}, {h - tt, -0.5 * web}, {tb, -0.5 * web}, {tb, -0.5 * bottom}});
}

TEST(BeamSolids, EarClippingCoversTheIOutlineWithCounterClockwiseTriangles) {
  const fe::SectionOutline outline = i_outline();
  const auto triangles = triangulate_polygon(outline.points);
  ASSERT_EQ(triangles.size(), outline.points.size() - 2);
  double area = 0.0;
  for (const auto& t : triangles) {
    const double twice = turn(outline.points[t[0]], outline.points[t[1]], outline.points[t[2]]);
    EXPECT_GT(twice, 0.0);
    area += 0.5 * twice;
  }
  // Non-overlapping triangles summing to the shoelace area: an exact cover (round-off only).
  const double expected = fe::polygon_properties(outline).area;
  EXPECT_NEAR(area, expected, 1e-12 * expected);
}

// Checks that `solids` is a closed, consistently outward surface and returns its volume
// (1/6 Σ a·(b × c) over a fan of each cell; exact for planar cells).
double closed_volume(const BeamSolids& solids) {
  std::map<std::pair<int, int>, int> edges;  // directed edge -> uses
  double volume = 0.0;
  for (int c = 0; c < solids.cell_count(); ++c) {
    const int first = solids.cell_offsets[c], n = solids.cell_offsets[c + 1] - first;
    for (int k = 0; k < n; ++k) {
      ++edges[{solids.connectivity[first + k], solids.connectivity[first + (k + 1) % n]}];
    }
    const Eigen::Vector3d a = solids.points_B.row(solids.connectivity[first]).transpose();
    for (int k = 1; k + 1 < n; ++k) {
      const Eigen::Vector3d b = solids.points_B.row(solids.connectivity[first + k]).transpose();
      const Eigen::Vector3d d = solids.points_B.row(solids.connectivity[first + k + 1]).transpose();
      volume += a.dot(b.cross(d)) / 6.0;
    }
  }
  // Closed and oriented: every directed edge once, and its reverse once.
  for (const auto& [edge, uses] : edges) {
    EXPECT_EQ(uses, 1) << edge.first << "-" << edge.second;
    EXPECT_EQ(edges.count({edge.second, edge.first}), 1u) << edge.first << "-" << edge.second;
  }
  return volume;
}

TEST(BeamSolids, SweptIBeamIsClosedAndEnclosesAreaTimesLength) {
  FlexibleMesh mesh = straight_mesh(3, Eigen::Vector3d(0.6, 0.3, -0.2));
  const Eigen::Vector3d y = Eigen::Vector3d::UnitZ().cross(Eigen::Vector3d(0.6, 0.3, -0.2));
  set_sections(mesh, i_outline(), y.normalized());
  const BeamSolids solids = beam_solids(mesh);
  const int n = static_cast<int>(i_outline().points.size());
  EXPECT_EQ(solids.points_B.rows(), 3 * 2 * n);
  EXPECT_EQ(solids.cell_count(), 3 * (n + 2 * (n - 2)));
  const double length = Eigen::Vector3d(0.6, 0.3, -0.2).norm();
  const double expected = fe::polygon_properties(i_outline()).area * length;
  // Positive: the cells face outward. Round-off only.
  EXPECT_NEAR(closed_volume(solids), expected, 1e-12 * expected);
}

TEST(BeamSolids, SweptBoxAndTubeAreClosedAroundTheirHoles) {
  for (const fe::SectionOutline& outline : {fe::box_outline(0.06, 0.04, 0.003, 0.002),
                                            fe::tube_outline(0.04, 0.03)}) {
    FlexibleMesh mesh = straight_mesh(2, Eigen::Vector3d(0.0, 0.0, 0.5));
    set_sections(mesh, outline, Eigen::Vector3d(1.0, 0.0, 0.0));
    const double expected = fe::polygon_properties(outline).area * 0.5;
    EXPECT_NEAR(closed_volume(beam_solids(mesh)), expected, 1e-12 * expected);
  }
}

TEST(BeamSolids, OutlineTurnsWithTheBeamsYAxis) {
  // A 40 (y) x 5 (z) mm rectangle on a beam along body x with its y axis along body z: the
  // 40 mm side then spans body z and the 5 mm side body -y (z_local = x × y = -y_body).
  FlexibleMesh mesh = straight_mesh(1, Eigen::Vector3d(0.2, 0.0, 0.0));
  set_sections(mesh, fe::rectangle_outline(0.04, 0.005), Eigen::Vector3d(0.0, 0.0, 1.0));
  const BeamSolids solids = beam_solids(mesh);
  const Eigen::Vector3d extent = solids.points_B.colwise().maxCoeff() - solids.points_B.colwise().minCoeff();
  EXPECT_NEAR(extent.x(), 0.2, 1e-15);
  EXPECT_NEAR(extent.y(), 0.005, 1e-15);
  EXPECT_NEAR(extent.z(), 0.04, 1e-15);
  // Each point follows the node at its end.
  for (Eigen::Index k = 0; k < solids.points_B.rows(); ++k) {
    EXPECT_EQ(solids.node[k], solids.points_B(k, 0) > 0.1 ? 1 : 0);
  }
}

TEST(BeamSolids, NoSectionsNoSolids) {
  const FlexibleMesh mesh = straight_mesh(2, Eigen::Vector3d(1.0, 0.0, 0.0));
  EXPECT_EQ(beam_solids(mesh).cell_count(), 0);
}

// A 0.2 m bar along ground x at z = 0.3 m, 4 beams, 40 mm along body y and 5 mm along z;
// beam_radius the equal-area tube (7.98 mm); written with or without its sections.
void write_bar(const std::filesystem::path& dir, bool with_sections) {
  results::ResultsWriter writer(dir, "bar", "beam_solids_test.cpp");
  results::FlexibleBodySpec bar;
  bar.name = "bar";
  bar.nodes.resize(5, 3);
  bar.lines.resize(4, 2);
  for (int k = 0; k < 5; ++k) bar.nodes.row(k) << 0.05 * k, 0.0, 0.0;
  for (int k = 0; k < 4; ++k) bar.lines.row(k) << k, k + 1;
  bar.beam_radius = std::sqrt(0.04 * 0.005 / M_PI);
  // One mode of zero shape: the bar stays straight.
  bar.mode_translations = Eigen::MatrixXd::Zero(15, 1);
  bar.frequencies_hz = Eigen::VectorXd::Ones(1);
  if (with_sections) {
    FlexibleMesh mesh;
    mesh.lines = bar.lines;
    set_sections(mesh, fe::rectangle_outline(0.04, 0.005), Eigen::Vector3d::UnitY());
    bar.beam_sections = mesh.beam_sections;
  }
  writer.add_flexible_body(bar);
  for (double t : {0.0, 1.0}) {
    results::Sample sample;
    sample.time = t;
    results::BodySample pose;
    pose.position = Eigen::Vector3d(0.0, 0.0, 0.3);
    pose.modal_coordinates = Eigen::VectorXd::Zero(1);
    pose.modal_velocities = Eigen::VectorXd::Zero(1);
    sample.bodies.push_back(pose);
    writer.append_sample(sample);
  }
  writer.finish(results::RunStatus::kOk);
}

// Drawn pixels across the bar (in the column through its middle, within 300 pixels of its axis,
// clear of the title) over its length between the projections of its end nodes, seen along
// ground `direction`.
double thickness_over_length(const Results& results, const std::array<double, 3>& direction) {
  RenderOptions o;
  o.width = 1280;
  o.height = 960;
  o.camera_direction = direction;
  o.ground = false;
  o.world_triad = false;
  o.time_stamp = false;
  o.joint_axes = false;
  o.anti_aliasing = AntiAliasing::kNone;
  FrameRenderer renderer(results, o, 0.0, 1.0);
  const Image image = renderer.render(0.0);
  const auto background = [&](int x, int y) {
    const auto p = image.pixel(x, y);
    for (int c = 0; c < 3; ++c) {
      if (std::abs(p[c] - static_cast<int>(std::lround(255 * kBackgroundColor[c]))) > 1) return false;
    }
    return true;
  };
  const Eigen::Vector2d start = renderer.project(Eigen::Vector3d(0.0, 0.0, 0.3));
  const Eigen::Vector2d end = renderer.project(Eigen::Vector3d(0.2, 0.0, 0.3));
  const Eigen::Vector2d middle = 0.5 * (start + end);
  const int mx = static_cast<int>(middle.x()), my = static_cast<int>(middle.y());
  int across = 0;
  for (int y = std::max(0, my - 300); y < std::min(image.height, my + 300); ++y) {
    across += background(mx, y) ? 0 : 1;
  }
  const double length = (end - start).norm();
  EXPECT_GT(length, 300.0);
  return across / length;
}

TEST(BeamSolidsPixels, RectangularBarLooksEightTimesThinnerAlongItsWidth) {
  unsetenv("DISPLAY");
  const auto dir = testing::fresh_directory("beam_solids_bar");
  write_bar(dir, true);
  const Results results = read_results(dir);
  ASSERT_FALSE(results.bodies[0].mesh.beam_sections.empty());
  // Seen along y (its 40 mm width) the 5 mm height shows; seen along z, the 40 mm width.
  const double along_width = thickness_over_length(results, {0.0, 1.0, 0.0});
  const double along_height = thickness_over_length(results, {0.0, 0.0, 1.0});
  // 8 in parallel projection. The 5 mm side is about 20 pixels wide, so a pixel at each edge
  // is 10 %, and perspective enlarges the face nearer the eye (20 mm nearer vs 2.5 mm, at
  // about 0.3 m) by a few percent: 15 %. A round tube would give 1.
  EXPECT_NEAR(along_height / along_width, 8.0, 8.0 * 0.15)
      << along_width << " " << along_height;
  // And each against its own size over the 0.2 m length, same tolerance.
  EXPECT_NEAR(along_width, 0.005 / 0.2, 0.15 * 0.025);
  EXPECT_NEAR(along_height, 0.04 / 0.2, 0.15 * 0.2);
}

TEST(BeamSolidsPixels, FileWithoutSectionsStillDrawsTheTube) {
  unsetenv("DISPLAY");
  const auto dir = testing::fresh_directory("beam_solids_tube");
  write_bar(dir, false);
  const Results results = read_results(dir);
  ASSERT_TRUE(results.bodies[0].mesh.beam_sections.empty());
  const double along_width = thickness_over_length(results, {0.0, 1.0, 0.0});
  const double along_height = thickness_over_length(results, {0.0, 0.0, 1.0});
  // A round tube of the equal-area radius (7.98 mm, 12 sides: 3.4 % narrower across its flats)
  // looks the same both ways and 16 mm thick over the 200 mm length, within 15 % as above.
  EXPECT_NEAR(along_height / along_width, 1.0, 0.15);
  EXPECT_NEAR(along_width, 2 * 0.00798 / 0.2, 0.15 * 0.0798);
}

TEST(BeamSolidsFile, InconsistentSectionsAreAnInputErrorNamingTheFile) {
  // An outline index past the table, and a y axis along the beam.
  for (const bool bad_index : {true, false}) {
    const auto dir = testing::fresh_directory("beam_solids_bad");
    {
      results::ResultsWriter writer(dir, "bad", "beam_solids_test.cpp");
      results::FlexibleBodySpec bar;
      bar.name = "bar";
      bar.nodes.resize(2, 3);
      bar.nodes << 0, 0, 0, 0.1, 0, 0;
      bar.lines.resize(1, 2);
      bar.lines << 0, 1;
      bar.mode_translations = Eigen::MatrixXd::Zero(6, 1);
      bar.frequencies_hz = Eigen::VectorXd::Ones(1);
      FlexibleMesh mesh;
      mesh.lines = bar.lines;
      set_sections(mesh, fe::rectangle_outline(0.04, 0.005),
                   bad_index ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX());
      if (bad_index) mesh.beam_sections.outline = {3};
      bar.beam_sections = mesh.beam_sections;
      writer.add_flexible_body(bar);
      writer.finish(results::RunStatus::kOk);
    }
    try {
      read_results(dir);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("results.h5"), std::string::npos) << message;
      EXPECT_NE(message.find(bad_index ? "beam_outline values in 0..0" : "normal to beams"),
                std::string::npos)
          << message;
    }
  }
}

TEST(BeamSolidsExport, VtuCarriesTheSurfaceCellsWithTheirBeamIndex) {
  const auto dir = testing::fresh_directory("beam_solids_vtu");
  write_bar(dir, true);
  const Results results = read_results(dir);
  ASSERT_EQ(write_vtk_series(results, dir / "vtk", 0.0, 1.0), 2);
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((dir / "vtk" / "bar_00000.vtu").c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  // 5 nodes and 4 lines, then per beam 2 x 4 corners and 4 sides + 2 x 2 cap triangles.
  ASSERT_EQ(grid->GetNumberOfPoints(), 5 + 4 * 8);
  ASSERT_EQ(grid->GetNumberOfCells(), 4 + 4 * 8);
  vtkDataArray* beam = grid->GetCellData()->GetArray("beam_index");
  ASSERT_NE(beam, nullptr);
  for (int e = 0; e < 4; ++e) EXPECT_EQ(beam->GetTuple1(e), e);  // the lines
  for (int c = 0; c < 32; ++c) EXPECT_EQ(beam->GetTuple1(4 + c), c / 8);  // their surfaces
  // The surface spans 40 mm along y and 5 mm along z about the bar's axis at z = 0.3 m.
  double bounds[6];
  grid->GetBounds(bounds);
  EXPECT_NEAR(bounds[3] - bounds[2], 0.04, 1e-12);
  EXPECT_NEAR(bounds[5] - bounds[4], 0.005, 1e-12);
  EXPECT_NEAR(0.5 * (bounds[4] + bounds[5]), 0.3, 1e-12);
}

}  // namespace
}  // namespace limber::render
