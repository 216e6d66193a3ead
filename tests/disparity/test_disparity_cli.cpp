// SPDX-License-Identifier: Apache-2.0
// The host's whole-image disparity (what `scw disparity` runs): the default mode's accuracy on
// Tsukuba against cv::StereoBM, equality with the direct reference and, on a colour PNG pair read
// by both, with cv::StereoBM; the image reader's and the stage's errors.
#include <catch2/catch.hpp>
#include <cstdint>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "host/disparity/run_model.hpp"
#include "host/io/image_file.hpp"
#include "host/io/tsukuba.hpp"
#include "host/reference/disparity_ref.hpp"
#include "host/reference/stereo_bm.hpp"

namespace {

using namespace scw;
using Catch::Matchers::Contains;
using hls::disparity::DisparityConfig;

struct Tsukuba {
  cv::Mat left, right, gt;  // 8UC1; gt = disparity * 16, 0 = unknown
};

const Tsukuba& tsukuba() {
  static const Tsukuba t = [] {
    const auto [left, right] = host::io::read_tsukuba_pair(SCW_DATA_DIR "/tsukuba");
    return Tsukuba{left, right, host::io::read_tsukuba_truth(SCW_DATA_DIR "/tsukuba")};
  }();
  return t;
}

std::vector<std::uint16_t> values(const cv::Mat& d16) {
  REQUIRE(d16.type() == CV_16SC1);
  REQUIRE(d16.isContinuous());
  const auto* p = d16.ptr<std::uint16_t>();
  return {p, p + d16.total()};
}

/// The share (%) of ground-truth pixels (gt > 0) inside the valid region (dmin = 0) with no
/// disparity or |d - gt| > 1 px, as tools/disparity_eval. A pixel has no disparity when it holds
/// the invalid code and the configuration can reject or has a distinct invalid code; thesis
/// mode (invalid 0, nothing rejected) has a disparity everywhere there, 0 meaning d = 0.
double bad_share(const std::vector<std::uint16_t>& disp, const DisparityConfig& cfg, int n,
                 int num_disp) {
  const cv::Mat& gt = tsukuba().gt;
  const int r = n / 2, w = gt.cols, h = gt.rows;
  const bool can_be_invalid = cfg.opencv_invalid || cfg.texture_threshold > 0 ||
                              cfg.uniqueness_ratio > 0 || cfg.sad_limit > 0;
  const std::uint16_t inv = hls::disparity::invalid_code(cfg);
  long pixels = 0, bad = 0;
  for (int v = r; v < h - r; ++v)
    for (int u = r + num_disp - 1; u < w - r; ++u) {
      const int g = gt.at<std::uint8_t>(v, u);
      if (g == 0) continue;
      ++pixels;
      const std::uint16_t d = disp[static_cast<std::size_t>(v) * w + u];
      if ((can_be_invalid && d == inv) ||
          std::abs(static_cast<std::int16_t>(d) / 16.0 - g / 16.0) > 1.0)
        ++bad;
    }
  REQUIRE(pixels > 80000);
  return 100.0 * static_cast<double>(bad) / static_cast<double>(pixels);
}

/// disparity_image on (a view of) Tsukuba equals the direct reference on every pixel.
void check_equal(cv::Rect roi, int n, int dmin, int dmax, const DisparityConfig& options) {
  const Tsukuba& t = tsukuba();
  const cv::Mat l = t.left(roi), r = t.right(roi);  // views: not continuous unless whole rows
  const auto got = values(disparity::disparity_image(l, r, n, dmin, dmax, options));
  DisparityConfig cfg = options;
  cfg.width = roi.width;
  cfg.height = roi.height;
  cfg.dmin = dmin;
  const cv::Mat lc = l.clone(), rc = r.clone();
  const auto ref = reference::disparity_reference(lc.ptr<std::uint8_t>(), rc.ptr<std::uint8_t>(),
                                                  roi.width, roi.height, n, dmax - dmin + 1, cfg);
  REQUIRE(got.size() == ref.size());
  std::size_t diff = 0;
  for (std::size_t i = 0; i < got.size(); ++i) diff += got[i] != ref[i] ? 1 : 0;
  INFO("N " << n << ", d " << dmin << ".." << dmax << ": " << diff << " of " << got.size()
            << " pixels differ");
  CHECK(diff == 0);
}

/// Writes a Tsukuba PPM as a colour PNG in the working directory; returns its name.
std::string colour_png(const char* ppm, const char* png) {
  const cv::Mat colour = cv::imread(std::string(SCW_DATA_DIR "/tsukuba/") + ppm, cv::IMREAD_COLOR);
  REQUIRE(colour.type() == CV_8UC3);
  REQUIRE(cv::imwrite(png, colour));
  return png;
}

}  // namespace

TEST_CASE("opencv mode on a colour PNG pair read by scw equals cv::StereoBM on the same files "
          "read with IMREAD_GRAYSCALE",
          "[disparity][host][io]") {
  const std::string lp = colour_png("scene1.row3.col3.ppm", "colour_pair_left.png");
  const std::string rp = colour_png("scene1.row3.col4.ppm", "colour_pair_right.png");
  // What scw reads and what an OpenCV user reads.
  const cv::Mat l = host::io::read_grey_image(lp), r = host::io::read_grey_image(rp);
  const cv::Mat ul = cv::imread(lp, cv::IMREAD_GRAYSCALE), ur = cv::imread(rp, cv::IMREAD_GRAYSCALE);
  REQUIRE(l.type() == CV_8UC1);
  CHECK(cv::countNonZero(l != ul) == 0);
  CHECK(cv::countNonZero(r != ur) == 0);
  // The codec's conversion is not cv::cvtColor's here, so a reader converting with cvtColor (as
  // scw once did) gives other grey levels and fails the checks above.
  cv::Mat cvt;
  cv::cvtColor(cv::imread(lp, cv::IMREAD_COLOR), cvt, cv::COLOR_BGR2GRAY);
  CHECK(cv::countNonZero(cvt != ul) > 0);

  constexpr int kNumDisp = 16;  // d 0..15
  for (const int n : {9, 21}) {
    const auto cfg = disparity::mode_config(disparity::Mode::opencv, l.cols, l.rows, 0);
    const auto ours = values(disparity::disparity_image(l, r, n, 0, kNumDisp - 1, cfg));
    const auto bm =
        reference::stereo_bm(ul.data, ur.data, ul.cols, ul.rows, n, kNumDisp, cfg, true);
    REQUIRE(ours.size() == bm.size());
    // Ties at the minimum SAD included: both keep the largest d (docs/disparity.md).
    long differ = 0;
    for (std::size_t i = 0; i < ours.size(); ++i) differ += ours[i] != bm[i];
    INFO("N " << n << ": " << differ << " of " << ours.size() << " pixels differ");
    CHECK(differ == 0);
  }
}

TEST_CASE("read_grey_image refuses what it cannot read, naming the file and what to give",
          "[disparity][host][io][errors]") {
  CHECK_THROWS_WITH(host::io::read_grey_image("no_such_image.png"),
                    Contains("cannot read 'no_such_image.png' as an image") &&
                        Contains("give a PNG, JPEG"));
  {
    std::ofstream("not_an_image.png") << "this is text, not a PNG\n";
  }
  CHECK_THROWS_WITH(host::io::read_grey_image("not_an_image.png"),
                    Contains("cannot read 'not_an_image.png' as an image"));
  REQUIRE(cv::imwrite("sixteen_bit.png", cv::Mat(8, 8, CV_16UC1, cv::Scalar(1000))));
  CHECK_THROWS_WITH(host::io::read_grey_image("sixteen_bit.png"),
                    Contains("'sixteen_bit.png' has 16-bit samples") && Contains("8-bit"));
  REQUIRE(cv::imwrite("eight_bit_bgr.png", cv::Mat(8, 8, CV_8UC3, cv::Scalar(10, 20, 30))));
  const cv::Mat g = host::io::read_grey_image("eight_bit_bgr.png");
  CHECK(g.type() == CV_8UC1);
  CHECK(cv::countNonZero(g != cv::imread("eight_bit_bgr.png", cv::IMREAD_GRAYSCALE)) == 0);
}

TEST_CASE("disparity_image in the default mode has no more bad pixels than cv::StereoBM on Tsukuba",
          "[disparity][host][accuracy]") {
  const Tsukuba& t = tsukuba();
  constexpr int kNumDisp = 16;  // 0..15
  const auto def = disparity::mode_config(disparity::kDefaultMode, t.left.cols, t.left.rows, 0);
  const auto bm_cfg = hls::disparity::opencv_mode(t.left.cols, t.left.rows, 0);
  for (const int n : {5, 9, 15, 21}) {
    const double ours =
        bad_share(values(disparity::disparity_image(t.left, t.right, n, 0, kNumDisp - 1, def)), def,
                  n, kNumDisp);
    const double bm = bad_share(reference::stereo_bm(t.left.data, t.right.data, t.left.cols,
                                                     t.left.rows, n, kNumDisp, bm_cfg, true),
                                bm_cfg, n, kNumDisp);
    INFO("N = " << n << ": " << disparity::mode_name(disparity::kDefaultMode) << " mode " << ours
                << " % bad, cv::StereoBM " << bm << " % bad");
    // opencv mode is cv::StereoBM, ties included; thesis mode is 1.2 .. 7 points below it.
    CHECK(ours <= bm);
  }
}

TEST_CASE("disparity_image equals the direct reference on Tsukuba", "[disparity][host]") {
  const Tsukuba& t = tsukuba();
  const cv::Rect whole(0, 0, t.left.cols, t.left.rows);
  SECTION("thesis mode, N = 9, d 0..15, whole image") {
    check_equal(whole, 9, 0, 15, disparity::mode_config(disparity::Mode::thesis, 0, 0, 0));
  }
  SECTION("opencv mode, N = 9, d 0..15, whole image") {
    check_equal(whole, 9, 0, 15, disparity::mode_config(disparity::Mode::opencv, 0, 0, 0));
  }
  SECTION("opencv mode with other options, N = 21, d 4..35, whole image") {
    auto cfg = disparity::mode_config(disparity::Mode::opencv, 0, 0, 0);
    cfg.prefilter_cap = 40;
    cfg.texture_threshold = 200;
    cfg.uniqueness_ratio = 8;
    cfg.sad_limit = 6000;
    check_equal(whole, 21, 4, 35, cfg);
  }
  SECTION("thesis mode with SAD limit and uniqueness, N = 3, d 2..17, crop (a view)") {
    auto cfg = disparity::mode_config(disparity::Mode::thesis, 0, 0, 0);
    cfg.sad_limit = 300;
    cfg.uniqueness_ratio = 10;
    check_equal(cv::Rect(40, 30, 200, 120), 3, 2, 17, cfg);
  }
  SECTION("opencv mode, 21 candidates d 3..23 (not a multiple of 16), N = 7") {
    check_equal(cv::Rect(20, 20, 240, 100), 7, 3, 23,
                disparity::mode_config(disparity::Mode::opencv, 0, 0, 0));
  }
  SECTION("thesis mode, the thesis's 45 candidates d 20..64, N = 23, crop (a view)") {
    check_equal(cv::Rect(64, 100, 160, 64), 23, 20, 64,
                disparity::mode_config(disparity::Mode::thesis, 0, 0, 0));
  }
}

TEST_CASE("disparity_image refuses what the built stages cannot do, saying what they can",
          "[disparity][host][errors]") {
  const cv::Mat a(32, 48, CV_8UC1, cv::Scalar(7)), b(32, 48, CV_8UC1, cv::Scalar(9));
  const auto cfg = disparity::mode_config(disparity::kDefaultMode, 0, 0, 0);
  const auto run = [&](const cv::Mat& l, const cv::Mat& r, int n, int dmin, int dmax) {
    return disparity::disparity_image(l, r, n, dmin, dmax, cfg);
  };
  CHECK_NOTHROW(run(a, b, 5, 0, 15));
  CHECK_THROWS_WITH(run(cv::Mat(), b, 5, 0, 15), Contains("empty"));
  CHECK_THROWS_WITH(run(a, cv::Mat(32, 50, CV_8UC1), 5, 0, 15),
                    Contains("left image is 48 x 32 px but the right one 50 x 32 px"));
  CHECK_THROWS_WITH(run(cv::Mat(32, 48, CV_8UC3), cv::Mat(32, 48, CV_8UC3), 5, 0, 15),
                    Contains("8-bit grey"));
  CHECK_THROWS_WITH(run(cv::Mat(32, 48, CV_16UC1), cv::Mat(32, 48, CV_16UC1), 5, 0, 15),
                    Contains("8-bit grey"));
  CHECK_THROWS_WITH(run(a, b, 6, 0, 15), Contains("window must be odd"));
  CHECK_THROWS_WITH(run(a, b, 25, 0, 15),
                    Contains("supported windows: 3, 5, 7, 9, 11, 13, 15, 17, 19, 21 or 23"));
  CHECK_THROWS_WITH(run(a(cv::Rect(0, 0, 48, 8)), b(cv::Rect(0, 0, 48, 8)), 9, 0, 15),
                    Contains("smaller than the 9 x 9 window"));
  CHECK_THROWS_WITH(run(a(cv::Rect(0, 0, 6, 32)), b(cv::Rect(0, 0, 6, 32)), 7, 0, 15),
                    Contains("smaller than the 7 x 7 window"));
  CHECK_THROWS_WITH(run(a, b, 5, 10, 9), Contains("largest disparity 9 is below the smallest 10"));
  CHECK_THROWS_WITH(run(a, b, 5, -4, 11), Contains("dmin >= 0"));
  CHECK_NOTHROW(run(a, b, 5, 0, 16));  // any count up to the built 128
  CHECK_THROWS_WITH(run(a, b, 5, 0, 128),
                    Contains("129 candidates; the built stage evaluates at most 128"));
  const cv::Mat wide(9, 2050, CV_8UC1, cv::Scalar(1));
  CHECK_THROWS_WITH(run(wide, wide, 5, 0, 15), Contains("at most 2048"));
  auto bad_cap = cfg;
  bad_cap.prefilter_cap = 64;
  CHECK_THROWS_WITH(disparity::disparity_image(a, b, 5, 0, 15, bad_cap),
                    Contains("prefilter cap must be 1 .. 63"));
}

TEST_CASE("disparity_image over a sequence equals the direct reference frame by frame",
          "[disparity][host]") {
  // disparity_image keeps its stage for the next frame of the same configuration: the second
  // and later frames start from the state the one before left, and must not depend on it.
  const Tsukuba& t = tsukuba();
  const auto cfg = disparity::mode_config(disparity::Mode::opencv, 0, 0, 0);
  cv::Mat flipped_l, flipped_r;  // another scene of the same size: the pair mirrored and swapped
  cv::flip(t.right, flipped_l, 1);
  cv::flip(t.left, flipped_r, 1);
  const std::vector<std::pair<cv::Mat, cv::Mat>> frames = {
      {t.left, t.right}, {flipped_l, flipped_r}, {t.left, t.right}};
  for (std::size_t i = 0; i < frames.size(); ++i) {
    INFO("frame " << i);
    const cv::Mat l = frames[i].first.clone(), r = frames[i].second.clone();
    DisparityConfig full = cfg;
    full.width = l.cols;
    full.height = l.rows;
    const auto want = reference::disparity_reference(l.ptr<std::uint8_t>(), r.ptr<std::uint8_t>(),
                                                     l.cols, l.rows, 9, 16, full);
    CHECK(values(disparity::disparity_image(l, r, 9, 0, 15, cfg)) == want);
  }
}
