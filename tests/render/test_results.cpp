#include "test_results.h"

#include "fe/section_outline.h"
#include "results/results_writer.h"

#include <cmath>

namespace limber::render::testing {

using results::FlexibleBodySpec;
using results::ResultsWriter;
using results::Sample;

Eigen::Vector3d box_position(double t) { return {-0.8 + 0.4 * t, -0.5, 0.1}; }

Eigen::Vector2d plate_eta(const TestScene& scene, double t) {
  const double s = scene.amplitude * std::sin(2.0 * M_PI * scene.frequency * t);
  return {s, 0.5 * s};
}

Eigen::Vector2d beam_eta(const TestScene& scene, double t) {
  const double w = 2.0 * M_PI * scene.frequency * t;
  return {scene.beam_amplitude * std::sin(w), scene.beam_amplitude * std::cos(w)};
}

Eigen::Vector3d plate_displacement(const TestScene& scene, double x, double y, double t) {
  const Eigen::Vector2d eta = plate_eta(scene, t);
  const double bend = std::sin(M_PI * x / scene.lx) * std::sin(M_PI * y / scene.ly);
  return {eta(1) * y / scene.ly, 0.0, eta(0) * bend};
}

Eigen::Vector3d beam_displacement(const TestScene& scene, double x, double t) {
  const Eigen::Vector2d eta = beam_eta(scene, t);
  const double s = (x / kBeamLength) * (x / kBeamLength);
  return {0.0, eta(0) * s, eta(1) * s};
}

Eigen::Vector3d plate_origin(int k) { return {0.0, 0.0, 0.3 + 0.5 * k}; }

Eigen::Vector3d beam_origin() { return {0.0, 0.9, 0.3}; }

namespace {

FlexibleBodySpec plate_spec(const TestScene& scene, int k) {
  FlexibleBodySpec plate;
  plate.name = "plate" + std::to_string(k);
  const int px = scene.nx + 1, py = scene.ny + 1;
  plate.nodes.resize(px * py, 3);
  plate.mode_translations.setZero(3 * px * py, 2);
  // Nodes row by row, with both mode shapes evaluated at them.
  for (int j = 0; j < py; ++j) {
    for (int i = 0; i < px; ++i) {
      const int n = j * px + i;
      const double x = scene.lx * i / scene.nx, y = scene.ly * j / scene.ny;
      plate.nodes.row(n) << x, y, 0.0;
      plate.mode_translations(3 * n + 2, 0) =
          std::sin(M_PI * x / scene.lx) * std::sin(M_PI * y / scene.ly);
      plate.mode_translations(3 * n + 0, 1) = y / scene.ly;
    }
  }
  plate.quads.resize(scene.nx * scene.ny, 4);
  for (int j = 0; j < scene.ny; ++j) {
    for (int i = 0; i < scene.nx; ++i) {
      const int n = j * px + i;
      plate.quads.row(j * scene.nx + i) << n, n + 1, n + 1 + px, n + px;
    }
  }
  plate.frequencies_hz = Eigen::Vector2d(12.0, 30.0);
  return plate;
}

FlexibleBodySpec beam_spec(bool tube_section, bool node_displacements) {
  FlexibleBodySpec beam;
  beam.name = "beam";
  beam.nodes.resize(kBeamNodes, 3);
  beam.lines.resize(kBeamNodes - 1, 2);
  beam.mode_translations.setZero(3 * kBeamNodes, 2);
  for (int n = 0; n < kBeamNodes; ++n) {
    const double x = kBeamLength * n / (kBeamNodes - 1);
    beam.nodes.row(n) << x, 0.0, 0.0;
    const double s = (x / kBeamLength) * (x / kBeamLength);
    beam.mode_translations(3 * n + 1, 0) = s;
    beam.mode_translations(3 * n + 2, 1) = s;
    if (n + 1 < kBeamNodes) beam.lines.row(n) << n, n + 1;
  }
  beam.beam_radius = 0.02;
  if (tube_section) {
    const fe::SectionOutline tube = fe::tube_outline(0.04, 0.03);
    results::BeamSections& s = beam.beam_sections;
    s.y_axes = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>(kBeamNodes - 1, 3);
    s.y_axes.rowwise() = Eigen::RowVector3d(0.0, 1.0, 0.0);
    s.outline.assign(kBeamNodes - 1, 0);
    s.points.resize(static_cast<Eigen::Index>(tube.points.size()), 2);
    for (std::size_t k = 0; k < tube.points.size(); ++k) s.points.row(static_cast<Eigen::Index>(k)) = tube.points[k].transpose();
    s.offsets = {0, static_cast<int>(tube.points.size())};
    s.hollow = {1};
    s.equivalent = {0};
  }
  beam.frequencies_hz = Eigen::Vector2d(5.0, 5.0);
  if (node_displacements) {
    beam.mode_translations.resize(3 * kBeamNodes, 0);
    beam.frequencies_hz.resize(0);
    beam.has_node_displacements = true;
  }
  return beam;
}

}  // namespace

void write_test_results(const std::filesystem::path& dir, const TestScene& scene) {
  ResultsWriter writer(dir, scene.title, "test_results.cpp");

  // Declarations: box, plates, beam, pin joint.
  if (scene.with_box) {
    results::ShapeSpec cube;
    cube.size = Eigen::Vector3d::Constant(0.2);
    cube.color = Eigen::Vector3d(0.85, 0.1, 0.1);
    writer.add_rigid_body({"box", {cube}});
  }
  for (int k = 0; k < scene.plates; ++k) writer.add_flexible_body(plate_spec(scene, k));
  if (scene.with_beam) writer.add_flexible_body(beam_spec(scene.beam_tube_section, scene.beam_node_displacements));
  if (scene.with_box) writer.add_joint({"pin", "spherical", "ground", "box"});
  if (scene.with_beam && scene.beam_mid_joint) writer.add_joint({"mid", "revolute", "ground", "beam"});
  const bool latch = scene.with_box && scene.latch_time >= 0.0;
  if (latch) writer.add_hinge_limit({"latch_pin", "latch", "pin", 0.0});

  // Samples: closed-form poses and modal coordinates.
  for (int s = 0; s < scene.samples; ++s) {
    const double t = scene.duration * s / std::max(scene.samples - 1, 1);
    Sample sample;
    sample.time = t;
    if (scene.with_box) {
      results::BodySample box;
      box.position = box_position(t);
      sample.bodies.push_back(box);
    }
    for (int k = 0; k < scene.plates; ++k) {
      results::BodySample plate;
      plate.position = plate_origin(k);
      plate.modal_coordinates = plate_eta(scene, t);
      plate.modal_velocities = Eigen::Vector2d::Zero();  // rendering reads η only
      sample.bodies.push_back(plate);
    }
    if (scene.with_beam) {
      results::BodySample beam;
      beam.position = beam_origin();
      if (scene.beam_node_displacements) {
        beam.modal_coordinates.resize(0);
        beam.modal_velocities.resize(0);
        beam.node_displacements.resize(3 * kBeamNodes);
        for (int n = 0; n < kBeamNodes; ++n) {
          const double x = kBeamLength * n / (kBeamNodes - 1);
          beam.node_displacements.segment<3>(3 * n) = beam_displacement(scene, x, t);
        }
      } else {
        beam.modal_coordinates = beam_eta(scene, t);
        beam.modal_velocities = Eigen::Vector2d::Zero();
      }
      sample.bodies.push_back(beam);
    }
    if (scene.with_box) {
      results::JointSample pin;
      pin.position = box_position(t);
      sample.joints.push_back(pin);
    }
    if (scene.with_beam && scene.beam_mid_joint) {
      results::JointSample mid;
      mid.position = beam_origin() + Eigen::Vector3d(0.5 * kBeamLength, 0.0, 0.0) +
                     beam_displacement(scene, 0.5 * kBeamLength, t);
      sample.joints.push_back(mid);
    }
    if (latch) {
      sample.hinge_limit_angles = {0.0};
      sample.hinge_limit_torques = {0.0};
      sample.hinge_limits_engaged = {static_cast<std::int8_t>(t >= scene.latch_time)};
    }
    writer.append_sample(sample);
  }
  if (latch) writer.append_event({scene.latch_time, 0, true, 0.0, 0.0});
  if (scene.with_box && scene.pin_release_time >= 0.0) writer.set_joint_release(0, scene.pin_release_time);
  if (scene.with_beam && scene.beam_mid_joint && scene.mid_release_time >= 0.0) {
    writer.set_joint_release(scene.with_box ? 1 : 0, scene.mid_release_time);
  }
  writer.finish(results::RunStatus::kOk);
}

}  // namespace limber::render::testing
