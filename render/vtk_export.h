// ParaView output: DIR/vtk/<body>_<sample>.vtu for every body and every sample in [t0, t1],
// and DIR/vtk/scene.pvd listing them with their times (one part per body).
//
// Flexible bodies: the mesh (quads as VTK_QUAD, lines as VTK_LINE) with points at the
// reference configuration carried by the body frame, x = p + R X0 [m], and point data
// "displacement" = R u (elastic displacement in ground axes [m]) and "displacement_magnitude"
// = |u| [m]; ParaView's "Warp By Vector" on "displacement" shows the deformed shape.
// Bodies with stress output (results.h5 "Stress") also carry cell data "stress" [Pa]: each
// element's equivalent stress (a shell's larger surface von Mises stress, a beam's extreme-fibre
// stress) of the stress history row at or before the sample, NaN for elements not recorded.
// Beams with sections (results.h5 "Beam sections") also appear as their swept surface
// (beam_solids.h: triangles, quads) after the lines, its points following their nodes; cell
// data "beam_index" is each line's and surface cell's beam (mesh line index), -1 on shells.
// Rigid bodies: their primitives' surfaces in ground with zero displacement.
// Files: vtkXMLUnstructuredGridWriter, appended raw binary data.
#pragma once

#include "results_reader.h"

#include <filesystem>

namespace limber::render {

// Writes the series; returns the number of .vtu files written. Throws std::runtime_error when
// a file cannot be written (naming it).
int write_vtk_series(const Results& results, const std::filesystem::path& vtk_directory,
                     double t0, double t1);

}  // namespace limber::render
