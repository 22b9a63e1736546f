#include "run/linear_mat_file.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <matio.h>

namespace limber::run {

namespace {

// An open .mat file that writes named variables, naming the file and variable on failure.
class MatWriter {
 public:
  explicit MatWriter(std::string file)
      : file_(std::move(file)), mat_(Mat_CreateVer(file_.c_str(), nullptr, MAT_FT_MAT5), &Mat_Close) {
    if (!mat_) throw std::runtime_error(fmt::format("cannot create {}", file_));
  }

  // A double matrix (matio wants column-major, as Eigen's default).
  void matrix(const char* name, const Eigen::MatrixXd& value) {
    std::size_t dims[2] = {static_cast<std::size_t>(value.rows()), static_cast<std::size_t>(value.cols())};
    write(name, Mat_VarCreate(name, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, const_cast<double*>(value.data()),
                              MAT_F_DONT_COPY_DATA));
  }

  // A column cell array of char rows.
  void strings(const char* name, const std::vector<std::string>& values) {
    std::size_t dims[2] = {values.size(), 1};
    matvar_t* cell = Mat_VarCreate(name, MAT_C_CELL, MAT_T_CELL, 2, dims, nullptr, 0);
    if (!cell) fail(name);
    for (std::size_t k = 0; k < values.size(); ++k) {
      std::size_t text_dims[2] = {1, values[k].size()};
      // Copied (no MAT_F_DONT_COPY_DATA): the cell frees its elements' data with itself.
      matvar_t* text = Mat_VarCreate(nullptr, MAT_C_CHAR, MAT_T_UTF8, 2, text_dims,
                                     const_cast<char*>(values[k].data()), 0);
      if (!text) {
        Mat_VarFree(cell);
        fail(name);
      }
      Mat_VarSetCell(cell, static_cast<int>(k), text);
    }
    write(name, cell);
  }

 private:
  void write(const char* name, matvar_t* variable) {
    if (!variable) fail(name);
    const int status = Mat_VarWrite(mat_.get(), variable, MAT_COMPRESSION_NONE);
    Mat_VarFree(variable);
    if (status != 0) fail(name);
  }
  [[noreturn]] void fail(const char* name) const {
    throw std::runtime_error(fmt::format("cannot write {} in {}", name, file_));
  }
  std::string file_;
  std::unique_ptr<mat_t, decltype(&Mat_Close)> mat_;
};

}  // namespace

std::filesystem::path write_linear_mat(const multibody::Model& model, const LinearizeSummary& summary,
                                       const std::filesystem::path& directory) {
  std::filesystem::create_directories(directory);
  const std::filesystem::path path = directory / "linear.mat";
  MatWriter mat(path.string());
  const multibody::StateSpace& ss = summary.state_space;
  mat.matrix("A", ss.A);
  mat.matrix("B", ss.B);
  mat.matrix("C", ss.C);
  mat.matrix("D", ss.D);
  mat.matrix("M", summary.tangent.M);
  mat.matrix("C_damping", summary.tangent.C);
  mat.matrix("K", summary.tangent.K);
  mat.matrix("Z", ss.Z);  // the states' basis: the joints' Z, grown by released drivers
  mat.matrix("frequencies_hz", summary.modes.frequencies_hz);
  mat.matrix("damping_ratios", summary.modes.damping);
  mat.matrix("undamped_hz", summary.modes.undamped_hz);
  mat.strings("state_names", ss.state_names);
  mat.strings("input_names", ss.input_names);
  mat.strings("output_names", ss.output_names);
  mat.strings("coordinate_names", coordinate_names(model));
  return path;
}

}  // namespace limber::run
