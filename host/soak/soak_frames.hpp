// SPDX-License-Identifier: Apache-2.0
// The frames of a soak or a reset trial: varied content, deterministic from a seed, and the
// malformed frames a broken camera link sends (short row, cut frame, sof in mid-frame, stray
// beats), as beats for both cameras with what each frame's result must show.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "hls/common/beat.hpp"

namespace scw::host::soak {

/// A rectified pair that is not a scene: the real crops come from it.
struct RealPair {
  cv::Mat left, right;  // CV_8UC1, at least as large as the soak's frames
};

/// The kinds of content, drawn per frame: a synthetic street (a few boxes at known disparities
/// on texture), clutter (up to 40 small boxes: many labels, the label pools and MaxObjects
/// tested), a crop of the real pair at a random place, and noise (the right image unrelated to
/// the left: a random disparity map, the labelling's worst case).
enum class Content { street, clutter, real, noise };
const char* content_name(Content c);

/// Frame k of the content drawn from `seed`: w x h, disparities within 0 .. max_disparity.
struct ContentFrame {
  cv::Mat left, right;
  Content kind = Content::street;
};
ContentFrame content_frame(int w, int h, int max_disparity, std::uint64_t seed, int k,
                           const RealPair& real);

/// What a broken link does to a frame (applied to one camera, or both for a sof mid-frame,
/// which splits the frame in two on both streams so that the two cameras keep the same count).
enum class Fault { none, short_row, cut_frame, sof_mid_frame, stray_beats };
const char* fault_name(Fault f);
/// The faults in the order a soak injects them, one every K frames.
inline constexpr Fault kFaults[] = {Fault::short_row, Fault::cut_frame, Fault::sof_mid_frame,
                                    Fault::stray_beats};

/// One result the pipeline must give: which content frame it comes from, whether its frame
/// was broken (and so must be flagged on those cameras, and is not checked against the
/// floating-point reference).
struct ExpectedResult {
  int frame = 0;  // content frame index
  Fault fault = Fault::none;
  bool left_broken = false, right_broken = false;
};

/// Both cameras' beats at P = 1 and the results they must give, frames back to back.
struct SoakStream {
  std::vector<hls::Beat<std::uint8_t, 1>> left, right;
  std::vector<ExpectedResult> expected;
};

/// Appends content frame `k` to `s`, broken by `fault` on the left camera (`on_left`) or the
/// right, at a place drawn from `seed` and k. A frame needs at least 4 rows for every fault.
void append_frame(SoakStream& s, const ContentFrame& f, int k, Fault fault, bool on_left,
                  std::uint64_t seed);

}  // namespace scw::host::soak
