// ParaView itself opens the VTU/PVD series: its PVD reader (pvpython, tests/render/
// paraview_check.py) finds every time step and the points of every body. Skipped when pvpython
// is not installed (Debian: package python3-paraview, which conflicts with libvtk9-dev on
// Debian 12, so a limber build machine usually lacks it).
#include "vtk_export.h"

#include "test_dir.h"
#include "test_results.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>

namespace limber::render {
namespace {

// Path of pvpython on PATH, if any.
std::optional<std::filesystem::path> find_pvpython() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::stringstream directories(path);
  std::string directory;
  while (std::getline(directories, directory, ':')) {
    const auto candidate = std::filesystem::path(directory) / "pvpython";
    if (!directory.empty() && access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return std::nullopt;
}

TEST(ParaView, OpensTheSeriesWithEveryTimeAndPoint) {
  const auto pvpython = find_pvpython();
  if (!pvpython) {
    GTEST_SKIP() << "pvpython not on PATH: ParaView's reader not tried (Debian package "
                    "python3-paraview; it conflicts with libvtk9-dev on Debian 12)";
  }
  const auto dir = testing::fresh_directory("paraview");
  testing::write_test_results(dir, testing::TestScene{});
  const Results results = read_results(dir);
  write_vtk_series(results, dir / "vtk", results.time(0), results.time(results.time.size() - 1));

  // Expected points: every body's VTU of the first sample, read with VTK's reader.
  long points = 0;
  for (const BodyTrack& body : results.bodies) {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((dir / "vtk" / (body.name + "_00000.vtu")).c_str());
    reader->Update();
    points += reader->GetOutput()->GetNumberOfPoints();
  }
  ASSERT_GT(points, 0);

  // pvpython paraview_check.py scene.pvd POINTS TIME...; stdout and stderr into a log.
  std::string command = pvpython->string() + " " + LIMBER_PARAVIEW_CHECK + " " +
                        (dir / "vtk" / "scene.pvd").string() + " " + std::to_string(points);
  for (Eigen::Index i = 0; i < results.time.size(); ++i) {
    char time[32];
    std::snprintf(time, sizeof time, " %.17g", results.time(i));
    command += time;
  }
  const auto log = dir / "pvpython.log";
  const int status = std::system(("env -u DISPLAY " + command + " >" + log.string() + " 2>&1").c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command << "\n" << text.str();
}

}  // namespace
}  // namespace limber::render
