#include "results_reader.h"

#include "core/error.h"

#include <hdf5.h>

#include <algorithm>
#include <utility>

namespace limber::render {
namespace {

// Owns an HDF5 identifier; closes it with the call matching its kind.
class Id {
 public:
  explicit Id(hid_t id = -1) : id_(id) {}
  Id(Id&& other) noexcept : id_(std::exchange(other.id_, -1)) {}
  Id& operator=(Id&&) = delete;
  Id(const Id&) = delete;
  ~Id() {
    if (id_ < 0) return;
    switch (H5Iget_type(id_)) {
      case H5I_FILE: H5Fclose(id_); break;
      case H5I_GROUP: H5Gclose(id_); break;
      case H5I_DATASET: H5Dclose(id_); break;
      case H5I_DATASPACE: H5Sclose(id_); break;
      case H5I_DATATYPE: H5Tclose(id_); break;
      case H5I_ATTR: H5Aclose(id_); break;
      default: break;
    }
  }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
};

// Silences HDF5's error-stack printing; failures become InputErrors below.
class SilentHdf5Errors {
 public:
  SilentHdf5Errors() {
    H5Eget_auto2(H5E_DEFAULT, &function_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~SilentHdf5Errors() { H5Eset_auto2(H5E_DEFAULT, function_, data_); }

 private:
  H5E_auto2_t function_ = nullptr;
  void* data_ = nullptr;
};

class Reader {
 public:
  Reader(hid_t file, std::filesystem::path path) : file_(file), path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& expected, const std::string& got) const {
    throw InputError("results file '" + path_.string() + "': expected " + expected + ", got " +
                     got);
  }

  bool exists(const std::string& object) const {
    return H5Lexists(file_, object.c_str(), H5P_DEFAULT) > 0;
  }

  // A string attribute (fixed or variable length); `fallback` when absent and optional.
  std::string string_attribute(const std::string& object, const char* name, bool required = true,
                               const std::string& fallback = "") const {
    if (H5Aexists_by_name(file_, object.c_str(), name, H5P_DEFAULT) <= 0) {
      if (required) fail(std::string("attribute '") + name + "' on " + object, "none");
      return fallback;
    }
    Id attribute(H5Aopen_by_name(file_, object.c_str(), name, H5P_DEFAULT, H5P_DEFAULT));
    Id type(H5Aget_type(attribute.get()));
    if (H5Tget_class(type.get()) != H5T_STRING) fail(std::string("a string ") + name, "another type");
    if (H5Tis_variable_str(type.get()) > 0) {
      Id memory_type(H5Tcopy(H5T_C_S1));
      H5Tset_size(memory_type.get(), H5T_VARIABLE);
      char* text = nullptr;
      if (H5Aread(attribute.get(), memory_type.get(), &text) < 0) fail(name, "an unreadable value");
      std::string value = text != nullptr ? text : "";
      H5free_memory(text);
      return value;
    }
    std::string value(H5Tget_size(type.get()), '\0');
    if (H5Aread(attribute.get(), type.get(), value.data()) < 0) fail(name, "an unreadable value");
    return value.substr(0, value.find('\0'));
  }

  // A real attribute of exactly n values.
  std::vector<double> doubles_attribute(const std::string& object, const char* name,
                                        std::size_t n) const {
    if (H5Aexists_by_name(file_, object.c_str(), name, H5P_DEFAULT) <= 0) {
      fail(std::string("attribute '") + name + "' on " + object, "none");
    }
    Id attribute(H5Aopen_by_name(file_, object.c_str(), name, H5P_DEFAULT, H5P_DEFAULT));
    Id space(H5Aget_space(attribute.get()));
    if (static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get())) != n) {
      fail(std::to_string(n) + " values in " + object + "@" + name, "another count");
    }
    std::vector<double> values(n);
    H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, values.data());
    return values;
  }

  // Dimensions of a dataset; fails when absent.
  std::vector<hsize_t> dims(const std::string& dataset) const {
    if (!exists(dataset)) fail("dataset " + dataset, "none");
    Id id(H5Dopen2(file_, dataset.c_str(), H5P_DEFAULT));
    Id space(H5Dget_space(id.get()));
    std::vector<hsize_t> d(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space.get())));
    H5Sget_simple_extent_dims(space.get(), d.data(), nullptr);
    return d;
  }

  // The first `rows` rows of a dataset, row-major, converted to T.
  template <typename T>
  std::vector<T> read(const std::string& dataset, hid_t memory_type, hsize_t rows) const {
    std::vector<hsize_t> d = dims(dataset);
    std::size_t per_row = 1;
    for (std::size_t k = 1; k < d.size(); ++k) per_row *= d[k];
    std::vector<T> values(static_cast<std::size_t>(rows) * per_row);
    if (values.empty()) return values;
    Id id(H5Dopen2(file_, dataset.c_str(), H5P_DEFAULT));
    Id file_space(H5Dget_space(id.get()));
    // Select the leading rows only (a killed run may have longer datasets).
    std::vector<hsize_t> start(d.size(), 0), count = d;
    if (!count.empty()) count[0] = rows;
    H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(),
                        nullptr);
    Id memory_space(H5Screate_simple(static_cast<int>(count.size()), count.data(), nullptr));
    if (H5Dread(id.get(), memory_type, memory_space.get(), file_space.get(), H5P_DEFAULT,
                values.data()) < 0) {
      fail("readable data in " + dataset, "a read failure (damaged file?)");
    }
    return values;
  }

  // Rows of a per-sample dataset with `width` columns, checked against the expected shape.
  hsize_t rows(const std::string& dataset, hsize_t width) const {
    std::vector<hsize_t> d = dims(dataset);
    const bool ok = width == 0 ? d.size() == 1 : (d.size() == 2 && d[1] == width);
    if (!ok) fail(dataset + " with " + std::to_string(width) + " columns", "another shape");
    return d[0];
  }

  // Names of the members of a group (empty when the group is absent).
  std::vector<std::string> members(const std::string& group) const {
    std::vector<std::string> names;
    if (!exists(group)) return names;
    Id id(H5Gopen2(file_, group.c_str(), H5P_DEFAULT));
    H5G_info_t info;
    H5Gget_info(id.get(), &info);
    for (hsize_t k = 0; k < info.nlinks; ++k) {
      const ssize_t n = H5Lget_name_by_idx(id.get(), ".", H5_INDEX_NAME, H5_ITER_INC, k, nullptr,
                                           0, H5P_DEFAULT);
      std::string name(static_cast<std::size_t>(n), '\0');
      H5Lget_name_by_idx(id.get(), ".", H5_INDEX_NAME, H5_ITER_INC, k, name.data(),
                         static_cast<std::size_t>(n) + 1, H5P_DEFAULT);
      names.push_back(name);
    }
    return names;
  }

 private:
  hid_t file_;
  std::filesystem::path path_;
};

Shape read_shape(const Reader& r, const std::string& group) {
  Shape shape;
  const std::string type = r.string_attribute(group, "type");
  if (type == "box") shape.type = Shape::Type::kBox;
  else if (type == "cylinder") shape.type = Shape::Type::kCylinder;
  else if (type == "sphere") shape.type = Shape::Type::kSphere;
  else r.fail("shape type box, cylinder or sphere in " + group, "'" + type + "'");
  const std::vector<double> size = r.doubles_attribute(group, "size", 3);
  const std::vector<double> offset = r.doubles_attribute(group, "offset", 7);
  const std::vector<double> color = r.doubles_attribute(group, "color", 3);
  shape.size = Eigen::Vector3d(size[0], size[1], size[2]);
  shape.offset_position = Eigen::Vector3d(offset[0], offset[1], offset[2]);
  shape.offset_orientation =
      Eigen::Quaterniond(offset[3], offset[4], offset[5], offset[6]).normalized();
  shape.color = Eigen::Vector3d(color[0], color[1], color[2]);
  return shape;
}

void read_mesh(const Reader& r, const std::string& body, FlexibleMesh& mesh) {
  // Nodes and elements.
  const std::string m = body + "/mesh/";
  const hsize_t nn = r.rows(m + "nodes", 3);
  const std::vector<double> nodes = r.read<double>(m + "nodes", H5T_NATIVE_DOUBLE, nn);
  mesh.nodes = Eigen::Map<const RowMatrix3d>(nodes.data(), static_cast<Eigen::Index>(nn), 3);
  const hsize_t nl = r.exists(m + "lines") ? r.rows(m + "lines", 2) : 0;
  const std::vector<int> lines = r.read<int>(m + "lines", H5T_NATIVE_INT, nl);
  mesh.lines.resize(static_cast<Eigen::Index>(nl), 2);
  std::copy(lines.begin(), lines.end(), mesh.lines.data());
  const hsize_t nq = r.exists(m + "quads") ? r.rows(m + "quads", 4) : 0;
  const std::vector<int> quads = r.read<int>(m + "quads", H5T_NATIVE_INT, nq);
  mesh.quads.resize(static_cast<Eigen::Index>(nq), 4);
  std::copy(quads.begin(), quads.end(), mesh.quads.data());
  const bool inside = (mesh.lines.size() == 0 || (mesh.lines.minCoeff() >= 0 &&
                                                  mesh.lines.maxCoeff() < static_cast<int>(nn))) &&
                      (mesh.quads.size() == 0 || (mesh.quads.minCoeff() >= 0 &&
                                                  mesh.quads.maxCoeff() < static_cast<int>(nn)));
  if (!inside) r.fail("element node indices in 0.." + std::to_string(nn - 1) + " in " + m, "others");
  if (r.exists(m + "beam_radius")) {
    mesh.beam_radius = r.read<double>(m + "beam_radius", H5T_NATIVE_DOUBLE, 1).at(0);
  }

  // Modes: [nm, nn, 3] row-major is the column-major (3 nn) x nm matrix.
  const std::vector<hsize_t> d = r.dims(body + "/modes/translations");
  if (d.size() != 3 || d[1] != nn || d[2] != 3) {
    r.fail(body + "/modes/translations of shape [nm, " + std::to_string(nn) + ", 3]",
           "another shape");
  }
  const std::vector<double> modes =
      r.read<double>(body + "/modes/translations", H5T_NATIVE_DOUBLE, d[0]);
  mesh.mode_translations = Eigen::Map<const Eigen::MatrixXd>(
      modes.data(), static_cast<Eigen::Index>(3 * nn), static_cast<Eigen::Index>(d[0]));
  if (r.exists(body + "/modes/frequencies_hz")) {
    const std::vector<double> f =
        r.read<double>(body + "/modes/frequencies_hz", H5T_NATIVE_DOUBLE, d[0]);
    mesh.frequencies_hz = Eigen::Map<const Eigen::VectorXd>(f.data(), static_cast<Eigen::Index>(f.size()));
  }
}

}  // namespace

Results read_results(const std::filesystem::path& directory) {
  Results results;
  results.file = directory / "results.h5";
  const std::string name = results.file.string();

  // The file must exist and be an HDF5 file (a truncated file is not).
  std::error_code error;
  if (!std::filesystem::is_regular_file(results.file, error)) {
    throw InputError("expected a results file '" + name + "', got no such file (run `limber run` first)");
  }
  SilentHdf5Errors silent;
  if (H5Fis_hdf5(name.c_str()) <= 0) {
    throw InputError("expected an HDF5 results file '" + name +
                     "', got a file HDF5 cannot open (truncated or not HDF5)");
  }
  Id file(H5Fopen(name.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!file.valid()) {
    throw InputError("expected a readable results file '" + name + "', got an HDF5 open failure");
  }
  Reader r(file.get(), results.file);

  // Root attributes.
  const std::string format = r.string_attribute("/", "format");
  if (format != "limber-results") r.fail("format 'limber-results'", "'" + format + "'");
  results.title = r.string_attribute("/", "title", false);
  results.case_file = r.string_attribute("/", "case_file", false);
  results.status = r.string_attribute("/", "status", false, "unknown");
  results.message = r.string_attribute("/", "message", false);

  // ns: the smallest row count over every per-sample dataset read.
  hsize_t ns = r.rows("/time", 0);
  const std::vector<std::string> body_names = r.members("/bodies");
  const std::vector<std::string> joint_names = r.members("/joints");
  for (const std::string& body : body_names) {
    const std::string g = "/bodies/" + body;
    ns = std::min({ns, r.rows(g + "/position", 3), r.rows(g + "/orientation", 4)});
    if (r.exists(g + "/modal_coordinates")) {
      ns = std::min(ns, r.dims(g + "/modal_coordinates").at(0));
    }
  }
  for (const std::string& joint : joint_names) {
    ns = std::min(ns, r.rows("/joints/" + joint + "/position", 3));
  }
  const auto n = static_cast<Eigen::Index>(ns);

  // Times.
  const std::vector<double> time = r.read<double>("/time", H5T_NATIVE_DOUBLE, ns);
  results.time = Eigen::Map<const Eigen::VectorXd>(time.data(), n);

  // Bodies: kind, shapes, pose track, mesh and modal coordinates.
  for (const std::string& body : body_names) {
    const std::string g = "/bodies/" + body;
    BodyTrack track;
    track.name = body;
    const std::string kind = r.string_attribute(g, "kind");
    if (kind != "rigid" && kind != "flexible") r.fail("kind rigid or flexible on " + g, "'" + kind + "'");
    track.flexible = kind == "flexible";
    for (const std::string& k : r.members(g + "/shapes")) {
      track.shapes.push_back(read_shape(r, g + "/shapes/" + k));
    }
    const std::vector<double> p = r.read<double>(g + "/position", H5T_NATIVE_DOUBLE, ns);
    track.position = Eigen::Map<const RowMatrix3d>(p.data(), n, 3);
    const std::vector<double> q = r.read<double>(g + "/orientation", H5T_NATIVE_DOUBLE, ns);
    track.orientation.resize(n, 4);
    std::copy(q.begin(), q.end(), track.orientation.data());
    if (track.flexible) {
      read_mesh(r, g, track.mesh);
      // Modal coordinates [ns, nm], row-major, into a column-major matrix.
      const Eigen::Index nm = track.mesh.mode_translations.cols();
      track.modal_coordinates.setZero(n, nm);
      if (nm > 0) {
        r.rows(g + "/modal_coordinates", static_cast<hsize_t>(nm));
        const std::vector<double> eta =
            r.read<double>(g + "/modal_coordinates", H5T_NATIVE_DOUBLE, ns);
        track.modal_coordinates = Eigen::Map<
            const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
            eta.data(), n, nm);
      }
    }
    results.bodies.push_back(std::move(track));
  }

  // Joints: type, bodies and the joint point track.
  for (const std::string& joint : joint_names) {
    const std::string g = "/joints/" + joint;
    JointTrack track;
    track.name = joint;
    track.type = r.string_attribute(g, "type", false);
    track.body_i = r.string_attribute(g, "body_i", false);
    track.body_j = r.string_attribute(g, "body_j", false);
    const std::vector<double> p = r.read<double>(g + "/position", H5T_NATIVE_DOUBLE, ns);
    track.position = Eigen::Map<const RowMatrix3d>(p.data(), n, 3);
    results.joints.push_back(std::move(track));
  }
  return results;
}

}  // namespace limber::render
