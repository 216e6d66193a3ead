// SPDX-License-Identifier: Apache-2.0
// The scenes that re-enact the thesis's experiments: the distance sweep (Fig. 5.5), the
// crossing cyclist (Fig. 5.12) and the running pedestrian beside a parked car (Fig. 5.13); and
// two streets with what real ones put beside the lane.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "host/scene/scene.hpp"

namespace scw::host::scene {

/// "distance-sweep", "cyclist-crossing", "pedestrian-running" (the thesis's experiments) and the
/// street presets "street-crossing" and "street-driving" (kerbs, pavements, building fronts,
/// parked cars, markings, road grain, a pitched camera: host/scene/street.hpp).
std::vector<std::string> preset_names();

/// The preset's own number of frames (49, 57, 38, 41, 41). Throws std::invalid_argument for an unknown
/// name, listing the known ones.
int default_frames(const std::string& preset);

/// The preset's frames; `frames` spreads that many poses evenly over the same motion (the frame
/// period grows as they thin out). The ego car stands still; the objects move. `seed` picks the
/// textures. Throws std::invalid_argument for an unknown preset (listing the names) or fewer
/// than 2 frames.
Sequence make_preset(const std::string& preset, std::optional<int> frames = std::nullopt,
                     std::uint32_t seed = 1);

}  // namespace scw::host::scene
