// limber_bench_render: frames per second of `limber render` at 1280 x 720 for a shell scene of
// about 5k nodes (four 35 x 35-quad plates = 4 x 1296 = 5184 nodes, plus a beam and a box),
// PNG writing included, with the split of the time (docs/benchmarks.md). For each
// anti-aliasing mode (all three unless some are named), `--runs` passes of `--frames` frames:
// per pass the rate, the per-frame split, the CPU of this process and of the rest of the
// machine (from /proc/stat, so a pass disturbed by other work shows as such); then the best
// and the median pass. `--keep DIR` leaves the frames of the last pass in DIR.
// `--wait-idle S` waits up to S seconds before each pass for a second in which the machine was
// at least 90 % idle. `--png-table N` times the PNG encoder's settings on N frames.
// `--beam-solids` gives the beam its section (a 40/30 mm tube), drawn as a swept solid
// (render/beam_solids.h) instead of the tube of its radius.
//   limber_bench_render [--frames 90] [--runs 3] [--keep DIR] [--wait-idle S] [--png-table N]
//                       [--beam-solids] [fxaa|gl-fxaa|none ...]
#include "frame_renderer.h"
#include "png_encoding.h"
#include "png_frame_writer.h"
#include "render_job.h"
#include "test_results.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

using namespace limber::render;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Busy and total jiffies of all cores (first line of /proc/stat), in seconds; {0, 0} when
// the file cannot be read.
struct MachineTime {
  double busy = 0.0;
  double total = 0.0;
};
MachineTime machine_time() {
  std::ifstream stat("/proc/stat");
  std::string cpu;
  long long user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0, steal = 0;
  if (!(stat >> cpu >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal)) {
    return {};
  }
  const double tick = static_cast<double>(sysconf(_SC_CLK_TCK));
  const long long busy = user + nice + system + irq + softirq + steal;
  return {busy / tick, (busy + idle + iowait) / tick};
}

// Waits until the machine has been at least `idle` (fraction) idle over one second, checking
// for at most `patience` seconds; returns whether it was.
bool wait_for_idle(double idle, double patience) {
  const auto start = std::chrono::steady_clock::now();
  while (seconds_since(start) < patience) {
    const MachineTime a = machine_time();
    std::this_thread::sleep_for(std::chrono::seconds(1));
    const MachineTime b = machine_time();
    if (b.total - a.total <= 0.0) return false;
    if (1.0 - (b.busy - a.busy) / (b.total - a.total) >= idle) return true;
  }
  return false;
}

struct Pass {
  double fps = 0.0;
  double update_ms = 0.0, draw_ms = 0.0, readback_ms = 0.0, smoothing_ms = 0.0, png_ms = 0.0;
  double cpu_ms = 0.0;    // this process, all threads, per frame
  double other_ms = 0.0;  // the rest of the machine, per frame
  double bytes = 0.0;     // mean PNG file size
};

// Renders `frames` frames at 30 frames/s of simulated time, PNG on the writer threads.
Pass measure(const Results& results, const RenderOptions& options, int frames, double duration) {
  std::filesystem::remove_all(options.directory / "frames");
  std::filesystem::create_directories(options.directory / "frames");
  FrameRenderer renderer(results, options, 0.0, duration);
  const MachineTime machine_start = machine_time();
  const std::clock_t cpu_start = std::clock();
  const auto loop = std::chrono::steady_clock::now();
  double png = 0.0;
  double smoothing = 0.0;
  {
    PngFrameWriter writer;
    for (int k = 0; k < frames; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%05d.png", k);
      // As render_results() does: the CPU FXAA on the writers.
      auto [image, smooth] = renderer.render_deferred(k / 30.0);
      writer.push(std::move(image), options.directory / "frames" / name, std::move(smooth));
    }
    writer.finish();
    png = writer.encode_seconds();
    smoothing = writer.prepare_seconds();
  }
  const double wall = seconds_since(loop);
  // Process CPU time: the render thread, llvmpipe's threads and the PNG writers.
  const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const MachineTime machine_end = machine_time();

  double bytes = 0.0;
  for (const auto& entry : std::filesystem::directory_iterator(options.directory / "frames")) {
    bytes += static_cast<double>(entry.file_size());
  }
  const RenderTiming& t = renderer.timing();
  const double ms = 1e3 / frames;
  Pass pass;
  pass.fps = frames / wall;
  pass.update_ms = t.scene_update * ms;
  pass.draw_ms = t.draw * ms;
  pass.readback_ms = t.readback * ms;
  pass.smoothing_ms = smoothing * ms;
  pass.png_ms = png * ms;
  pass.cpu_ms = cpu * ms;
  pass.other_ms = std::max(0.0, (machine_end.busy - machine_start.busy) - cpu) * ms;
  pass.bytes = bytes / frames;
  return pass;
}

// CPU time of the calling thread [s]: unlike wall time, hardly changed by other processes.
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The PNG encoder's CPU time and size per setting, on `frames` frames of the default
// rendering (best of 3 encodings per frame, encoding only: no file written).
void png_table(const Results& results, RenderOptions options, int frames, double duration) {
  options.anti_aliasing = AntiAliasing::kFxaa;
  std::vector<Image> images;
  {
    FrameRenderer renderer(results, options, 0.0, duration);
    for (int k = 0; k < frames; ++k) images.push_back(renderer.render(duration * k / frames));
  }
  std::printf("PNG encoding (CPU time, one thread), %d frames of the default rendering:\n", frames);
  for (const PngFilter filter : {PngFilter::kNone, PngFilter::kSub}) {
    for (const int level : {1, 2, 4, 6, 9}) {
      PngEncoder encoder({filter, level});
      double seconds = 0.0, bytes = 0.0;
      for (const Image& image : images) {
        double best = 1e300;
        for (int r = 0; r < 3; ++r) {
          const double start = thread_cpu_seconds();
          const std::size_t size = encoder.encode(image).size();
          best = std::min(best, thread_cpu_seconds() - start);
          if (r == 0) bytes += static_cast<double>(size);
        }
        seconds += best;
      }
      std::printf("  filter %-4s level %d: %5.2f ms, %6.1f KiB per frame\n",
                  filter == PngFilter::kSub ? "Sub" : "None", level, 1e3 * seconds / frames,
                  bytes / frames / 1024.0);
    }
  }
}

void print(const char* what, const Pass& p) {
  std::printf("  %-7s %5.1f frames/s | update %.2f, draw %.2f, readback %.2f ms; on the writers: "
              "FXAA %.2f, PNG %.2f ms | CPU %.1f ms, other processes %.1f ms | PNG %.0f KiB\n",
              what, p.fps, p.update_ms, p.draw_ms, p.readback_ms, p.smoothing_ms, p.png_ms,
              p.cpu_ms, p.other_ms, p.bytes / 1024.0);
}

}  // namespace

int main(int argc, char** argv) {
  int frames = 90;
  int runs = 3;
  std::filesystem::path keep;
  double patience = 0.0;
  int table_frames = 0;
  bool beam_solids = false;
  std::vector<std::string> modes;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--frames" && i + 1 < argc) frames = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--keep" && i + 1 < argc) keep = argv[++i];
    else if (arg == "--wait-idle" && i + 1 < argc) patience = std::atof(argv[++i]);
    else if (arg == "--png-table" && i + 1 < argc) table_frames = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--beam-solids") beam_solids = true;
    else if (arg == "fxaa" || arg == "gl-fxaa" || arg == "none") modes.push_back(arg);
    else {
      std::fprintf(stderr,
                   "usage: limber_bench_render [--frames 90] [--runs 3] [--keep DIR] "
                   "[--wait-idle S] [--png-table N] [--beam-solids] [fxaa|gl-fxaa|none ...]\n");
      return 2;
    }
  }
  if (modes.empty() && table_frames == 0) modes = {"fxaa", "gl-fxaa", "none"};

  // The scene: four stacked 35 x 35 plates, 3 s of motion sampled at 100 Hz.
  const auto dir = std::filesystem::temp_directory_path() / "limber_bench_render";
  std::filesystem::remove_all(dir);
  testing::TestScene scene;
  scene.plates = 4;
  scene.beam_tube_section = beam_solids;
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
    std::printf("limber_bench_render: %d frames x %d runs, 1280x720, %ld nodes, %s, "
                "%u hardware threads\n",
                frames, runs, nodes, probe.backend().c_str(),
                std::thread::hardware_concurrency());
  }
  for (const std::string& mode : modes) {
    options.anti_aliasing = parse_anti_aliasing(mode);
    std::printf("--anti-aliasing %s%s\n", mode.c_str(),
                mode == "fxaa" ? " (default; light kit, colour bar, text)" : "");
    std::vector<Pass> passes;
    for (int r = 0; r < runs; ++r) {
      if (patience > 0.0 && !wait_for_idle(0.9, patience)) {
        std::printf("  (the machine was not 90 %% idle within %g s: measuring anyway)\n", patience);
      }
      passes.push_back(measure(results, options, frames, scene.duration));
      print(("run " + std::to_string(r + 1)).c_str(), passes.back());
    }
    std::sort(passes.begin(), passes.end(),
              [](const Pass& a, const Pass& b) { return a.fps > b.fps; });
    print("best", passes.front());
    print("median", passes[passes.size() / 2]);
  }
  if (table_frames > 0) png_table(results, options, table_frames, scene.duration);
  if (!keep.empty() && !modes.empty()) {
    std::filesystem::remove_all(keep);
    std::filesystem::create_directories(keep.parent_path().empty() ? "." : keep.parent_path());
    std::filesystem::copy(dir / "frames", keep, std::filesystem::copy_options::recursive);
  }
  std::filesystem::remove_all(dir);
  return 0;
}
