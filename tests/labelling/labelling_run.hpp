// SPDX-License-Identifier: Apache-2.0
// Runs labelling frames through any cycle model (C++ or RTL) and checks them against the
// flood-fill reference: shared by the [hls] and [rtl] tests.
#pragma once

#include <catch2/catch.hpp>
#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "hls/labelling/labelling_params.hpp"
#include "host/labelling/second_pass.hpp"
#include "host/reference/labelling_ref.hpp"
#include "host/vectors/labelling_maps.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/core/stream_check.hpp"
#include "sim/models/labelling_model.hpp"
#include "sim/words/labelling_pack.hpp"

namespace scw::test {

// The maps are the golden vectors' fixtures too, so they live in host/vectors/.
using fixtures::adversarial_maps;
using fixtures::blank_map;
using fixtures::comb_map;
using fixtures::DispMap;
using fixtures::dots_map;
using fixtures::mesh_map;
using fixtures::nested_u_map;
using fixtures::random_map;
using fixtures::spiral_map;
using fixtures::staircase_map;

using hls::labelling::FrameStatus;
using hls::labelling::LabelPacket;
using hls::labelling::LabellingConfig;
using hls::labelling::Object;
using InBeat = hls::Beat<std::uint16_t, 1>;

/// One frame's output burst, split.
struct FrameOut {
  std::vector<Object> objects;
  FrameStatus status;
};

/// Splits a packet stream into frames; fails the test if a frame's burst is malformed.
inline std::vector<FrameOut> split_frames(const std::vector<LabelPacket>& out) {
  std::vector<FrameOut> frames(1);
  for (const auto& p : out) {
    if (p.data.is_status) {
      CHECK(p.last);
      frames.back().status = p.data.status;
      frames.emplace_back();
    } else {
      CHECK_FALSE(p.last);
      frames.back().objects.push_back(p.data.object);
    }
  }
  frames.pop_back();
  return frames;
}

using labelling::raster_sorted;

/// The maps' frames as beats of `Beat` (one pixel each unless a lane build's).
template <typename Beat = InBeat>
std::vector<Beat> map_beats(const std::vector<DispMap>& maps) {
  std::vector<Beat> beats;
  for (const auto& m : maps) {
    const auto b = sim::frame_beats_of<Beat>(m.d.data(), m.w, m.h);
    beats.insert(beats.end(), b.begin(), b.end());
  }
  return beats;
}

/// A stream whose first frame is broken (the stage must flag it) and whose last is `good`.
template <typename Beat>
struct BrokenStream {
  const char* name;
  std::vector<Beat> beats;
  bool first_whole;  // the first frame holds every pixel (its objects equal the next frame's)
};

/// Three broken streams, each giving two frames: a frame cut short after `cut` beats by the
/// next sof; four beats before the first sof (flagged on the frame they precede); an eol on
/// beat `eol_at`, inside a row.
template <typename Beat>
std::vector<BrokenStream<Beat>> broken_streams(const DispMap& good, std::size_t cut,
                                               std::size_t eol_at) {
  const auto whole = map_beats<Beat>({good});
  auto then_whole = [&](std::vector<Beat> v, int times) {
    for (int i = 0; i < times; ++i) v.insert(v.end(), whole.begin(), whole.end());
    return v;
  };
  auto misplaced = whole;
  misplaced[eol_at].eol = true;
  return {
      {"a frame cut short by the next sof", then_whole({whole.begin(), whole.begin() + cut}, 1),
       false},
      {"beats before the first sof", then_whole({whole.begin() + 5, whole.begin() + 9}, 2), true},
      {"a row with a misplaced eol", then_whole(misplaced, 1), false},
  };
}

/// The reference's objects of each map: the output words they make (objects + status).
inline std::size_t expected_words(const std::vector<DispMap>& maps, const LabellingConfig& cfg) {
  std::size_t n = 0;
  for (const auto& m : maps)
    n += reference::labelling_reference(m.d.data(), m.w, m.h, cfg).objects.size() + 1;
  return n;
}

/// The frames a model gave equal the reference's, object for object, with a clean status.
inline void check_against_reference(const std::vector<FrameOut>& frames,
                                    const std::vector<DispMap>& maps,
                                    const LabellingConfig& cfg) {
  REQUIRE(frames.size() == maps.size());
  for (std::size_t i = 0; i < maps.size(); ++i) {
    INFO("map " << maps[i].name);
    const auto ref = reference::labelling_reference(maps[i].d.data(), maps[i].w, maps[i].h, cfg);
    CHECK(frames[i].status.objects == ref.objects.size());
    CHECK_FALSE(frames[i].status.tile_overflow);
    CHECK_FALSE(frames[i].status.object_overflow);
    CHECK_FALSE(frames[i].status.stream_error);
    CHECK(raster_sorted(frames[i].objects) == ref.objects);
  }
}

/// Every map back to back through `model` under `pattern`.
template <typename Model>
sim::RunResult<LabelPacket> run_maps(Model& model, const std::vector<DispMap>& maps,
                                     const LabellingConfig& cfg, const sim::StallPattern& pattern) {
  return sim::run_stream(model, map_beats<typename Model::in_type>(maps), pattern,
                         expected_words(maps, cfg), 4'000'000);
}

/// Runs `beats` through `model` under `pattern` until `frames` status words have come out
/// (for streams whose object counts the reference cannot tell: overflows, broken frames).
template <typename Model>
sim::RunResult<LabelPacket> run_until_frames(Model& model,
                                             std::vector<typename Model::in_type> beats,
                                             std::size_t frames,
                                             const sim::StallPattern& pattern = {}) {
  std::size_t seen = 0, closed = 0;  // count new words only: the check runs every cycle
  return sim::run_stream_until(
      model, std::move(beats), pattern,
      [frames, seen, closed](const std::vector<LabelPacket>& out) mutable {
        for (; seen < out.size(); ++seen) closed += out[seen].data.is_status ? 1 : 0;
        return closed >= frames;
      },
      400'000);
}

/// Every broken stream of `good` through the C++ model built with `Params`: the broken frame
/// flagged, the next frame correct.
template <typename Params>
void check_broken_streams(const LabellingConfig& cfg, const DispMap& good, std::size_t cut,
                          std::size_t eol_at) {
  for (const auto& s : broken_streams<typename Params::in_beat>(good, cut, eol_at)) {
    INFO(s.name);
    auto m = std::make_unique<sim::LabellingModel<Params>>(cfg);
    const auto r = run_until_frames(*m, s.beats, 2);
    CHECK_FALSE(r.timed_out);
    CHECK(r.violations.empty());
    const auto f = split_frames(r.out);
    REQUIRE(f.size() == 2);
    CHECK(f[0].status.stream_error);
    if (s.first_whole) CHECK(raster_sorted(f[0].objects) == raster_sorted(f[1].objects));
    check_against_reference({f[1]}, {good}, cfg);
  }
}

/// A run with every beat offered and the output taken, except for `hold` cycles from the first
/// object word on; per frame, the cycle its first beat was taken and its status word left.
struct HeldRun {
  std::vector<FrameOut> frames;
  std::vector<std::int64_t> first_in, status_out;
  std::vector<sim::StreamOutputs<LabelPacket>> trace;  // every cycle's outputs, to compare twins
};

template <typename Model>
HeldRun run_with_held_output(Model& m, const std::vector<typename Model::in_type>& beats,
                             std::size_t frames_n, std::int64_t hold) {
  HeldRun r;
  std::vector<LabelPacket> out;
  std::size_t next = 0;
  std::int64_t hold_from = -1;
  for (std::int64_t c = 0; r.status_out.size() < frames_n; ++c) {
    REQUIRE(c < 200'000);  // a stage that never finishes fails here, not by hanging
    const bool valid = next < beats.size();
    const bool ready = hold_from < 0 || c >= hold_from + hold;
    const auto o = m.eval(valid, valid ? beats[next] : typename Model::in_type{}, ready);
    r.trace.push_back(o);
    if (valid && o.in_ready && beats[next].sof) r.first_in.push_back(c);
    if (o.out_valid && hold_from < 0) hold_from = c;
    if (o.out_valid && ready) {
      out.push_back(o.out);
      if (o.out.last) r.status_out.push_back(c);
    }
    m.tick();
    if (valid && o.in_ready) ++next;
  }
  r.frames = split_frames(out);
  return r;
}

/// `maps` (at least three, the first with objects) back to back, twice: output always taken,
/// and held from the first object word for longer than two frames. The next frame streams in
/// while the last one's objects leave; with the output held, the frame after waits for them
/// (its Resolve would overwrite the sums being sent); the frames equal the reference. Returns
/// both runs, for twins to compare.
template <typename Model, typename MakeModel>
std::vector<HeldRun> check_emit_overlap(MakeModel make, const std::vector<DispMap>& maps,
                                        const LabellingConfig& cfg) {
  const auto beats = map_beats<typename Model::in_type>(maps);
  const std::int64_t frame_beats = static_cast<std::int64_t>(beats.size() / maps.size());
  std::vector<HeldRun> runs;
  for (const std::int64_t hold : {std::int64_t{0}, 3 * frame_beats}) {
    INFO("output held for " << hold << " cycles");
    auto m = make();
    auto r = run_with_held_output(*m, beats, maps.size(), hold);
    check_against_reference(r.frames, maps, cfg);
    REQUIRE(r.first_in.size() == maps.size());
    CHECK(r.first_in[1] < r.status_out[0]);  // frame 1 came in while frame 0's objects left
    if (hold > 0) CHECK(r.first_in[2] > r.status_out[0]);  // frame 1's Resolve waited
    runs.push_back(std::move(r));
  }
  return runs;
}

}  // namespace scw::test
