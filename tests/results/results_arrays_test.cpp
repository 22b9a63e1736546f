// The typed reader of the file as written (results/results_arrays.h) against the writer: a
// small run written on disk and in memory, read back, every value compared exactly with what
// was written (float64 in, float64 out: no tolerance). Also the spectra's longest step
// (probe_reader.h), and a series the reader hands over uncut where results_reader.h cuts.
#include "results/results_arrays.h"

#include "core/error.h"
#include "results/results_writer.h"
#include "results/shock_spectra.h"

#include <gtest/gtest.h>

#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace limber::results {
namespace {

constexpr int kSamples = 4;
constexpr double kLongestStep = 2.5e-4;  // [s]

// A rigid crank and a flexible rod (2 modes, 2 beams and a quad, stress on beam 0 and the quad),
// a revolute between them, a driver, an energy, a stop engaged at samples 1 and 2 with one
// event, an acceleration probe with its spectra, and the accuracy of a finished run. Sample k's
// values encode k.
void write_run(ResultsWriter& writer) {
  writer.add_rigid_body({"crank", {ShapeSpec{}}});
  FlexibleBodySpec rod;
  rod.name = "rod";
  rod.nodes.resize(4, 3);
  rod.nodes << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  rod.lines.resize(2, 2);
  rod.lines << 0, 1, 1, 2;
  rod.quads.resize(1, 4);
  rod.quads << 0, 1, 2, 3;
  rod.mode_translations = Eigen::MatrixXd::Constant(12, 2, 0.5);
  rod.frequencies_hz = Eigen::Vector2d(10.0, 20.0);
  rod.has_deflection = true;
  rod.has_stress = true;
  rod.stress_elements = {0, 2};  // beam 0 and the quad (element nl + 0)
  writer.add_flexible_body(rod);
  writer.add_joint(JointSpec("R1", "revolute", "crank", "rod", "R1.i", "R1.j"));
  writer.add_driver("motor", "N m");
  writer.add_energy("kinetic");
  writer.add_hinge_limit(HingeLimitSpec{"stop", "stop", "R1", 0.5});
  writer.add_acceleration_probe({"tip", "rod", 3, Eigen::Vector3d(1, 0, 0)});
  writer.set_integrator("galpha");
  for (int k = 0; k < kSamples; ++k) {
    Sample sample;
    sample.time = 0.125 * k;
    BodySample rigid, flexible;
    rigid.position = Eigen::Vector3d(k, 2.0 * k, 3.0 * k);
    flexible.modal_coordinates = Eigen::Vector2d(0.1 * k, -0.2 * k);
    flexible.modal_velocities = Eigen::Vector2d(1.0 + k, 2.0 / (k + 1));
    flexible.deflection = Eigen::Vector3d(0.0, 0.01 * k, 0.0);
    flexible.stress_peak = 1e6 * k;
    flexible.stress_peak_element = 2;
    flexible.stress_recorded = true;
    flexible.stress_equivalent = Eigen::Vector2d(1e5, 1e6 * k);
    flexible.stress_beam_resultants = Eigen::VectorXd::LinSpaced(12, k, k + 11.0);
    flexible.stress_shell_resultants = Eigen::VectorXd::LinSpaced(8, -k, 7.0 - k);
    sample.bodies = {rigid, flexible};
    JointSample joint;
    joint.force_joint = Eigen::Vector3d(k, 0.0, -1.0);
    joint.force_ground = Eigen::Vector3d(0.0, k, 1.0 / 3.0);
    joint.indeterminate = k == 3;
    sample.joints = {joint};
    sample.driver_efforts = {4.0 * k};
    sample.energies = {5.0 * k};
    sample.steps = 10 * k + 1;
    sample.hinge_limit_angles = {0.1 * k};
    sample.hinge_limit_torques = {-0.5 * k};
    sample.hinge_limits_engaged = {static_cast<std::int8_t>(k == 1 || k == 2)};
    sample.probe_accelerations = {Eigen::Vector3d(k, 0.0, -9.81)};
    writer.append_sample(sample);
  }
  ShockSpectra spectra;
  spectra.longest_step = kLongestStep;
  spectra.frequency_hz = {5.0, 5.0 * std::exp2(1.0 / 6.0)};
  spectra.windows = {{"whole run", 0.0, 0.375}};
  ShockSpectrum axis;
  axis.frequency_hz = Eigen::Map<const Eigen::VectorXd>(spectra.frequency_hz.data(), 2);
  axis.maximax = axis.primary = axis.residual = Eigen::Vector2d(1.0, 2.0);
  spectra.probes = {{"tip", {{axis, axis, axis}}}};
  writer.set_shock_spectra(spectra);
  writer.append_event(HingeEventRecord{0.2, 0, true, 0.5, 1.5});
  writer.set_accuracy(1e-6, 2e-5, 3e-7, "first warning\nsecond warning");
  writer.finish(RunStatus::kOk);
}

// Every value the Python module hands over, against write_run's.
void expect_written_values(const ResultsArrays& a) {
  EXPECT_EQ(a.status, "ok");
  EXPECT_EQ(a.title, "arrays");
  EXPECT_EQ(a.case_file, "case.yaml");
  EXPECT_EQ(a.integrator, "galpha");
  EXPECT_EQ(a.accuracy.energy_relative, 1e-6);
  EXPECT_EQ(a.accuracy.local_error, 2e-5);
  EXPECT_EQ(a.accuracy.drift_relative, 3e-7);
  EXPECT_EQ(a.accuracy.warnings, (std::vector<std::string>{"first warning", "second warning"}));
  ASSERT_EQ(a.time.size(), kSamples);
  ASSERT_EQ(a.steps.size(), kSamples);
  ASSERT_EQ(a.bodies.size(), 2U);
  const BodyArrays& crank = a.bodies[0];
  const BodyArrays& rod = a.bodies[1];
  EXPECT_EQ(crank.kind, "rigid");
  EXPECT_FALSE(crank.modal_velocities || crank.frequencies_hz || crank.stress);
  EXPECT_EQ(rod.kind, "flexible");
  ASSERT_TRUE(rod.modal_velocities && rod.frequencies_hz && rod.deflection && rod.stress);
  EXPECT_EQ(*rod.frequencies_hz, Eigen::Vector2d(10.0, 20.0));
  const StressArrays& stress = *rod.stress;
  ASSERT_TRUE(stress.elements && stress.peak_element && stress.beam_resultants && stress.shell_resultants);
  EXPECT_EQ(*stress.elements, (VectorXi64(2) << 0, 2).finished());
  EXPECT_EQ(stress.beam_resultants->rows(), kSamples);
  EXPECT_EQ(stress.beam_resultants->cols(), 12);
  EXPECT_EQ(stress.shell_resultants->cols(), 8);
  const JointArrays& joint = a.joints.at(0);
  ASSERT_EQ(a.hinge_limits.size(), 1U);
  const HingeLimitArrays& stop = a.hinge_limits[0];
  EXPECT_EQ(stop.kind, "stop");
  EXPECT_EQ(stop.joint, "R1");
  EXPECT_EQ(stop.limit_angle, 0.5);
  for (int k = 0; k < kSamples; ++k) {
    EXPECT_EQ(a.time(k), 0.125 * k);
    EXPECT_EQ(a.steps(k), 10 * k + 1);
    EXPECT_EQ(crank.position.row(k), Eigen::RowVector3d(k, 2.0 * k, 3.0 * k));
    EXPECT_EQ(rod.modal_coordinates->row(k), Eigen::RowVector2d(0.1 * k, -0.2 * k));
    EXPECT_EQ(rod.modal_velocities->row(k), Eigen::RowVector2d(1.0 + k, 2.0 / (k + 1)));
    EXPECT_EQ(rod.deflection->row(k), Eigen::RowVector3d(0.0, 0.01 * k, 0.0));
    EXPECT_EQ((*stress.peak)(k), 1e6 * k);
    EXPECT_EQ((*stress.peak_element)(k), 2);
    EXPECT_EQ((*stress.time)(k), 0.125 * k);
    EXPECT_EQ(stress.equivalent->row(k), Eigen::RowVector2d(1e5, 1e6 * k));
    EXPECT_EQ(stress.beam_resultants->row(k), Eigen::RowVectorXd::LinSpaced(12, k, k + 11.0));
    EXPECT_EQ(stress.shell_resultants->row(k), Eigen::RowVectorXd::LinSpaced(8, -k, 7.0 - k));
    EXPECT_EQ(joint.force_joint.row(k), Eigen::RowVector3d(k, 0.0, -1.0));
    EXPECT_EQ(joint.force_ground.row(k), Eigen::RowVector3d(0.0, k, 1.0 / 3.0));
    EXPECT_EQ(joint.indeterminate(k), k == 3);
    EXPECT_EQ(a.drivers.at(0).values(k), 4.0 * k);
    EXPECT_EQ(a.energy.at(0).values(k), 5.0 * k);
    EXPECT_EQ(stop.angle(k), 0.1 * k);
    EXPECT_EQ(stop.torque(k), -0.5 * k);
    EXPECT_EQ(stop.engaged(k), k == 1 || k == 2);
    EXPECT_EQ(a.acceleration_probes.at(0).acceleration.row(k), Eigen::RowVector3d(k, 0.0, -9.81));
  }
  EXPECT_EQ(a.drivers[0].name, "motor");
  EXPECT_EQ(a.energy[0].name, "kinetic");
  ASSERT_TRUE(a.events);
  EXPECT_EQ(a.events->time, Eigen::VectorXd::Constant(1, 0.2));
  EXPECT_EQ(a.events->limit, std::vector<std::string>{"stop"});
  EXPECT_TRUE(a.events->engaged(0));
  EXPECT_EQ(a.events->rate(0), 1.5);
}

std::filesystem::path fresh_directory(const char* name) {
  const std::filesystem::path directory = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(directory);
  return directory;
}

TEST(ResultsArrays, ReadBackWhatTheWriterWroteOnDisk) {
  const std::filesystem::path directory = fresh_directory("limber_results_arrays_disk");
  ResultsWriter writer(directory, "arrays", "case.yaml");
  write_run(writer);
  expect_written_values(read_results_arrays(directory / kResultsFileName));
  std::filesystem::remove_all(directory);
}

TEST(ResultsArrays, ReadBackWhatTheWriterWroteInMemory) {
  ResultsWriter writer(InMemoryFile{}, "arrays", "case.yaml");
  write_run(writer);
  expect_written_values(read_results_arrays(writer.file_image()));
}

TEST(ResultsArrays, AFileWithoutAStatusIsAnInputError) {
  const std::filesystem::path directory = fresh_directory("limber_results_arrays_no_status");
  std::filesystem::create_directories(directory);
  const std::filesystem::path file = directory / kResultsFileName;
  H5Fclose(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  EXPECT_THROW(read_results_arrays(file), InputError);
  EXPECT_THROW(read_results_arrays(directory / "missing.h5"), InputError);
  std::filesystem::remove_all(directory);
}

// A killed run may leave one series a row ahead of the others: the arrays keep that row,
// read_results (results_reader.h) cuts every series to the rows complete in all.
TEST(ResultsArrays, KeepsTheRowsOfASeriesAheadOfTheOthers) {
  const std::filesystem::path directory = fresh_directory("limber_results_arrays_uncut");
  ResultsWriter writer(directory, "arrays", "case.yaml");
  write_run(writer);
  const std::filesystem::path file = directory / kResultsFileName;
  const hid_t id = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  const hid_t kinetic = H5Dopen2(id, "/energy/kinetic", H5P_DEFAULT);
  const hsize_t grown = kSamples + 1;
  ASSERT_GE(H5Dset_extent(kinetic, &grown), 0);
  H5Dclose(kinetic);
  H5Fclose(id);
  const ResultsArrays arrays = read_results_arrays(file);
  EXPECT_EQ(arrays.energy.at(0).values.size(), kSamples + 1);
  EXPECT_EQ(arrays.time.size(), kSamples);
  Results cut = read_results(directory);
  const RunRecords records = read_run_records(cut);
  EXPECT_EQ(records.energies.at(0).values.size(), kSamples);
  std::filesystem::remove_all(directory);
}

TEST(ProbeReader, ReadsTheSpectraLongestStepAsWritten) {
  const std::filesystem::path directory = fresh_directory("limber_results_arrays_longest_step");
  ResultsWriter writer(directory, "arrays", "case.yaml");
  write_run(writer);
  Results results = read_results(directory);
  const RunRecords records = read_run_records(results);
  ASSERT_TRUE(records.shock_spectra && records.shock_spectra->longest_step);
  EXPECT_EQ(*records.shock_spectra->longest_step, kLongestStep);
  std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace limber::results
