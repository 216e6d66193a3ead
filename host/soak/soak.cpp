// SPDX-License-Identifier: Apache-2.0
// The soak run (host/soak/soak.hpp).
#include "host/soak/soak.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <sstream>
#include <stdexcept>

#include "host/pipeline/reference_chain.hpp"
#include "host/soak/small_top.hpp"

namespace scw::host::soak {

namespace {

using namespace small;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

std::string count_line(const char* who, std::int64_t cycle, std::size_t results, std::size_t n) {
  std::ostringstream s;
  s << "soak: " << who << " cycle " << cycle << ", " << results << " of " << n << " results";
  return s.str();
}

/// The soak's frames: content frame k broken by the next fault every K frames (never the last
/// frame: a broken frame is closed by the next frame's sof).
SoakStream make_stream(const SoakOptions& o, SoakSummary& s) {
  SoakStream st;
  std::mt19937_64 side(o.seed + 17);
  const int dmax = soak_stage_options().num_disp - 1;
  int broken = 0;
  for (int k = 0; k < o.frames; ++k) {
    const auto f = content_frame(o.width, o.height, dmax, o.seed, k, o.real);
    ++s.content[content_name(f.kind)];
    Fault fault = Fault::none;
    if (o.malformed_every > 0 && k % o.malformed_every == o.malformed_every - 1 &&
        k + 1 < o.frames)
      fault = kFaults[broken++ % std::size(kFaults)];
    if (fault != Fault::none) {
      ++s.malformed;
      ++s.faults[fault_name(fault)];
    }
    append_frame(st, f, k, fault, (side() & 1) != 0, o.seed);
  }
  return st;
}

/// The flags each result must carry.
void check_flags(const std::vector<hls::pipeline::PipelineResultPacket>& r,
                 const std::vector<ExpectedResult>& e, SoakSummary& s) {
  for (std::size_t i = 0; i < r.size() && i < e.size(); ++i) {
    const auto& d = r[i].data;
    const bool ok = e[i].fault == Fault::none
                        ? !d.input_error_left && !d.input_error_right && !d.frame.stream_error
                        : d.input_error_left == e[i].left_broken &&
                              d.input_error_right == e[i].right_broken;
    if (ok) continue;
    ++s.flag_mismatches;
    if (s.first_flag_mismatch.empty())
      s.first_flag_mismatch = "result " + std::to_string(i) + " (frame " +
                              std::to_string(e[i].frame) + ", " + fault_name(e[i].fault) +
                              "): flags left " + std::to_string(d.input_error_left) + " right " +
                              std::to_string(d.input_error_right) + " stream " +
                              std::to_string(d.frame.stream_error);
  }
}

/// Frame `i` of a recorded rectified stream as an image.
cv::Mat frame_of(const std::vector<hls::Beat<std::uint8_t, P>>& beats, std::size_t i, int w, int h) {
  cv::Mat m(h, w, CV_8U);
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  for (std::size_t k = 0; k < n; ++k) m.data[k] = beats[i * n + k].px[0];
  return m;
}

/// Every frame the rectifiers gave through the reference chain (its road carried from frame to
/// frame as the stage's is, broken frames included); the good ones' objects and results compared.
void check_reference(const Chain& cpp, const SoakStream& st, const SoakOptions& o,
                     SoakSummary& s) {
  const auto& l = cpp.rect_left().recorded();
  const auto& r = cpp.rect_right().recorded();
  const std::size_t n = static_cast<std::size_t>(o.width) * static_cast<std::size_t>(o.height);
  const auto opt = soak_stage_options();
  pipeline::ReferenceChain ref(Build::kWindow, opt);
  const auto& results = cpp.results();
  const auto objects = objects_per_frame(cpp.object_table());
  for (std::size_t i = 0; i < results.size() && (i + 1) * n <= l.size() && (i + 1) * n <= r.size();
       ++i) {
    const cv::Mat lf = frame_of(l, i, o.width, o.height), rf = frame_of(r, i, o.width, o.height);
    const auto f = ref.next(lf, rf);
    if (st.expected[i].fault != Fault::none) continue;
    ++s.reference_checked;
    // The objects must be the reference's exactly; the warning's decisions may differ only
    // through an object at a decision boundary.
    auto why = pipeline::object_mismatch(objects[i], f);
    const bool objects_differ = !why.empty();
    if (!objects_differ)
      why = pipeline::reference_mismatch(results[i].data.frame, f, o.width, o.height, opt);
    if (why.empty()) continue;
    const auto boundary =
        objects_differ ? std::string() : pipeline::decision_boundary(f, o.width, o.height, opt);
    if (!boundary.empty()) {
      ++s.reference_boundary;
      if (s.first_reference_boundary.empty())
        s.first_reference_boundary = "result " + std::to_string(i) + " (frame " +
                                     std::to_string(st.expected[i].frame) + "): " + why + "; " +
                                     boundary;
      continue;
    }
    ++s.reference_mismatches;
    if (s.first_reference_mismatch.empty())
      s.first_reference_mismatch = "result " + std::to_string(i) + " (frame " +
                                   std::to_string(st.expected[i].frame) + "): " + why;
  }
}

/// Runs the top again from the start with a trace of the cycles around the divergence.
std::string trace_divergence(const SoakOptions& o, const sim::PipelineSetup& setup,
                             const SoakStream& st, const sim::StallPattern& stalls,
                             std::int64_t cycle, std::size_t results) {
  std::filesystem::create_directories(o.fst_dir);
  Top top(setup);  // untraced: only its start cycle is wanted
  const auto start = top.run({}, {}, 0, 1).harness_start;
  const auto from = static_cast<std::uint64_t>(std::max<std::int64_t>(0, cycle - o.fst_window));
  const std::string window = std::to_string(start + from) + ":" +
                             std::to_string(start + static_cast<std::uint64_t>(cycle + o.fst_window));
  ::setenv("SCW_FST_DIR", o.fst_dir.c_str(), 1);
  ::setenv("SCW_FST_WINDOW", window.c_str(), 1);
  {
    Top traced(setup);
    sim::TopRunControl ctl;
    ctl.stop_at = cycle + o.fst_window;
    traced.run(st.left, st.right, results, cycle + o.fst_window + 1, stalls, stalls, ctl);
  }
  ::unsetenv("SCW_FST_DIR");
  ::unsetenv("SCW_FST_WINDOW");
  const auto fst = std::filesystem::path(o.fst_dir) / "pipeline.fst";
  if (!std::filesystem::exists(fst))
    return "(none: this build's top is Verilated without tracing, scw_pipeline_build TRACE_TOP)";
  return fst.string();
}

}  // namespace

std::vector<std::vector<hls::labelling::Object>> objects_per_frame(
    const std::vector<hls::labelling::LabelPacket>& table) {
  std::vector<std::vector<hls::labelling::Object>> v(1);
  for (const auto& w : table) {
    if (!w.data.is_status) v.back().push_back(w.data.object);
    if (w.last) v.emplace_back();
  }
  return v;
}

pipeline::StageOptions soak_stage_options() {
  auto o = pipeline::small_build_options();
  o.road_min_count = 50;  // a 64 x 32 frame has 2,048 pixels
  return o;
}

SoakSummary run_soak(const SoakOptions& o) {
  if (o.frames < 1) throw std::invalid_argument("soak: --frames must be at least 1");
  if (o.malformed_every == 1)
    throw std::invalid_argument("soak: --malformed-every 1 breaks every frame: give 0 (none) or 2 and up");
  SoakSummary s;
  s.frames = o.frames;
  const SoakStream st = make_stream(o, s);
  const auto knots = pipeline::identity_knots(o.width, o.height, Build::kGridLog2);
  const auto setup =
      pipeline::make_setup(o.width, o.height, Build::kGridLog2, soak_stage_options(), knots, knots, 2);
  const auto stalls = o.stalls ? sim::StallPattern::parse("random:" + std::to_string(o.seed))
                               : sim::StallPattern{};
  const std::size_t n = st.expected.size();
  // A frame takes a few thousand cycles at this size, a few times more under the stalls: far
  // below this bound unless the pipeline is stuck.
  const std::int64_t bound = static_cast<std::int64_t>(n + 2) * (64LL * o.width * o.height + 50000);
  const auto say = [&](const std::string& line) {
    if (o.progress) o.progress(line);
  };

  RunOutput cpp_out, rtl_out;
  Chain cpp(setup, sim::PipelineEngines::all(sim::Engine::cpp), st.left, st.right, stalls, stalls);
  cpp.rect_left().record(true);
  cpp.rect_right().record(true);
  auto t = Clock::now();
  try {
    cpp.run(n, bound, [&](std::int64_t c, std::size_t r) { say(count_line("C++ chain", c, r, n)); });
  } catch (const std::exception& e) {
    ++s.deadlocks;
    s.deadlock = std::string("C++ chain: ") + e.what();
  }
  s.cpp_seconds = since(t);
  s.cycles = cpp.cycles();
  cpp_out = output_of(cpp);

  t = Clock::now();
  {
    Top top(setup);
    sim::TopRunControl ctl;
    ctl.progress = [&](std::int64_t c, std::size_t r) { say(count_line("RTL top", c, r, n)); };
    try {
      rtl_out = output_of(top.run(st.left, st.right, n, bound, stalls, stalls, ctl));
    } catch (const std::exception& e) {
      ++s.deadlocks;
      if (s.deadlock.empty()) s.deadlock = std::string("RTL top: ") + e.what();
    }
  }
  s.rtl_seconds = since(t);
  if (o.inject_divergence >= 0 && static_cast<std::size_t>(o.inject_divergence) < rtl_out.results.size())
    rtl_out.results[static_cast<std::size_t>(o.inject_divergence)].data.frame.objects ^= 1;

  s.results = static_cast<int>(cpp_out.results.size());
  auto [count, first] = compare_runs(cpp_out, rtl_out);
  s.divergences = count;
  if (first && !o.fst_dir.empty() && first->cycle >= 0) {
    say("soak: tracing cycles around the first divergence");
    first->fst = trace_divergence(o, setup, st, stalls, first->cycle, n);
  }
  s.first_divergence = first;
  check_flags(cpp_out.results, st.expected, s);
  say("soak: the floating-point reference chain");
  t = Clock::now();
  check_reference(cpp, st, o, s);
  s.reference_seconds = since(t);
  return s;
}

}  // namespace scw::host::soak
