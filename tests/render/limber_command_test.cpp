// `limber render` and the mode-shape animations of `limber modes`, run as a user would (the
// built executable, DISPLAY unset): files, frame sizes, exit codes, and a mode moving between
// two frames where the body is.
#include "scene.h"
#include "test_dir.h"
#include "test_results.h"
#include "video_encoder.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace limber::render {
namespace {

struct CommandRun {
  int exit_code = -1;
  std::string out, err;
};

std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs `limber ARGS` with DISPLAY unset; stdout and stderr kept.
CommandRun run_limber(const std::string& args, const std::filesystem::path& dir) {
  const std::filesystem::path out = dir / "stdout.txt";
  const std::filesystem::path err = dir / "stderr.txt";
  const std::string command = "env -u DISPLAY " + std::string(LIMBER_EXE) + " " + args + " >" +
                              out.string() + " 2>" + err.string();
  const int status = std::system(command.c_str());
  CommandRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = file_text(out);
  run.err = file_text(err);
  return run;
}

// A PNG frame as RGB rows from the top (VTK reads rows bottom-up).
struct Png {
  int width = 0, height = 0;
  std::vector<std::array<int, 3>> pixels;
  const std::array<int, 3>& at(int x, int y) const { return pixels[y * width + x]; }
};

Png read_png(const std::filesystem::path& file) {
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  Png png{dims[0], dims[1], {}};
  for (int y = 0; y < png.height; ++y) {
    for (int x = 0; x < png.width; ++x) {
      std::array<int, 3> p{};
      for (int c = 0; c < 3; ++c) {
        p[c] = static_cast<int>(image->GetScalarComponentAsDouble(x, png.height - 1 - y, 0, c));
      }
      png.pixels.push_back(p);
    }
  }
  return png;
}

// Frames are 8-bit: a flat colour comes back within 1 of round(255 c).
bool is_background(const std::array<int, 3>& p) {
  for (int c = 0; c < 3; ++c) {
    if (std::abs(p[c] - static_cast<int>(std::lround(255 * kBackgroundColor[c]))) > 1) return false;
  }
  return true;
}

TEST(LimberRender, RendersTheTestSceneAndRejectsAMissingFile) {
  const auto dir = testing::fresh_directory("cli_render");
  testing::write_test_results(dir, testing::TestScene{});
  const CommandRun ok = run_limber("render " + dir.string() +
                                       " --size 160x120 --fps 4 --no-video --no-progress",
                                   dir);
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  // [0, 1] s at 4 frames/s: 5 frames.
  EXPECT_TRUE(std::filesystem::exists(dir / "frames" / "frame_00004.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "frames" / "frame_00005.png"));
  // The default ParaView output: the one-file scene and its script, no VTU series.
  EXPECT_TRUE(std::filesystem::exists(dir / "vtk" / "scene.xmf"));
  EXPECT_TRUE(std::filesystem::exists(dir / "vtk" / "scene.h5"));
  EXPECT_TRUE(std::filesystem::exists(dir / "vtk" / "open_in_paraview.py"));
  EXPECT_FALSE(std::filesystem::exists(dir / "vtk" / "scene.pvd"));

  // --paraview pvd: the VTU series replaces the scene of the earlier render.
  const CommandRun pvd = run_limber("render " + dir.string() +
                                        " --size 160x120 --fps 4 --no-video --no-progress --paraview pvd",
                                    dir);
  EXPECT_EQ(pvd.exit_code, 0) << pvd.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "vtk" / "scene.pvd"));
  EXPECT_FALSE(std::filesystem::exists(dir / "vtk" / "scene.xmf"));
  const CommandRun bad = run_limber("render " + dir.string() + " --paraview vtk", dir);
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("--paraview: expected xdmf, pvd, both or none, got 'vtk'"), std::string::npos) << bad.err;

  // Bad input: "limber: error: expected ..., got ..." and exit code 1.
  const auto empty = testing::fresh_directory("cli_render_missing");
  const CommandRun missing = run_limber("render " + empty.string(), empty);
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("limber: error: expected a results file"), std::string::npos)
      << missing.err;
  const CommandRun size = run_limber("render " + dir.string() + " --size 100000x2", dir);
  EXPECT_EQ(size.exit_code, 1);
  const CommandRun mode = run_limber("render " + dir.string() + " --anti-aliasing msaa", dir);
  EXPECT_EQ(mode.exit_code, 1);
  EXPECT_NE(mode.err.find("expected fxaa, gl-fxaa or none, got 'msaa'"), std::string::npos)
      << mode.err;
  const CommandRun both =
      run_limber("render " + dir.string() + " --no-fxaa --anti-aliasing gl-fxaa", dir);
  EXPECT_EQ(both.exit_code, 1);
}

TEST(LimberRender, SlowMotionSetsTheSamplingAndThePlaybackRateStays) {
  const auto dir = testing::fresh_directory("cli_slow_motion");
  testing::write_test_results(dir, testing::TestScene{});
  // [0.2, 0.3] s at 10x slow motion and 20 frames/s playback: 200 frames per simulated second,
  // 21 frames, 1.05 s of video.
  const CommandRun slow = run_limber("render " + dir.string() +
                                         " --size 160x120 --t0 0.2 --t1 0.3 --slow-motion 10 "
                                         "--playback-fps 20 --no-video --no-vtk --no-progress",
                                     dir);
  ASSERT_EQ(slow.exit_code, 0) << slow.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "frames" / "frame_00020.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "frames" / "frame_00021.png"));
  EXPECT_NE(slow.out.find("200 frames per simulated second played at 20 frames/s: 10x slow "
                          "motion, 1.05 s of video"),
            std::string::npos)
      << slow.out;
  // --fps and --slow-motion both set the sampling: one or the other.
  const CommandRun both = run_limber("render " + dir.string() + " --fps 10 --slow-motion 2", dir);
  EXPECT_EQ(both.exit_code, 1);
  const CommandRun playback = run_limber("render " + dir.string() + " --playback-fps 0", dir);
  EXPECT_EQ(playback.exit_code, 1);
  EXPECT_NE(playback.err.find("--playback-fps: expected a frame rate in (0, 1000]"), std::string::npos)
      << playback.err;
}

TEST(LimberModes, AnimatesEveryModeOfThePlate) {
  const auto dir = testing::fresh_directory("cli_modes");
  const CommandRun run = run_limber("modes " + std::string(LIMBER_CASES_DIR) +
                                        "/plate_modes.yaml -o " + dir.string() +
                                        " --animation-size 160x120",
                                    dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;

  // 8 modes (6 normal, 2 constraint) of 24 frames, 160 x 120.
  const std::filesystem::path modes = dir / "modes" / "plate";
  for (int mode = 1; mode <= 8; ++mode) {
    char name[16];
    std::snprintf(name, sizeof name, "mode_%02d", mode);
    EXPECT_TRUE(std::filesystem::exists(modes / name / "frame_00023.png")) << name;
    EXPECT_FALSE(std::filesystem::exists(modes / name / "frame_00024.png")) << name;
  }
  EXPECT_FALSE(std::filesystem::exists(modes / "mode_09"));

  // Mode 1 at rest (frame 0) and at its peak (frame 6, a quarter period): same size, and they
  // differ, only where the plate is (the title and colour bar are the same in both frames).
  const Png rest = read_png(modes / "mode_01" / "frame_00000.png");
  const Png peak = read_png(modes / "mode_01" / "frame_00006.png");
  ASSERT_EQ(rest.width, 160);
  ASSERT_EQ(rest.height, 120);
  ASSERT_EQ(peak.width, 160);
  ASSERT_EQ(peak.height, 120);
  int changed = 0, changed_off_body = 0;
  for (int y = 0; y < rest.height; ++y) {
    for (int x = 0; x < rest.width; ++x) {
      if (rest.at(x, y) == peak.at(x, y)) continue;
      ++changed;
      if (is_background(rest.at(x, y)) && is_background(peak.at(x, y))) ++changed_off_body;
      // Title band (top 10 %) and colour bar box are the same in every frame of a mode.
      const bool in_title = y < rest.height / 10;
      const bool in_bar = x >= kColorBarBox[0] * rest.width;
      EXPECT_FALSE(in_title || in_bar) << "pixel (" << x << ", " << y << ") changed";
    }
  }
  // The tip moves by 10 % of the plate's diagonal: hundreds of pixels change at 160 x 120.
  EXPECT_GT(changed, 100);
  EXPECT_EQ(changed_off_body, 0);

  if (!find_ffmpeg()) GTEST_SKIP() << "ffmpeg not installed: GIFs not checked";
  EXPECT_TRUE(std::filesystem::exists(modes / "mode_01.gif"));
  EXPECT_TRUE(std::filesystem::exists(modes / "mode_08.gif"));
}

TEST(LimberModes, NoAnimationWritesNoFrames) {
  const auto dir = testing::fresh_directory("cli_modes_off");
  const CommandRun run = run_limber("modes " + std::string(LIMBER_CASES_DIR) +
                                        "/plate_modes.yaml -o " + dir.string() + " --no-animation",
                                    dir);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "modes.h5"));
  EXPECT_FALSE(std::filesystem::exists(dir / "modes"));
}

}  // namespace
}  // namespace limber::render
