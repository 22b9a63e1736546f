// The VTK source of a rigid body's primitive (results.h5 shapes) for the ParaView outputs: a
// cube of the box's edges, a 32-sided cylinder of radius size.x and length size.z, a sphere of
// radius size.x, each about its own origin. VTK's cylinder lies along y: the shape's axis is z,
// so the source comes with a turn of +90 degrees about x, post-multiplied onto `transform`;
// the caller post-multiplies the shape's offset (and the body's pose) after it.
#pragma once

#include "results_reader.h"

#include <vtkPolyDataAlgorithm.h>
#include <vtkSmartPointer.h>
#include <vtkTransform.h>

namespace limber::render {

// Precondition: `transform` is in PostMultiply mode.
vtkSmartPointer<vtkPolyDataAlgorithm> primitive_source(const Shape& shape, vtkTransform* transform);

}  // namespace limber::render
