// The VTU/PVD series read back with VTK's XML readers: point counts, coordinates and
// displacements against the test scene's closed forms, and the PVD's times.
#include "vtk_export.h"

#include "test_dir.h"
#include "test_results.h"

#include <gtest/gtest.h>

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cstdio>
#include <map>

namespace limber::render {
namespace {

using testing::TestScene;

vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const std::filesystem::path& file) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  return reader->GetOutput();
}

TEST(VtkExport, SeriesMatchesTheClosedForms) {
  const auto dir = testing::fresh_directory("vtk");
  const TestScene scene;
  testing::write_test_results(dir, scene);
  const Results results = read_results(dir);
  const int written = write_vtk_series(results, dir / "vtk", 0.0, 1.0);
  EXPECT_EQ(written, 3 * scene.samples);

  // The PVD lists every body at every sample, times exact (printed with 17 digits).
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName((dir / "vtk" / "scene.pvd").c_str());
  ASSERT_EQ(parser->Parse(), 1);
  vtkXMLDataElement* root = parser->GetRootElement();
  ASSERT_STREQ(root->GetName(), "VTKFile");
  EXPECT_STREQ(root->GetAttribute("type"), "Collection");
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  ASSERT_NE(collection, nullptr);
  ASSERT_EQ(collection->GetNumberOfNestedElements(), 3 * scene.samples);
  std::map<std::string, int> per_part;
  for (int e = 0; e < collection->GetNumberOfNestedElements(); ++e) {
    vtkXMLDataElement* dataset = collection->GetNestedElement(e);
    EXPECT_STREQ(dataset->GetName(), "DataSet");
    const int k = e / 3;
    EXPECT_EQ(std::stod(dataset->GetAttribute("timestep")), scene.duration * k / (scene.samples - 1));
    ++per_part[dataset->GetAttribute("part")];
    EXPECT_TRUE(std::filesystem::exists(dir / "vtk" / dataset->GetAttribute("file")));
  }
  EXPECT_EQ(per_part.size(), 3u);

  // Plate at sample k: points = origin + X0, displacement = closed form.
  // Tolerance 1e-14 m: same products, summed in another order, on values <= 0.1 m.
  for (int k : {0, 3, 7}) {
    const double t = scene.duration * k / (scene.samples - 1);
    char name[32];
    std::snprintf(name, sizeof name, "plate0_%05d.vtu", k);
    const auto grid = read_vtu(dir / "vtk" / name);
    ASSERT_EQ(grid->GetNumberOfPoints(), (scene.nx + 1) * (scene.ny + 1));
    EXPECT_EQ(grid->GetNumberOfCells(), scene.nx * scene.ny);
    vtkDataArray* u = grid->GetPointData()->GetArray("displacement");
    vtkDataArray* magnitude = grid->GetPointData()->GetArray("displacement_magnitude");
    ASSERT_NE(u, nullptr);
    ASSERT_NE(magnitude, nullptr);
    for (vtkIdType n = 0; n < grid->GetNumberOfPoints(); ++n) {
      const int i = static_cast<int>(n) % (scene.nx + 1), j = static_cast<int>(n) / (scene.nx + 1);
      const double x = scene.lx * i / scene.nx, y = scene.ly * j / scene.ny;
      const Eigen::Vector3d expected = testing::plate_displacement(scene, x, y, t);
      double* p = grid->GetPoint(n);
      EXPECT_NEAR(p[0], x, 1e-14);
      EXPECT_NEAR(p[1], y, 1e-14);
      EXPECT_NEAR(p[2], testing::plate_origin(0).z(), 1e-14);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(u->GetComponent(n, c), expected(c), 1e-14);
      EXPECT_NEAR(magnitude->GetTuple1(n), expected.norm(), 1e-14);
    }
  }

  // Beam: 21 points on 20 lines; tip displacement (0, B sin, B cos) at t = 0.3 s.
  const auto beam = read_vtu(dir / "vtk" / "beam_00003.vtu");
  ASSERT_EQ(beam->GetNumberOfPoints(), testing::kBeamNodes);
  EXPECT_EQ(beam->GetNumberOfCells(), testing::kBeamNodes - 1);
  const Eigen::Vector3d tip = testing::beam_displacement(scene, testing::kBeamLength, 0.3);
  vtkDataArray* u = beam->GetPointData()->GetArray("displacement");
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(u->GetComponent(testing::kBeamNodes - 1, c), tip(c), 1e-14);

  // Box: its surface centred on the box position (bounds +-0.1 m around it).
  const auto box = read_vtu(dir / "vtk" / "box_00005.vtu");
  double bounds[6];
  box->GetBounds(bounds);
  const Eigen::Vector3d centre = testing::box_position(0.5);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(bounds[2 * c], centre(c) - 0.1, 1e-6);  // vtkCubeSource stores float points
    EXPECT_NEAR(bounds[2 * c + 1], centre(c) + 0.1, 1e-6);
  }
}

TEST(VtkExport, TimeRangeSelectsSamples) {
  const auto dir = testing::fresh_directory("vtk_range");
  testing::write_test_results(dir, TestScene{});
  // Samples at 0.0, 0.1, ..., 1.0 s: [0.25, 0.55] holds 0.3, 0.4, 0.5.
  EXPECT_EQ(write_vtk_series(read_results(dir), dir / "vtk", 0.25, 0.55), 3 * 3);
}

}  // namespace
}  // namespace limber::render
