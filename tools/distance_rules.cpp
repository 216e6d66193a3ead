// SPDX-License-Identifier: Apache-2.0
// Which per-object disparity gives the distance best? Reads what `scw run` wrote for a scene
// (NNNN_disparity16.png, NNNN_labels.png, results.jsonl) and the scene's truth.jsonl, and for
// every frame whose deciding object the run and the truth agree on, measures the deciding
// object's distance with each candidate rule: the largest disparity (the thesis's closest
// point, what the warning stage uses today), the mean, and percentiles of the object's
// disparities. All coordinates of an object scale with 1 / d, so a rule's distance is
// (D + z_v) * d_run / d_rule - z_v with D the run's distance, d_run the disparity that placed it
// (NNNN_objects.csv's deciding row: d_max under the thesis's rule) and z_v the bumper's offset.
// docs/scene.md ("A robust distance") reports its output; the rule was chosen on one preset
// and reported on the others.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include "host/warning/reference.hpp"
#include "host/warning/setup.hpp"
#include "tools/jsonl.hpp"

namespace {

namespace fs = std::filesystem;

using scw::tools::read_jsonl;

cv::Mat read16(const fs::path& p) {
  cv::Mat m = cv::imread(p.string(), cv::IMREAD_UNCHANGED);
  if (m.empty() || m.depth() != CV_16U)
    throw std::runtime_error("'" + p.string() + "' is not a 16-bit image written by scw run");
  return m;
}

/// The q-quantile (0..1) of sorted values, nearest rank.
double quantile(const std::vector<int>& sorted, double q) {
  const auto n = sorted.size();
  const auto k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(n)));
  return sorted[std::min(n - 1, k == 0 ? 0 : k - 1)];
}

/// The "disparity" column of the deciding row of a NNNN_objects.csv `scw run` wrote.
double deciding_disparity(const fs::path& p) {
  std::ifstream f(p);
  std::string line;
  if (!std::getline(f, line)) throw std::runtime_error("'" + p.string() + "' is empty");
  auto split = [](const std::string& l) {
    std::vector<std::string> out;
    std::stringstream ss(l);
    for (std::string c; std::getline(ss, c, ',');) out.push_back(c);
    return out;
  };
  const auto head = split(line);
  const auto col = [&](const char* n) {
    const auto it = std::find(head.begin(), head.end(), n);
    if (it == head.end()) throw std::runtime_error("'" + p.string() + "' has no column " + n);
    return static_cast<std::size_t>(it - head.begin());
  };
  const std::size_t disp = col("disparity"), deciding = col("deciding");
  while (std::getline(f, line)) {
    const auto row = split(line);
    if (row.size() == head.size() && row[deciding] == "1") return std::stod(row[disp]);
  }
  throw std::runtime_error("'" + p.string() + "' has no deciding object");
}

struct Rule {
  std::string name;
  std::vector<double> err;  // relative distance error per frame
  int severity_ok = 0;
};

/// Eq. 5.2 as `scw run`'s defaults judge it (host/warning/reference.hpp), for objects in the
/// tunnel; outside it the gap matters, which results.jsonl does not give: "?".
const char* severity(double d_m, bool in_tunnel) {
  if (!in_tunnel) return "?";
  return scw::hls::warning::severity_name(
      scw::host::warning::judge_severity(true, 0.0, d_m, scw::host::warning::WarningSetup{}));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Distance rules on a scw run of a synthetic scene (docs/scene.md)"};
  std::string run_dir, truth_file;
  // The bumper's offset ahead of the camera, as scw run's default setup has it.
  const double z_v = scw::host::warning::WarningSetup{}.vehicle_origin.z();
  bool list = false;
  app.add_option("--run", run_dir, "Folder `scw run` wrote")->required()->check(CLI::ExistingDirectory);
  app.add_option("--truth", truth_file, "The scene's truth.jsonl")->required()->check(CLI::ExistingFile);
  app.add_flag("--list", list, "Print every frame: the truth and each rule's distance");
  CLI11_PARSE(app, argc, argv);
  try {
    const auto results = read_jsonl(fs::path(run_dir) / "results.jsonl");
    const auto truth = read_jsonl(truth_file);
    std::map<int, nlohmann::json> truth_by_frame;
    for (const auto& t : truth) truth_by_frame[t.at("frame").get<int>()] = t;
    std::vector<Rule> rules{{"max (closest)", {}, 0}, {"mean", {}, 0}, {"median", {}, 0},
                            {"p75", {}, 0},         {"p90", {}, 0},  {"p95", {}, 0},
                            {"p99", {}, 0},         {"mean+0.5sd", {}, 0},
                            {"mean+0.75sd", {}, 0}, {"mean+1sd", {}, 0},
                            {"mean+1.25sd", {}, 0},
                            {"mean+1.5sd", {}, 0},  {"mean+1.73sd", {}, 0},
                            {"mean+2sd", {}, 0},    {"max of 3x3 min", {}, 0},
                            {"max of 5x5 min", {}, 0}, {"max of 1x3 min", {}, 0},
                            {"max of 3x1 min", {}, 0}};
    int frames = 0, skipped = 0;
    for (const auto& r : results) {
      const int f = r.at("frame").get<int>();
      const auto t = truth_by_frame.find(f);
      if (t == truth_by_frame.end() || !r.contains("label") || r.at("label").get<int>() == 0 ||
          t->second.at("deciding").is_null() || r.at("flags").size() != 0) {
        ++skipped;
        continue;
      }
      char prefix[16];
      std::snprintf(prefix, sizeof prefix, "%04d_", f);
      const cv::Mat disp = read16(fs::path(run_dir) / (std::string(prefix) + "disparity16.png"));
      const cv::Mat labels = read16(fs::path(run_dir) / (std::string(prefix) + "labels.png"));
      const int label = r.at("label").get<int>();
      auto eroded_max = [&](int kw, int kh) {
        cv::Mat e;
        cv::erode(disp, e, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(kw, kh)));
        int m = 0;
        for (int y = 0; y < labels.rows; ++y)
          for (int x = 0; x < labels.cols; ++x)
            if (labels.at<std::uint16_t>(y, x) == label) m = std::max<int>(m, e.at<std::uint16_t>(y, x));
        return double(m);
      };
      std::vector<int> d;
      for (int y = 0; y < labels.rows; ++y)
        for (int x = 0; x < labels.cols; ++x)
          if (labels.at<std::uint16_t>(y, x) == label) d.push_back(disp.at<std::uint16_t>(y, x));
      if (d.empty()) throw std::runtime_error("frame " + std::to_string(f) + ": label not found");
      std::sort(d.begin(), d.end());
      double mean = 0, sq = 0;
      for (int v : d) mean += v, sq += double(v) * v;
      mean /= static_cast<double>(d.size());
      const double sd = std::sqrt(std::max(0.0, sq / static_cast<double>(d.size()) - mean * mean));
      if (std::abs(r.at("disparity").get<double>() * 16.0 - d.back()) > 0.5)
        throw std::runtime_error("frame " + std::to_string(f) + ": the run's disparity is not its "
                                 "object's largest: a different build wrote these files");
      const double d_run =
          16.0 * deciding_disparity(fs::path(run_dir) / (std::string(prefix) + "objects.csv"));
      const double dist_run = r.at("distance_m").get<double>();
      const double truth_m = t->second.at("distance_m").get<double>();
      const bool in_tunnel = r.at("in_tunnel").get<bool>();
      const std::string truth_sev = t->second.at("severity").get<std::string>();
      const double cand[] = {double(d.back()),    mean,
                             quantile(d, 0.50),   quantile(d, 0.75),
                             quantile(d, 0.90),   quantile(d, 0.95),
                             quantile(d, 0.99),   mean + 0.5 * sd,
                             mean + 0.75 * sd,    mean + sd,
                             mean + 1.25 * sd,
                             mean + 1.5 * sd,     mean + std::sqrt(3.0) * sd,
                             mean + 2 * sd,       eroded_max(3, 3),
                             eroded_max(5, 5),    eroded_max(3, 1),
                             eroded_max(1, 3)};
      if (list) std::printf("frame %3d truth %7.3f m %-6s:", f, truth_m, truth_sev.c_str());
      for (std::size_t i = 0; i < rules.size(); ++i) {
        const double dist = (dist_run + z_v) * d_run / cand[i] - z_v;
        if (list)
          std::printf(" %7.3f%s", dist,
                      truth_sev == severity(dist, in_tunnel) ? " " : "*");
        rules[i].err.push_back(dist / truth_m - 1.0);
        if (truth_sev == severity(dist, in_tunnel)) ++rules[i].severity_ok;
      }
      if (list) std::printf("\n");
      ++frames;
    }
    std::printf("%d frames (%d skipped: no deciding object in one of them, or flagged)\n", frames,
                skipped);
    std::printf("%-12s %10s %10s %10s %9s %9s\n", "rule", "worst %", "mean %", "rms %",
                "<= 2 %", "severity");
    for (const auto& rule : rules) {
      double worst = 0, sum = 0, sq = 0;
      int within = 0;
      for (double e : rule.err) {
        if (std::abs(e) > std::abs(worst)) worst = e;
        sum += e;
        sq += e * e;
        within += std::abs(e) <= 0.02;
      }
      const double n = std::max<std::size_t>(1, rule.err.size());
      std::printf("%-12s %+10.2f %+10.2f %10.2f %5d/%-3d %5d/%-3d\n", rule.name.c_str(),
                  100 * worst, 100 * sum / n, 100 * std::sqrt(sq / n), within, frames,
                  rule.severity_ok, frames);
    }
  } catch (const std::exception& e) {
    std::cerr << "distance_rules: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
