// SPDX-License-Identifier: Apache-2.0
// Registration of the `scw` subcommands: one function per cmd_<name>.cpp.
#pragma once

#include <CLI/CLI.hpp>

namespace scw::cli {

void add_info_command(CLI::App& app);
void add_vectors_command(CLI::App& app);
void add_stream_command(CLI::App& app);
void add_rectify_command(CLI::App& app);
void add_disparity_command(CLI::App& app);
void add_segment_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_train_command(CLI::App& app);
void add_synth_command(CLI::App& app);  // `scw synth`
void add_sim_command(CLI::App& app);    // `scw sim`
void add_scene_command(CLI::App& app);  // `scw scene`
void add_eval_command(CLI::App& app);   // `scw eval`
void add_soak_command(CLI::App& app);   // `scw soak`
void add_merge_command(CLI::App& app);  // `scw merge`
/// `scw vectors rectify`, added under the `vectors` subcommand.
void add_vectors_rectify_command(CLI::App& vectors);
/// `scw vectors disparity`, added under the `vectors` subcommand.
void add_vectors_disparity_command(CLI::App& vectors);
void add_vectors_labelling_command(CLI::App& vectors);  // `scw vectors labelling`
void add_vectors_warning_command(CLI::App& vectors);    // `scw vectors warning`
void add_vectors_road_command(CLI::App& vectors);       // `scw vectors road`
void add_vectors_pipeline_command(CLI::App& vectors);   // `scw vectors pipeline`

}  // namespace scw::cli
