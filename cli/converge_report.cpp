#include "converge_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "json_output.h"
#include "option_parsing.h"
#include "render_report.h"

namespace radiant::cli {

namespace {

std::string csv_number(double value) {
  if (!std::isfinite(value)) return "inf";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

Json step_json(const ConvergeSeries& series, const LadderStep& step) {
  return {{"spp", step.spp},
          {"seconds", json_number(step.seconds)},
          {"denoise_seconds", json_number(step.denoise_seconds)},
          {"rays", step.rays},
          {"rmse", json_number(step.error.rmse)},
          {"relative_mse", json_number(step.error.relative_mse)},
          {"psnr", json_number(step.error.psnr)},
          {"edge_rmse", json_number(step.error.edge_rmse)},
          {"time_multiple", json_number(time_multiple(series, step))}};
}

Json series_json(const ConvergeSeries& s) {
  const LadderStep* first = s.steps.empty() ? nullptr : &s.steps.front();
  Json j;
  j["name"] = s.name;
  j["mode"] = first ? mode_name(first->mode) : "";
  j["sampler"] = first ? sampler_name(first->sampler) : "";
  j["fit"] = {{"scale", json_number(s.error_by_spp.scale)}, {"exponent", json_number(s.error_by_spp.exponent)}};
  if (s.prediction) j["prediction"] = {{"spp", json_number(s.prediction->spp)}, {"seconds", json_number(s.prediction->seconds)}};
  Json steps = Json::array();
  for (const LadderStep& step : s.steps) steps.push_back(step_json(s, step));
  j["steps"] = steps;
  return j;
}

std::string format(const char* pattern, auto... values) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, pattern, values...);
  return buffer;
}

}  // namespace

double time_multiple(const ConvergeSeries& series, const LadderStep& step) {
  const LadderStep* base = series.steps.empty() ? &step : &series.steps.front();
  for (const LadderStep& s : series.steps)
    if (s.spp == 1) base = &s;
  return base->seconds > 0 ? step.seconds / base->seconds : 0;
}

ImageMetadata converge_chart_metadata(const ConvergeReport& report, const std::string& command_line, uint32_t seed) {
  std::vector<std::string> modes, samplers, spps;
  auto add = [](std::vector<std::string>& list, const std::string& value) {
    if (std::find(list.begin(), list.end(), value) == list.end()) list.push_back(value);
  };
  double step_seconds = 0, reference_seconds = 0;
  uint64_t rays = 0;
  for (const ConvergeSeries& s : report.series)
    for (const LadderStep& step : s.steps) {
      add(modes, mode_name(step.mode)), add(samplers, sampler_name(step.sampler)), add(spps, std::to_string(step.spp));
      step_seconds += step.seconds, rays += step.rays;
    }
  for (const ReferenceNote& r : report.references) reference_seconds += r.seconds;
  auto joined = [](const std::vector<std::string>& list) {
    std::string text;
    for (const std::string& item : list) text += (text.empty() ? "" : ",") + item;
    return text;
  };
  return {{"Software", "radiant " RADIANT_VERSION},
          {"Comment", command_line},
          {"radiant:scene", report.scene},
          {"radiant:mode", joined(modes)},
          {"radiant:sampler", joined(samplers)},
          {"radiant:spp", joined(spps)},
          {"radiant:seed", std::to_string(seed)},
          {"radiant:render_seconds", csv_number(step_seconds + reference_seconds)},
          {"radiant:rays", std::to_string(rays)},  // the references' are not counted
          {"radiant:rays_per_second", csv_number(step_seconds > 0 ? double(rays) / step_seconds : 0)}};
}

std::string converge_csv(const ConvergeReport& report) {
  std::string csv = "series,mode,sampler,spp,seconds,rays,rmse,relative_mse,psnr,edge_rmse,time_multiple\n";
  for (const ConvergeSeries& s : report.series)
    for (const LadderStep& step : s.steps)
      csv += s.name + "," + mode_name(step.mode) + "," + sampler_name(step.sampler) + "," + std::to_string(step.spp) + "," +
             csv_number(step.seconds) + "," + std::to_string(step.rays) + "," + csv_number(step.error.rmse) + "," +
             csv_number(step.error.relative_mse) + "," + csv_number(step.error.psnr) + "," +
             csv_number(step.error.edge_rmse) + "," + csv_number(time_multiple(s, step)) + "\n";
  return csv;
}

std::string converge_json(const ConvergeReport& report) {
  Json j;
  j["scene"] = report.scene;
  j["kind"] = report.kind;
  j["metric"] = report.metric;
  j["title"] = report.title;
  j["width"] = report.width;
  j["height"] = report.height;
  j["edge_fraction"] = json_number(report.edge_fraction);
  j["target_error"] = report.target_error > 0 ? json_number(report.target_error) : Json(nullptr);
  Json references = Json::array();
  for (const ReferenceNote& r : report.references)
    references.push_back({{"mode", r.mode}, {"file", r.file}, {"spp", r.spp}, {"seconds", json_number(r.seconds)}});
  j["references"] = references;
  Json series = Json::array();
  for (const ConvergeSeries& s : report.series) series.push_back(series_json(s));
  j["series"] = series;
  Json metadata = Json::object();
  for (const auto& [name, value] : report.chart_metadata) metadata[name] = value;
  j["metadata"] = metadata;
  return json_text(j);
}

std::string supersampling_sentences(const ConvergeReport& report) {
  std::string text;
  for (const ConvergeSeries& s : report.series) {
    auto one = std::find_if(s.steps.begin(), s.steps.end(), [](const LadderStep& step) { return step.spp == 1; });
    if (one == s.steps.end() || !(one->error.edge_rmse > 0)) continue;
    for (const LadderStep& step : s.steps)
      if (step.spp > 1) {
        double multiple = time_multiple(s, step);
        text += format("%s: %d samples per pixel cost %.*fx the time of one and cut edge error to %.2g%%\n", s.name.c_str(),
                       step.spp, multiple < 10 ? 1 : 0, multiple, 100 * step.error.edge_rmse / one->error.edge_rmse);
      }
  }
  return text;
}

std::string converge_table(const ConvergeReport& report) {
  std::string text = report.title + " (" + std::to_string(report.width) + "x" + std::to_string(report.height) + ")\n";
  for (const ReferenceNote& r : report.references)
    text += r.file.empty() ? format("reference: %s, %d spp, %.2f s\n", r.mode.c_str(), r.spp, r.seconds)
                           : "reference: " + r.file + "\n";
  text += format("%-13s %-8s %6s %10s %12s %10s %10s %8s %10s %8s\n", "series", "sampler", "spp", "seconds", "rays", "RMSE",
                 "relMSE", "PSNR", "edge RMSE", "time x");
  for (const ConvergeSeries& s : report.series)
    for (const LadderStep& step : s.steps)
      text += format("%-13s %-8s %6d %10.4f %12llu %10.5f %10.5f %8.2f %10.5f %8.1f\n", s.name.c_str(),
                     sampler_name(step.sampler), step.spp, step.seconds, (unsigned long long)step.rays, step.error.rmse,
                     step.error.relative_mse, step.error.psnr, step.error.edge_rmse, time_multiple(s, step));
  for (const ConvergeSeries& s : report.series) {
    text += format("%s: RMSE = %.4g * spp^%.3f", s.name.c_str(), s.error_by_spp.scale, s.error_by_spp.exponent);
    if (s.prediction && std::isfinite(s.prediction->spp))
      text += format("; RMSE %.4g needs ~%.0f spp, ~%.3g s", report.target_error, std::ceil(s.prediction->spp),
                     s.prediction->seconds);
    else if (s.prediction)
      text += format("; RMSE %.4g is not reached (the error does not fall with spp)", report.target_error);
    text += "\n";
  }
  if (report.kind == "supersampling") text += supersampling_sentences(report);
  return text;
}

}  // namespace radiant::cli
