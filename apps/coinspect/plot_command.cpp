// `coinspect plot-features --out FILE.png [--size WxH] [--stage STAGE] RUN[=LABEL]...`: the
// features of one stage over mission time of feature missions, one curve per run, from their
// report.json (doc/evaluation.md, "Features over time"; the SLEI3D paper's Fig. 15).
#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <system_error>

#include "coinspect/core/error.h"
#include "coinspect/eval/feature_plot.h"
#include "commands.h"
#include "feature_report.h"
#include "option_checks.h"
#include "picture_options.h"

namespace coinspect::app {

namespace {

struct PlotFeaturesOptions {
  std::string out;
  std::string size = "1200x800";
  std::string stage = "collected";
  std::vector<std::string> runs;
};

struct RunArgument {
  std::string text;  // as given, for the messages
  std::filesystem::path path;
  std::optional<std::string> label;
};

// "RUN=LABEL" splits at its last '=', so that a label holds no '=' but a path may; a RUN that
// exists as given (a folder named "seed=1") is taken whole, without a label.
RunArgument parseRunArgument(const std::string& text) {
  std::error_code error;
  const size_t equals = text.rfind('=');
  if (equals == std::string::npos || std::filesystem::exists(text, error)) return {text, text, {}};
  const std::string path = text.substr(0, equals), label = text.substr(equals + 1);
  if (path.empty()) throw InputError(text, "", "no RUN before '=' (expected RUN[=LABEL])");
  if (label.empty()) throw InputError(text, "", "empty LABEL after '=' (expected RUN[=LABEL])");
  return {text, path, label};
}

void requireStage(const std::string& stage) {
  const auto& stages = featureStages();
  if (std::find(stages.begin(), stages.end(), stage) != stages.end()) return;
  // The list from featureStages(), so that a new stage cannot be left out of the message.
  std::string known;
  for (size_t i = 0; i < stages.size(); ++i)
    known += (i == 0 ? "" : i + 1 == stages.size() ? " or " : ", ") + stages[i];
  throw InputError("--stage", "", "'" + stage + "' is not a stage: " + known);
}

// The given labels; for the others the strategy, and when another run without a label has the
// same strategy, its folder too (then the RUN as given, if that is still ambiguous).
std::vector<std::string> runLabels(const std::vector<RunArgument>& arguments,
                                   const std::vector<FeatureRunReport>& reports) {
  const auto strategyOf = [&](size_t i) {
    return reports[i].strategy.empty() ? reports[i].folder : reports[i].strategy;
  };
  const auto sharedBy = [&](size_t i, const auto& labelOf) {
    for (size_t j = 0; j < arguments.size(); ++j)
      if (j != i && !arguments[j].label && labelOf(j) == labelOf(i)) return true;
    return false;
  };
  const auto withFolder = [&](size_t i) { return strategyOf(i) + " (" + reports[i].folder + ")"; };
  std::vector<std::string> labels;
  for (size_t i = 0; i < arguments.size(); ++i) {
    if (arguments[i].label)
      labels.push_back(*arguments[i].label);
    else if (!sharedBy(i, strategyOf))
      labels.push_back(strategyOf(i));
    else if (!sharedBy(i, withFolder))
      labels.push_back(withFolder(i));
    else
      labels.push_back(strategyOf(i) + " (" + arguments[i].text + ")");
  }
  return labels;
}

void plotFeatures(const PlotFeaturesOptions& options) {
  const PictureSize size = parsePictureSize(options.size, "--size");
  requireStage(options.stage);
  std::vector<RunArgument> arguments;
  std::vector<FeatureRunReport> reports;
  for (const auto& text : options.runs) {
    arguments.push_back(parseRunArgument(text));
    reports.push_back(readFeatureRunReport(arguments.back().path, options.stage));
  }
  const std::vector<std::string> labels = runLabels(arguments, reports);
  std::vector<eval::FeatureCurve> curves;
  for (size_t i = 0; i < reports.size(); ++i)
    curves.push_back(
        {labels[i], reports[i].scenario, reports[i].times, reports[i].total, reports[i].budget});

  const std::filesystem::path out(options.out);
  if (out.has_parent_path()) {
    std::error_code error;
    std::filesystem::create_directories(out.parent_path(), error);
    if (error)
      throw InputError(out.parent_path().string(), "--out",
                       "cannot create the folder: " + error.message());
  }
  eval::writePng(eval::renderFeaturePlot(options.stage, curves, size.width, size.height), out);
  std::printf("%s\n", out.string().c_str());
}

}  // namespace

void addPlotFeaturesCommand(CLI::App& root) {
  auto options = std::make_shared<PlotFeaturesOptions>();
  auto* plot = root.add_subcommand(
      "plot-features",
      "Draw features of one stage over mission time, one curve per feature-mission run");
  plot->add_option("--out", options->out, "the PNG to write")->check(nonEmptyPath())->required();
  plot->add_option("--size", options->size, "picture size, WIDTHxHEIGHT in pixels")
      ->capture_default_str();
  plot->add_option(
          "--stage", options->stage,
          "discovered, assigned, inspected, collected or priority (the high-priority features "
          "collected)")
      ->capture_default_str();
  plot->add_option("RUN[=LABEL]", options->runs,
                   "run folder written by coinspect run --out (or its report.json), and the "
                   "curve's legend label (default: the strategy, with the folder when two runs "
                   "share it)")
      ->required();
  plot->footer(
      "Reads features.timeline.<stage>, features.total (features.priority.total for priority) "
      "and clock.budget from each report.json "
      "and prints the PNG's path. Exit status: 0, 2 for bad input (a missing or malformed "
      "report, a run without features, a bad option).");
  plot->callback([options] { plotFeatures(*options); });
}

}  // namespace coinspect::app
