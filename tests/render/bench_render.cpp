// limber_bench_render: frames per second of `limber render` at 1280 x 720 for a shell scene of
// about 5k nodes (four 35 x 35-quad plates = 4 x 1296 = 5184 nodes, plus a beam and a box),
// PNG writing included, with the split of the time (docs/benchmarks.md).
//   limber_bench_render [frames=90]
#include "frame_renderer.h"
#include "png_frame_writer.h"
#include "render_job.h"
#include "test_results.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  using namespace limber::render;
  const int frames = argc > 1 ? std::atoi(argv[1]) : 90;

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

  // Render `frames` frames at 30 frames/s of simulated time, PNG on the writer thread.
  RenderOptions options;
  options.directory = dir;
  options.width = 1280;
  options.height = 720;
  std::filesystem::create_directories(dir / "frames");
  const auto start = std::chrono::steady_clock::now();
  FrameRenderer renderer(results, options, 0.0, scene.duration);
  const double setup =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto loop = std::chrono::steady_clock::now();
  double png = 0.0;
  {
    PngFrameWriter writer;
    for (int k = 0; k < frames; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%05d.png", k);
      writer.push(renderer.render(k / 30.0), dir / "frames" / name);
    }
    writer.finish();
    png = writer.encode_seconds();
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - loop).count();

  // Report.
  const RenderTiming& t = renderer.timing();
  const double ms = 1e3 / frames;
  std::printf("limber_bench_render: %d frames, 1280x720, %ld nodes, %s\n", frames, nodes,
              renderer.backend().c_str());
  std::printf("  frames/s (PNG included): %.1f\n", frames / wall);
  std::printf("  set-up (context, scene): %.0f ms\n", 1e3 * setup);
  std::printf("  per frame [ms]: scene update %.2f, draw %.2f, readback %.2f; "
              "PNG encode+write %.2f (writer thread)\n",
              t.scene_update * ms, t.draw * ms, t.readback * ms, png * ms);
  std::filesystem::remove_all(dir);
  return 0;
}
