#include "video_encoder.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

extern char** environ;

namespace limber::render {

std::optional<std::filesystem::path> find_ffmpeg() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::stringstream directories(path);
  std::string directory;
  while (std::getline(directories, directory, ':')) {
    const std::filesystem::path candidate = std::filesystem::path(directory) / "ffmpeg";
    if (!directory.empty() && access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return std::nullopt;
}

std::string encode_video(const std::filesystem::path& ffmpeg,
                         const std::filesystem::path& frame_directory, double fps,
                         const std::filesystem::path& output) {
  // Arguments: quiet, overwrite, numbered PNG input at the frame rate.
  const std::string rate = std::to_string(fps);
  std::vector<std::string> args = {ffmpeg.string(), "-nostdin", "-hide_banner", "-loglevel",
                                   "error", "-y", "-framerate", rate, "-i",
                                   (frame_directory / "frame_%05d.png").string()};
  if (output.extension() == ".gif") {
    // GIF: reduced rate and width, one palette for the whole clip.
    char filter[160];
    std::snprintf(filter, sizeof filter,
                  "fps=%g,scale='min(640,iw)':-2:flags=lanczos,split[a][b];[a]palettegen[p];"
                  "[b][p]paletteuse",
                  std::min(fps, 15.0));
    args.insert(args.end(), {"-vf", filter});
  } else {
    // MP4: H.264 in yuv420p (needs even sides), playable everywhere.
    args.insert(args.end(), {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264",
                             "-preset", "veryfast", "-crf", "20", "-pix_fmt", "yuv420p",
                             "-movflags", "+faststart"});
  }
  args.push_back(output.string());

  // ffmpeg's stderr goes to a log beside the output, read back on failure.
  const std::filesystem::path log = output.string() + ".log";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, ffmpeg.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return "cannot start " + ffmpeg.string();

  // Wait, then report ffmpeg's own words when it failed.
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
  }
  std::ifstream log_file(log);
  std::stringstream complaint;
  complaint << log_file.rdbuf();
  log_file.close();
  std::error_code ignored;
  std::filesystem::remove(log, ignored);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  const std::string text = complaint.str();
  return "ffmpeg failed writing " + output.string() + (text.empty() ? "" : ": " + text);
}

}  // namespace limber::render
