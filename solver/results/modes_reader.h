// The one reader of modes.h5 (docs/modes-format.md, written by `limber modes` through
// io/modes_file.h), and of the mesh and mode groups that results.h5 shares with it: render's
// mode-shape animations and results reader, the report's mode tables and the tests of the modal
// solver's output all read through here, on the shared HDF5 reader (h5_reader.h) at the paths
// of results_layout.h and modes_layout.h. Plain values only (Eigen, strings): no solver classes.
//
// Every failure is an InputError naming the file: missing, not HDF5, not a limber modes file,
// a dataset missing or of the wrong shape.
#pragma once

#include "results/beam_sections.h"

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <vector>

namespace limber::results {

class H5Reader;

// A body's FE mesh and the translational part of its modes, body frame (<body>/mesh and
// <body>/modes/{translations, frequencies_hz}: the same layout in results.h5 and modes.h5).
struct MeshData {
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> nodes;  // nn x 3 [m]
  std::vector<int> node_ids;  // nn user ids (empty when the file has none)
  Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor> lines;  // beams, 0-based node indices
  Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor> quads;  // shells (triangles: last node repeated)
  double beam_radius = 0.0;            // [m] (results.h5; 0 in modes.h5)
  BeamSections beam_sections;          // y axes and outlines (empty in older files)
  Eigen::MatrixXd mode_translations;   // (3 nn) x nm, column i = mode i, node-major xyz [m]
  Eigen::VectorXd frequencies_hz;      // nm (empty when the file has none)
};

// Reads the mesh and mode translations of the group `body` (e.g. "/bodies/plate"); element
// node indices are checked to lie in 0..nn-1.
MeshData read_mesh(const H5Reader& file, const std::string& body);

// A mode's kind ("rigid", "normal", "constraint", "attachment": modal::to_string), its
// frequency [Hz] and label ("constraint uz at node 101").
struct ModeRecord {
  std::string kind;
  double frequency_hz = 0.0;
  std::string label;
};

// The floating-frame invariants (docs/modal-method.md), nm modes.
struct InvariantsData {
  double mass = 0.0;                                   // [kg]
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();  // [kg m]
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();       // [kg m^2]
  Eigen::MatrixXd translation_coupling, rotation_coupling;  // 3 x nm
  std::vector<Eigen::Matrix3d> inertia_first_order;         // nm
  std::vector<Eigen::Matrix3d> inertia_second_order;        // nm nm, (i, j) at i nm + j
  std::vector<Eigen::MatrixXd> rotation_coupling_first_order;  // nm of 3 x nm
};

struct ModesBody {
  std::string name;  // the case's text (/body_names)
  MeshData mesh;
  std::vector<ModeRecord> modes;  // nm, as mesh.mode_translations' columns
  // kAll only:
  int dof_count = 0;                                            // n = 6 nn
  Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor> fixed;  // (node index, local dof)
  Eigen::MatrixXd shapes;                                       // n x nm, M-orthonormal
  Eigen::VectorXd modal_stiffness;                              // nm [1/s^2]
  std::vector<ModeRecord> rigid_modes;                          // the rigid modes set aside
  InvariantsData invariants;
  // Element resultants per unit modal coordinate, (12 beams) x nm and (6 shells) x nm; empty
  // when the file predates them (docs/stress-recovery.md).
  Eigen::MatrixXd beam_stress_modal, shell_stress_modal;
};

struct ModesData {
  std::filesystem::path file;
  std::string title, case_file;
  std::vector<ModesBody> bodies;  // case-file order (/body_names)
};

// kDrawing reads the mesh and the modes' translations, kinds and labels only (what pictures
// and tables need: the full shapes are 2 of 3 numbers of a large file); kAll everything.
enum class ModesContent { kDrawing, kAll };

// Reads `modes_file`. Throws InputError (expected/got, naming the file) when it is missing,
// not HDF5, not a limber modes file, or lacks a dataset or has one of the wrong shape.
ModesData read_modes(const std::filesystem::path& modes_file, ModesContent content = ModesContent::kAll);

}  // namespace limber::results
