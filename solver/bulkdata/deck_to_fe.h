// Deck (deck.h) -> limber's FE model of one component (fe::FeModelBuilder), the component
// frame being NASTRAN's basic system (docs/bulk-data.md, "From deck to FE model"):
//   GRID            node (id = GRID id) at its CP position transformed to basic
//   CBAR, CBEAM     2-node beam (fe/beam_element.h); v from G0 or X1-X3 (in GA's CD system
//                   unless OFFT starts with B); PBAR I1 -> Iz, I2 -> Iy
//   CQUAD4          flat 4-node shell (fe/shell_element.h) with PSHELL's T, 12I/T³, TS/T, NSM
//   CTRIA3          flat 3-node shell (fe/shell_triangle.h: CST + DKT), PSHELL's T, 12I/T³, NSM
//   CONM2           point mass and inertia (about the grid, rotated from CID to basic)
//   CONM1           6x6 mass matrix at the grid, rotated from CID (rectangular) to basic
//   CELAS1/2, CMASS1/2  scalar spring / mass k v v^T, v the difference of the two ends'
//                   components along their grids' CD directions (grounded ends add nothing)
//   CBUSH           K1-K6 along and about CID's axes, coincident grids or to ground
//   CROD, CONROD    axial E A / L and torsion G J / L; consistent translational mass
//   RBE2, RBE3      multipoint constraints (fe/rigid_elements.h), eliminated before the
//                   modal reduction (modal/constrained_matrices.h)
//   MAT1            E, nu, rho (rho, NSM and CONM2 mass times PARAM,WTMASS)
//   GRID PS         DOFs held at zero, always (permanent constraints)
//   SPC, SPC1       DOFs held at zero when the set is selected (SPCADD sets combine)
//   SET1            node set "set<id>" when every member is a GRID id
// DOFs are along basic axes: a constraint on a grid whose CD system is not basic must hold all
// three translations or none (and all three rotations or none), the only subsets that mean the
// same in every system.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bulkdata/deck.h"
#include "fe/fe_model_builder.h"

namespace limber::bulkdata {

struct DeckOptions {
  std::optional<int> spc_set;   // SPC/SPC1/SPCADD set to apply, none by default
  SourceLocation spc_where;     // where the set was chosen (for an unknown set)
  bool unsupported_is_error = true;  // false: unsupported cards become a notice
  SourceLocation where;         // what named the deck (for the unsupported-cards error)
};

// Adds the deck's nodes, elements, masses, constraints and node sets to `builder`; returns
// notices for the user (ignored cards, unsupported cards when allowed, approximations taken).
// Throws InputError at the referring field for an unknown grid, property, material or
// coordinate system, a property of the wrong kind, a CONM2 offset, a constraint subset in a
// rotated CD system (SPC, RBE2 CM, RBE3 REFC and Ci), a CBUSH between separate grids, an RBE3
// that leaves a rigid motion of its reference free; at `options.where` for unsupported cards (unless allowed); and as the
// builder does (e.g. a degenerate quad), at the element's card.
std::vector<std::string> add_deck(const Deck& deck, const DeckOptions& options,
                                  fe::FeModelBuilder& builder);

}  // namespace limber::bulkdata
