// SPDX-License-Identifier: Apache-2.0
// `scw eval`: a synthetic scene's truth against `scw run`'s results.jsonl: distance errors
// against the thesis's 5 % bar and warning severity per frame, as a table, JSON and two plots
// (docs/eval.md).
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "host/cli/commands.hpp"
#include "host/eval/compare.hpp"
#include "host/eval/plots.hpp"
#include "host/eval/records.hpp"
#include "host/eval/report.hpp"
#include "host/eval/surfaces.hpp"
#include "host/io/image_file.hpp"

namespace scw::cli {
namespace {

namespace fs = std::filesystem;
namespace ev = host::eval;

struct EvalOptions {
  std::string truth, results, json, plot, severity_plot;
};

void run_eval(const EvalOptions& o) {
  const ev::TruthFile truth = ev::read_truth(o.truth);
  const ev::ResultsFile results = ev::read_results(o.results);
  ev::EvalReport report = ev::compare(truth, results);
  // The plots go beside results.jsonl unless told otherwise: one run's folder holds its story.
  const fs::path dir = fs::path(o.results).parent_path();
  // A scene folder knows what every pixel shows: say what decided each frame.
  const fs::path truth_dir = fs::is_directory(o.truth) ? fs::path(o.truth)
                                                       : fs::path(o.truth).parent_path();
  if (const auto view = ev::load_scene_view(truth_dir))
    ev::trace_deciding_surfaces(report, *view, dir);
  ev::print_report(std::cout, report);

  const fs::path plot = o.plot.empty() ? dir / "distance_error.png" : fs::path(o.plot);
  const fs::path sev = o.severity_plot.empty() ? dir / "severity.png" : fs::path(o.severity_plot);
  host::io::write_image(plot, ev::distance_error_plot(report));
  host::io::write_image(sev, ev::severity_plot(report));
  std::cout << "wrote " << plot.string() << ", " << sev.string();
  if (!o.json.empty()) {
    ev::write_report_json(o.json, report);
    std::cout << ", " << o.json;
  }
  std::cout << "\n";
}

}  // namespace

void add_eval_command(CLI::App& app) {
  auto o = std::make_shared<EvalOptions>();
  auto* cmd = app.add_subcommand(
      "eval", "Compare scw run's results.jsonl with a synthetic scene's truth (scw scene): "
              "relative distance error against the thesis's 5 % bar, severity per frame");
  cmd->add_option("--truth", o->truth, "Folder scw scene wrote (truth.jsonl, scene.json)")
      ->required()
      ->check(CLI::ExistingPath);
  cmd->add_option("--results", o->results, "results.jsonl of scw run --sequence on that folder")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--json", o->json, "Write the summary and per-frame records here");
  cmd->add_option("--plot", o->plot,
                  "Distance-error plot (default: distance_error.png beside results.jsonl)");
  cmd->add_option("--severity-plot", o->severity_plot,
                  "Severity-per-frame plot (default: severity.png beside results.jsonl)");
  cmd->callback([o] { run_eval(*o); });
}

}  // namespace scw::cli
