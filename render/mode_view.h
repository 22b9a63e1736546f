// The view a mode animation is drawn from (issue 15: in-plane and out-of-plane bending must be
// distinguishable). A slender body (a beam mesh: its nodes' second-largest principal spread is
// below kSlenderRatio of the largest) bends in the plane of its long axis a and the mode's
// dominant displacement direction d (largest principal direction of Σ_n φ_n φ_nᵀ, φ_n the
// mode's nodal translation); the camera looks along that plane's normal n = a' × d,
// a' = a − (a·d) d, so the bending shows at full size and the title can name the plane. A mode
// along the body's length (axial: a ∥ d) uses the mesh's second principal direction instead
// of a. Other bodies (plates, solids) keep the preset view: their bending is out of their own
// plane and the oblique view shows it.
#pragma once

#include "render_options.h"
#include "results_reader.h"

#include <Eigen/Core>

#include <optional>
#include <string>

namespace limber::render {

inline constexpr double kSlenderRatio = 0.05;

struct ModeView {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitY();  // focal point -> eye, body axes
  std::string plane;  // "body x-z plane": the plane shown, "" when not axis-aligned
};

// The view of mode `mode` of `mesh`; nothing for non-slender meshes or a zero mode.
std::optional<ModeView> mode_view(const FlexibleMesh& mesh, Eigen::Index mode);

// The view square to the plane of a mode for a still picture (the report's mode images, issue
// 28): a slender body's mode_view(), else the least-spread principal direction of the mesh's
// nodes (a panel's normal), from its side towards body +z (+y, +x when the normal lies in a
// plane of those). Body axes, unit length. Precondition: at least one node.
Eigen::Vector3d mode_plane_direction(const FlexibleMesh& mesh, Eigen::Index mode);

// Options for a still picture of one mode of `body` drawn at its first sample's pose: the view
// square to the mode's plane (mode_plane_direction, turned into ground axes), no ground, no
// world triad, no time stamp; width x height pixels.
RenderOptions mode_image_options(const BodyTrack& body, Eigen::Index mode, int width, int height);

}  // namespace limber::render
