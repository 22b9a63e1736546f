// Stress recovery of a nonlinear body's co-rotational beams (docs/nonlinear-beams.md,
// "Stresses"): each element's resultants from its local forces f_l = K_l p_l
// (nonlinear_beam/corotational_beam.h), in the same order, axes and sign convention as the
// modal beams' (fe/element_stress.h), and the extreme-fibre stress from them by the same
// formula (fe::beam_extreme_fibre_stress).
//
// With f_l = (N, m_a, m_b) in the element frame (chord r1, r2, r3), the element, loaded only at
// its nodes, is in equilibrium in its current chord frame: the force on node b is
// F_b = (N, −(m_a,z + m_b,z)/l, (m_a,y + m_b,y)/l), l the current chord length, and F_a = −F_b.
// The resultants (N, Vy, Vz, T, My, Mz) are then (F_b, −m_a) at end 0 and (F_b, m_b) at end 1:
// at a small motion the modal recovery's −(K_L T d)_end0, (K_L T d)_end1 (to the strain, l
// against l0).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "fe/fe_model.h"
#include "nonlinear_beam/beam_structure.h"

namespace limber::multibody {

// The resultants of every element of `structure` at `state`, element e at rows 12 e .. 12 e + 11
// (fe::kBeamResultants order) [N, N m].
Eigen::VectorXd nonlinear_beam_resultants(const nonlinear_beam::BeamStructure& structure,
                                          const nonlinear_beam::BeamState& state);

// Per element, the largest |σx| over its section at either end [Pa] (fe::beam_extreme_fibre_stress)
// from `resultants` (nonlinear_beam_resultants). `sections`: one per element (the FE model's
// beams' properties, in FeModel::beams order). Precondition: sections.size() == resultants / 12.
Eigen::VectorXd nonlinear_beam_fibre_stresses(const Eigen::VectorXd& resultants,
                                              const std::vector<fe::BeamSection>& sections);

// The sections of `model`'s beams, in FeModel::beams order.
std::vector<fe::BeamSection> beam_sections_of(const fe::FeModel& model);

}  // namespace limber::multibody
