// limber_render_driver: try `limber render` before the limber executable wires it in.
//   limber_render_driver scene DIR            write the render test scene to DIR/results.h5
//   limber_render_driver render DIR [options] render it (options as `limber render`)
#include "render_command.h"
#include "test_results.h"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app("limber render test driver");
  app.require_subcommand(1);

  // `scene DIR`: the known scene of tests/render/test_results.h.
  std::string scene_directory;
  CLI::App* scene = app.add_subcommand("scene", "write the render test scene");
  scene->add_option("DIR", scene_directory)->required();
  scene->callback([&] {
    limber::render::testing::write_test_results(scene_directory, {});
  });

  limber::render::add_render_command(app);
  CLI11_PARSE(app, argc, argv);
  return 0;
}
