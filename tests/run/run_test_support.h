// Helpers of the run tests: case files edited from the shipped ones, fresh output directories,
// the `limber` command run as a user would (popen), and HDF5 string datasets.
#pragma once

#include <hdf5.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace limber::test {

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The case at `path` with the first `from` replaced by `to` (throws when `from` is absent).
inline std::string edited_case(const std::string& path, const std::string& from, const std::string& to) {
  std::string text = read_text(path);
  const std::size_t at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("edited_case: '" + from + "' not in " + path);
  return text.replace(at, from.size(), to);
}

// An empty directory under the test temp dir, unique per process.
inline std::filesystem::path fresh_directory(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("limber_run_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

// Writes `text` as <temp>/limber_run_<name>_<pid>.yaml and returns its path.
inline std::string write_case(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("limber_run_" + name + "_" + std::to_string(getpid()) + ".yaml");
  std::ofstream(path) << text;
  return path.string();
}

struct CommandRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Runs `executable ARGS`, capturing stdout, stderr and the exit code.
inline CommandRun run_command(const std::string& executable, const std::string& args) {
  static int calls = 0;
  const auto err_path = std::filesystem::temp_directory_path() /
                        ("limber_run_stderr_" + std::to_string(getpid()) + "_" + std::to_string(++calls));
  const std::string command = executable + " " + args + " 2>" + err_path.string();
  CommandRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  char buffer[4096];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) run.out.append(buffer, n);
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.err = read_text(err_path.string());
  std::filesystem::remove(err_path);
  return run;
}

// A one-dimensional dataset of fixed-length strings (as the results writer stores them).
inline std::vector<std::string> read_fixed_strings(hid_t file, const std::string& path) {
  const hid_t dataset = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (dataset < 0) return {};
  const hid_t type = H5Dget_type(dataset);
  const hid_t space = H5Dget_space(dataset);
  const std::size_t width = H5Tget_size(type);
  const auto count = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
  std::string packed(width * count, '\0');
  if (count > 0) H5Dread(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, packed.data());
  std::vector<std::string> values;
  for (std::size_t k = 0; k < count; ++k) {
    const std::string value = packed.substr(k * width, width);
    values.push_back(value.substr(0, value.find('\0')));
  }
  H5Sclose(space);
  H5Tclose(type);
  H5Dclose(dataset);
  return values;
}

}  // namespace limber::test
