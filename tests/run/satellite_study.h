// The deployed satellite's studies (study_deployed_frequencies.cpp, study_deployed_response.cpp;
// docs/linearize.md): cases/satellite_deployment.yaml edited in memory, and the panels' channels
// of the linear model. Used by the studies, not by the product.
#pragma once

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "multibody/body.h"
#include "run/linearize_run.h"

namespace limber::study {

inline constexpr const char* kSatellitePanels[] = {"panel_R1", "panel_R2", "panel_L1", "panel_L2"};

// `text` with `what` inserted before `before` (which must be there).
inline std::string inserted(std::string text, const std::string& before, const std::string& what) {
  const std::size_t at = text.find(before);
  if (at == std::string::npos) throw std::runtime_error("not in the case: " + before);
  return text.insert(at, what);
}

// cases/satellite_deployment.yaml with a marker `bus_center` at the bus's centre, the `forces`
// entry `load_entry` (its whole text, indented as a force) before spring_R3, t_end, the run's
// step replaced when `step` is not empty, and with `sharp` the latches' damping share a step
// (damping_depth 0).
inline std::string satellite_case_text(double t_end, const std::string& load_entry, const std::string& step = "",
                                       bool sharp = false) {
  std::ifstream file(std::string(LIMBER_CASES_DIR) + "/satellite_deployment.yaml");
  std::stringstream text;
  text << file.rdbuf();
  std::string edited = inserted(text.str(), "joints:\n", "markers:\n  bus_center: {body: bus}\n\n");
  edited = inserted(edited, "  spring_R3:", load_entry);
  for (std::size_t depth = edited.find("damping_depth: 1.0e-3"); sharp && depth != std::string::npos;
       depth = edited.find("damping_depth: 1.0e-3")) {
    edited.replace(depth, 21, "damping_depth: 0");
  }
  if (!step.empty()) {
    const std::size_t at_step = edited.find("step: 5.0e-4");
    if (at_step == std::string::npos) throw std::runtime_error("no step: 5.0e-4 in the case");
    edited.replace(at_step, 12, "step: " + step);
  }
  const std::size_t at = edited.find("t_end: 6.0");
  if (at == std::string::npos) throw std::runtime_error("no t_end: 6.0 in the case");
  return edited.replace(at, 10, fmt::format("t_end: {}", t_end));
}

inline io::Mechanism built_mechanism(const io::Case& input) {
  return io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
}

inline int marker_index(const multibody::Model& model, const std::string& name) {
  for (std::size_t m = 0; m < model.markers.size(); ++m) {
    if (model.markers[m].name == name) return static_cast<int>(m);
  }
  throw std::runtime_error("no marker " + name);
}

// The orientation R_WB of `body` at configuration q.
inline Eigen::Matrix3d body_orientation(const multibody::Model& model, int body, const Eigen::VectorXd& q) {
  multibody::FrameKinematics X;
  multibody::body_frame_kinematics(model, body, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), q, nullptr, X);
  return X.R_WF;
}

// The panels' channels of the linear model's state x: per panel its rotation relative to the
// bus to first order, R_rel0 δθ_panel − δθ_bus (bus axes; ξ's rotations are in body axes: the
// left increment of R_busᵀ R_panel), and its modal coordinates (rows of ξ = Z y).
class LinearPanelChannels {
 public:
  LinearPanelChannels(const run::LinearizeSummary& linear, const multibody::Model& model)
      : linear_(linear), model_(model), bus_(model.find_body("bus")) {}

  std::vector<double> operator()(const Eigen::VectorXd& x) const {
    const Eigen::MatrixXd& Z = linear_.state_space.Z;
    const Eigen::VectorXd xi = Z * x.head(Z.cols());
    const multibody::Body& bus = model_.bodies[static_cast<std::size_t>(bus_)];
    const Eigen::Matrix3d R_bus = body_orientation(model_, bus_, linear_.point.q);
    std::vector<double> values;
    for (const char* name : kSatellitePanels) {
      const int p = model_.find_body(name);
      const multibody::Body& panel = model_.bodies[static_cast<std::size_t>(p)];
      const Eigen::Vector3d turn = R_bus.transpose() * body_orientation(model_, p, linear_.point.q) *
                                       xi.segment<3>(panel.v_offset + 3) -
                                   xi.segment<3>(bus.v_offset + 3);
      for (int k = 0; k < 3; ++k) values.push_back(turn(k));
      for (int k = 6; k < panel.nv; ++k) values.push_back(xi(panel.v_offset + k));
    }
    return values;
  }

 private:
  const run::LinearizeSummary& linear_;
  const multibody::Model& model_;
  int bus_;
};

}  // namespace limber::study
