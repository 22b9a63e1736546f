// Stress recovery of single elements: linear maps from an element's nodal displacements
// (global axes, node-major ux uy uz rx ry rz) to its stress resultants in the element's local
// axes, and the scalar stresses derived from the resultants. Linear maps can be applied to mode
// shapes once and superposed with modal coordinates (modal/modal_stress.h); the scalar stresses
// are not linear and are evaluated after superposition. Units SI (N, N·m, Pa).
// Formulation and verification: docs/stress-recovery.md.
#pragma once

#include <array>

#include <Eigen/Core>

#include "fe/fe_model.h"

namespace limber::fe {

// Beam resultants per element: (N, Vy, Vz, T, My, Mz) at end 0, then at end 1 [N, N·m], local
// axes (beam_element.h). They are the forces and moments that the part of the beam beyond the
// section (larger local x) exerts on the part before it: N > 0 in tension, and the axial stress
// at the section point (y, z) is σx = N/A + My z/Iy − Mz y/Iz. From the element's own
// stiffness, r = [−(K_L T d)_end0 ; (K_L T d)_end1] (Przemieniecki 1968, ch. 5): exact for an
// element loaded only at its nodes (a static mode, or a quasi-static deflection), and the
// usual mode-displacement recovery in dynamics (the element's own inertia load is not included).
inline constexpr int kBeamResultants = 12;
using BeamResultantOperator = Eigen::Matrix<double, kBeamResultants, 12>;
BeamResultantOperator beam_resultant_operator(const Eigen::Vector3d& p_node0,
                                              const Eigen::Vector3d& p_node1,
                                              const Eigen::Vector3d& orientation,
                                              const BeamProperty& property);

// Largest |σx| over the section at either end of the beam from its resultants r [Pa]:
//   rectangle (and a general section with fibre distances): |N|/A + |My| c_z/Iy + |Mz| c_y/Iz,
//     exact for a rectangle (the worst corner) and for any doubly symmetric section whose
//     extreme fibres in y and z meet at a corner, an upper bound otherwise;
//   circle: |N|/A + sqrt(My² + Mz²) (d/2)/I, exact.
// Transverse shear and torsion stresses are not included (they peak elsewhere in the section).
// Precondition: section.fibre_y, fibre_z > 0 (else the bending part is missing; the case
// reader rejects stress output for such sections).
double beam_extreme_fibre_stress(const Eigen::Matrix<double, kBeamResultants, 1>& r,
                                 const BeamSection& section);

// Shell resultants per element at its centre (ξ = η = 0), local axes of the quad's mean plane
// (shell_frame.h): membrane forces (Nxx, Nyy, Nxy) [N/m] = D_m ε and moments
// (Mxx, Myy, Mxy) [N·m/m] = D_b κ, with ε the membrane strain (incompatible modes recovered,
// shell_membrane.h) and κ the MITC4 curvature (shell_plate.h). Throws as shell_frame.
inline constexpr int kShellResultants = 6;
using ShellResultantOperator = Eigen::Matrix<double, kShellResultants, 24>;
ShellResultantOperator shell_resultant_operator(const std::array<Eigen::Vector3d, 4>& corners,
                                                const ShellProperty& property);

// Distance of the reported surfaces from the mid-surface [m]: property.fibre_distance, or T/2.
double shell_fibre_distance(const ShellProperty& property);

// Plane-stress von Mises stress on the top (+e3) and bottom surface [Pa]:
//   σ(z) = N/T + z M/I,  I = bending_ratio T³/12,  z = ± shell_fibre_distance,
//   σ_vm = sqrt(σxx² + σyy² − σxx σyy + 3 σxy²)
// (homogeneous plate: σ = N/T ± 6 M/T²). Returns (top, bottom).
Eigen::Vector2d shell_von_mises(const Eigen::Matrix<double, kShellResultants, 1>& r,
                                const ShellProperty& property);

}  // namespace limber::fe
