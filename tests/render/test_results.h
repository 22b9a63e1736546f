// Writes a known results file with limber_results for the render tests and benchmark:
//  - "box": rigid 0.2 m cube, red, sliding along x: p(t) = (-0.8 + 0.4 t, -0.5, 0.1) m;
//  - "plate<k>": flexible nx x ny quad plate, Lx x Ly in the body xy plane, frame at
//    (0, 0, 0.3 + 0.5 k) m; mode 0: phi_z = sin(pi x/Lx) sin(pi y/Ly), mode 1: phi_x = y/Ly;
//    eta(t) = (A sin(2 pi f t), 0.5 A sin(2 pi f t));
//  - "beam": flexible 21-node line along body x, length 1 m, tube radius 0.02 m, frame at
//    (0, 0.9, 0.3) m; mode 0: phi_y = (x/L)^2, mode 1: phi_z = (x/L)^2;
//    eta(t) = (B sin(2 pi f t), B cos(2 pi f t));
//  - joint "pin" at the box centre; with beam_mid_joint, joint "mid" at the beam's mid node.
// Samples at t_k = k T/(ns - 1), k = 0..ns-1.
#pragma once

#include <Eigen/Core>

#include <filesystem>
#include <string>

namespace limber::render::testing {

struct TestScene {
  int plates = 1;        // number of plates (stacked in z)
  int nx = 20, ny = 12;  // quads per plate side
  double lx = 1.0, ly = 0.6;   // plate size [m]
  int samples = 11;            // ns
  double duration = 1.0;       // T [s]
  double amplitude = 0.1;      // A [m]
  double beam_amplitude = 0.05;  // B [m]
  double frequency = 1.0;      // f [Hz]
  bool with_beam = true;
  // The beam's section in the file (results/beam_sections.h): a tube 40 mm outer, 30 mm inner
  // diameter (16-gons), y axes along body y; false: none (drawn as the tube of its radius).
  bool beam_tube_section = false;
  bool with_box = true;
  // Joint "mid" (revolute, ground - beam) at the beam's mid node (x = L/2), following it: the
  // beam's relative deflection is then u(x) - u(L/2) (one joint node: the rigid fit is a
  // translation).
  bool beam_mid_joint = false;
  // The beam stored as a nonlinear body is (docs/results-format.md, "Nonlinear bodies"): no
  // modes, its node displacements per sample (the same closed form, beam_displacement).
  bool beam_node_displacements = false;
  // >= 0: a latch "latch_pin" on joint "pin" (with the box) that locks at this time [s]: one
  // /events row.
  double latch_time = -1.0;
  // >= 0: joint "pin" is a hold-down released at this time [s] (its attribute release_time).
  double pin_release_time = -1.0;
  // >= 0: joint "mid" (with beam_mid_joint) is a hold-down released at this time [s].
  double mid_release_time = -1.0;
  std::string title = "render test scene";
};

constexpr double kBeamLength = 1.0;
constexpr int kBeamNodes = 21;

// Writes dir/results.h5 for `scene` (finished, status "ok").
void write_test_results(const std::filesystem::path& dir, const TestScene& scene);

// Closed forms of the scene, for comparisons.
Eigen::Vector3d box_position(double t);
Eigen::Vector2d plate_eta(const TestScene& scene, double t);
Eigen::Vector2d beam_eta(const TestScene& scene, double t);
// Elastic displacement of the plate point at body coordinates (x, y) [m], body axes.
Eigen::Vector3d plate_displacement(const TestScene& scene, double x, double y, double t);
// Elastic displacement of the beam node at body x [m], body axes.
Eigen::Vector3d beam_displacement(const TestScene& scene, double x, double t);
Eigen::Vector3d plate_origin(int k);
Eigen::Vector3d beam_origin();

}  // namespace limber::render::testing
