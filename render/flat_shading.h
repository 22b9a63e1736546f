// The colour a flat, matte surface takes under a renderer's lights, computed once so that the
// surface can be drawn unlit in that colour: the same pixels for a fraction of the cost.
//
// VTK's fragment shader (OpenGL2 back end) colours a fragment with unit normal n under
// directional lights k (unit direction d_k from the light towards its focal point, colour
// c_k = diffuse colour x intensity) as
//     C = a A + d D * sum_k max(0, n . (-d_k)) c_k + (specular terms),
// A, D the property's ambient and diffuse colours, a, d their coefficients (Phong, 1975; the
// light kit: vtkLightKit). On a plane n is one vector, every d_k is the same at every
// fragment, and without specular reflection (coefficient 0) C does not depend on the
// fragment: the plane has one colour. With two-sided lighting (VTK's default) n is the normal
// on the side the camera sees. In llvmpipe the lit shader costs about 6 ms of CPU per
// 1280 x 720 frame for a ground plane covering half of it; unlit, nothing measurable
// (docs/benchmarks.md).
#pragma once

#include <Eigen/Core>

#include <optional>

class vtkProperty;
class vtkRenderer;

namespace limber::render {

// The colour (RGB 0..1, clamped as the 8-bit frame buffer does) of the plane through p_W with
// normal n_W (ground axes; any length > 0) drawn with `property` under the renderer's lights,
// seen by its active camera. std::nullopt when the colour is not uniform: a positional light
// (spot or point), a specular coefficient > 0, or the camera in the plane. Updates the
// renderer's light geometry to its camera first (as a render does).
std::optional<Eigen::Vector3d> flat_surface_color(vtkRenderer* renderer, vtkProperty* property,
                                                  const Eigen::Vector3d& p_W,
                                                  const Eigen::Vector3d& n_W);

// Draws `property`'s surface unlit in `color` (RGB 0..1): lighting off, ambient 0, diffuse 1.
void set_unlit_color(vtkProperty* property, const Eigen::Vector3d& color);

}  // namespace limber::render
