// SPDX-License-Identifier: Apache-2.0
// Entry point of `scw`: parses arguments with CLI11 and reports errors as one clear line.
#include <exception>
#include <iostream>

#include "host/cli/commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"scw: stereo collision warning as streaming hardware (HLS C++ and RTL models)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "scw 0.1.0");
  scw::cli::add_info_command(app);
  scw::cli::add_stream_command(app);
  scw::cli::add_rectify_command(app);
  scw::cli::add_disparity_command(app);
  scw::cli::add_segment_command(app);
  scw::cli::add_run_command(app);
  scw::cli::add_train_command(app);
  scw::cli::add_synth_command(app);
  scw::cli::add_sim_command(app);
  scw::cli::add_soak_command(app);
  scw::cli::add_merge_command(app);
  scw::cli::add_scene_command(app);
  scw::cli::add_eval_command(app);
  scw::cli::add_vectors_command(app);
  scw::cli::add_vectors_rectify_command(*app.get_subcommand("vectors"));
  scw::cli::add_vectors_disparity_command(*app.get_subcommand("vectors"));
  scw::cli::add_vectors_labelling_command(*app.get_subcommand("vectors"));
  scw::cli::add_vectors_warning_command(*app.get_subcommand("vectors"));
  scw::cli::add_vectors_road_command(*app.get_subcommand("vectors"));
  scw::cli::add_vectors_pipeline_command(*app.get_subcommand("vectors"));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "scw: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
