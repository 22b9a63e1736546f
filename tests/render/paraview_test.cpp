// ParaView itself opens limber's output (pvpython on tests/render/paraview_check.py): the
// VTU/PVD series with its PVD reader; the one-file scene (scene.xmf over scene.h5) with both of
// its XDMF readers, every time step against the VTUs of the same sample and one deformed point
// against the closed form; and
// open_in_paraview.py under pvbatch saves a screenshot of the ready view. Skipped when pvpython
// (pvbatch, and xvfb-run for its display) is not installed: scripts/install-paraview.sh, which
// the README's test command runs, installs them.
#include "render_job.h"
#include "vtk_export.h"
#include "xdmf_export.h"
#include "xdmf_grids.h"

#include "test_dir.h"
#include "test_results.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkUnsignedCharArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>

namespace limber::render {
namespace {

// Path of `program` on PATH, if any.
std::optional<std::filesystem::path> find_program(const char* program) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::stringstream directories(path);
  std::string directory;
  while (std::getline(directories, directory, ':')) {
    const auto candidate = std::filesystem::path(directory) / program;
    if (!directory.empty() && access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return std::nullopt;
}

// Runs `command` without a display, its output into `log`; "" when it exits with 0, else the
// command and its output.
std::string run(const std::string& command, const std::filesystem::path& log) {
  // xvfb-run's X server sometimes is not up when pvbatch connects on a loaded machine ("bad X
  // server connection", seen in CI rehearsals): that is the harness, not ParaView or the
  // script, so such a run is tried once more; any other failure is reported at once.
  std::string text;
  for (int attempt = 0; attempt < 2; ++attempt) {
    const int status = std::system(("env -u DISPLAY " + command + " >" + log.string() + " 2>&1").c_str());
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
    std::ifstream in(log);
    std::stringstream read;
    read << in.rdbuf();
    text = read.str();
    if (text.find("bad X server connection") == std::string::npos) break;
  }
  return command + "\n" + text;
}

// " t0 t1 ..." with 17 significant digits.
std::string time_arguments(const Results& results) {
  std::string text;
  for (Eigen::Index i = 0; i < results.time.size(); ++i) {
    char time[32];
    std::snprintf(time, sizeof time, " %.17g", results.time(i));
    text += time;
  }
  return text;
}

#define REQUIRE_PROGRAM(variable, name)                                                         \
  const auto variable = find_program(name);                                                   \
  if (!variable) {                                                                            \
    GTEST_SKIP() << name " not on PATH: ParaView not tried (scripts/install-paraview.sh "     \
                    "installs it)";                                                           \
  }

TEST(ParaView, OpensTheSeriesWithEveryTimeAndPoint) {
  REQUIRE_PROGRAM(pvpython, "pvpython");
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
  EXPECT_EQ(run(pvpython->string() + " " + LIMBER_PARAVIEW_CHECK + " pvd " +
                    (dir / "vtk" / "scene.pvd").string() + " " + std::to_string(points) +
                    time_arguments(results),
                dir / "pvpython.log"),
            "");
}

// The test scene without and with its beam's section (a hollow tube: its swept surface's
// points and cells follow the mesh's in both files): both readers give one grid per time step,
// the VTUs' points, cells and arrays one after the other.
TEST(ParaView, BothXdmfReadersReadEveryStepAsTheVtuSeries) {
  REQUIRE_PROGRAM(pvpython, "pvpython");
  for (const bool section : {false, true}) {
    const auto dir = testing::fresh_directory(section ? "paraview_xdmf_section" : "paraview_xdmf");
    testing::TestScene scene;
    scene.beam_tube_section = section;
    testing::write_test_results(dir, scene);
    const Results results = read_results(dir);
    const double t0 = results.time(0), t1 = results.time(results.time.size() - 1);
    write_xdmf_scene(results, dir / "vtk", t0, t1, false);
    write_vtk_series(results, dir / "vtk", t0, t1);

    // The grid's points (every body's, one after the other in results.h5's order), and the
    // plate's far corner node (lx, ly) at t = 0.3 s (the plate bent; flat at the last sample):
    // origin + (lx, ly, 0) + u, u the closed form results.h5 holds (the plate frame is not
    // turned).
    long points = 0, corner = -1;
    for (const BodyTrack& body : results.bodies) {
      if (body.name == "plate0") corner = points + (scene.nx + 1) * (scene.ny + 1) - 1;
      points += body_grid(body).points_B.rows();
    }
    ASSERT_GE(corner, 0);
    const double t = results.time(3);
    ASSERT_GT(testing::plate_displacement(scene, scene.lx, scene.ly, t).norm(), 1e-3);
    const Eigen::Vector3d x = testing::plate_origin(0) + Eigen::Vector3d(scene.lx, scene.ly, 0.0) +
                              testing::plate_displacement(scene, scene.lx, scene.ly, t);
    char point[160];
    std::snprintf(point, sizeof point, " %ld %ld %.17g %.17g %.17g %.17g", points, corner, t, x.x(), x.y(), x.z());
    for (const char* reader : {"xdmf", "xdmf3"}) {
      EXPECT_EQ(run(pvpython->string() + " " + LIMBER_PARAVIEW_CHECK + " " + reader + " " +
                        (dir / "vtk" / "scene.xmf").string() + point + time_arguments(results),
                    dir / (std::string(reader) + ".log")),
                "")
          << (section ? "with the beam's section" : "without sections");
    }
  }
}

// The screenshot of the test scene: the frame size asked for; the bodies in the colour map's
// low end, as the video: at the last sample (t = 1 s) the plate is flat (sin 2 pi = 0) and the
// box rigid, both drawn in viridis's lowest colour, RGB (68, 1, 84), shaded by the lights (red
// and blue well above green), on over 1 % of the pixels; over a quarter the render's
// background (219, 227, 237).
void expect_bodies_on_background(const std::filesystem::path& png, const RenderOptions& options) {
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(png.c_str());
  reader->Update();
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  EXPECT_EQ(dims[0], options.width);
  EXPECT_EQ(dims[1], options.height);
  vtkUnsignedCharArray* pixels =
      vtkUnsignedCharArray::SafeDownCast(reader->GetOutput()->GetPointData()->GetScalars());
  ASSERT_NE(pixels, nullptr);
  const int channels = pixels->GetNumberOfComponents();
  long body = 0, background = 0;
  for (vtkIdType p = 0; p < pixels->GetNumberOfTuples(); ++p) {
    const int r = pixels->GetValue(p * channels), g = pixels->GetValue(p * channels + 1),
              b = pixels->GetValue(p * channels + 2);
    if (b > 40 && b > g + 40 && r > g + 30) ++body;
    if (std::abs(r - 219) <= 2 && std::abs(g - 227) <= 2 && std::abs(b - 237) <= 2) ++background;
  }
  const long total = static_cast<long>(dims[0]) * dims[1];
  EXPECT_GT(body, total / 100) << "body pixels";
  EXPECT_GT(background, total / 4) << "background pixels";
}

TEST(ParaView, StateScriptSavesTheViewUnderPvbatch) {
  REQUIRE_PROGRAM(pvbatch, "pvbatch");
  // Debian's ParaView draws through X: without a display, in a virtual one (package xvfb).
  const auto xvfb_run = find_program("xvfb-run");
  if (!xvfb_run) GTEST_SKIP() << "xvfb-run not on PATH: pvbatch has no display to draw in (scripts/install-paraview.sh "
                                 "installs it)";
  const auto dir = testing::fresh_directory("paraview_script");
  testing::write_test_results(dir, testing::TestScene{});
  RenderOptions options;
  options.directory = dir;
  options.write_png = false;
  options.write_video = false;
  options.progress = false;
  options.width = 400;
  options.height = 300;
  options.scale = 5.0;
  render_results(options);

  // The folder moved (as when mailed): the script finds scene.xmf beside itself, not where it
  // was written (now gone).
  const auto moved = testing::fresh_directory("paraview_script_moved");
  std::filesystem::remove_all(moved);
  std::filesystem::rename(dir, moved);
  const auto png = moved / "view.png";
  ASSERT_EQ(run(xvfb_run->string() + " -a " + pvbatch->string() + " " + (moved / "vtk" / "open_in_paraview.py").string() +
                    " --screenshot " + png.string(),
                moved / "pvbatch.log"),
            "");
  expect_bodies_on_background(png, options);
}

TEST(ParaView, StateScriptFindsItsFolderWithoutFile) {
  // As under `paraview --script=PATH`: the script's text run without __file__, from another
  // directory, with "--script=PATH" on the command line; the folder moved after the render.
  REQUIRE_PROGRAM(pvbatch, "pvbatch");
  const auto xvfb_run = find_program("xvfb-run");
  if (!xvfb_run) GTEST_SKIP() << "xvfb-run not on PATH: pvbatch has no display to draw in";
  const auto written = testing::fresh_directory("paraview_no_file");
  testing::write_test_results(written, testing::TestScene{});
  RenderOptions options;
  options.directory = written;
  options.write_png = false;
  options.write_video = false;
  options.progress = false;
  options.width = 200;
  options.height = 150;
  render_results(options);
  const auto moved = testing::fresh_directory("paraview_no_file_moved");
  std::filesystem::remove_all(moved);
  std::filesystem::rename(written, moved);

  const auto script = moved / "vtk" / "open_in_paraview.py";
  const auto png = moved / "view.png";
  const auto runner = moved / "runner.py";
  std::ofstream(runner) << "import sys\n"
                           "sys.argv = ['paraview', '--script=" << script.string() << "', '--screenshot', '"
                        << png.string() << "']\n"
                           "exec(compile(open(sys.argv[1].split('=', 1)[1]).read(), 'script', 'exec'), "
                           "{'__name__': '__main__'})\n";
  ASSERT_EQ(run(xvfb_run->string() + " -a " + pvbatch->string() + " " + runner.string(), moved / "pvbatch.log"), "");
  // Without its folder the view would be empty: the bodies show.
  expect_bodies_on_background(png, options);
}

}  // namespace
}  // namespace limber::render
