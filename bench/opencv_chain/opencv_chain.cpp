// SPDX-License-Identifier: Apache-2.0
// The chain an OpenCV user would write instead of scw, as the yardstick for `scw run`'s speed
// (docs/performance.md, "scw run against the OpenCV chain"): for each pair of a sequence folder,
// cv::remap of both images with the calibration's maps, cv::StereoBM, connected components of the
// valid disparities and the nearest object's distance. One thread; OpenCV only, no scw code.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

int usage() {
  std::cerr << "usage: opencv_chain SEQUENCE_DIR CALIB.yml [MIN_DISP MAX_DISP WINDOW MIN_AREA]\n"
               "  SEQUENCE_DIR holds NNNN_left.png / NNNN_right.png (scw scene writes them);\n"
               "  CALIB.yml is OpenCV FileStorage with M1 D1 M2 D2 R T (metres).\n"
               "  Defaults: 12 56 21 50, the distance sweep's own `scw run` settings.\n";
  return 2;
}

cv::Mat read_matrix(const cv::FileStorage& fs, const char* name) {
  cv::Mat m;
  fs[name] >> m;
  if (m.empty()) throw std::runtime_error(std::string("the calibration has no ") + name);
  return m;
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc != 3 && argc != 7) return usage();
  const fs::path dir = argv[1];
  const int min_disp = argc == 7 ? std::stoi(argv[3]) : 12;
  const int max_disp = argc == 7 ? std::stoi(argv[4]) : 56;
  const int window = argc == 7 ? std::stoi(argv[5]) : 21;
  const int min_area = argc == 7 ? std::stoi(argv[6]) : 50;
  cv::setNumThreads(1);

  std::vector<fs::path> lefts;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (n.size() > 9 && n.substr(n.size() - 9) == "_left.png") lefts.push_back(e.path());
  }
  std::sort(lefts.begin(), lefts.end());
  if (lefts.empty()) throw std::runtime_error("no NNNN_left.png in " + dir.string());

  const cv::FileStorage fs(argv[2], cv::FileStorage::READ);
  if (!fs.isOpened()) throw std::runtime_error(std::string("cannot read ") + argv[2]);
  const cv::Mat m1 = read_matrix(fs, "M1"), d1 = read_matrix(fs, "D1");
  const cv::Mat m2 = read_matrix(fs, "M2"), d2 = read_matrix(fs, "D2");
  const cv::Mat r = read_matrix(fs, "R"), t = read_matrix(fs, "T");
  const cv::Mat first = cv::imread(lefts.front().string(), cv::IMREAD_GRAYSCALE);
  const cv::Size size = first.size();

  const auto t0 = std::chrono::steady_clock::now();
  cv::Mat r1, r2, p1, p2, q, map1x, map1y, map2x, map2y;
  cv::stereoRectify(m1, d1, m2, d2, size, r, t, r1, r2, p1, p2, q, cv::CALIB_ZERO_DISPARITY, -1);
  cv::initUndistortRectifyMap(m1, d1, r1, p1, size, CV_16SC2, map1x, map1y);
  cv::initUndistortRectifyMap(m2, d2, r2, p2, size, CV_16SC2, map2x, map2y);
  const double focal = p1.at<double>(0, 0);
  const double baseline = -p2.at<double>(0, 3) / p2.at<double>(0, 0);
  const int num_disp = (max_disp - min_disp + 1 + 15) / 16 * 16;  // StereoBM: a multiple of 16
  const auto bm = cv::StereoBM::create(num_disp, window);
  bm->setMinDisparity(min_disp);

  double pixel_s = 0;  // reading and the chain, without the maps' set-up
  for (const auto& lp : lefts) {
    fs::path rp = lp;
    rp.replace_filename(
        lp.filename().string().replace(lp.filename().string().size() - 9, 5, "_right"));
    const auto f0 = std::chrono::steady_clock::now();
    const cv::Mat l = cv::imread(lp.string(), cv::IMREAD_GRAYSCALE);
    const cv::Mat rr = cv::imread(rp.string(), cv::IMREAD_GRAYSCALE);
    if (l.size() != size || rr.size() != size)
      throw std::runtime_error(lp.string() + ": the pairs must all be " +
                               std::to_string(size.width) + "x" + std::to_string(size.height));
    cv::Mat lr, rrr, disp;
    cv::remap(l, lr, map1x, map1y, cv::INTER_LINEAR);
    cv::remap(rr, rrr, map2x, map2y, cv::INTER_LINEAR);
    bm->compute(lr, rrr, disp);  // CV_16S, disparity x 16
    const cv::Mat valid = disp > (min_disp - 1) * 16;
    cv::Mat labels, stats, centroids;
    const int n = cv::connectedComponentsWithStats(valid, labels, stats, centroids, 8, CV_32S);
    // The nearest object: the largest mean disparity among components of at least min_area.
    std::vector<double> sum(static_cast<std::size_t>(n), 0.0);
    for (int y = 0; y < disp.rows; ++y)
      for (int x = 0; x < disp.cols; ++x) {
        const int k = labels.at<int>(y, x);
        if (k > 0) sum[static_cast<std::size_t>(k)] += disp.at<short>(y, x) / 16.0;
      }
    double best = 0;
    for (int k = 1; k < n; ++k) {
      const int area = stats.at<int>(k, cv::CC_STAT_AREA);
      if (area >= min_area) best = std::max(best, sum[static_cast<std::size_t>(k)] / area);
    }
    pixel_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - f0).count();
    std::printf("%s %.3f\n", lp.filename().string().c_str(),
                best > 0 ? focal * baseline / best : 0.0);
  }
  const double all_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("frames %zu, %dx%d, N %d, d %d..%d: %.3f s (%.4f s a frame; chain %.4f s a frame)\n",
              lefts.size(), size.width, size.height, window, min_disp, min_disp + num_disp - 1,
              all_s, all_s / static_cast<double>(lefts.size()),
              pixel_s / static_cast<double>(lefts.size()));
  return 0;
} catch (const std::exception& e) {
  std::cerr << "opencv_chain: " << e.what() << "\n";
  return 1;
}
