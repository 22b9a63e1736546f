// Section properties of PBARL cross-section types (MSC/NX Nastran library sections, group
// MSCBML0), in the element's local axes as NASTRAN draws them: DIM2 (BAR, BOX) runs along local
// y (plane 1), DIM1 along local z. So I1 (= fe::BeamSection::inertia_z, bending in plane 1)
// is DIM1 DIM2³ / 12 for BAR.
//   ROD   r = DIM1:            A = π r², I1 = I2 = π r⁴/4, J = π r⁴/2 (exact)
//   TUBE  ro = DIM1, ri = DIM2: A = π (ro² − ri²), I1 = I2 = π (ro⁴ − ri⁴)/4, J = 2 I1 (exact)
//   BAR   b = DIM1 (z), h = DIM2 (y): A = b h, I1 = b h³/12, I2 = h b³/12, J = St-Venant
//         series of a solid rectangle (fe::rectangle_torsion_constant; NASTRAN uses a closed
//         approximation of it, within about 0.5 %)
//   BOX   b = DIM1 (z), h = DIM2 (y), top/bottom walls t1 = DIM3, side walls t2 = DIM4:
//         A = b h − (b − 2 t2)(h − 2 t1), I1 = (b h³ − bi hi³)/12, I2 = (h b³ − hi bi³)/12,
//         J = 2 t1 t2 (b − t2)² (h − t1)² / (b t2 + h t1 − t2² − t1²)  (Bredt's thin-walled
//         closed section on the wall mid-lines; Roark's Formulas for Stress and Strain,
//         table 10.7 "hollow rectangle")
//   I     height h = DIM1 (y), bottom flange DIM2 (z) x DIM5 (y), top flange DIM3 x DIM6, web
//         thickness DIM4 (z)
//   CHAN  width DIM1 (z, web included), height DIM2 (y), web DIM3, flanges DIM4 (flanges
//         pointing to +z)
//   T     flange DIM1 (z) x DIM3 (y) on a web DIM4 wide, total height DIM2
//   HAT   height DIM1 (y), wall thickness DIM2, crown width DIM3 (outer), brims DIM4 beyond
//         the walls
//   (dimensions as in the MSC/NX Nastran PBARL figures: y up, z across). These four are
//   made of rectangles: A, I1 = ∫ y² dA and I2 = ∫ z² dA about the centroid by parallel axes;
//   J = Σ b t³/3 over the rectangles (open thin-walled section; NASTRAN's corner terms differ
//   by a few percent for thick walls). As in NASTRAN's PBARL, the offset between centroid
//   and shear centre (CHAN, T, HAT) is not modelled: the beam axis is the centroidal axis.
// Shear factors are left at fe::BeamSection's defaults; PBARL beams are Euler-Bernoulli.
// Outlines (fe/section_outline.h, for drawing): the same shapes as polygons about the centroid,
// ROD and TUBE as inscribed 16-gons; their area and second moments equal A, I1, I2 above
// (the 16-gons' fall short by 2.5 % and 5 %).
#pragma once

#include <string>
#include <vector>

#include "fe/fe_model.h"

namespace limber::bulkdata {

// The number of DIMi a type takes, or 0 when limber does not know the type.
int pbarl_dimension_count(const std::string& type);

// The section of `type` with dimensions `dims` (pbarl_dimension_count of them, each > 0).
// Returns a message in `error` (and an empty section) when the dimensions are inconsistent
// (e.g. a tube's inner radius not below the outer one) or beyond about 1e-77 to 1e77 m (their
// fourth powers not normal doubles).
fe::BeamSection pbarl_section(const std::string& type, const std::vector<double>& dims,
                              std::string& error);

}  // namespace limber::bulkdata
