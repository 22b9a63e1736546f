#include "run/linear_file.h"

#include "results/h5_group.h"
#include "results/linear_layout.h"
#include "results/results_layout.h"

namespace limber::run {

namespace {

namespace L = results::linear_layout;
using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Writes the datasets and attributes of one group of linear.h5 through limber_results' typed
// writer (float64 values, fixed-length null-padded strings, as linear.h5 always had).
class GroupWriter {
 public:
  explicit GroupWriter(results::Hdf5Group group) : group_(std::move(group)) {}

  GroupWriter group(const char* name) const { return GroupWriter(group_.create_group(name)); }
  void matrix(const char* name, const Eigen::MatrixXd& value) const {
    const RowMajor rows = value;
    group_.write_doubles(name, {static_cast<unsigned long long>(rows.rows()), static_cast<unsigned long long>(rows.cols())},
                         rows.data());
  }
  void vector(const char* name, const Eigen::VectorXd& value) const {
    group_.write_doubles(name, {static_cast<unsigned long long>(value.size())}, value.data());
  }
  void scalar(const char* name, double value) const { group_.write_doubles(name, {}, &value); }
  void strings(const char* name, const std::vector<std::string>& values) const {
    group_.write_fixed_strings(name, values);
  }
  void attribute(const char* name, const std::string& value) const { group_.write_fixed_attribute(name, value); }
  void attribute(const char* name, double value) const { group_.write_attribute(name, value); }
  void attribute(const char* name, int value) const { group_.write_attribute(name, value); }

 private:
  results::Hdf5Group group_;
};

}  // namespace

std::filesystem::path write_linear_h5(const multibody::Model& model, const LinearizeSummary& summary,
                                      const std::filesystem::path& directory, const std::string& title,
                                      const std::string& case_file) {
  std::filesystem::create_directories(directory);
  const std::filesystem::path path = directory / "linear.h5";
  const std::string file = path.string();

  // Root: what this is, and the system's coordinates and tangent matrices.
  const GroupWriter root(results::Hdf5Group::create_file(file, results::Hdf5Format::kLibraryDefault));
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
    const GroupWriter modes = root.group(L::kModes);
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
    const GroupWriter state_space = root.group(L::kStateSpace);
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
    const GroupWriter mass = root.group(L::kMassProperties);
    mass.scalar(L::kTotalMass, summary.mass.mass);
    mass.vector(L::kCenterOfMass, summary.mass.com_W);
    mass.matrix(L::kInertiaAboutCom, summary.mass.inertia_com_W);
  }
  // The modes with the reference body held.
  if (summary.cantilevered) {
    const multibody::CantileveredModes& c = *summary.cantilevered;
    const GroupWriter held = root.group(L::kCantilevered);
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
