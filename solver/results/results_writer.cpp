#include "results/results_writer.h"

#include <array>

#include "core/error.h"
#include "core/input_file.h"
#include "results/directory_lock.h"
#include "results/h5_handle.h"
#include "results/h5_write.h"
#include "results/link_name.h"
#include "results/results_layout.h"
#include "results/sample_series.h"
#include "results/shock_spectra_file.h"

#include <algorithm>
#include <chrono>
#include <set>
#include <stdexcept>
#include <system_error>

#include <unistd.h>

namespace limber::results {
namespace {

// File access of every results file: the 1.8-compatible format, so that no "open for writing"
// flag survives a crash.
H5Handle file_access() {
  H5Handle access(H5Pcreate(H5P_FILE_ACCESS));
  check(H5Pset_libver_bounds(access.get(), H5F_LIBVER_EARLIEST, H5F_LIBVER_V18), "choose the file format");
  return access;
}

// An in-memory file grows by this much at a time [bytes].
constexpr std::size_t kInMemoryIncrement = std::size_t{1} << 20;

// The longest text of a string attribute, in bytes: an attribute holds at most 64 KiB in the
// 1.8 file format. The case's names and title are shorter (core/names.h, io/case_reader.cpp);
// longer text (a run's message, which may quote many names) is cut, ending "… (N bytes)".
constexpr std::size_t kMaxAttributeText = 16384;

// A fixed-length, null-padded string attribute (replacing one of the same name: status is
// rewritten at finish).
void write_string_attribute(hid_t object, const char* name, const std::string& value) {
  check(try_write_string_attribute(object, name, abbreviated(value, kMaxAttributeText)) ? 0 : -1,
        "write a string attribute");
}

void write_int_attribute(hid_t object, const char* name, int value) {
  check(try_write_scalar_attribute(object, name, H5T_STD_I32LE, H5T_NATIVE_INT, &value) ? 0 : -1,
        "write an integer attribute");
}

void write_doubles_attribute(hid_t object, const char* name, const double* values,
                             hsize_t count) {
  H5Handle space = checked(H5Screate_simple(1, &count, nullptr), "create a dataspace");
  H5Handle attribute = checked(
      H5Acreate2(object, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
      "create a real attribute");
  check(H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, values), "write a real attribute");
}

// Mass, centre of mass and inertia about it (row-major) as the body group's attributes.
void write_mass_properties(hid_t body, const MassProperties& m) {
  write_doubles_attribute(body, layout::body::kMassAttribute, &m.mass, 1);
  write_doubles_attribute(body, layout::body::kCenterOfMassAttribute, m.com_B.data(), 3);
  // Symmetric: column-major storage is the row-major one.
  write_doubles_attribute(body, layout::body::kInertiaAttribute, m.inertia_com_B.data(), 9);
}

H5Handle create_group(hid_t parent, const std::string& name) {
  return checked(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                 "create a group");
}

// Writes a whole fixed-size dataset (results/h5_write.h); rank 0 means a scalar.
void write_dataset(hid_t parent, const char* name, hid_t file_type, hid_t memory_type,
                         const std::vector<hsize_t>& dims, const void* data) {
  check(try_write_dataset(parent, name, file_type, memory_type, dims, data) ? 0 : -1,
        "write a dataset");
}

const char* shape_type_name(ShapeSpec::Type type) {
  switch (type) {
    case ShapeSpec::Type::kBox: return layout::shape::kBox;
    case ShapeSpec::Type::kCylinder: return layout::shape::kCylinder;
    case ShapeSpec::Type::kSphere: return layout::shape::kSphere;
  }
  LIMBER_DEMAND(false);
}

void write_shapes(hid_t body_group, const std::vector<ShapeSpec>& shapes) {
  if (shapes.empty()) return;
  H5Handle group = create_group(body_group, layout::body::kShapes);
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    const ShapeSpec& shape = shapes[k];
    H5Handle shape_group = create_group(group.get(), std::to_string(k));
    write_string_attribute(shape_group.get(), layout::shape::kTypeAttribute, shape_type_name(shape.type));
    write_doubles_attribute(shape_group.get(), layout::shape::kSizeAttribute, shape.size.data(), 3);
    // Offset: position xyz then quaternion wxyz.
    const Eigen::Quaterniond& q = shape.offset_orientation;
    const double offset[7] = {shape.offset_position.x(), shape.offset_position.y(),
                              shape.offset_position.z(), q.w(), q.x(), q.y(), q.z()};
    write_doubles_attribute(shape_group.get(), layout::shape::kOffsetAttribute, offset, 7);
    write_doubles_attribute(shape_group.get(), layout::shape::kColorAttribute, shape.color.data(), 3);
  }
}

// A one-dimensional dataset of fixed-length, null-padded strings.
void write_string_dataset(hid_t parent, const char* name, const std::vector<std::string>& values) {
  check(try_write_string_dataset(parent, name, values) ? 0 : -1, "write a string dataset");
}

// The link of a declared name (results/link_name.h), new within its kind: names are unique on
// input and the mapping is injective, so a repeat is a caller bug.
std::string new_link(std::set<std::string>& links, const std::string& name) {
  std::string link = link_name(name);
  LIMBER_DEMAND(links.insert(link).second);
  return link;
}

// A group named by a free-text name: its link, and the name itself in the attribute `name`.
H5Handle create_named_group(hid_t parent, std::set<std::string>& links, const std::string& name) {
  H5Handle group = create_group(parent, new_link(links, name));
  write_string_attribute(group.get(), kNameAttribute, name);
  return group;
}

// /bodies/<body>/stress: the peak at every sample, the history at every `every`-th, and the
// running peak of the run written as attributes at finish.
struct StressSeries {
  H5Handle group;
  Series peak, peak_element, time, equivalent, beam_resultants, shell_resultants;
  std::int64_t rows = 0;          // history rows in the file
  std::int64_t pending_rows = 0;  // history rows waiting in the series' buffers
  hsize_t elements = 0, beam_width = 0, shell_width = 0;
  double max_value = -1.0, max_time = 0.0;
  int max_element = -1;
};

}  // namespace

struct ResultsWriter::Impl {
  // HDF5 prints no error stack while the writer lives: its failures are exceptions (check).
  SilentHdf5Errors silent;
  DirectoryLock lock;  // released after the file is closed
  std::filesystem::path path;
  H5Handle file;
  H5Handle bodies_group;
  H5Handle joints_group;
  H5Handle drivers_group;
  H5Handle energy_group;
  H5Handle limits_group;
  std::set<std::string> body_links, joint_links, driver_links, energy_links, limit_links;
  // Per hinge limit: angle, torque and engaged; the event table and its row count.
  std::vector<std::array<Series, 3>> limit_series;
  H5Handle events_group;
  Series event_time, event_limit, event_engaged, event_angle, event_rate;
  std::int64_t ne = 0;

  // Per body: position, orientation, then modal_coordinates, modal_velocities, deflection and
  // node_displacements (flexible only, the last two when declared); nm or -1 (rigid); the
  // places of deflection and node_displacements in its series, or -1; 3 nn of the latter.
  std::vector<std::vector<Series>> body_series;
  std::vector<int> body_nmodes;
  std::vector<int> body_deflection, body_displacements;
  std::vector<Eigen::Index> body_displacement_width;
  // Per body: its stress output, or none.
  std::vector<std::unique_ptr<StressSeries>> body_stress;
  // Per joint: position, force_joint, torque_joint, force_ground, torque_ground, indeterminate,
  // then marker_i's position and orientation, marker_j's position and orientation.
  std::vector<std::vector<Series>> joint_series;
  std::vector<H5Handle> joint_groups;  // kept open for set_joint_release
  std::vector<Series> driver_series;
  std::vector<Series> energy_series;
  Series position_violation, velocity_violation, steps, time;
  // Per acceleration probe: its acceleration [ns, 3].
  H5Handle probes_group;
  std::set<std::string> probe_links;
  std::vector<Series> probe_series;
  bool has_shock_spectra = false;
  // /momentum, when declared.
  Series momentum;
  bool has_momentum = false;
  // /clearance/minimum and /clearance/pair, when pairs were declared.
  Series clearance_minimum, clearance_pair;
  bool has_clearance = false;
  std::int64_t ns = 0;          // samples appended
  std::int64_t ns_written = 0;  // samples in the file (the rest wait in the series' buffers)
  std::chrono::steady_clock::time_point last_flush = std::chrono::steady_clock::now();
  bool finished = false;
  // An in-memory file (InMemoryFile) and, once finished, its bytes.
  bool in_memory = false;
  std::vector<unsigned char> image;

  // The root attributes and the groups and series every file has.
  void write_root(const std::string& title, const std::string& case_file) {
    const hid_t root = file.get();
    write_string_attribute(root, layout::kFormatAttribute, layout::kFormat);
    write_int_attribute(root, layout::kVersionAttribute, 1);
    write_string_attribute(root, layout::kTitleAttribute, title);
    write_string_attribute(root, layout::kCaseFileAttribute, case_file);
    write_string_attribute(root, layout::kStatusAttribute, layout::status::kRunning);
    write_string_attribute(root, layout::kMessageAttribute, "");
    bodies_group = create_group(root, layout::kBodies);
    H5Handle constraints = create_group(root, layout::kConstraints);
    position_violation = create_series(constraints.get(), layout::constraints::kPositionViolation, H5T_IEEE_F64LE,
                                       H5T_NATIVE_DOUBLE, 0);
    velocity_violation = create_series(constraints.get(), layout::constraints::kVelocityViolation, H5T_IEEE_F64LE,
                                       H5T_NATIVE_DOUBLE, 0);
    H5Handle solver = create_group(root, layout::kSolver);
    steps = create_series(solver.get(), layout::solver::kSteps, H5T_STD_I64LE, H5T_NATIVE_INT64, 0);
    time = create_series(root, layout::kTime, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0);
    check(H5Fflush(root, H5F_SCOPE_GLOBAL), "flush the file");
  }

  // A copy of the in-memory file's bytes (after its last flush).
  void keep_image() {
    const ssize_t size = H5Fget_file_image(file.get(), nullptr, 0);
    check(size < 0 ? -1 : 0, "copy the file from memory");
    image.resize(static_cast<std::size_t>(size));
    check(H5Fget_file_image(file.get(), image.data(), image.size()) < 0 ? -1 : 0, "copy the file from memory");
  }

  // Writes the buffered samples to every per-sample dataset, /time last, and flushes the file.
  void write_block() {
    const std::int64_t rows = ns - ns_written;
    for (std::vector<Series>& body : body_series) {
      for (Series& series : body) write_pending(series, ns_written, rows);
    }
    for (std::vector<Series>& joint : joint_series) {
      for (Series& series : joint) write_pending(series, ns_written, rows);
    }
    for (Series& series : driver_series) write_pending(series, ns_written, rows);
    for (Series& series : energy_series) write_pending(series, ns_written, rows);
    for (std::array<Series, 3>& limit : limit_series) {
      for (Series& series : limit) write_pending(series, ns_written, rows);
    }
    for (Series& series : probe_series) write_pending(series, ns_written, rows);
    for (Series* series : {&position_violation, &velocity_violation, &steps}) {
      write_pending(*series, ns_written, rows);
    }
    if (has_clearance) {
      write_pending(clearance_minimum, ns_written, rows);
      write_pending(clearance_pair, ns_written, rows);
    }
    if (has_momentum) write_pending(momentum, ns_written, rows);
    for (const std::unique_ptr<StressSeries>& stress : body_stress) {
      if (stress) write_stress_block(*stress, ns_written, rows);
    }
    // Time last: a reader never sees a time without its data.
    write_pending(time, ns_written, rows);
    ns_written = ns;
    check(H5Fflush(file.get(), H5F_SCOPE_GLOBAL), "flush the file");
    last_flush = std::chrono::steady_clock::now();
  }

  // The stress group of a flexible body: element list, `every`, and its series.
  std::unique_ptr<StressSeries> create_stress(hid_t body_group, const FlexibleBodySpec& body) {
    const auto lines = static_cast<int>(body.lines.rows());
    const auto elements = static_cast<int>(body.lines.rows() + body.quads.rows());
    LIMBER_DEMAND(body.stress_every >= 1);
    LIMBER_DEMAND(std::is_sorted(body.stress_elements.begin(), body.stress_elements.end()));
    auto stress = std::make_unique<StressSeries>();
    stress->group = create_group(body_group, layout::body::kStress);
    write_int_attribute(stress->group.get(), layout::stress::kEveryAttribute, body.stress_every);
    const hid_t g = stress->group.get();
    write_dataset(g, layout::stress::kElements, H5T_STD_I32LE, H5T_NATIVE_INT, {body.stress_elements.size()},
                  body.stress_elements.data());
    hsize_t beams = 0, shells = 0;
    for (int e : body.stress_elements) {
      LIMBER_DEMAND(e >= 0 && e < elements);
      (e < lines ? beams : shells) += 1;
    }
    stress->elements = body.stress_elements.size();
    stress->beam_width = 12 * beams;
    stress->shell_width = 8 * shells;
    stress->peak = create_series(g, layout::stress::kPeak, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0);
    stress->peak_element = create_series(g, layout::stress::kPeakElement, H5T_STD_I32LE, H5T_NATIVE_INT, 0);
    stress->time = create_series(g, layout::stress::kTime, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0);
    stress->equivalent = create_series(g, layout::stress::kEquivalent, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, stress->elements);
    LIMBER_DEMAND(stress->elements > 0);
    // Resultants of the kinds of element declared (a width of 0 would make a [ns] series).
    if (beams > 0) {
      stress->beam_resultants =
          create_series(g, layout::stress::kBeamResultants, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, stress->beam_width);
    }
    if (shells > 0) {
      stress->shell_resultants =
          create_series(g, layout::stress::kShellResultants, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, stress->shell_width);
    }
    return stress;
  }

  // The peak of this sample (buffered with the sample), and a history row when the sample
  // carries one (written at once: its own rows, flushed with the next block).
  void append_stress(StressSeries& stress, const BodySample& body, double time) {
    append_row(stress.peak, &body.stress_peak);
    append_row(stress.peak_element, &body.stress_peak_element);
    if (body.stress_peak > stress.max_value) {
      stress.max_value = body.stress_peak;
      stress.max_element = body.stress_peak_element;
      stress.max_time = time;
    }
    if (!body.stress_recorded) return;
    LIMBER_DEMAND(static_cast<hsize_t>(body.stress_equivalent.size()) == stress.elements);
    LIMBER_DEMAND(static_cast<hsize_t>(body.stress_beam_resultants.size()) == stress.beam_width);
    LIMBER_DEMAND(static_cast<hsize_t>(body.stress_shell_resultants.size()) == stress.shell_width);
    append_row(stress.equivalent, body.stress_equivalent.data());
    if (stress.beam_width > 0) append_row(stress.beam_resultants, body.stress_beam_resultants.data());
    if (stress.shell_width > 0) append_row(stress.shell_resultants, body.stress_shell_resultants.data());
    append_row(stress.time, &time);
    ++stress.pending_rows;
  }

  // Writes a body's buffered stress rows: the per-sample peaks, then the history, time last.
  static void write_stress_block(StressSeries& stress, std::int64_t first_sample, std::int64_t samples) {
    write_pending(stress.peak, first_sample, samples);
    write_pending(stress.peak_element, first_sample, samples);
    write_pending(stress.equivalent, stress.rows, stress.pending_rows);
    if (stress.beam_width > 0) write_pending(stress.beam_resultants, stress.rows, stress.pending_rows);
    if (stress.shell_width > 0) write_pending(stress.shell_resultants, stress.rows, stress.pending_rows);
    write_pending(stress.time, stress.rows, stress.pending_rows);
    stress.rows += stress.pending_rows;
    stress.pending_rows = 0;
  }

  void demand_declaring() const { LIMBER_DEMAND(ns == 0 && !finished); }

  // Lazily creates an optional top-level group.
  hid_t group(H5Handle& handle, const char* name) {
    if (!handle.valid()) handle = create_group(file.get(), name);
    return handle.get();
  }

  // Creates a body group with its kind, shapes and pose series.
  H5Handle begin_body(const std::string& name, const char* kind, const std::vector<ShapeSpec>& shapes,
                      const std::optional<MassProperties>& mass_properties) {
    demand_declaring();
    H5Handle body = create_named_group(bodies_group.get(), body_links, name);
    write_string_attribute(body.get(), layout::body::kKindAttribute, kind);
    if (mass_properties) write_mass_properties(body.get(), *mass_properties);
    write_shapes(body.get(), shapes);
    std::vector<Series> series;
    series.push_back(create_series(body.get(), layout::body::kPosition, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 3));
    series.push_back(
        create_series(body.get(), layout::body::kOrientation, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 4));
    body_series.push_back(std::move(series));
    body_stress.emplace_back();
    body_deflection.push_back(-1);
    body_displacements.push_back(-1);
    body_displacement_width.push_back(0);
    return body;
  }
};

ResultsWriter::ResultsWriter(const std::filesystem::path& directory, const std::string& title,
                             const std::string& case_file)
    : impl_(std::make_unique<Impl>()) {
  const std::lock_guard lock(hdf5_lock());
  // Create the run directory.
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) {
    throw InputError("cannot create the results directory '" + directory.string() +
                     "': " + error.message());
  }
  // No other run may be writing here: creating the file truncates it.
  impl_->lock = DirectoryLock(directory);
  impl_->path = directory / kResultsFileName;
  impl_->file = H5Handle(H5Fcreate(impl_->path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, file_access().get()));
  if (!impl_->file.valid()) {
    throw InputError("expected a writable results file, got an HDF5 failure creating '" +
                     impl_->path.string() + "'");
  }
  impl_->write_root(title, case_file);
}

ResultsWriter::ResultsWriter(InMemoryFile, const std::string& title, const std::string& case_file)
    : impl_(std::make_unique<Impl>()) {
  const std::lock_guard lock(hdf5_lock());
  // The core driver without a backing store; HDF5 tells open files apart by name, so each
  // in-memory file gets one of its own (looked up on disk by HDF5, never created there).
  static std::int64_t files_made = 0;
  const std::string name = "(limber results in memory " + std::to_string(getpid()) + "." +
                           std::to_string(++files_made) + ")";
  const H5Handle access = file_access();
  check(H5Pset_fapl_core(access.get(), kInMemoryIncrement, /*backing_store=*/false), "keep the file in memory");
  impl_->in_memory = true;
  impl_->file = checked(H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()), "create a file in memory");
  impl_->write_root(title, case_file);
}

ResultsWriter::~ResultsWriter() {
  const std::lock_guard lock(hdf5_lock());
  // Not finished (an exception passed by): keep the buffered samples; status stays "running".
  if (impl_ && !impl_->finished && impl_->file.valid()) {
    try {
      impl_->write_block();
    } catch (const std::exception&) {
      // The file is unusable; the samples of earlier blocks stay readable.
    }
  }
}

int ResultsWriter::add_rigid_body(const RigidBodySpec& body) {
  const std::lock_guard lock(hdf5_lock());
  impl_->begin_body(body.name, layout::body::kRigid, body.shapes, body.mass_properties);
  impl_->body_nmodes.push_back(-1);
  return static_cast<int>(impl_->body_series.size()) - 1;
}

int ResultsWriter::add_flexible_body(const FlexibleBodySpec& body) {
  const std::lock_guard lock(hdf5_lock());
  // Consistent sizes: modes over all nodes, element indices inside the mesh.
  const Eigen::Index nn = body.nodes.rows();
  const Eigen::Index nm = body.mode_translations.cols();
  LIMBER_DEMAND(body.mode_translations.rows() == 3 * nn || nm == 0);
  LIMBER_DEMAND(body.frequencies_hz.size() == nm);
  LIMBER_DEMAND(body.node_ids.empty() || static_cast<Eigen::Index>(body.node_ids.size()) == nn);
  LIMBER_DEMAND(body.lines.size() == 0 || (body.lines.minCoeff() >= 0 && body.lines.maxCoeff() < nn));
  LIMBER_DEMAND(body.quads.size() == 0 || (body.quads.minCoeff() >= 0 && body.quads.maxCoeff() < nn));

  LIMBER_DEMAND(body.mode_kinds.size() == body.mode_labels.size());
  LIMBER_DEMAND(body.mode_kinds.empty() || static_cast<Eigen::Index>(body.mode_kinds.size()) == nm);

  H5Handle group = impl_->begin_body(body.name, layout::body::kFlexible, body.shapes, body.mass_properties);
  if (!body.component.empty()) write_string_attribute(group.get(), layout::body::kComponentAttribute, body.component);

  // Mesh: nodes, ids, elements, tube radius.
  H5Handle mesh = create_group(group.get(), layout::body::kMesh);
  const auto n = static_cast<hsize_t>(nn);
  write_dataset(mesh.get(), layout::mesh::kNodes, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {n, 3}, body.nodes.data());
  std::vector<int> ids = body.node_ids;
  if (ids.empty()) {
    for (Eigen::Index i = 0; i < nn; ++i) ids.push_back(static_cast<int>(i) + 1);
  }
  write_dataset(mesh.get(), layout::mesh::kNodeIds, H5T_STD_I32LE, H5T_NATIVE_INT, {n}, ids.data());
  write_dataset(mesh.get(), layout::mesh::kLines, H5T_STD_I32LE, H5T_NATIVE_INT,
                {static_cast<hsize_t>(body.lines.rows()), 2}, body.lines.data());
  write_dataset(mesh.get(), layout::mesh::kQuads, H5T_STD_I32LE, H5T_NATIVE_INT,
                {static_cast<hsize_t>(body.quads.rows()), 4}, body.quads.data());
  write_dataset(mesh.get(), layout::mesh::kBeamRadius, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {},
                &body.beam_radius);
  if (!body.beam_sections.empty()) {
    LIMBER_DEMAND(static_cast<Eigen::Index>(body.beam_sections.outline.size()) == body.lines.rows());
    check(try_write_beam_sections(mesh.get(), body.beam_sections) ? 0 : -1, "write the beam sections");
  }

  // Modes: column-major (3 nn) x nm is exactly the row-major [nm, nn, 3] layout.
  H5Handle modes = create_group(group.get(), layout::body::kModes);
  const Eigen::MatrixXd translations =
      nm == 0 ? Eigen::MatrixXd(3 * nn, 0) : body.mode_translations;
  write_dataset(modes.get(), layout::modes::kTranslations, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                {static_cast<hsize_t>(nm), n, 3}, translations.data());
  write_dataset(modes.get(), layout::modes::kFrequenciesHz, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                {static_cast<hsize_t>(nm)}, body.frequencies_hz.data());
  if (!body.mode_kinds.empty()) {
    write_string_dataset(modes.get(), layout::modes::kKinds, body.mode_kinds);
    write_string_dataset(modes.get(), layout::modes::kLabels, body.mode_labels);
  }

  // Modal coordinates and rates; a flexible body without modes keeps [ns, 0] datasets.
  for (const char* name : {layout::body::kModalCoordinates, layout::body::kModalVelocities}) {
    impl_->body_series.back().push_back(create_columns(
        group.get(), name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, static_cast<hsize_t>(nm)));
  }
  impl_->body_nmodes.push_back(static_cast<int>(nm));
  std::vector<Series>& series = impl_->body_series.back();
  if (body.has_deflection) {
    impl_->body_deflection.back() = static_cast<int>(series.size());
    series.push_back(create_series(group.get(), layout::body::kDeflection, H5T_IEEE_F64LE,
                                          H5T_NATIVE_DOUBLE, 3));
  }
  if (body.has_node_displacements) {
    impl_->body_displacements.back() = static_cast<int>(series.size());
    impl_->body_displacement_width.back() = 3 * nn;
    series.push_back(create_columns(group.get(), layout::body::kNodeDisplacements,
                                           H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, static_cast<hsize_t>(3 * nn)));
  }
  if (body.has_stress) impl_->body_stress.back() = impl_->create_stress(group.get(), body);
  return static_cast<int>(impl_->body_series.size()) - 1;
}

int ResultsWriter::add_joint(const JointSpec& joint) {
  const std::lock_guard lock(hdf5_lock());
  impl_->demand_declaring();
  H5Handle group = create_named_group(impl_->group(impl_->joints_group, layout::kJoints),
                                      impl_->joint_links, joint.name);
  write_string_attribute(group.get(), layout::joint::kTypeAttribute, joint.type);
  write_string_attribute(group.get(), layout::joint::kBodyIAttribute, joint.body_i);
  write_string_attribute(group.get(), layout::joint::kBodyJAttribute, joint.body_j);
  std::vector<Series> series;
  for (const char* name :
       {layout::joint::kPosition, layout::joint::kForceJoint, layout::joint::kTorqueJoint,
        layout::joint::kForceGround, layout::joint::kTorqueGround}) {
    series.push_back(
        create_series(group.get(), name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 3));
  }
  series.push_back(
      create_series(group.get(), layout::joint::kIndeterminate, H5T_STD_I8LE, H5T_NATIVE_INT8, 0));
  // The two marker frames: the frames a reader can express the reaction in.
  for (int side = 0; side < 2; ++side) {
    H5Handle marker = create_group(group.get(), layout::kMarkerGroups[side]);
    const std::string& marker_name = side == 0 ? joint.marker_i : joint.marker_j;
    if (!marker_name.empty()) write_string_attribute(marker.get(), kNameAttribute, marker_name);
    series.push_back(create_series(marker.get(), layout::kMarkerPosition, H5T_IEEE_F64LE,
                                          H5T_NATIVE_DOUBLE, 3));
    series.push_back(create_series(marker.get(), layout::kMarkerOrientation,
                                          H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 4));
  }
  impl_->joint_series.push_back(std::move(series));
  impl_->joint_groups.push_back(std::move(group));
  return static_cast<int>(impl_->joint_series.size()) - 1;
}

int ResultsWriter::add_driver(const std::string& name, const std::string& unit) {
  const std::lock_guard lock(hdf5_lock());
  impl_->demand_declaring();
  H5Handle group =
      create_named_group(impl_->group(impl_->drivers_group, layout::kDrivers), impl_->driver_links, name);
  if (!unit.empty()) write_string_attribute(group.get(), layout::driver::kUnitAttribute, unit);
  impl_->driver_series.push_back(
      create_series(group.get(), layout::driver::kEffort, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0));
  return static_cast<int>(impl_->driver_series.size()) - 1;
}

int ResultsWriter::add_energy(const std::string& name) {
  const std::lock_guard lock(hdf5_lock());
  impl_->demand_declaring();
  // A dataset per energy, its name in its `name` attribute as for groups.
  const std::string link = new_link(impl_->energy_links, name);
  impl_->energy_series.push_back(create_series(impl_->group(impl_->energy_group, layout::kEnergy),
                                                      link.c_str(), H5T_IEEE_F64LE,
                                                      H5T_NATIVE_DOUBLE, 0));
  write_string_attribute(impl_->energy_series.back().dataset.get(), kNameAttribute, name);
  return static_cast<int>(impl_->energy_series.size()) - 1;
}

int ResultsWriter::add_hinge_limit(const HingeLimitSpec& limit) {
  const std::lock_guard lock(hdf5_lock());
  Impl& m = *impl_;
  m.demand_declaring();
  H5Handle group =
      create_named_group(m.group(m.limits_group, layout::kHingeLimits), m.limit_links, limit.name);
  write_string_attribute(group.get(), layout::hinge_limit::kKindAttribute, limit.kind);
  write_string_attribute(group.get(), layout::hinge_limit::kJointAttribute, limit.joint);
  write_doubles_attribute(group.get(), layout::hinge_limit::kAngleAttribute, &limit.angle, 1);
  // Groups list by name; the index keeps the model's order that /events/limit refers to.
  write_int_attribute(group.get(), layout::hinge_limit::kIndexAttribute, static_cast<int>(m.limit_series.size()));
  m.limit_series.push_back(
      {create_series(group.get(), layout::hinge_limit::kAngle, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0),
       create_series(group.get(), layout::hinge_limit::kTorque, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0),
       create_series(group.get(), layout::hinge_limit::kEngaged, H5T_STD_I8LE, H5T_NATIVE_INT8, 0)});
  // The event table exists in every file with hinge limits, empty until the first switch.
  if (!m.events_group.valid()) {
    const hid_t events = m.group(m.events_group, layout::kEvents);
    m.event_time = create_series(events, layout::events::kTime, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0);
    m.event_limit = create_series(events, layout::events::kLimit, H5T_STD_I32LE, H5T_NATIVE_INT32, 0);
    m.event_engaged = create_series(events, layout::events::kEngaged, H5T_STD_I8LE, H5T_NATIVE_INT8, 0);
    m.event_angle = create_series(events, layout::events::kAngle, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0);
    m.event_rate = create_series(events, layout::events::kRate, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0);
  }
  return static_cast<int>(m.limit_series.size()) - 1;
}

int ResultsWriter::add_acceleration_probe(const AccelerationProbeSpec& probe) {
  const std::lock_guard lock(hdf5_lock());
  Impl& m = *impl_;
  m.demand_declaring();
  H5Handle group = create_named_group(m.group(m.probes_group, layout::kAccelerationProbes), m.probe_links, probe.name);
  write_string_attribute(group.get(), layout::acceleration_probe::kBodyAttribute, probe.body);
  write_int_attribute(group.get(), layout::acceleration_probe::kNodeAttribute, probe.node);
  write_doubles_attribute(group.get(), layout::acceleration_probe::kPointAttribute, probe.point.data(), 3);
  m.probe_series.push_back(create_series(group.get(), layout::acceleration_probe::kAcceleration, H5T_IEEE_F64LE,
                                           H5T_NATIVE_DOUBLE, 3));
  return static_cast<int>(m.probe_series.size()) - 1;
}

void ResultsWriter::append_event(const HingeEventRecord& event) {
  const std::lock_guard lock(hdf5_lock());
  Impl& m = *impl_;
  LIMBER_DEMAND(!m.finished && m.events_group.valid());
  LIMBER_DEMAND(event.limit >= 0 && event.limit < static_cast<int>(m.limit_series.size()));
  const std::int32_t limit = event.limit;
  const std::int8_t engaged = event.engaged ? 1 : 0;
  write_rows(m.event_limit, m.ne, 1, &limit);
  write_rows(m.event_engaged, m.ne, 1, &engaged);
  write_rows(m.event_angle, m.ne, 1, &event.angle);
  write_rows(m.event_rate, m.ne, 1, &event.rate);
  // Time last, as for samples.
  write_rows(m.event_time, m.ne, 1, &event.time);
  ++m.ne;
  check(H5Fflush(m.file.get(), H5F_SCOPE_GLOBAL), "flush the file");
}

void ResultsWriter::set_joint_release(int joint, double t) {
  const std::lock_guard lock(hdf5_lock());
  Impl& m = *impl_;
  LIMBER_DEMAND(!m.finished && joint >= 0 && joint < static_cast<int>(m.joint_groups.size()));
  const hid_t group = m.joint_groups[static_cast<std::size_t>(joint)].get();
  LIMBER_DEMAND(H5Aexists(group, layout::joint::kReleaseTimeAttribute) == 0);
  check(try_write_scalar_attribute(group, layout::joint::kReleaseTimeAttribute, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &t)
            ? 0
            : -1,
        "write a real attribute");
  check(H5Fflush(m.file.get(), H5F_SCOPE_GLOBAL), "flush the file");
}

void ResultsWriter::set_redundant_equations(const std::vector<std::string>& names,
                                            const std::vector<std::string>& depends_on) {
  const std::lock_guard lock(hdf5_lock());
  impl_->demand_declaring();
  LIMBER_DEMAND(names.size() == depends_on.size());
  H5Handle constraints =
      checked(H5Gopen2(impl_->file.get(), layout::kConstraints, H5P_DEFAULT), "open /constraints");
  LIMBER_DEMAND(H5Lexists(constraints.get(), layout::constraints::kRedundant, H5P_DEFAULT) == 0);
  write_string_dataset(constraints.get(), layout::constraints::kRedundant, names);
  write_string_dataset(constraints.get(), layout::constraints::kRedundantWith, depends_on);
}

void ResultsWriter::set_clearance_pairs(const std::vector<std::string>& pairs) {
  const std::lock_guard lock(hdf5_lock());
  impl_->demand_declaring();
  LIMBER_DEMAND(!impl_->has_clearance);
  H5Handle group = create_group(impl_->file.get(), layout::kClearance);
  write_string_dataset(group.get(), layout::clearance::kPairs, pairs);
  impl_->clearance_minimum =
      create_series(group.get(), layout::clearance::kMinimum, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0);
  impl_->clearance_pair =
      create_series(group.get(), layout::clearance::kPair, H5T_STD_I32LE, H5T_NATIVE_INT, 0);
  impl_->has_clearance = true;
}

void ResultsWriter::record_momentum() {
  const std::lock_guard lock(hdf5_lock());
  impl_->demand_declaring();
  LIMBER_DEMAND(!impl_->has_momentum);
  impl_->momentum =
      create_series(impl_->file.get(), layout::kMomentum, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 6);
  impl_->has_momentum = true;
}

void ResultsWriter::set_integrator(const std::string& name) {
  const std::lock_guard lock(hdf5_lock());
  impl_->demand_declaring();
  write_string_attribute(impl_->file.get(), layout::kIntegratorAttribute, name);
}

void ResultsWriter::set_axis_names(const std::array<std::string, 3>& names) {
  const std::lock_guard lock(hdf5_lock());
  impl_->demand_declaring();
  write_string_attribute(impl_->file.get(), layout::kAxisNamesAttribute, names[0] + ", " + names[1] + ", " + names[2]);
}

void ResultsWriter::append_sample(const Sample& sample) {
  const std::lock_guard lock(hdf5_lock());
  Impl& m = *impl_;
  LIMBER_DEMAND(!m.finished);
  LIMBER_DEMAND(sample.bodies.size() == m.body_series.size());
  LIMBER_DEMAND(sample.joints.size() == m.joint_series.size());
  LIMBER_DEMAND(sample.driver_efforts.size() == m.driver_series.size());
  LIMBER_DEMAND(sample.energies.size() == m.energy_series.size());
  LIMBER_DEMAND(sample.hinge_limit_angles.size() == m.limit_series.size());
  LIMBER_DEMAND(sample.hinge_limit_torques.size() == m.limit_series.size());
  LIMBER_DEMAND(sample.hinge_limits_engaged.size() == m.limit_series.size());
  LIMBER_DEMAND(sample.probe_accelerations.size() == m.probe_series.size());

  // Bodies: pose, then modal coordinates, rates, deflection and node displacements.
  for (std::size_t b = 0; b < sample.bodies.size(); ++b) {
    const BodySample& body = sample.bodies[b];
    std::vector<Series>& series = m.body_series[b];
    append_vector3(series[0], body.position);
    const Eigen::Quaterniond& q = body.orientation;
    const double wxyz[4] = {q.w(), q.x(), q.y(), q.z()};
    append_row(series[1], wxyz);
    if (m.body_nmodes[b] >= 0) {
      LIMBER_DEMAND(body.modal_coordinates.size() == m.body_nmodes[b]);
      LIMBER_DEMAND(body.modal_velocities.size() == m.body_nmodes[b]);
      append_row(series[2], body.modal_coordinates.data());
      append_row(series[3], body.modal_velocities.data());
    }
    if (const int k = m.body_deflection[b]; k >= 0) append_vector3(series[static_cast<std::size_t>(k)], body.deflection);
    if (const int k = m.body_displacements[b]; k >= 0) {
      LIMBER_DEMAND(body.node_displacements.size() == m.body_displacement_width[b]);
      append_row(series[static_cast<std::size_t>(k)], body.node_displacements.data());
    }
    if (m.body_stress[b]) m.append_stress(*m.body_stress[b], body, sample.time);
  }

  // Joints: point, reactions in both frames, redundancy flag, marker poses.
  for (std::size_t j = 0; j < sample.joints.size(); ++j) {
    const JointSample& joint = sample.joints[j];
    std::vector<Series>& series = m.joint_series[j];
    append_vector3(series[0], joint.position);
    append_vector3(series[1], joint.force_joint);
    append_vector3(series[2], joint.torque_joint);
    append_vector3(series[3], joint.force_ground);
    append_vector3(series[4], joint.torque_ground);
    const std::int8_t flag = joint.indeterminate ? 1 : 0;
    append_row(series[5], &flag);
    const MarkerPose* markers[2] = {&joint.marker_i, &joint.marker_j};
    for (int side = 0; side < 2; ++side) {
      append_vector3(series[6 + 2 * side], markers[side]->position);
      const Eigen::Quaterniond& q = markers[side]->orientation;
      const double wxyz[4] = {q.w(), q.x(), q.y(), q.z()};
      append_row(series[7 + 2 * side], wxyz);
    }
  }

  // Drivers, energies, constraint violations, step count.
  for (std::size_t d = 0; d < sample.driver_efforts.size(); ++d) {
    append_row(m.driver_series[d], &sample.driver_efforts[d]);
  }
  for (std::size_t e = 0; e < sample.energies.size(); ++e) {
    append_row(m.energy_series[e], &sample.energies[e]);
  }
  for (std::size_t k = 0; k < m.limit_series.size(); ++k) {
    append_row(m.limit_series[k][0], &sample.hinge_limit_angles[k]);
    append_row(m.limit_series[k][1], &sample.hinge_limit_torques[k]);
    append_row(m.limit_series[k][2], &sample.hinge_limits_engaged[k]);
  }
  for (std::size_t p = 0; p < m.probe_series.size(); ++p) append_vector3(m.probe_series[p], sample.probe_accelerations[p]);
  append_row(m.position_violation, &sample.position_violation);
  append_row(m.velocity_violation, &sample.velocity_violation);
  append_row(m.steps, &sample.steps);
  if (m.has_clearance) {
    append_row(m.clearance_minimum, &sample.clearance_minimum);
    append_row(m.clearance_pair, &sample.clearance_pair);
  }
  if (m.has_momentum) append_row(m.momentum, sample.momentum.data());

  append_row(m.time, &sample.time);
  ++m.ns;
  // A block per kBlockRows samples or per kFlushInterval of wall time (results_writer.h).
  if (m.ns - m.ns_written >= static_cast<std::int64_t>(kBlockRows) ||
      std::chrono::steady_clock::now() - m.last_flush >= kFlushInterval) {
    m.write_block();
  }
}

void ResultsWriter::flush() {
  const std::lock_guard lock(hdf5_lock());
  LIMBER_DEMAND(!impl_->finished);
  impl_->write_block();
}

void ResultsWriter::set_accuracy(double energy_relative, double local_error, double drift_relative,
                                 const std::string& warnings) {
  const std::lock_guard lock(hdf5_lock());
  LIMBER_DEMAND(!impl_->finished);
  const hid_t root = impl_->file.get();
  write_doubles_attribute(root, layout::kAccuracyEnergyAttribute, &energy_relative, 1);
  write_doubles_attribute(root, layout::kAccuracyLocalErrorAttribute, &local_error, 1);
  write_doubles_attribute(root, layout::kAccuracyDriftAttribute, &drift_relative, 1);
  write_string_attribute(root, layout::kAccuracyWarningsAttribute, warnings);
}

void ResultsWriter::set_singular_passages(const std::vector<double>& time,
                                          const std::vector<double>& ratio,
                                          const std::vector<std::string>& joints,
                                          const std::vector<double>& velocity_jump) {
  const std::lock_guard lock(hdf5_lock());
  LIMBER_DEMAND(!impl_->finished);
  LIMBER_DEMAND(time.size() == ratio.size() && time.size() == joints.size() &&
                time.size() == velocity_jump.size());
  H5Handle constraints =
      checked(H5Gopen2(impl_->file.get(), layout::kConstraints, H5P_DEFAULT), "open /constraints");
  LIMBER_DEMAND(H5Lexists(constraints.get(), layout::constraints::kSingularPassages, H5P_DEFAULT) == 0);
  H5Handle group = create_group(constraints.get(), layout::constraints::kSingularPassages);
  const std::vector<hsize_t> dims{time.size()};
  write_dataset(group.get(), layout::singular::kTime, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dims, time.data());
  write_dataset(group.get(), layout::singular::kRatio, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dims, ratio.data());
  write_string_dataset(group.get(), layout::singular::kJoints, joints);
  write_dataset(group.get(), layout::singular::kVelocityJump, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dims,
                velocity_jump.data());
}

void ResultsWriter::set_event_peaks(const EventPeaks& peaks) {
  const std::lock_guard lock(hdf5_lock());
  LIMBER_DEMAND(!impl_->finished);
  LIMBER_DEMAND(H5Lexists(impl_->file.get(), layout::kEventPeaks, H5P_DEFAULT) == 0);
  H5Handle group = create_group(impl_->file.get(), layout::kEventPeaks);
  write_doubles_attribute(group.get(), layout::event_peaks::kWindowAttribute, &peaks.window, 1);
  write_string_dataset(group.get(), layout::event_peaks::kJoints, peaks.joints);
  // The window table, then [nw, nj] and [nw, nj, 3] tables row-major.
  const std::size_t nw = peaks.windows.size(), nj = peaks.joints.size();
  std::vector<std::string> labels;
  std::vector<double> start, end;
  std::vector<std::int64_t> states;
  std::vector<std::vector<double>> scalars(4), vectors(4);
  for (const PeakWindow& window : peaks.windows) {
    LIMBER_DEMAND(window.joints.size() == nj);
    labels.push_back(window.start.label);
    start.push_back(window.start.t);
    end.push_back(window.end);
    states.push_back(window.states);
    for (const JointPeak& joint : window.joints) {
      const double scalar[4] = {joint.force, joint.force_time, joint.torque, joint.torque_time};
      const Eigen::Vector3d* vector[4] = {&joint.force_component, &joint.force_component_time,
                                          &joint.torque_component, &joint.torque_component_time};
      for (std::size_t k = 0; k < 4; ++k) {
        scalars[k].push_back(scalar[k]);
        vectors[k].insert(vectors[k].end(), vector[k]->data(), vector[k]->data() + 3);
      }
    }
  }
  namespace ep = layout::event_peaks;
  write_string_dataset(group.get(), ep::kLabel, labels);
  write_dataset(group.get(), ep::kStart, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {nw}, start.data());
  write_dataset(group.get(), ep::kEnd, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {nw}, end.data());
  write_dataset(group.get(), ep::kStates, H5T_STD_I64LE, H5T_NATIVE_INT64, {nw}, states.data());
  const char* scalar_names[] = {ep::kForce, ep::kForceTime, ep::kTorque, ep::kTorqueTime};
  const char* vector_names[] = {ep::kForceComponent, ep::kForceComponentTime, ep::kTorqueComponent,
                                ep::kTorqueComponentTime};
  for (std::size_t k = 0; k < 4; ++k) {
    write_dataset(group.get(), scalar_names[k], H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {nw, nj}, scalars[k].data());
    write_dataset(group.get(), vector_names[k], H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {nw, nj, 3}, vectors[k].data());
  }
}

void ResultsWriter::set_shock_spectra(const ShockSpectra& spectra) {
  const std::lock_guard lock(hdf5_lock());
  LIMBER_DEMAND(!impl_->finished && !impl_->has_shock_spectra);
  impl_->has_shock_spectra = true;
  check(try_write_shock_spectra(impl_->file.get(), spectra) ? 0 : -1, "write the shock spectra");
}

void ResultsWriter::finish(RunStatus status, const std::string& message) {
  const std::lock_guard lock(hdf5_lock());
  Impl& m = *impl_;
  LIMBER_DEMAND(!m.finished);
  const hid_t root = m.file.get();
  m.write_block();
  write_string_attribute(root, layout::kStatusAttribute, status == RunStatus::kOk           ? layout::status::kOk
                                         : status == RunStatus::kInaccurate ? layout::status::kInaccurate
                                         : status == RunStatus::kFailed     ? layout::status::kFailed
                                                                            : layout::status::kInterrupted);
  write_string_attribute(root, layout::kMessageAttribute, message);
  check(H5Fflush(root, H5F_SCOPE_GLOBAL), "flush the file");

  // The run's peak stress per body, where and when.
  for (const std::unique_ptr<StressSeries>& stress : m.body_stress) {
    if (!stress || stress->max_element < 0) continue;
    write_doubles_attribute(stress->group.get(), layout::stress::kPeakValueAttribute, &stress->max_value, 1);
    write_int_attribute(stress->group.get(), layout::stress::kPeakElementAttribute, stress->max_element);
    write_doubles_attribute(stress->group.get(), layout::stress::kPeakTimeAttribute, &stress->max_time, 1);
  }
  check(H5Fflush(root, H5F_SCOPE_GLOBAL), "flush the file");
  if (m.in_memory) m.keep_image();

  // Close every dataset and group before the file.
  m.body_stress.clear();
  m.body_series.clear();
  m.joint_series.clear();
  m.joint_groups.clear();
  m.driver_series.clear();
  m.energy_series.clear();
  m.probe_series.clear();
  m.limit_series.clear();
  m.event_time = {};
  m.event_limit = {};
  m.event_engaged = {};
  m.event_angle = {};
  m.event_rate = {};
  m.position_violation = {};
  m.velocity_violation = {};
  m.steps = {};
  m.time = {};
  m.clearance_minimum = {};
  m.clearance_pair = {};
  m.momentum = {};
  m.bodies_group.reset();
  m.joints_group.reset();
  m.drivers_group.reset();
  m.energy_group.reset();
  m.limits_group.reset();
  m.events_group.reset();
  m.probes_group.reset();
  m.file.reset();
  m.finished = true;
}

std::int64_t ResultsWriter::sample_count() const { return impl_->ns; }

const std::filesystem::path& ResultsWriter::path() const { return impl_->path; }

const std::vector<unsigned char>& ResultsWriter::file_image() const { return impl_->image; }

}  // namespace limber::results
