// SPDX-License-Identifier: Apache-2.0
// The whole pipeline as one HLS top: the stage tops as DATAFLOW processes linked by streams, the
// graph of rtl_models/pipeline/scw_pipeline.sv (and of sim::PipelineChain), a frame a call.
#pragma once

#include "hls/common/stream.hpp"
#include "hls/disparity/disparity.hpp"
#include "hls/labelling/labelling.hpp"
#include "hls/pipeline/frame_check.hpp"
#include "hls/pipeline/pipeline_config.hpp"
#include "hls/pipeline/pipeline_params.hpp"
#include "hls/pipeline/pipeline_result.hpp"
#include "hls/rectify/map_grid.hpp"
#include "hls/rectify/rectify.hpp"
#include "hls/road/road.hpp"
#include "hls/warning/warning.hpp"

namespace scw::hls::pipeline {

/// Every register and RAM of the top: one object per stage, kept between calls as the
/// hardware keeps them between frames. Without the optional ground filter (scw_pipeline has
/// none either).
template <typename Build>
struct PipelineStages {
  static constexpr int P = Build::kPpc;
  using Check = FrameCheck<P, Build::kMaxWidthPx, Build::kMaxHeight>;

  explicit PipelineStages(const PipelineConfig& c)
      : check_left(FrameCheckConfig{c.width, c.height}),
        check_right(FrameCheckConfig{c.width, c.height}),
        grid_left(rectify::MapGridConfig{c.width, c.height}),
        grid_right(rectify::MapGridConfig{c.width, c.height}),
        rect_left(rectify::RectifyConfig{c.width, c.height, c.lead_rows}),
        rect_right(rectify::RectifyConfig{c.width, c.height, c.lead_rows}),
        disparity(c.disparity_config()),
        road(c.road),
        labelling(c.labelling_config()),
        warning(c.warning_config()),
        beats(c.width / P * c.height) {}

  Check check_left, check_right;
  rectify::MapGrid<typename Build::map_grid> grid_left, grid_right;
  rectify::Rectify<typename Build::rectify> rect_left, rect_right;
  disparity::Disparity<typename Build::disparity> disparity;
  road::Road<typename Build::road> road;
  labelling::Labelling<typename Build::labelling> labelling;
  warning::Warning<typename Build::warning> warning;
  ResultMerge merge;
  int beats;  // beats of one camera's frame
};

/// Both cameras' knots (`cols` x `rows` each, row after row), before the first frame: the top's
/// knot port, as sim::PipelineChain loads it.
template <typename Build>
void pipeline_load_knots(PipelineStages<Build>& s, const rectify::KnotPoint* left,
                         const rectify::KnotPoint* right, int cols, int rows) {
  rectify::map_grid_load(s.grid_left, left, cols, rows);
  rectify::map_grid_load(s.grid_right, right, cols, rows);
}

// The loop label names the loop in HLS reports; g++ would call it unused.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-label"
/// `frames` frames' object words (at most `max_words`) to the warning stage and, in lockstep,
/// out as the object table.
template <typename In, typename Out, typename Table>
void fork_words(In& in, Out& warning, Table& table, int frames, int max_words) {
  int closed = 0;
loop_word:
  for (int i = 0; i < max_words && closed < frames; ++i) {
    // clang-format off
#pragma HLS PIPELINE II=1
    // clang-format on
    const labelling::LabelPacket w = in.read();
    warning.write(w);
    table.write(w);
    closed += w.last ? 1 : 0;
  }
}
#pragma GCC diagnostic pop

/// One frame of each camera (`s.beats` beats) through the whole pipeline: its result (the
/// warning stage's with both input flags) to `result`, its object words to `table`. The stage
/// tops run as DATAFLOW processes; each link is a stream with one producer and one consumer.
///
/// Link depths: in hardware the STREAM pragmas set them (pixel links 2 .. 4, the road line and
/// flag links 4, as sim::PipelineDepths). The C simulation runs the processes one after the
/// other, so there each link holds a whole frame (`kFrame` beats, fixed storage: no heap).
template <typename Build, typename RawIn, typename ResultOut, typename TableOut>
void pipeline_frame(PipelineStages<Build>& s, RawIn& left, RawIn& right, ResultOut& result,
                    TableOut& table) {
  // clang-format off
#pragma HLS INTERFACE axis port=left
#pragma HLS INTERFACE axis port=right
#pragma HLS INTERFACE axis port=result
#pragma HLS INTERFACE axis port=table
#pragma HLS INTERFACE ap_ctrl_chain port=return
#pragma HLS DATAFLOW
  // clang-format on
  constexpr int kFrame = Build::kMaxWidthPx / Build::kPpc * Build::kMaxHeight;
  constexpr int kWords = Build::kMaxObjects + 1;  // a frame's objects and its status word
  // Generous: a stage's frame takes a few rows more than its beats (labelling a little more).
  constexpr long kClocks = 4L * kFrame + 100000;
  using raw_beat = typename Build::rectify::pixel_beat;
  static stream<raw_beat, kFrame> checked_l("checked_left"), checked_r("checked_right");
  static stream<FlagPacket, 4> flag_l("flag_left"), flag_r("flag_right");
  static stream<typename Build::rectify::map_beat, kFrame> map_l("map_left"), map_r("map_right");
  static stream<raw_beat, kFrame> rect_l("rect_left"), rect_r("rect_right");
  static stream<typename Build::disparity::disp_beat, kFrame> disp("disparity");
  static stream<typename Build::labelling::in_beat, kFrame> road("road");
  static stream<road::Line, 4> lines("road_line");
  static stream<labelling::LabelPacket, kWords> objects("objects"), words("objects_warning");
  static stream<warning::ResultPacket, 2> frame_result("frame_result");
  // clang-format off
#pragma HLS STREAM variable=checked_l depth=2
#pragma HLS STREAM variable=checked_r depth=2
#pragma HLS STREAM variable=map_l depth=4
#pragma HLS STREAM variable=map_r depth=4
#pragma HLS STREAM variable=rect_l depth=4
#pragma HLS STREAM variable=rect_r depth=4
#pragma HLS STREAM variable=disp depth=4
#pragma HLS STREAM variable=road depth=4
#pragma HLS STREAM variable=objects depth=2
#pragma HLS STREAM variable=words depth=2
#pragma HLS STREAM variable=flag_l depth=4
#pragma HLS STREAM variable=flag_r depth=4
#pragma HLS STREAM variable=lines depth=4
#pragma HLS STREAM variable=frame_result depth=2
  // clang-format on
  const int n = s.beats;
  frame_check_frame(s.check_left, left, checked_l, flag_l, n);
  frame_check_frame(s.check_right, right, checked_r, flag_r, n);
  rectify::map_grid_frame(s.grid_left, map_l, n);
  rectify::map_grid_frame(s.grid_right, map_r, n);
  rectify::rectify_frame(s.rect_left, checked_l, map_l, rect_l, n, kClocks);
  rectify::rectify_frame(s.rect_right, checked_r, map_r, rect_r, n, kClocks);
  disparity::disparity_frame(s.disparity, rect_l, rect_r, disp, n, kClocks);
  road::road_frame(s.road, disp, road, lines, n);
  labelling::labelling_frame(s.labelling, road, objects, kWords, 1, kClocks);
  fork_words(objects, words, table, 1, kWords);
  warning::warning_frame(s.warning, words, 1, frame_result, lines, kClocks);
  merge_frame(s.merge, frame_result, flag_l, flag_r, result, 1, kClocks);
}

}  // namespace scw::hls::pipeline
