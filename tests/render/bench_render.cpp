// limber_bench_render: frames per second of `limber render` at 1280 x 720 for a shell scene of
// about 5k nodes (four 35 x 35-quad plates = 4 x 1296 = 5184 nodes, plus a beam and a box),
// PNG writing included, with the split of the time (docs/benchmarks.md). One pass per
// anti-aliasing mode: as `limber render` draws by default (FXAA on the CPU), with VTK's OpenGL
// FXAA pass, and without anti-aliasing; or only the modes named.
//   limber_bench_render [frames=90] [fxaa|gl-fxaa|none ...]
#include "frame_renderer.h"
#include "png_frame_writer.h"
#include "render_job.h"
#include "test_results.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace limber::render;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Renders `frames` frames at 30 frames/s of simulated time, PNG on the writer thread, and
// prints the rate and the per-frame split.
void measure(const Results& results, RenderOptions options, int frames, double duration,
             const char* label) {
  std::filesystem::create_directories(options.directory / "frames");
  const auto start = std::chrono::steady_clock::now();
  FrameRenderer renderer(results, options, 0.0, duration);
  const double setup = seconds_since(start);
  const auto loop = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  double png = 0.0;
  {
    PngFrameWriter writer;
    for (int k = 0; k < frames; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%05d.png", k);
      writer.push(renderer.render(k / 30.0), options.directory / "frames" / name);
    }
    writer.finish();
    png = writer.encode_seconds();
  }
  const double wall = seconds_since(loop);
  // Process CPU time: the render thread, llvmpipe's threads and the PNG writer.
  const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;

  const RenderTiming& t = renderer.timing();
  const double ms = 1e3 / frames;
  std::printf("%s\n", label);
  std::printf("  frames/s (PNG included): %.1f\n", frames / wall);
  std::printf("  set-up (context, scene): %.0f ms\n", 1e3 * setup);
  std::printf("  per frame [ms]: scene update %.2f, draw %.2f, readback %.2f, FXAA on the CPU "
              "%.2f; PNG encode+write %.2f (writer thread); CPU, all threads %.1f\n",
              t.scene_update * ms, t.draw * ms, t.readback * ms, t.smoothing * ms, png * ms,
              cpu * ms);
}

}  // namespace

int main(int argc, char** argv) {
  const int frames = argc > 1 ? std::atoi(argv[1]) : 90;
  std::vector<std::string> modes(argv + std::min(argc, 2), argv + argc);
  if (modes.empty()) modes = {"fxaa", "gl-fxaa", "none"};

  // The scene: four stacked 35 x 35 plates, 3 s of motion sampled at 100 Hz.
  const auto dir = std::filesystem::temp_directory_path() / "limber_bench_render";
  std::filesystem::remove_all(dir);
  testing::TestScene scene;
  scene.plates = 4;
  scene.nx = scene.ny = 35;
  scene.ly = 1.0;
  scene.samples = 301;
  scene.duration = 3.0;
  scene.title = "benchmark: 4 x 35 x 35 quad plates";
  testing::write_test_results(dir, scene);
  const Results results = read_results(dir);
  long nodes = 0;
  for (const BodyTrack& body : results.bodies) nodes += body.mesh.nodes.rows();

  RenderOptions options;
  options.directory = dir;
  options.width = 1280;
  options.height = 720;
  {
    // Only for the header line: the route and the OpenGL renderer.
    FrameRenderer probe(results, options, 0.0, scene.duration);
    std::printf("limber_bench_render: %d frames, 1280x720, %ld nodes, %s, %u hardware threads\n",
                frames, nodes, probe.backend().c_str(), std::thread::hardware_concurrency());
  }
  for (const std::string& mode : modes) {
    options.anti_aliasing = parse_anti_aliasing(mode);
    const std::string label = "--anti-aliasing " + mode +
                              (mode == "fxaa" ? " (default; light kit, colour bar, text)" : "");
    measure(results, options, frames, scene.duration, label.c_str());
  }
  std::filesystem::remove_all(dir);
  return 0;
}
