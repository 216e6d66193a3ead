// SPDX-License-Identifier: Apache-2.0
// Frame check: raw pixels pass unchanged; one flag per frame says whether its geometry was wrong.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "hls/common/beat.hpp"
#include "hls/common/bits.hpp"
#include "hls/common/stream.hpp"

namespace scw::hls::pipeline {

/// Bits of a count 0 .. n (the RTL's $clog2(n + 1)).
constexpr int count_bits(int n) { return clog2(n + 1LL); }

/// Built-in capacity of one frame check (the RTL's parameters, by their names).
template <int P, int MaxWidthPx, int MaxHeight>
struct FrameCheckParams {
  static_assert(P == 1 || P == 2 || P == 4, "P (pixels per beat) must be 1, 2 or 4");
  static_assert(MaxWidthPx >= P && MaxWidthPx % P == 0, "whole beats per row");
  static_assert(MaxHeight >= 1, "at least one row");
  static constexpr int kPpc = P;
  static constexpr int kMaxWidthPx = MaxWidthPx;
  static constexpr int kMaxHeight = MaxHeight;
  /// Widths of the RTL's cfg_width_i and cfg_height_i.
  static constexpr int kWidthBits = count_bits(MaxWidthPx);
  static constexpr int kHeightBits = count_bits(MaxHeight);
  /// Clocks from accepting a beat to presenting it (and its frame's flag): the output registers.
  static constexpr int kLatency = 1;
  using beat_type = Beat<pixel_t, P>;
};

/// Run-time geometry (the RTL's cfg_* ports, static while frames stream).
struct FrameCheckConfig {
  int width = 0;   // pixels per row, a multiple of P
  int height = 0;  // rows per frame
};

/// Throws std::invalid_argument unless `cfg` fits the build. A frame must have at least two
/// beats: only a beat without sof closes a frame by count (a sof beat may already emit the
/// previous frame's flag, and one flag register takes one flag per clock).
template <typename Params>
void check_frame_check_config([[maybe_unused]] const FrameCheckConfig& cfg) {
#ifndef __SYNTHESIS__  // the host's check: a synthesised top trusts its registers
  const auto fail = [&](const std::string& why) {
    throw std::invalid_argument("frame check: " + std::to_string(cfg.width) + " x " +
                                std::to_string(cfg.height) + ": " + why);
  };
  if (cfg.width < Params::kPpc || cfg.width > Params::kMaxWidthPx)
    fail("width outside " + std::to_string(Params::kPpc) + " .. " +
         std::to_string(Params::kMaxWidthPx));
  if (cfg.width % Params::kPpc != 0)
    fail("width not a multiple of " + std::to_string(Params::kPpc) + " pixels per beat");
  if (cfg.height < 1 || cfg.height > Params::kMaxHeight)
    fail("height outside 1 .. " + std::to_string(Params::kMaxHeight));
  if (cfg.width / Params::kPpc * cfg.height < 2) fail("a frame needs at least two beats");
#endif
}

/// One frame's verdict.
struct FrameFlag {
  bool error = false;  // the frame's geometry was wrong (or stray beats came before it)

  friend bool operator==(const FrameFlag& a, const FrameFlag& b) { return a.error == b.error; }
  friend bool operator!=(const FrameFlag& a, const FrameFlag& b) { return !(a == b); }
};

/// The flag stream: one one-word burst (last = true) per frame.
using FrameFlagPacket = Packet<FrameFlag>;

/// The twin of rtl_models/pipeline/scw_frame_check.sv: the geometry state machine. The rules,
/// applied to every accepted beat (beats per row = width / P; counting is by the configured
/// geometry, never by eol, because the rectifiers downstream repair frames and would hide the
/// error):
///  - not in a frame: a sof beat starts one (beat 0 of row 0); a beat without sof is stray and
///    marks the next frame erroneous;
///  - in a frame, a sof beat closes the frame early (its flag, error = 1, leaves with this beat)
///    and starts a new, clean frame;
///  - every beat of a frame must carry eol exactly when it is the last beat of its row;
///  - the last beat of the last row (a beat without sof) closes the frame: its flag leaves with
///    it, then not in a frame.
/// `step()` is the per-beat body of the II=1 loop; `emits_flag()` tells a cycle model whether
/// accepting a beat needs the flag register (the RTL's in_ready looks at it).
template <int P, int MaxWidthPx, int MaxHeight>
class FrameCheck {
 public:
  using params = FrameCheckParams<P, MaxWidthPx, MaxHeight>;
  using in_type = Beat<pixel_t, P>;
  using out_type = in_type;
  using flag_type = FrameFlagPacket;

  explicit FrameCheck(const FrameCheckConfig& cfg)
      : beats_per_row_(cfg.width / P), height_(cfg.height) {
    check_frame_check_config<params>(cfg);
  }

  /// Would accepting `in` now emit a frame's flag?
  bool emits_flag(const in_type& in) const {
    return in_frame_ && (in.sof || (col_ == beats_per_row_ - 1 && row_ == height_ - 1));
  }

  /// One accepted beat (it passes unchanged). Returns true and sets `flag` if a frame's flag
  /// leaves with it.
  bool step(const in_type& in, FrameFlag& flag) {
    // clang-format off
#pragma HLS INLINE
    // clang-format on
    if (!in_frame_ && !in.sof) {
      stray_ = true;
      return false;
    }
    bool emitted = false;
    if (in_frame_ && in.sof) {
      flag.error = true;  // cut short
      emitted = true;
    }
    // The beat's place: a sof restarts the count; a new frame inherits stray beats only when it
    // follows a gap between frames.
    const int col = in.sof ? 0 : col_;
    const int row = in.sof ? 0 : row_;
    bool err = in.sof ? (!in_frame_ && stray_) : err_;
    if (in.sof) stray_ = false;
    const bool last_col = col == beats_per_row_ - 1;
    err = err || in.eol != last_col;
    if (!in.sof && last_col && row == height_ - 1) {
      flag.error = err;
      emitted = true;
      in_frame_ = false;
    } else {
      in_frame_ = true;
      err_ = err;
      col_ = last_col ? 0 : col + 1;
      row_ = last_col ? row + 1 : row;
    }
    if (emitted) {
      ++frames_;
      if (flag.error) ++flagged_;
    }
    return emitted;
  }

  /// Flags emitted so far, and how many of them said error (for tests; not in the RTL).
  std::int64_t frames() const { return frames_; }
  std::int64_t frames_flagged() const { return flagged_; }

 private:
  int beats_per_row_;
  int height_;
  bool in_frame_ = false;
  bool err_ = false;    // the current frame's error so far
  bool stray_ = false;  // stray beats since the last frame: the next frame is erroneous
  int col_ = 0;         // beat within the row of the next beat
  int row_ = 0;
  std::int64_t frames_ = 0;
  std::int64_t flagged_ = 0;
};

// The loop label names the loop in HLS reports; g++ would call it unused.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-label"
/// `n` beats through the check with no stalls: every beat on to `out`, each frame's flag to
/// `flags` as it leaves (with the frame's last beat, or with the sof that cut it short). What an
/// HLS tool synthesises as the check's top; hls::stream ports (or ArrayIn / ArrayOut).
template <int P, int MaxWidthPx, int MaxHeight, typename In, typename Out, typename Flags>
void frame_check_frame(FrameCheck<P, MaxWidthPx, MaxHeight>& k, In& in, Out& out, Flags& flags,
                       int n) {
  // clang-format off
#pragma HLS INTERFACE axis port=in
#pragma HLS INTERFACE axis port=out
#pragma HLS INTERFACE axis port=flags
#pragma HLS INTERFACE s_axilite port=n
#pragma HLS INTERFACE s_axilite port=return
  // clang-format on
loop_beat:
  for (int i = 0; i < n; ++i) {
    // clang-format off
#pragma HLS PIPELINE II=1
    // clang-format on
    const Beat<pixel_t, P> b = in.read();
    FrameFlag f;
    if (k.step(b, f)) flags.write(FrameFlagPacket{f, true});
    out.write(b);
  }
}
#pragma GCC diagnostic pop

}  // namespace scw::hls::pipeline
