#include "run/linear_file.h"

#include <stdexcept>

#include <fmt/format.h>

#include "results/h5_handle.h"
#include "results/h5_write.h"
#include "results/linear_layout.h"
#include "results/results_layout.h"

namespace limber::run {

namespace {

namespace L = results::linear_layout;
using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Writes datasets and attributes of one group, naming the file and object on failure.
class GroupWriter {
 public:
  GroupWriter(hid_t group, std::string file) : group_(group), file_(std::move(file)) {}

  void matrix(const char* name, const Eigen::MatrixXd& value) {
    const RowMajor rows = value;
    check(results::try_write_dataset(group_, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                                     {static_cast<hsize_t>(rows.rows()), static_cast<hsize_t>(rows.cols())},
                                     rows.data()),
          name);
  }
  void vector(const char* name, const Eigen::VectorXd& value) {
    check(results::try_write_dataset(group_, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                                     {static_cast<hsize_t>(value.size())}, value.data()),
          name);
  }
  void scalar(const char* name, double value) {
    check(results::try_write_dataset(group_, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {}, &value), name);
  }
  void strings(const char* name, const std::vector<std::string>& values) {
    check(results::try_write_string_dataset(group_, name, values), name);
  }
  void attribute(const char* name, const std::string& value) {
    check(results::try_write_string_attribute(group_, name, value), name);
  }
  void attribute(const char* name, double value) {
    check(results::try_write_scalar_attribute(group_, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value), name);
  }
  void attribute(const char* name, int value) {
    check(results::try_write_scalar_attribute(group_, name, H5T_STD_I32LE, H5T_NATIVE_INT, &value), name);
  }

 private:
  void check(bool ok, const char* name) const {
    if (!ok) throw std::runtime_error(fmt::format("cannot write {} in {}", name, file_));
  }
  hid_t group_;
  std::string file_;
};

results::H5Handle create_group(hid_t parent, const char* name, const std::string& file) {
  results::H5Handle group(H5Gcreate2(parent, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  if (!group.valid()) throw std::runtime_error(fmt::format("cannot create group {} in {}", name, file));
  return group;
}

}  // namespace

std::filesystem::path write_linear_h5(const multibody::Model& model, const LinearizeSummary& summary,
                                      const std::filesystem::path& directory, const std::string& title,
                                      const std::string& case_file) {
  std::filesystem::create_directories(directory);
  const std::filesystem::path path = directory / "linear.h5";
  const std::string file = path.string();
  const std::lock_guard<std::recursive_mutex> lock(results::hdf5_lock());
  const results::SilentHdf5Errors silent;
  results::H5Handle h5(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  if (!h5.valid()) throw std::runtime_error(fmt::format("cannot create {}", file));

  // Root: what this is, and the system's coordinates and tangent matrices.
  GroupWriter root(h5.get(), file);
  root.attribute(results::layout::kFormatAttribute, std::string(L::kFormat));
  root.attribute(results::layout::kVersionAttribute, L::kVersion);
  root.attribute(results::layout::kTitleAttribute, title);
  root.attribute(results::layout::kCaseFileAttribute, case_file);
  root.attribute(L::kAboutAttribute, linearization_point_kind(summary));
  root.attribute(L::kTimeAttribute, summary.point.t);
  root.strings(L::kCoordinateNames, coordinate_names(model));
  root.matrix(L::kMass, summary.tangent.M);
  root.matrix(L::kDamping, summary.tangent.C);
  root.matrix(L::kStiffness, summary.tangent.K);
  root.matrix(L::kNullSpace, summary.state_space.Z);  // the states' basis (released drivers included)

  // The system modes.
  {
    const results::H5Handle group = create_group(h5.get(), L::kModes, file);
    GroupWriter modes(group.get(), file);
    modes.vector(L::kFrequencies, summary.modes.frequencies_hz);
    modes.vector(L::kDampingRatios, summary.modes.damping);
    modes.vector(L::kUndamped, summary.modes.undamped_hz);
    modes.matrix(L::kShapes, summary.modes.shapes);
    modes.attribute(L::kRigidModesAttribute, summary.modes.rigid_modes);
    modes.attribute(L::kZeroThresholdAttribute, summary.modes.zero_threshold_hz);
  }
  // The state-space model.
  {
    const multibody::StateSpace& ss = summary.state_space;
    const results::H5Handle group = create_group(h5.get(), L::kStateSpace, file);
    GroupWriter state_space(group.get(), file);
    state_space.matrix(L::kStateMatrix, ss.A);
    state_space.matrix(L::kInputMatrix, ss.B);
    state_space.matrix(L::kOutputMatrix, ss.C);
    state_space.matrix(L::kFeedthroughMatrix, ss.D);
    state_space.strings(L::kStateNames, ss.state_names);
    state_space.strings(L::kInputNames, ss.input_names);
    state_space.strings(L::kOutputNames, ss.output_names);
  }
  // The whole mechanism's mass properties.
  {
    const results::H5Handle group = create_group(h5.get(), L::kMassProperties, file);
    GroupWriter mass(group.get(), file);
    mass.scalar(L::kTotalMass, summary.mass.mass);
    mass.vector(L::kCenterOfMass, summary.mass.com_W);
    mass.matrix(L::kInertiaAboutCom, summary.mass.inertia_com_W);
  }
  // The modes with the reference body held.
  if (summary.cantilevered) {
    const multibody::CantileveredModes& c = *summary.cantilevered;
    const results::H5Handle group = create_group(h5.get(), L::kCantilevered, file);
    GroupWriter held(group.get(), file);
    held.attribute(L::kReferenceBodyAttribute, model.bodies[static_cast<std::size_t>(c.reference_body)].name);
    held.vector(L::kReferencePoint, c.p_WP);
    held.vector(L::kFrequencies, c.modes.frequencies_hz);
    held.vector(L::kDampingRatios, c.modes.damping);
    held.matrix(L::kParticipation, c.participation);
    held.matrix(L::kEffectiveMass, c.effective_mass);
    held.matrix(L::kRigidMass, c.rigid_mass);
  }
  return path;
}

}  // namespace limber::run
