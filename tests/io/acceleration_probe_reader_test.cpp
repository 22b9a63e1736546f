// The case sections acceleration_probes and shock_spectrum (io/acceleration_probe_reader.h):
// probes on FE nodes of a flexible body (by id, by node set, at a marker) and on a point of a
// rigid body land in the model; the spectrum settings in the run settings; bad input names
// file, line and what was expected.
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"

#include <gtest/gtest.h>

#include "input_error_matchers.h"

namespace limber::io {
namespace {

using test::fails_at;
using test::location_of;

// A 1 m steel beam of 10 elements (node ids 1..11), hinged to ground, and a free rigid box.
const std::string kCase = R"(title: probes
materials:
  steel: {E: 206.8e9, nu: 0.3, rho: 7820}
sections:
  bar: {shape: rectangle, width: 0.01, height: 0.02}
flexible_bodies:
  beam:
    beams:
      - {from: [0, 0, 0], to: [1, 0, 0], elements: 10, section: bar, material: steel,
         orientation: [0, 1, 0], first_node_id: 1}
    node_sets: {root: [1], tip: [11]}
    modes: {normal: 3}
bodies:
  arm: {flexible: beam, position: [0.5, 0, 0]}
  box: {mass: 1, inertia: [1, 1, 1], position: [0, 0, 2]}
markers:
  end: {body: arm, node: tip}
joints:
  hinge: {type: revolute, body_i: ground, body_j: arm, position: [0.5, 0, 0]}
acceleration_probes:
  tip: {body: arm, node: tip}
  middle: {body: arm, node: 6}
  at_end: {marker: end}
  corner: {body: box, position: [0.1, 0.2, 0.3]}
shock_spectrum: {min_frequency: 10, q: 20, window: 0.5}
run: {t_end: 0.1, sample_interval: 1e-4}
)";

std::string edited(const std::string& from, const std::string& to) { return test::replaced(kCase, from, to); }

TEST(AccelerationProbeReader, ProbesAndSettingsLandInTheModel) {
  const Case input = read_case_text(kCase, test::kCaseName);
  const Mechanism built = build_mechanism(input, reduce_case(input, ReductionScope::kMechanismBodies));
  const multibody::Model& model = built.model;
  ASSERT_EQ(model.acceleration_probes.size(), 4u);
  const int arm = model.find_body("arm"), box = model.find_body("box");
  // Node ids 11 and 6 are indices 10 and 5; the marker's probe is its node.
  EXPECT_EQ(model.acceleration_probes[0].body, arm);
  EXPECT_EQ(model.acceleration_probes[0].node, 10);
  EXPECT_TRUE(model.acceleration_probes[0].p_B.isApprox(Eigen::Vector3d(1, 0, 0)));
  EXPECT_EQ(model.acceleration_probes[1].node, 5);
  EXPECT_EQ(model.acceleration_probes[2].name, "at_end");
  EXPECT_EQ(model.acceleration_probes[2].node, 10);
  EXPECT_EQ(model.acceleration_probes[3].body, box);
  EXPECT_EQ(model.acceleration_probes[3].node, -1);
  EXPECT_TRUE(model.acceleration_probes[3].p_B.isApprox(Eigen::Vector3d(0.1, 0.2, 0.3)));
  const results::ShockSpectrumSettings& srs = built.run.shock_spectrum;
  EXPECT_EQ(srs.min_frequency_hz, 10.0);
  EXPECT_EQ(srs.max_frequency_hz, 0.0);  // the band limit, 1/(10 h)
  EXPECT_EQ(srs.q, 20.0);
  EXPECT_EQ(srs.window_seconds, 0.5);
}

TEST(AccelerationProbeReader, BadInputNamesFileLineAndWhatWasExpected) {
  // No such body, ground, no such marker (the builder's checks, at the value).
  std::string text = edited("{body: box, position: [0.1, 0.2, 0.3]}", "{body: nobody, position: [0, 0, 0]}");
  EXPECT_TRUE(fails_at(text, location_of(text, "nobody"), "expected an existing body, got \"nobody\""));
  text = edited("{body: box, position: [0.1, 0.2, 0.3]}", "{body: ground, position: [0, 0, 0]}");
  EXPECT_TRUE(fails_at(text, location_of(text, "ground, position"), "expected a moving body"));
  text = edited("{marker: end}", "{marker: nowhere}");
  EXPECT_TRUE(fails_at(text, location_of(text, "nowhere"), "expected an existing marker"));
  // A node the body does not have; a node on a rigid body; a point on a flexible one.
  text = edited("{body: arm, node: 6}", "{body: arm, node: 99}");
  EXPECT_TRUE(fails_at(text, location_of(text, "99"), "expected a node id of flexible body 'beam'"));
  text = edited("{body: box, position: [0.1, 0.2, 0.3]}", "{body: box, node: 3}");
  EXPECT_TRUE(fails_at(text, location_of(text, "3}", 1), "expected 'position' (body frame)"));
  text = edited("{body: arm, node: 6}", "{body: arm, position: [0, 0, 0]}");
  EXPECT_TRUE(fails_at(text, location_of(text, "[0, 0, 0]}"), "expected 'node' for acceleration probe 'middle'"));
  text = edited("{marker: end}", "{marker: end, body: arm}");
  EXPECT_TRUE(fails_at(text, location_of(text, "{marker: end, body"), "expected either 'marker' or 'body'"));
  // Spectra without probes; a band the steps do not support (IDA without max_step: the sample
  // interval, 1/(10 h) = 1 kHz here).
  text = edited("acceleration_probes:", "unused_probes:");
  text = text.substr(0, text.find("unused_probes:")) + text.substr(text.find("shock_spectrum:"));
  EXPECT_TRUE(fails_at(text, location_of(text, "{min_frequency"), "expected 'acceleration_probes'"));
  text = edited("q: 20,", "q: 20, max_frequency: 5000,");
  EXPECT_TRUE(fails_at(text, location_of(text, "5000"), "at most 1000 Hz"));
  text = edited("sample_interval: 1e-4", "sample_interval: 0.05");  // 1/(10 h) = 2 Hz < 10 Hz
  EXPECT_TRUE(fails_at(text, location_of(text, "10, q"), "SRS minimum frequency of at most 2 Hz"));
  // Generalized-α records at its step: 1 ms supports 100 Hz, whatever the samples.
  text = edited("q: 20,", "q: 20, max_frequency: 500,");
  text = text.replace(text.find("run: {"), 6, "run: {integrator: galpha, step: 1e-3, ");
  EXPECT_TRUE(fails_at(text, location_of(text, "500"), "at most 100 Hz"));
  text = edited("{min_frequency: 10,", "{min_frequency: 10, max_frequency: 8,");
  EXPECT_TRUE(fails_at(text, location_of(text, "8,"), "expected max_frequency >= min_frequency"));
}

}  // namespace
}  // namespace limber::io
