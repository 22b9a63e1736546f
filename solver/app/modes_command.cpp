// `limber modes`: reads a case, computes every flexible body's mode set (io::reduce_case:
// normal, constraint and attachment modes, seed paper eq. 4-11), prints the frequency table and
// writes DIR/modes.h5 (docs/modes-format.md), DIR/modes_<body>.vtu (ParaView) and, from
// modes.h5 through render/, animated mode shapes in DIR/modes/ (docs/rendering.md).
#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/command.h"
#include "core/error.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/modes_file.h"
#include "io/modes_json.h"
#include "io/vtu_writer.h"
#include "modal/component_modes.h"
#include "mode_animation.h"
#include "render_options.h"
#include "results/file_names.h"

namespace limber::app {

namespace {

struct ModesOptions {
  std::string case_file;
  std::string output_dir;
  bool json = false;
  std::string vtu_format = "binary";
  bool animate = true;
  std::string animation_size = "640x480";
  double animation_amplitude = 0.1;  // largest drawn displacement / body size
};

// One body's outcome.
struct BodyOutcome {
  const io::FlexibleBodyCase* body = nullptr;
  modal::ModalResult result;
};

// The frequency table of one body, rigid modes found and notices.
void print_table(std::FILE* out, const BodyOutcome& outcome) {
  const fe::FeModel& model = outcome.body->model;
  const modal::ModeSet& set = outcome.result.mode_set;
  fmt::print(out, "\nbody '{}': {} nodes, {} DOFs ({} fixed), {} beam and {} shell elements\n",
             outcome.body->name, model.node_count(), model.dof_count(), model.fixed_dofs.size(),
             model.beams.size(), model.shells.size() + model.triangles.size());
  fmt::print(out, "  {:>4}  {:<10}  {:>14}  {}\n", "mode", "kind", "frequency [Hz]", "label");
  for (std::size_t i = 0; i < set.modes.size(); ++i) {
    const modal::ModeInfo& mode = set.modes[i];
    fmt::print(out, "  {:>4}  {:<10}  {:>14.4f}  {}\n", i + 1, modal::to_string(mode.kind),
               mode.frequency_hz, mode.label);
  }
  // Rigid-body modes are carried by the floating frame, not by the mode set.
  if (!set.rigid_modes.empty()) {
    fmt::print(out, "  rigid-body modes found and set aside: {}\n", set.rigid_modes.size());
    for (const modal::ModeInfo& mode : set.rigid_modes) {
      fmt::print(out, "        {:<10}  {:>14.4g}  {}\n", modal::to_string(mode.kind),
                 mode.frequency_hz, mode.label);
    }
  }
  for (const std::string& notice : outcome.body->notices) {
    fmt::print(out, "  notice: {}\n", notice);
  }
  for (const std::string& notice : outcome.result.notices) {
    fmt::print(out, "  notice: {}\n", notice);
  }
}

// One PNG loop (and GIF) per body and mode. A machine without an offscreen OpenGL context
// (std::runtime_error) keeps modes.h5 and the VTU files: a warning, not a failure.
void animate(const render::ModeAnimationOptions& animation, const std::string& h5_path,
             const std::filesystem::path& directory, std::FILE* table) {
  try {
    const render::ModeAnimationSummary summary =
        render::animate_modes(h5_path, directory, animation);
    fmt::print(table, "wrote {} mode-shape animations ({} frames{}) in {}\n", summary.animations,
               summary.frames, summary.gifs.empty() ? "" : " and GIFs",
               (directory / "modes").string());
    for (const std::string& warning : summary.warnings) {
      fmt::print(stderr, "limber modes: warning: {}\n", warning);
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& error) {
    fmt::print(stderr, "limber modes: warning: no mode-shape animations: {}\n", error.what());
  }
}

int run_modes(const ModesOptions& options) {
  // Animation options are checked before any work.
  render::ModeAnimationOptions animation;
  render::parse_frame_size(options.animation_size, animation.width, animation.height);
  animation.amplitude_fraction = options.animation_amplitude;

  const io::Case input = io::read_case_file(options.case_file);
  if (input.flexible_bodies.empty()) {
    throw InputError("expected at least one body under 'flexible_bodies', got none",
                     SourceLocation{options.case_file, 0, 0});
  }
  // The table goes to stdout, or to stderr when stdout carries JSON.
  std::FILE* table = options.json ? stderr : stdout;
  fmt::print(table, "limber modes: {} ({})\n", input.title, input.file);

  // Every body's modes; a numerical failure is reported and the others still written.
  io::CaseReduction reduction = io::reduce_case(input, io::ReductionScope::kAllBodies);
  std::vector<BodyOutcome> outcomes;
  std::vector<std::string> failures;
  for (std::size_t b = 0; b < input.flexible_bodies.size(); ++b) {
    const io::FlexibleBodyCase& body = input.flexible_bodies[b];
    BodyOutcome outcome{&body, std::move(reduction.bodies[b].result)};
    if (outcome.result.status != modal::ModalStatus::kOk) {
      failures.push_back(fmt::format("body '{}': {}: {}", body.name,
                                     modal::to_string(outcome.result.status), outcome.result.message));
      continue;
    }
    print_table(table, outcome);
    outcomes.push_back(std::move(outcome));
  }

  // Files: one HDF5 file for all bodies computed, one VTU per body.
  const std::filesystem::path directory =
      options.output_dir.empty()
          ? std::filesystem::path("out") / std::filesystem::path(options.case_file).stem()
          : std::filesystem::path(options.output_dir);
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) {
    throw InputError("cannot create the output directory '" + directory.string() +
                     "': " + error.message());
  }
  std::vector<io::BodyModesRef> written;
  for (const BodyOutcome& outcome : outcomes) {
    written.push_back({outcome.body->name, &outcome.body->model, &outcome.result.mode_set});
  }
  const std::string h5_path = (directory / results::kModesFileName).string();
  io::write_modes_file(h5_path, input.title, input.file, written);
  fmt::print(table, "\nwrote {}\n", h5_path);
  const io::VtuEncoding encoding =
      options.vtu_format == "ascii" ? io::VtuEncoding::kAscii : io::VtuEncoding::kBase64;
  for (const BodyOutcome& outcome : outcomes) {
    const std::string vtu_path = (directory / ("modes_" + outcome.body->name + ".vtu")).string();
    io::write_modes_vtu(vtu_path, outcome.body->model, outcome.result.mode_set, encoding);
    fmt::print(table, "wrote {}\n", vtu_path);
  }

  // Mode-shape animations, drawn from the modes.h5 just written (render/ reads files only).
  if (options.animate && !outcomes.empty()) animate(animation, h5_path, directory, table);

  if (options.json) fmt::print(stdout, "{}\n", io::modes_json(written, failures));
  for (const std::string& failure : failures) fmt::print(stderr, "limber: error: {}\n", failure);
  return failures.empty() ? kExitOk : kExitNumerical;
}

}  // namespace

Command add_modes_command(CLI::App& app) {
  auto options = std::make_shared<ModesOptions>();
  CLI::App* cli = app.add_subcommand(
      "modes", "Compute the flexible bodies' mode sets; write modes.h5 and VTU files");
  cli->footer(
      "Prints each body's frequency table (mode, kind, label, frequency), the rigid-body modes\n"
      "found and set aside, and notices (e.g. dropped dependent static modes). Writes\n"
      "DIR/modes.h5 (every body: mesh, mode shapes, frequencies, invariants; see\n"
      "docs/modes-format.md) and DIR/modes_<body>.vtu (each mode shape as a point vector\n"
      "array, for ParaView's Warp By Vector) and DIR/modes/<body>/mode_<k>/frame_*.png: one\n"
      "period of each mode shape, offscreen (and mode_<k>.gif with ffmpeg; docs/rendering.md).\n"
      "Exit codes: 0 success, 1 bad input (message 'limber: error: case.yaml:LINE:COL: ...'),\n"
      "2 an eigen-solver failed (the bodies computed so far are still written), 3 internal error.");
  cli->add_option("case", options->case_file, "Case file (YAML, docs/case-format.md)")->required();
  cli->add_option("-o,--output", options->output_dir,
                  "Output directory, created when missing (default: out/<case file stem>)");
  cli->add_flag("--json", options->json,
                "Print exactly one JSON object on stdout: {\"bodies\": {<name>: {\"dofs\": N, "
                "\"modes\": [{\"kind\", \"frequency_hz\", \"label\"}]}}}, rigid modes included; "
                "the table goes to stderr");
  cli->add_option("--vtu-format", options->vtu_format,
                  "Encoding of the VTU files: binary (base64) or ascii")
      ->check(CLI::IsMember({"binary", "ascii"}))
      ->capture_default_str();
  cli->add_flag("!--no-animation", options->animate,
                "Do not render the mode-shape animations (DIR/modes/<body>/mode_<k>/*.png)");
  cli->add_option("--animation-size", options->animation_size,
                  "Frame size WIDTHxHEIGHT of the mode-shape animations [pixels]")
      ->capture_default_str();
  cli->add_option("--animation-amplitude", options->animation_amplitude,
                  "Largest drawn displacement of a mode, as a fraction of the body's size "
                  "(diagonal of its bounding box)")
      ->capture_default_str();
  return {cli, [options] { return run_modes(*options); }};
}

}  // namespace limber::app
