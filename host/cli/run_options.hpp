// SPDX-License-Identifier: Apache-2.0
// `scw run`'s two large option groups: how the pairs were taken (calibration or rectified
// camera) and the warning's geometry (tunnel, heights, distance rule).
#pragma once

#include <CLI/CLI.hpp>

#include "host/app/camera.hpp"
#include "host/app/run.hpp"

namespace scw::cli {

/// --calib, --rectified, --focal, --baseline, --cx, --cy, --calib-unit-m, --maps, --grid-log2.
void add_camera_options(CLI::App* cmd, app::CameraInput& camera);

/// --min-height, --distance-rule, --spread-k, --near, --car-width, --car-height.
void add_warning_options(CLI::App* cmd, host::warning::WarningSetup& warning);

}  // namespace scw::cli
