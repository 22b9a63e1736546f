// results.h5 written by the writer with every optional part declared, then read back through
// the shared reader (results/h5_reader.h) at the paths of results/results_layout.h: every path
// of the layout is there with its documented shape (docs/results-format.md), the file holds no
// object or attribute the layout does not name, and the values come back bit for bit (float64
// in, float64 out: no tolerance).
#include <gtest/gtest.h>

#include <hdf5.h>

#include "results/h5_reader.h"
#include "results/link_name.h"
#include "results/results_layout.h"
#include "results/results_writer.h"
#include "results/shock_spectra.h"

#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace limber::results {
namespace {

namespace L = layout;
using Dims = std::vector<hsize_t>;

constexpr int kSamples = 3;

// A run with a rigid and a flexible body (2 beams and a quad, 2 modes with kinds and labels,
// deflection, stress; both with mass properties), a joint, a driver, an energy, a hinge limit
// with one event, redundancy, clearance, momentum, an acceleration probe with its shock spectra
// (2 windows, 2 frequencies) and every root attribute.
std::filesystem::path write_full_run() {
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() / "limber_layout_round_trip";
  std::filesystem::remove_all(directory);
  ResultsWriter writer(directory, "round trip", "case.yaml");
  MassProperties crank_mass{2.0, Eigen::Vector3d(0.1, 0.0, 0.0), Eigen::Matrix3d::Identity()};
  crank_mass.inertia_com_B(0, 1) = crank_mass.inertia_com_B(1, 0) = 0.25;
  RigidBodySpec crank{"crank", {ShapeSpec{}}, crank_mass};
  writer.add_rigid_body(crank);
  FlexibleBodySpec rod;
  rod.name = "rod";
  rod.nodes.resize(4, 3);
  rod.nodes << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  rod.lines.resize(2, 2);
  rod.lines << 0, 1, 1, 2;
  rod.quads.resize(1, 4);
  rod.quads << 0, 1, 2, 3;
  rod.beam_radius = 0.01;
  rod.mode_translations = Eigen::MatrixXd::Constant(12, 2, 0.5);
  rod.frequencies_hz = Eigen::Vector2d(10.0, 20.0);
  rod.mode_kinds = {"normal", "attachment"};
  rod.mode_labels = {"normal 1", "attachment uz at node 3"};
  rod.component = "beam";
  rod.mass_properties = MassProperties{};
  rod.has_deflection = true;
  rod.has_stress = true;
  rod.stress_elements = {0, 2};  // beam 0 and the quad (element nl + 0)
  writer.add_flexible_body(rod);
  writer.add_joint(JointSpec("R1", "revolute", "crank", "rod", "R1.i", "R1.j"));
  writer.add_driver("motor", "N m");
  writer.add_energy("kinetic");
  writer.add_hinge_limit(HingeLimitSpec{"stop", "stop", "R1", 0.5});
  writer.set_redundant_equations({"R1.rot_x"}, {"R1.x"});
  writer.set_clearance_pairs({"crank, rod"});
  writer.record_momentum();
  writer.add_acceleration_probe({"tip", "rod", 3, Eigen::Vector3d(1, 0, 0)});
  writer.set_integrator("galpha");
  writer.set_axis_names({"X", "Y", "Z"});
  for (int k = 0; k < kSamples; ++k) {
    Sample sample;
    sample.time = 0.125 * k;
    BodySample rigid, flexible;
    rigid.position = Eigen::Vector3d(k, 2.0 * k, 3.0 * k);
    flexible.modal_coordinates = Eigen::Vector2d(0.1 * k, -0.2 * k);
    flexible.modal_velocities = Eigen::Vector2d(1.0, 2.0);
    flexible.stress_peak = 1e6 * k;
    flexible.stress_peak_element = 2;
    flexible.stress_recorded = true;
    flexible.stress_equivalent = Eigen::Vector2d(1e5, 1e6 * k);
    flexible.stress_beam_resultants = Eigen::VectorXd::Constant(12, k);
    flexible.stress_shell_resultants = Eigen::VectorXd::Constant(8, k);
    sample.bodies = {rigid, flexible};
    JointSample joint;
    joint.force_joint = Eigen::Vector3d(k, 0.0, -1.0);
    sample.joints = {joint};
    sample.driver_efforts = {4.0 * k};
    sample.energies = {5.0 * k};
    sample.steps = 10 * k;
    sample.hinge_limit_angles = {0.1 * k};
    sample.hinge_limit_torques = {0.0};
    sample.hinge_limits_engaged = {0};
    sample.clearance_minimum = 0.25;
    sample.clearance_pair = 0;
    sample.probe_accelerations = {Eigen::Vector3d(k, 0.0, -9.81)};
    sample.momentum << k, 0, 0, 0, 0, -k;
    writer.append_sample(sample);
  }
  ShockSpectra spectra;
  spectra.frequency_hz = {5.0, 5.0 * std::exp2(1.0 / 6.0)};
  spectra.windows = {{"whole run", 0.0, 0.25}, {"start", 0.0, 0.25}};
  ShockSpectrum axis;
  axis.frequency_hz = Eigen::Map<const Eigen::VectorXd>(spectra.frequency_hz.data(), 2);
  axis.maximax = axis.primary = axis.residual = Eigen::Vector2d(1.0, 2.0);
  spectra.probes = {{"tip", {{axis, axis, axis}, {axis, axis, axis}}}};
  writer.set_shock_spectra(spectra);
  writer.append_event(HingeEventRecord{0.2, 0, true, 0.5, 1.5});
  writer.set_joint_release(0, 0.25);
  writer.set_accuracy(1e-6, 1e-5, 1e-7, "");
  writer.set_singular_passages({0.1}, {1e-3}, {"R1"}, {-1.0});
  writer.finish(RunStatus::kOk);
  return directory / kResultsFileName;
}

// Every object of the file ("" for groups' contents walk), and every attribute as "path@name".
herr_t collect(hid_t object, const char* name, const H5O_info_t* info, void* data) {
  auto& found = *static_cast<std::set<std::string>*>(data);
  const std::string path = std::string(name) == "." ? "" : "/" + std::string(name);
  if (!path.empty()) found.insert(path);
  for (hsize_t k = 0; k < info->num_attrs; ++k) {
    char attribute[256];
    H5Aget_name_by_idx(object, name, H5_INDEX_NAME, H5_ITER_INC, k, attribute, sizeof attribute,
                       H5P_DEFAULT);
    found.insert((path.empty() ? "/" : path) + "@" + attribute);
  }
  return 0;
}

std::set<std::string> file_tree(const std::filesystem::path& file) {
  std::set<std::string> found;
  const hid_t id = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  H5Ovisit2(id, H5_INDEX_NAME, H5_ITER_INC, collect, &found, H5O_INFO_NUM_ATTRS);
  H5Fclose(id);
  return found;
}

TEST(ResultsLayout, EveryPathOfTheLayoutReadsBackThroughTheSharedReader) {
  const std::filesystem::path file = write_full_run();
  const hsize_t ns = kSamples;
  const std::string crank = L::at(L::kBodies, link_name("crank"));
  const std::string rod = L::at(L::kBodies, link_name("rod"));
  const std::string shape = L::at(L::at(crank, L::body::kShapes), "0");
  const std::string mesh = L::at(rod, L::body::kMesh);
  const std::string modes = L::at(rod, L::body::kModes);
  const std::string stress = L::at(rod, L::body::kStress);
  const std::string joint = L::at(L::kJoints, link_name("R1"));
  const std::string driver = L::at(L::kDrivers, link_name("motor"));
  const std::string energy = L::at(L::kEnergy, link_name("kinetic"));
  const std::string limit = L::at(L::kHingeLimits, link_name("stop"));
  const std::string singular = L::at(L::kConstraints, L::constraints::kSingularPassages);
  const std::string probe = L::at(L::kAccelerationProbes, link_name("tip"));
  const std::string srs_probes = L::at(L::kShockSpectra, L::shock_spectra::kProbes);
  const std::string srs_probe = L::at(srs_probes, link_name("tip"));

  // Datasets with their documented shapes (docs/results-format.md).
  std::map<std::string, Dims> datasets = {
      {L::kTime, {ns}},
      {L::at(crank, L::body::kPosition), {ns, 3}},
      {L::at(crank, L::body::kOrientation), {ns, 4}},
      {L::at(rod, L::body::kPosition), {ns, 3}},
      {L::at(rod, L::body::kOrientation), {ns, 4}},
      {L::at(mesh, L::mesh::kNodes), {4, 3}},
      {L::at(mesh, L::mesh::kNodeIds), {4}},
      {L::at(mesh, L::mesh::kLines), {2, 2}},
      {L::at(mesh, L::mesh::kQuads), {1, 4}},
      {L::at(mesh, L::mesh::kBeamRadius), {}},
      {L::at(modes, L::modes::kTranslations), {2, 4, 3}},
      {L::at(modes, L::modes::kFrequenciesHz), {2}},
      {L::at(modes, L::modes::kKinds), {2}},
      {L::at(modes, L::modes::kLabels), {2}},
      {L::kMomentum, {ns, 6}},
      {L::at(rod, L::body::kModalCoordinates), {ns, 2}},
      {L::at(rod, L::body::kModalVelocities), {ns, 2}},
      {L::at(rod, L::body::kDeflection), {ns, 3}},
      {L::at(stress, L::stress::kElements), {2}},
      {L::at(stress, L::stress::kPeak), {ns}},
      {L::at(stress, L::stress::kPeakElement), {ns}},
      {L::at(stress, L::stress::kTime), {ns}},
      {L::at(stress, L::stress::kEquivalent), {ns, 2}},
      {L::at(stress, L::stress::kBeamResultants), {ns, 12}},
      {L::at(stress, L::stress::kShellResultants), {ns, 8}},
      {L::at(joint, L::joint::kPosition), {ns, 3}},
      {L::at(joint, L::joint::kForceJoint), {ns, 3}},
      {L::at(joint, L::joint::kTorqueJoint), {ns, 3}},
      {L::at(joint, L::joint::kForceGround), {ns, 3}},
      {L::at(joint, L::joint::kTorqueGround), {ns, 3}},
      {L::at(joint, L::joint::kIndeterminate), {ns}},
      {L::at(driver, L::driver::kEffort), {ns}},
      {energy, {ns}},
      {L::at(L::kConstraints, L::constraints::kPositionViolation), {ns}},
      {L::at(L::kConstraints, L::constraints::kVelocityViolation), {ns}},
      {L::at(L::kConstraints, L::constraints::kRedundant), {1}},
      {L::at(L::kConstraints, L::constraints::kRedundantWith), {1}},
      {L::at(singular, L::singular::kTime), {1}},
      {L::at(singular, L::singular::kRatio), {1}},
      {L::at(singular, L::singular::kJoints), {1}},
      {L::at(singular, L::singular::kVelocityJump), {1}},
      {L::at(L::kSolver, L::solver::kSteps), {ns}},
      {L::at(limit, L::hinge_limit::kAngle), {ns}},
      {L::at(limit, L::hinge_limit::kTorque), {ns}},
      {L::at(limit, L::hinge_limit::kEngaged), {ns}},
      {L::at(L::kEvents, L::events::kTime), {1}},
      {L::at(L::kEvents, L::events::kLimit), {1}},
      {L::at(L::kEvents, L::events::kEngaged), {1}},
      {L::at(L::kEvents, L::events::kAngle), {1}},
      {L::at(L::kEvents, L::events::kRate), {1}},
      {L::at(L::kClearance, L::clearance::kPairs), {1}},
      {L::at(L::kClearance, L::clearance::kMinimum), {ns}},
      {L::at(L::kClearance, L::clearance::kPair), {ns}},
      {L::at(probe, L::acceleration_probe::kAcceleration), {ns, 3}},
      {L::at(L::kShockSpectra, L::shock_spectra::kFrequency), {2}},
      {L::at(L::kShockSpectra, L::shock_spectra::kWindowName), {2}},
      {L::at(L::kShockSpectra, L::shock_spectra::kWindowStart), {2}},
      {L::at(L::kShockSpectra, L::shock_spectra::kWindowEnd), {2}},
      {L::at(srs_probe, L::shock_spectra::kMaximax), {2, 3, 2}},
      {L::at(srs_probe, L::shock_spectra::kPrimary), {2, 3, 2}},
      {L::at(srs_probe, L::shock_spectra::kResidual), {2, 3, 2}},
  };
  for (int side = 0; side < 2; ++side) {
    const std::string marker = L::at(joint, L::kMarkerGroups[side]);
    datasets[L::at(marker, L::kMarkerPosition)] = {ns, 3};
    datasets[L::at(marker, L::kMarkerOrientation)] = {ns, 4};
  }
  const std::vector<std::string> groups = {
      L::kBodies, crank, L::at(crank, L::body::kShapes), shape, rod, mesh, modes, stress,
      L::kJoints, joint, L::at(joint, L::kMarkerGroups[0]), L::at(joint, L::kMarkerGroups[1]),
      L::kDrivers, driver, L::kEnergy, L::kConstraints, singular, L::kSolver, L::kHingeLimits,
      limit, L::kEvents, L::kClearance, L::kAccelerationProbes, probe, L::kShockSpectra, srs_probes, srs_probe};
  // Attributes by object.
  const std::map<std::string, std::vector<const char*>> attributes = {
      {"/",
       {L::kFormatAttribute, L::kVersionAttribute, L::kTitleAttribute, L::kCaseFileAttribute,
        L::kStatusAttribute, L::kMessageAttribute, L::kIntegratorAttribute,
        L::kAxisNamesAttribute, L::kAccuracyEnergyAttribute, L::kAccuracyLocalErrorAttribute,
        L::kAccuracyDriftAttribute, L::kAccuracyWarningsAttribute}},
      {crank, {kNameAttribute, L::body::kKindAttribute, L::body::kMassAttribute,
               L::body::kCenterOfMassAttribute, L::body::kInertiaAttribute}},
      {rod, {kNameAttribute, L::body::kKindAttribute, L::body::kMassAttribute,
             L::body::kCenterOfMassAttribute, L::body::kInertiaAttribute, L::body::kComponentAttribute}},
      {shape, {L::shape::kTypeAttribute, L::shape::kSizeAttribute, L::shape::kOffsetAttribute,
               L::shape::kColorAttribute}},
      {stress, {L::stress::kEveryAttribute, L::stress::kPeakValueAttribute,
                L::stress::kPeakElementAttribute, L::stress::kPeakTimeAttribute}},
      {joint, {kNameAttribute, L::joint::kTypeAttribute, L::joint::kBodyIAttribute,
               L::joint::kBodyJAttribute, L::joint::kReleaseTimeAttribute}},
      {L::at(joint, L::kMarkerGroups[0]), {kNameAttribute}},
      {L::at(joint, L::kMarkerGroups[1]), {kNameAttribute}},
      {driver, {kNameAttribute, L::driver::kUnitAttribute}},
      {energy, {kNameAttribute}},
      {limit, {kNameAttribute, L::hinge_limit::kKindAttribute, L::hinge_limit::kJointAttribute,
               L::hinge_limit::kAngleAttribute, L::hinge_limit::kIndexAttribute}},
      {probe, {kNameAttribute, L::acceleration_probe::kBodyAttribute, L::acceleration_probe::kNodeAttribute,
               L::acceleration_probe::kPointAttribute}},
      {L::kShockSpectra, {L::shock_spectra::kQAttribute, L::shock_spectra::kWindowLengthAttribute,
                          L::shock_spectra::kMinFrequencyAttribute, L::shock_spectra::kMaxFrequencyAttribute,
                          L::shock_spectra::kLongestStepAttribute}},
      {srs_probe, {kNameAttribute}},
  };

  // Everything in the file, listed before the shared reader opens it: HDF5 refuses a second
  // open in one process whose file-locking setting differs (H5Reader opens without the lock).
  const std::set<std::string> tree = file_tree(file);
  // The layout's paths, read through the shared reader.
  const H5Reader r(file, "results file", "");
  std::set<std::string> expected;
  for (const auto& [path, dims] : datasets) {
    EXPECT_EQ(r.dims(path), dims) << path;
    expected.insert(path);
  }
  for (const std::string& group : groups) {
    EXPECT_TRUE(r.exists(group)) << group;
    expected.insert(group);
  }
  for (const auto& [object, names] : attributes) {
    std::set<std::string> read;
    for (const auto& [name, text] : r.attribute_texts(object)) read.insert(name);
    for (const char* name : names) {
      EXPECT_EQ(read.count(name), 1U) << object << "@" << name;
      expected.insert(object + "@" + name);
    }
  }
  // Nothing in the file that the layout does not name.
  EXPECT_EQ(tree, expected);

  // Values come back as written.
  EXPECT_EQ(r.string_attribute("/", L::kFormatAttribute), L::kFormat);
  EXPECT_EQ(r.string_attribute("/", L::kStatusAttribute), "ok");
  EXPECT_EQ(r.string_attribute("/", L::kAxisNamesAttribute), "X, Y, Z");
  EXPECT_EQ(r.string_attribute(rod, L::body::kKindAttribute), L::body::kFlexible);
  EXPECT_EQ(r.string_attribute(crank, kNameAttribute), "crank");
  EXPECT_EQ(r.string_attribute(rod, L::body::kComponentAttribute), "beam");
  EXPECT_EQ(r.doubles_attribute(crank, L::body::kMassAttribute, 1), std::vector<double>{2.0});
  EXPECT_EQ(r.doubles_attribute(joint, L::joint::kReleaseTimeAttribute, 1), std::vector<double>{0.25});
  EXPECT_EQ(r.doubles_attribute(crank, L::body::kCenterOfMassAttribute, 3), (std::vector<double>{0.1, 0, 0}));
  EXPECT_EQ(r.doubles_attribute(crank, L::body::kInertiaAttribute, 9),
            (std::vector<double>{1, 0.25, 0, 0.25, 1, 0, 0, 0, 1}));
  EXPECT_EQ(r.strings(L::at(modes, L::modes::kLabels)),
            (std::vector<std::string>{"normal 1", "attachment uz at node 3"}));
  EXPECT_EQ(r.read<double>(L::kMomentum, H5T_NATIVE_DOUBLE, ns),
            (std::vector<double>{0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 2, 0, 0, 0, 0, -2}));
  EXPECT_EQ(r.string_attribute(shape, L::shape::kTypeAttribute), L::shape::kBox);
  EXPECT_EQ(r.string_attribute(L::at(joint, L::kMarkerGroups[1]), kNameAttribute), "R1.j");
  EXPECT_EQ(r.read<double>(L::kTime, H5T_NATIVE_DOUBLE, ns), (std::vector<double>{0.0, 0.125, 0.25}));
  EXPECT_EQ(r.read<double>(L::at(crank, L::body::kPosition), H5T_NATIVE_DOUBLE, ns),
            (std::vector<double>{0, 0, 0, 1, 2, 3, 2, 4, 6}));
  EXPECT_EQ(r.read<double>(L::at(rod, L::body::kModalCoordinates), H5T_NATIVE_DOUBLE, ns),
            (std::vector<double>{0.0, -0.0, 0.1, -0.2, 0.2, -0.4}));
  EXPECT_EQ(r.read<double>(L::at(joint, L::joint::kForceJoint), H5T_NATIVE_DOUBLE, ns),
            (std::vector<double>{0, 0, -1, 1, 0, -1, 2, 0, -1}));
  EXPECT_EQ(r.read<long long>(L::at(L::kSolver, L::solver::kSteps), H5T_NATIVE_LLONG, ns),
            (std::vector<long long>{0, 10, 20}));
  EXPECT_EQ(r.read<int>(L::at(stress, L::stress::kElements), H5T_NATIVE_INT, 2),
            (std::vector<int>{0, 2}));
  EXPECT_EQ(r.strings(L::at(L::kConstraints, L::constraints::kRedundant)),
            std::vector<std::string>{"R1.rot_x"});
  EXPECT_EQ(r.strings(L::at(L::kClearance, L::clearance::kPairs)),
            std::vector<std::string>{"crank, rod"});
  EXPECT_EQ(r.strings(L::at(singular, L::singular::kJoints)), std::vector<std::string>{"R1"});
  EXPECT_EQ(r.read<double>(L::at(L::kEvents, L::events::kRate), H5T_NATIVE_DOUBLE, 1),
            std::vector<double>{1.5});
  EXPECT_EQ(r.members(L::kEnergy), std::vector<std::string>{"kinetic"});
  EXPECT_EQ(r.read<double>(L::at(probe, L::acceleration_probe::kAcceleration), H5T_NATIVE_DOUBLE, ns),
            (std::vector<double>{0, 0, -9.81, 1, 0, -9.81, 2, 0, -9.81}));
  EXPECT_EQ(r.strings(L::at(L::kShockSpectra, L::shock_spectra::kWindowName)),
            (std::vector<std::string>{"whole run", "start"}));
  EXPECT_EQ(r.read<double>(L::at(srs_probe, L::shock_spectra::kMaximax), H5T_NATIVE_DOUBLE, 2),
            (std::vector<double>{1, 2, 1, 2, 1, 2, 1, 2, 1, 2, 1, 2}));
}

}  // namespace
}  // namespace limber::results
