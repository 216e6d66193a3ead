// SPDX-License-Identifier: Apache-2.0
// Whole images through the disparity model: one built stage per (window, candidate count).
#include "host/disparity/run_model.hpp"

#include <algorithm>
#include <utility>

#include "hls/disparity/disparity.hpp"
#include "sim/core/frame_beats.hpp"

namespace scw::disparity {

namespace {

// The built windows as a template pack; it must list kHostWindows.
using Windows = std::integer_sequence<int, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23>;

template <int... V, std::size_t K>
constexpr bool same(std::integer_sequence<int, V...>, const std::array<int, K>& a) {
  if (sizeof...(V) != K) return false;
  const int v[] = {V...};
  for (std::size_t i = 0; i < K; ++i)
    if (v[i] != a[i]) return false;
  return true;
}
static_assert(same(Windows{}, kHostWindows));

using Runner = cv::Mat (*)(const cv::Mat&, const cv::Mat&, const DisparityConfig&);

bool same(const DisparityConfig& a, const DisparityConfig& b) {
  return a.width == b.width && a.height == b.height && a.dmin == b.dmin &&
         a.num_disp == b.num_disp && a.prefilter == b.prefilter &&
         a.prefilter_cap == b.prefilter_cap && a.sad_limit == b.sad_limit &&
         a.texture_threshold == b.texture_threshold && a.uniqueness_ratio == b.uniqueness_ratio &&
         a.subpixel == b.subpixel && a.opencv_invalid == b.opencv_invalid &&
         a.edge_candidates == b.edge_candidates;
}

template <int N>
cv::Mat run_built(const cv::Mat& left, const cv::Mat& right, const DisparityConfig& cfg) {
  using Params = hls::disparity::DisparityParams<1, kHostMaxWidthPx, N, kHostMaxNumDisp>;
  using Kernel = hls::disparity::Disparity<Params>;
  // One stage per thread and configuration takes a sequence's frames back to back, as the
  // pipeline's does (every output pixel depends on its own frame only): its 0.6 MB of line
  // buffers and sums are not allocated and cleared again for every frame. A frame that fails
  // leaves no stage behind. The frame runs through the stage's top loop (disparity_frame: one
  // clock of the kernel an iteration, the output never stalled; its C-simulation test holds it
  // equal to the clocked model), straight from the images to the map.
  thread_local std::unique_ptr<Kernel> kernel;
  thread_local DisparityConfig built{};
  if (!kernel || !same(built, cfg)) {
    kernel.reset();
    kernel = std::make_unique<Kernel>(cfg);
    built = cfg;
  }
  using In = typename Params::pixel_beat;
  sim::FrameBeatsIn<In> l(left.ptr<std::uint8_t>(), cfg.width, cfg.height);
  sim::FrameBeatsIn<In> r(right.ptr<std::uint8_t>(), cfg.width, cfg.height);
  cv::Mat out(cfg.height, cfg.width, CV_16SC1);
  sim::FrameBeatsOut<typename Params::disp_beat> o(out.ptr<std::uint16_t>());
  const int n = cfg.width * cfg.height;
  if (hls::disparity::disparity_frame(*kernel, l, r, o, n, sim::frame_clock_limit(n)) != n ||
      kernel->error()) {
    kernel.reset();
    throw std::logic_error("disparity_image: the stage stopped or flagged a frame error");
  }
  return out;
}

template <int... N>
Runner find(int n, std::integer_sequence<int, N...>) {
  Runner f = nullptr;
  ((n == N ? (f = &run_built<N>, 0) : 0), ...);
  return f;
}

template <std::size_t K>
std::string list(const std::array<int, K>& a) {
  std::string s;
  for (std::size_t i = 0; i < K; ++i)
    s += (i ? (i + 1 == K ? " or " : ", ") : "") + std::to_string(a[i]);
  return s;
}

void fail(const std::string& what) { throw std::invalid_argument("disparity_image: " + what); }

std::string size_text(const cv::Mat& m) {
  return std::to_string(m.cols) + " x " + std::to_string(m.rows);
}

}  // namespace

const char* mode_name(Mode m) { return m == Mode::thesis ? "thesis" : "opencv"; }

Mode mode_from_name(const std::string& name) {
  for (const Mode m : {Mode::thesis, Mode::opencv})
    if (name == mode_name(m)) return m;
  throw std::invalid_argument("disparity mode '" + name + "': use thesis or opencv");
}

DisparityConfig mode_config(Mode m, int width, int height, int dmin) {
  return m == Mode::thesis ? hls::disparity::thesis_mode(width, height, dmin)
                           : hls::disparity::opencv_mode(width, height, dmin);
}

cv::Mat disparity_image(const cv::Mat& left, const cv::Mat& right, int window_n, int dmin, int dmax,
                        const DisparityConfig& options) {
  if (left.empty() || right.empty()) fail("an input image is empty");
  if (left.type() != CV_8UC1 || right.type() != CV_8UC1)
    fail("the images must be 8-bit grey (CV_8UC1); convert colour images first");
  if (left.size() != right.size())
    fail("the left image is " + size_text(left) + " px but the right one " + size_text(right) +
         " px; a stereo pair must have one size");
  if (window_n % 2 == 0 || window_n < 1)
    fail("the window must be odd (N x N around the pixel), got " + std::to_string(window_n));
  if (std::find(kHostWindows.begin(), kHostWindows.end(), window_n) == kHostWindows.end())
    fail("window " + std::to_string(window_n) +
         " is not built; supported windows: " + list(kHostWindows));
  if (left.cols < window_n || left.rows < window_n)
    fail("the images (" + size_text(left) + " px) are smaller than the " +
         std::to_string(window_n) + " x " + std::to_string(window_n) + " window");
  if (left.cols > kHostMaxWidthPx)
    fail("the images are " + std::to_string(left.cols) +
         " px wide; the built stage takes at most " + std::to_string(kHostMaxWidthPx));
  if (dmax < dmin)
    fail("the largest disparity " + std::to_string(dmax) + " is below the smallest " +
         std::to_string(dmin) + "; give a range whose largest is at least its smallest, e.g. " +
         std::to_string(dmax) + " .. " + std::to_string(dmin));
  if (dmin < 0)
    fail("the smallest disparity is " + std::to_string(dmin) +
         "; the streaming stage takes dmin >= 0 (it matches the right image only to the left "
         "of the newest pixel)");
  const int count = dmax - dmin + 1;
  if (count > kHostMaxNumDisp)
    fail("the range " + std::to_string(dmin) + " .. " + std::to_string(dmax) + " has " +
         std::to_string(count) + " candidates; the built stage evaluates at most " +
         std::to_string(kHostMaxNumDisp) + " (narrow the range)");
  const Runner run = find(window_n, Windows{});
  if (options.prefilter_cap < 1 || options.prefilter_cap > 63)
    fail("the prefilter cap must be 1 .. 63, got " + std::to_string(options.prefilter_cap));
  if (options.sad_limit < 0 || options.texture_threshold < 0 || options.uniqueness_ratio < 0)
    fail("the SAD limit, texture threshold and uniqueness ratio must be >= 0 (0 = off)");
  if (options.uniqueness_ratio > 255)  // the stage's 8-bit cfg_uniqueness_i
    fail("the uniqueness ratio must be 0 .. 255 %, got " +
         std::to_string(options.uniqueness_ratio));

  DisparityConfig cfg = options;
  cfg.width = left.cols;
  cfg.height = left.rows;
  cfg.dmin = dmin;
  cfg.num_disp = count;
  const cv::Mat l = left.isContinuous() ? left : left.clone();
  const cv::Mat r = right.isContinuous() ? right : right.clone();
  return run(l, r, cfg);
}

}  // namespace scw::disparity
