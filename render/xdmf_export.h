// ParaView's one-file output: DIR/vtk/scene.h5 (the nodal data of every sample in [t0, t1],
// layout in render/xdmf_layout.h) and DIR/vtk/scene.xmf, its XDMF 2 description
// (render/xdmf_description.h), which ParaView 5.11 opens with its "XDMF Reader" and its
// "Xdmf3ReaderS". A Temporal collection over the samples; per sample one grid holding every
// body, one after the other in results.h5's order, the cell data `body` (the body's index)
// telling them apart.
//
// The data are those of the VTU series (render/vtk_export.h), plus the relative deflection the
// render colours by (render/relative_deflection.h):
// - points: the reference configuration carried by the body frame, x = p + R X0 [m] (rigid
//   bodies: their primitives' surfaces);
// - point data: displacement R u and its magnitude |u| (elastic, ground axes) [m];
//   relative_deflection R u_rel and |u_rel| [m], u_rel the elastic displacement relative to the
//   rigid fit through the body's joint nodes; zero on rigid bodies. The render's picture at
//   deformation scale s is x + displacement + (s - 1) relative_deflection;
// - cell data: stress [Pa] where the run recorded it (as in the VTU; NaN elsewhere),
//   beam_radius [m] (the beams' section radius on line cells, 0 on surfaces), body (index).
// Cells: XDMF Mixed, per body the VTU's cells in the VTU's order (flexible: quads, lines, then
// the beams' swept surfaces, render/beam_solids.h, whose points follow their nodes).
#pragma once

#include "results_reader.h"

#include <array>
#include <filesystem>

namespace limber::render {

struct XdmfSceneSummary {
  int samples = 0;  // time steps written
  int grids = 0;    // bodies drawn over all samples (samples x bodies with points)
  // Box holding every deformed point (x + displacement) of every sample [m].
  std::array<double, 3> lo{0.0, 0.0, 0.0}, hi{0.0, 0.0, 0.0};
  double relative_deflection_max = 0.0;  // largest |u_rel| [m]
  double stress_max = 0.0;               // largest recorded stress [Pa] (0: none)
  bool stress = false;                   // some body carries stress
  bool beams = false;                    // some body has line cells without sections (tubes)
  bool relative = false;                 // some flexible body has joint nodes (u_rel != u)
};

// Writes DIR/vtk/scene.h5 and scene.xmf for the samples with t0 <= t <= t1; a progress bar
// (render/progress_bar.h) when `progress`. Throws std::runtime_error naming the file when it
// cannot be written.
XdmfSceneSummary write_xdmf_scene(const Results& results, const std::filesystem::path& vtk_directory,
                                  double t0, double t1, bool progress);

}  // namespace limber::render
