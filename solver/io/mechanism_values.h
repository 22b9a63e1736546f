// Readers of the compound values used by the mechanism sections (docs/case-format.md):
// orientations, inertia tensors and functions of time. Each throws InputError at the value's
// file:line:col with an expected/got message.
#pragma once

#include <Eigen/Dense>

#include "io/yaml_reader.h"
#include "multibody/time_function.h"

namespace limber::io {

// A rotation matrix (columns: the frame's x, y, z axes in the parent axes) from one of
//   {quaternion: [w, x, y, z]}        normalised here; must not be zero
//   {axis: [ax, ay, az], angle: a}    right-handed rotation of a [rad] about the axis
//   {z_axis: [..], x_axis: [..]}      frame with that z axis; x = the part of x_axis normal
//                                     to z (x_axis optional: a ground axis is chosen)
Eigen::Matrix3d read_rotation(const YamlValue& value);

// Inertia tensor about the centre of mass, body axes [kg m²]: [Ixx, Iyy, Izz] (principal
// axes along the body axes) or [Ixx, Iyy, Izz, Ixy, Ixz, Iyz] with the tensor's off-diagonal
// entries Ixy = −∫ x y dm. Positive definiteness is checked by the model builder.
Eigen::Matrix3d read_inertia(const YamlValue& value);

// A function of time (or angle), multibody::TimeFunction:
//   a number                                   constant
//   {type: constant, value}
//   {type: constant_speed, initial: 0, speed}
//   {type: ramp, initial: 0, speed, duration, shape: quintic | cubic}
//   {type: table, x: [...], y: [...], interpolation: linear | cubic}
multibody::TimeFunction read_time_function(const YamlValue& value);

}  // namespace limber::io
