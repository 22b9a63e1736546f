// End to end: `limber render` through CLI11 on the test scene writes the frames, the series
// and (with ffmpeg installed) a valid MP4 and GIF; bad input is an InputError.
#include "render_command.h"
#include "render_job.h"
#include "video_encoder.h"

#include "core/error.h"
#include "test_dir.h"
#include "test_results.h"

#include <gtest/gtest.h>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>

namespace limber::render {
namespace {

std::string first_bytes(const std::filesystem::path& file, std::size_t n) {
  std::ifstream in(file, std::ios::binary);
  std::string bytes(n, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(n));
  return bytes;
}

// Parses `render args...` and runs the sub-command, as the limber executable does.
int run_render_command(std::vector<std::string> args) {
  CLI::App app("limber");
  const cli::Command command = add_render_command(app);
  args.insert(args.begin(), "render");
  std::reverse(args.begin(), args.end());  // CLI11 parses a reversed vector
  app.parse(args);
  return command.run();
}

TEST(RenderCommand, WritesFramesSeriesAndVideo) {
  unsetenv("DISPLAY");
  const auto dir = testing::fresh_directory("command");
  testing::write_test_results(dir, testing::TestScene{});
  EXPECT_EQ(run_render_command({dir.string(), "--size", "160x120", "--fps", "10", "--t1", "0.5",
                                "--gif", "--no-progress", "--paraview", "both"}),
            0);

  // [0, 0.5] s at 10 frames/s: 6 frames of 160 x 120.
  for (int k = 0; k < 6; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", k);
    vtkNew<vtkPNGReader> reader;
    reader->SetFileName((dir / "frames" / name).c_str());
    reader->Update();
    int dims[3];
    reader->GetOutput()->GetDimensions(dims);
    EXPECT_EQ(dims[0], 160) << name;
    EXPECT_EQ(dims[1], 120) << name;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "frames" / "frame_00006.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "vtk" / "scene.pvd"));
  EXPECT_TRUE(std::filesystem::exists(dir / "vtk" / "plate0_00005.vtu"));
  EXPECT_FALSE(std::filesystem::exists(dir / "vtk" / "plate0_00006.vtu"));
  EXPECT_TRUE(std::filesystem::exists(dir / "vtk" / "scene.xmf"));

  // Videos: an ISO-BMFF 'ftyp' box and a GIF89a header.
  if (!find_ffmpeg()) GTEST_SKIP() << "ffmpeg not installed: video not checked";
  EXPECT_EQ(first_bytes(dir / "animation.mp4", 8).substr(4), "ftyp");
  EXPECT_EQ(first_bytes(dir / "animation.gif", 6), "GIF89a");
}

TEST(RenderCommand, BadInputIsAnInputError) {
  const auto dir = testing::fresh_directory("command_bad");
  // Missing results file and impossible size, through the command (main turns InputError
  // into "limber: error: ..." and exit code 1).
  EXPECT_THROW(run_render_command({dir.string(), "--no-progress"}), InputError);
  EXPECT_THROW(run_render_command({dir.string(), "--size", "0x720"}), InputError);
  // Empty time range and impossible size, through the library call.
  testing::write_test_results(dir, testing::TestScene{});
  RenderOptions options;
  options.directory = dir;
  options.t0 = 5.0;
  options.t1 = 6.0;
  EXPECT_THROW(render_results(options), InputError);
  options = RenderOptions{};
  options.directory = dir;
  options.width = 100000;
  EXPECT_THROW(render_results(options), InputError);
  // Colouring by stress a file without stress output names the case key to add.
  options = RenderOptions{};
  options.directory = dir;
  options.color = ColorBy::kVonMises;
  options.write_video = false;
  options.paraview = ParaViewOutput::kNone;
  options.progress = false;
  try {
    render_results(options);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("expected a results file with stress output"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace limber::render
