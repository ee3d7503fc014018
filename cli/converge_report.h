// What `radiant converge` writes: the table it prints, converge.csv and converge.json.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "converge/convergence.h"
#include "image/image_io_module.h"

namespace radiant::cli {

// One line of the chart: a mode (ladder report) or a sampler (supersampling report).
struct ConvergeSeries {
  std::string name;
  std::vector<LadderStep> steps;
  PowerFit error_by_spp;                 // RMSE against spp, fitted over the steps
  std::optional<Prediction> prediction;  // with --target-error
};

// The reference a series was measured against.
struct ReferenceNote {
  std::string mode;  // the mode that rendered it, or "file"
  std::string file;  // --reference, or empty
  int spp = 0;
  double seconds = 0;
};

struct ConvergeReport {
  std::string scene;
  std::string kind;    // "ladder" or "supersampling"
  std::string metric;  // the error the chart plots: "rmse" or "edge_rmse"
  std::string title;
  int width = 0, height = 0;
  double edge_fraction = 0;
  double target_error = 0;  // 0 = none
  std::vector<ReferenceNote> references;
  std::vector<ConvergeSeries> series;
  ImageMetadata chart_metadata;  // what the chart records (converge.json's "metadata")
};

// What the chart of `report` records about how it was made (docs/cli.md, "Image metadata"): the
// command line, the scene, the modes, samplers and spp of its steps (comma lists), the seed, the
// render time of its steps and references summed, and the steps' rays and rays per second.
ImageMetadata converge_chart_metadata(const ConvergeReport& report, const std::string& command_line, uint32_t seed);

// A step's render time over the time of the series' 1-spp step (its first step without one).
double time_multiple(const ConvergeSeries& series, const LadderStep& step);

// Header line, then one row per step of every series; numbers as plain decimals.
std::string converge_csv(const ConvergeReport& report);
// The report as a JSON document (scripts/plot_convergence.py reads it).
std::string converge_json(const ConvergeReport& report);
// For a supersampling report, each step against its sampler's 1-spp step in a sentence: "sobol:
// 81 samples per pixel cost 80x the time of one and cut edge error to 4%".
std::string supersampling_sentences(const ConvergeReport& report);

// The table `radiant converge` prints, with the fits and predictions (and the sentences).
std::string converge_table(const ConvergeReport& report);

}  // namespace radiant::cli
