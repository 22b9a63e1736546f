// A flexible body as the animation draws it (render/scene.h): its deformed FE mesh, shells as
// a surface of quads, beams as their swept sections (beam_solids.h) or as tubes of the mesh's
// beam radius, coloured through the scene's lookup table by |u_rel| per node or by element
// stress per cell [MPa]. Internal to limber_render (exposes VTK types).
#pragma once

#include "beam_solids.h"
#include "body_pose.h"
#include "results_reader.h"
#include "stress_reader.h"

#include <vtkDoubleArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstddef>

class vtkLookupTable;
class vtkRenderer;

namespace limber::render {

// A flexible body: points in ground updated per frame, quads as a surface, lines as tubes.
struct FlexibleView {
  const BodyTrack* body = nullptr;
  std::size_t index = 0;  // in results.bodies
  vtkSmartPointer<vtkPoints> points;
  vtkSmartPointer<vtkDoubleArray> magnitude;
  vtkSmartPointer<vtkPolyData> surface;
  vtkSmartPointer<vtkPolyData> beams;
  // Colouring by stress: the body's stress history (none: drawn in the NaN colour) and the
  // per-cell values of the quads and lines [MPa].
  const StressTrack* stress = nullptr;
  vtkSmartPointer<vtkDoubleArray> quad_stress;
  vtkSmartPointer<vtkDoubleArray> line_stress;
  // Beams as swept sections (beam_solids.h; null for files without them): the surface, per
  // point its node and offset from that node (body frame) and |u|, per cell the stress.
  vtkSmartPointer<vtkPolyData> solids;
  vtkSmartPointer<vtkDoubleArray> solid_magnitude;
  vtkSmartPointer<vtkDoubleArray> solid_stress;
  BeamSolids solid_mesh;
  RowMatrix3d solid_offset_B;
};

// How every flexible body is coloured.
struct FlexibleColoring {
  vtkLookupTable* lut = nullptr;
  double range_max = 1.0;  // upper end of the colour range, in the coloured unit
  bool by_stress = false;  // element stress per cell, else |u_rel| per node
};

// The body's actors added to `renderer`; `index` is its place in results.bodies; `stress` its
// history when colouring by stress (null: drawn in the NaN colour).
FlexibleView add_flexible_view(vtkRenderer* renderer, const BodyTrack& body, std::size_t index,
                               const StressTrack* stress, const FlexibleColoring& coloring);

// The body at `state` (time t [s]): nodes at x_W [m] (ground), coloured by u_norm [m] x
// per_unit, or by the element stresses of the history row at or before t.
void update_flexible_view(FlexibleView& view, const BodyState& state, const RowMatrix3d& x_W,
                          const Eigen::VectorXd& u_norm, double per_unit, double t);

}  // namespace limber::render
