// SPDX-License-Identifier: Apache-2.0
// Soak content and faults (host/soak/soak_frames.hpp).
#include "host/soak/soak_frames.hpp"

#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>

#include <opencv2/imgproc.hpp>

#include "host/pipeline/synthetic.hpp"
#include "sim/core/frame_beats.hpp"

namespace scw::host::soak {

namespace {

using Rng = std::mt19937_64;
using pipeline::SyntheticBox;

int draw(Rng& rng, int lo, int hi) {  // lo .. hi inclusive
  return std::uniform_int_distribution<int>(lo, std::max(lo, hi))(rng);
}

SyntheticBox random_box(Rng& rng, int w, int h, int min_side, int max_w, int max_h, int dlo,
                        int dhi) {
  SyntheticBox b;
  const int bw = draw(rng, min_side, max_w), bh = draw(rng, min_side, max_h);
  b.x0 = draw(rng, 0, w - bw);
  b.y0 = draw(rng, 0, h - bh);
  b.x1 = b.x0 + bw;
  b.y1 = b.y0 + bh;
  b.disparity = draw(rng, dlo, dhi);
  return b;
}

ContentFrame boxes(Rng& rng, int w, int h, int dmax, Content kind) {
  const int bg = draw(rng, 0, std::min(3, dmax));
  std::vector<SyntheticBox> v;
  if (kind == Content::street) {
    for (int i = draw(rng, 1, 3); i > 0; --i)
      v.push_back(random_box(rng, w, h, 6, w / 3, h * 3 / 4, bg + 1, dmax));
  } else {
    for (int i = draw(rng, 10, 40); i > 0; --i)
      v.push_back(random_box(rng, w, h, 2, 8, 8, 0, dmax));
  }
  const auto p = pipeline::synthetic_pair(w, h, bg, v, static_cast<std::uint32_t>(rng()));
  return {p.left, p.right, kind};
}

cv::Mat noise(Rng& rng, int w, int h) {
  cv::Mat m(h, w, CV_8U);
  cv::RNG cv_rng(rng());
  cv_rng.fill(m, cv::RNG::UNIFORM, 0, 256);
  return m;
}

}  // namespace

const char* content_name(Content c) {
  switch (c) {
    case Content::street: return "street";
    case Content::clutter: return "clutter";
    case Content::real: return "real";
    case Content::noise: return "noise";
  }
  return "?";
}

const char* fault_name(Fault f) {
  switch (f) {
    case Fault::none: return "none";
    case Fault::short_row: return "short row";
    case Fault::cut_frame: return "cut frame";
    case Fault::sof_mid_frame: return "sof mid-frame";
    case Fault::stray_beats: return "stray beats";
  }
  return "?";
}

ContentFrame content_frame(int w, int h, int max_disparity, std::uint64_t seed, int k,
                           const RealPair& real) {
  Rng rng(seed * 1000003u + static_cast<std::uint64_t>(k));
  const auto kind = static_cast<Content>(draw(rng, 0, 3));
  switch (kind) {
    case Content::street:
    case Content::clutter:
      return boxes(rng, w, h, max_disparity, kind);
    case Content::real: {
      if (real.left.cols < w || real.left.rows < h || real.right.size() != real.left.size())
        throw std::invalid_argument("soak: the real pair (" + std::to_string(real.left.cols) +
                                    " x " + std::to_string(real.left.rows) +
                                    ") must be two images of one size, at least " +
                                    std::to_string(w) + " x " + std::to_string(h));
      const cv::Rect r(draw(rng, 0, real.left.cols - w), draw(rng, 0, real.left.rows - h), w, h);
      return {real.left(r).clone(), real.right(r).clone(), kind};
    }
    case Content::noise:
      return {noise(rng, w, h), noise(rng, w, h), kind};
  }
  throw std::logic_error("soak: unknown content");
}

void append_frame(SoakStream& s, const ContentFrame& f, int k, Fault fault, bool on_left,
                  std::uint64_t seed) {
  const int w = f.left.cols, h = f.left.rows;
  if (h < 4 || w < 4) throw std::invalid_argument("soak: frames need at least 4 x 4 pixels");
  const cv::Mat l = f.left.isContinuous() ? f.left : f.left.clone();
  const cv::Mat r = f.right.isContinuous() ? f.right : f.right.clone();
  auto lb = sim::frame_beats<1>(l.ptr<std::uint8_t>(), w, h);
  auto rb = sim::frame_beats<1>(r.ptr<std::uint8_t>(), w, h);
  Rng rng(seed * 7919u + static_cast<std::uint64_t>(k) * 31u + 5u);
  auto& b = on_left ? lb : rb;
  const auto at = [w](int row) { return static_cast<std::ptrdiff_t>(row) * w; };
  ExpectedResult e{k, fault, fault != Fault::none && on_left, fault != Fault::none && !on_left};
  switch (fault) {
    case Fault::none:
      break;
    case Fault::short_row: {  // a row ends 1 .. 3 pixels early
      const int row = draw(rng, 0, h - 2), cut = draw(rng, 1, std::min(3, w - 1));
      b.erase(b.begin() + at(row) + w - cut, b.begin() + at(row) + w);
      b[static_cast<std::size_t>(at(row) + w - cut - 1)].eol = true;
      break;
    }
    case Fault::cut_frame:  // the link drops after some rows; the next frame's sof follows
      b.resize(static_cast<std::size_t>(at(draw(rng, 1, h - 1))));
      break;
    case Fault::sof_mid_frame: {  // the frame restarts at a row: two frames, both broken
      const int row = draw(rng, 2, h - 2);
      lb[static_cast<std::size_t>(at(row))].sof = true;
      rb[static_cast<std::size_t>(at(row))].sof = true;
      e.left_broken = e.right_broken = true;
      s.expected.push_back(e);
      break;
    }
    case Fault::stray_beats: {  // beats before the sof, outside any frame
      std::vector<hls::Beat<std::uint8_t, 1>> stray(static_cast<std::size_t>(draw(rng, 1, 3)));
      for (auto& x : stray) x.px[0] = static_cast<std::uint8_t>(rng());
      b.insert(b.begin(), stray.begin(), stray.end());
      break;
    }
  }
  s.expected.push_back(e);
  s.left.insert(s.left.end(), lb.begin(), lb.end());
  s.right.insert(s.right.end(), rb.begin(), rb.end());
}

}  // namespace scw::host::soak
