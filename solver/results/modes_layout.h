// Paths and attribute names of modes.h5 (docs/modes-format.md), shared by its writer
// (modes_writer.h) and its reader (modes_reader.h). The mesh and the translations and
// frequencies of the modes are the same as in results.h5: results/results_layout.h
// (layout::mesh, layout::modes).
//
// Every name here is a link name within its parent group (Hdf5Group, h5_group.h, works relative
// to a group); a reader of absolute paths builds them with layout::at(parent, name), the root's
// parent being "" (at("", kBodyNames) == "/body_names").
#pragma once

#include "results/results_layout.h"

namespace limber::results::modes_layout {

// Root attributes (plus title and case_file, as in results.h5: layout::kTitleAttribute, ...).
inline constexpr const char* kFormat = "limber-modes";  // value of layout::kFormatAttribute
inline constexpr int kVersion = 1;                       // value of layout::kVersionAttribute

inline constexpr const char* kBodyNames = "body_names";  // string [nbodies], case-file order
// bodies/<body>/: attributes name, dof_count (n) and mode_count (nm).
inline constexpr const char* kBodies = "bodies";
inline constexpr const char* kDofCountAttribute = "dof_count";
inline constexpr const char* kModeCountAttribute = "mode_count";
// Groups of a body: mesh (layout::mesh), dofs, modes, rigid_modes, invariants.
inline constexpr const char* kMesh = "mesh";
inline constexpr const char* kDofs = "dofs";
inline constexpr const char* kModes = "modes";
inline constexpr const char* kRigidModes = "rigid_modes";
inline constexpr const char* kInvariants = "invariants";
inline constexpr const char* kStress = "stress";  // modal stresses (docs/stress-recovery.md)

// dofs/: attributes dofs_per_node (int 6) and dof_index (string).
namespace dofs {
inline constexpr const char* kPerNodeAttribute = "dofs_per_node";
inline constexpr const char* kIndexAttribute = "dof_index";
inline constexpr const char* kNames = "names";  // string [6]: ux uy uz rx ry rz
inline constexpr const char* kFixed = "fixed";  // int32 [nf, 2]: (node index, local dof)
}  // namespace dofs

// modes/ (translations and frequencies_hz: layout::modes) and rigid_modes/ (frequencies_hz,
// kinds, labels).
namespace modes {
inline constexpr const char* kShapes = "shapes";                    // float64 [n, nm], M-orthonormal
using layout::modes::kKinds;   // string [nm]
using layout::modes::kLabels;  // string [nm]
inline constexpr const char* kModalStiffness = "modal_stiffness";  // float64 [nm] [1/s^2]
}  // namespace modes

// invariants/ (docs/modal-method.md).
// Under kStress: element resultants per unit modal coordinate (files before them lack the group).
namespace stress {
inline constexpr const char* kBeamModal = "beam_modal";    // float64 [12 beams, nm]
inline constexpr const char* kShellModal = "shell_modal";  // float64 [6 shells, nm]
inline constexpr const char* kBeamResultantsAttribute = "beam_resultants";    // text: the 12 rows
inline constexpr const char* kShellResultantsAttribute = "shell_resultants";  // text: the 6 rows
}  // namespace stress

namespace invariants {
inline constexpr const char* kMass = "mass";                          // float64 scalar [kg]
inline constexpr const char* kFirstMoment = "first_moment";           // float64 [3] [kg m]
inline constexpr const char* kInertia = "inertia";                    // float64 [3, 3] [kg m^2]
inline constexpr const char* kTranslationCoupling = "translation_coupling";  // float64 [3, nm]
inline constexpr const char* kRotationCoupling = "rotation_coupling";        // float64 [3, nm]
inline constexpr const char* kInertiaFirstOrder = "inertia_first_order";     // float64 [nm, 3, 3]
inline constexpr const char* kInertiaSecondOrder = "inertia_second_order";   // float64 [nm nm, 3, 3]
inline constexpr const char* kRotationCouplingFirstOrder =
    "rotation_coupling_first_order";  // float64 [nm, 3, nm]
}  // namespace invariants

}  // namespace limber::results::modes_layout
