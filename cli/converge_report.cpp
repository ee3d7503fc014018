#include "converge_report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "option_parsing.h"
#include "render_report.h"

namespace radiant::cli {

namespace {

// JSON has no infinity: a value that never gets there is null.
std::string json_number(double value) {
  if (!std::isfinite(value)) return "null";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

std::string csv_number(double value) {
  if (!std::isfinite(value)) return "inf";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

std::string step_json(const ConvergeSeries& series, const LadderStep& step) {
  std::ostringstream j;
  j << "{\"spp\": " << step.spp << ", \"seconds\": " << json_number(step.seconds) << ", \"rays\": " << step.rays
    << ", \"rmse\": " << json_number(step.error.rmse) << ", \"relative_mse\": " << json_number(step.error.relative_mse)
    << ", \"psnr\": " << json_number(step.error.psnr) << ", \"edge_rmse\": " << json_number(step.error.edge_rmse)
    << ", \"time_multiple\": " << json_number(time_multiple(series, step)) << "}";
  return j.str();
}

std::string series_json(const ConvergeSeries& s) {
  std::ostringstream j;
  const LadderStep* first = s.steps.empty() ? nullptr : &s.steps.front();
  j << "    {\"name\": \"" << json_escape(s.name) << "\", \"mode\": \"" << (first ? mode_name(first->mode) : "")
    << "\", \"sampler\": \"" << (first ? sampler_name(first->sampler) : "") << "\",\n"
    << "     \"fit\": {\"scale\": " << json_number(s.error_by_spp.scale)
    << ", \"exponent\": " << json_number(s.error_by_spp.exponent) << "},\n";
  if (s.prediction)
    j << "     \"prediction\": {\"spp\": " << json_number(s.prediction->spp)
      << ", \"seconds\": " << json_number(s.prediction->seconds) << "},\n";
  j << "     \"steps\": [\n";
  for (size_t i = 0; i < s.steps.size(); ++i)
    j << "       " << step_json(s, s.steps[i]) << (i + 1 < s.steps.size() ? ",\n" : "\n");
  j << "     ]}";
  return j.str();
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
  std::ostringstream j;
  j << "{\n"
    << "  \"scene\": \"" << json_escape(report.scene) << "\",\n"
    << "  \"kind\": \"" << report.kind << "\", \"metric\": \"" << report.metric << "\",\n"
    << "  \"title\": \"" << json_escape(report.title) << "\",\n"
    << "  \"width\": " << report.width << ", \"height\": " << report.height
    << ", \"edge_fraction\": " << json_number(report.edge_fraction) << ",\n"
    << "  \"target_error\": " << (report.target_error > 0 ? json_number(report.target_error) : "null") << ",\n"
    << "  \"references\": [";
  for (size_t i = 0; i < report.references.size(); ++i) {
    const ReferenceNote& r = report.references[i];
    j << (i ? ", " : "") << "{\"mode\": \"" << r.mode << "\", \"file\": \"" << json_escape(r.file)
      << "\", \"spp\": " << r.spp << ", \"seconds\": " << json_number(r.seconds) << "}";
  }
  j << "],\n  \"series\": [\n";
  for (size_t i = 0; i < report.series.size(); ++i)
    j << series_json(report.series[i]) << (i + 1 < report.series.size() ? ",\n" : "\n");
  j << "  ]\n}\n";
  return j.str();
}

std::string converge_table(const ConvergeReport& report) {
  std::string text = report.title + " (" + std::to_string(report.width) + "x" + std::to_string(report.height) + ")\n";
  for (const ReferenceNote& r : report.references)
    text += r.file.empty() ? format("reference: %s, %d spp, %.2f s\n", r.mode.c_str(), r.spp, r.seconds)
                           : "reference: " + r.file + "\n";
  text += format("%-10s %-8s %6s %10s %12s %10s %10s %8s %10s %8s\n", "series", "sampler", "spp", "seconds", "rays", "RMSE",
                 "relMSE", "PSNR", "edge RMSE", "time x");
  for (const ConvergeSeries& s : report.series)
    for (const LadderStep& step : s.steps)
      text += format("%-10s %-8s %6d %10.4f %12llu %10.5f %10.5f %8.2f %10.5f %8.1f\n", s.name.c_str(),
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
  return text;
}

}  // namespace radiant::cli
