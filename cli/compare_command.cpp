// `radiant compare A B`: image comparison for CI regression jobs (docs/compare.md).
#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <optional>
#include <sstream>

#include "commands.h"
#include "image/compare.h"
#include "image/false_color.h"
#include "image/image_writer.h"
#include "json_output.h"
#include "output/output_paths.h"
#include "output/output_set.h"
#include "option_parsing.h"

namespace radiant::cli {

namespace {

enum class McMode { automatic, on, off };

struct CompareOptions {
  std::string a, b;
  CompareThresholds thresholds;
  ZTestParams z_test;
  McMode mc = McMode::automatic;
  std::string variance_file;  // per-sample variance of A, divided by samples_per_pixel
  int samples_per_pixel = 0;
  std::string diff_file;
  std::optional<double> diff_scale;
  bool json = false;
  std::string max_memory;
};

// Everything one comparison found, for printing.
struct CompareReport {
  CompareImage a, b;
  CompareMetrics metrics;
  std::optional<ZTestResult> z_test;
  Verdict verdict = Verdict::pass;
  std::string nonfinite;  // why a non-finite statistic failed the comparison, or ""
  std::string implausible;  // the first variance beyond plausible_variance, or ""
};

void add_options(CLI::App& app, CompareOptions& options) {
  app.add_option("A", options.a, "first image (e.g. the new render)")->required();
  app.add_option("B", options.b, "second image (e.g. the reference)")->required();
  CompareThresholds& t = options.thresholds;
  const double huge = 1e30;
  CLI::Validator non_negative = number_in(0, huge), percent = number_in(0, 100);
  app.add_option("--fail", t.fail, "a pixel fails when a channel differs by more")
      ->capture_default_str()->check(non_negative);
  app.add_option("--fail-percent", t.fail_percent, "fail when more than this % of pixels fail")
      ->capture_default_str()->check(percent);
  app.add_option("--warn", t.warn, "a pixel warns when a channel differs by more")
      ->capture_default_str()->check(non_negative);
  app.add_option("--warn-percent", t.warn_percent, "warn when more than this % of pixels warn")
      ->capture_default_str()->check(percent);
  app.add_option("--fail-relative", t.fail_relative, "fail when the mean relative error exceeds")
      ->capture_default_str()->check(non_negative);
  app.add_option("--warn-relative", t.warn_relative, "warn when the mean relative error exceeds")
      ->capture_default_str()->check(non_negative);
  auto* mc = app.add_flag_function(
      "--mc", [&](int64_t) { options.mc = McMode::on; }, "use the Monte Carlo z-test (needs a variance)");
  auto* no_mc = app.add_flag_function(
      "--no-mc", [&](int64_t) { options.mc = McMode::off; }, "use plain thresholds even with a variance");
  mc->excludes(no_mc);
  app.add_option("--alpha", options.z_test.alpha, "z-test: chance that equal-mean renders fail")
      ->capture_default_str()->check(number_in(1e-12, 0.5));
  app.add_option("--mc-fail-percent", options.z_test.allowed_fail_percent,
                 "z-test: % of pixels allowed to fail")
      ->capture_default_str()->check(percent);
  app.add_option("--mc-epsilon", options.z_test.epsilon, "z-test: relative deviation floor")
      ->capture_default_str()->check(non_negative);
  app.add_flag("--mc-bias", options.z_test.bias_test,
               "z-test: also fail a significant whole-image bias (independent pixels only)");
  auto* variance = app.add_option("--variance", options.variance_file,
                                  "per-sample variance image of A (with --spp)");
  auto* spp = app.add_option("--spp", options.samples_per_pixel, "samples per pixel of A")
                  ->check(CLI::Range(1, 1 << 30));
  variance->needs(spp);
  spp->needs(variance);
  app.add_option("--diff", options.diff_file, "write a false-color difference image");
  app.add_option("--diff-scale", options.diff_scale,
                 "difference mapped to white (default --fail, or the critical |z|)")
      ->check(number_in(1e-30, huge));
  app.add_flag("--json", options.json, "print one JSON object on stdout");
  app.add_option("--max-memory", options.max_memory, "memory cap in GiB (default 1/4 of RAM)");
}

bool use_z_test(const CompareOptions& options, const CompareImage& a, const CompareImage& b) {
  bool has_variance = !a.variance.empty() || !b.variance.empty();
  if (options.mc == McMode::on && !has_variance)
    throw CompareError("--mc needs a variance: variance.R/G/B channels in " + a.path + " or " +
                       b.path + ", or --variance FILE --spp N");
  return options.mc != McMode::off && has_variance;
}

CompareReport compare_files(const CompareOptions& options, MemoryBudget& budget) {
  CompareReport report;
  report.a = read_compare_image(options.a, &budget);
  report.b = read_compare_image(options.b, &budget);
  match_alpha(report.a, report.b);
  check_comparable(report.a, report.b);
  if (!options.variance_file.empty())
    report.a.variance =
        read_variance_image(options.variance_file, report.a, options.samples_per_pixel, &budget);
  report.metrics = compute_metrics(report.a, report.b, options.thresholds);
  report.verdict = threshold_verdict(report.metrics, options.thresholds);
  if (use_z_test(options, report.a, report.b)) {
    report.z_test = run_z_test(report.a, report.b, options.z_test);
    report.verdict = report.z_test->verdict;
  }
  if (report.metrics.nonfinite_pixels > 0 || (report.z_test && report.z_test->nonfinite_values > 0))
    report.nonfinite = first_nonfinite(report.a, report.b);
  if (report.z_test && report.z_test->implausible_values > 0)
    report.implausible = first_implausible_variance(report.a, report.b, options.z_test.max_relative_deviation);
  return report;
}

// Before any image is read: --diff names a format radiant writes, can be created where it goes,
// and is none of the inputs.
void check_difference_output(const CompareOptions& options) {
  DistinctFiles files;
  files.add_input({"A", options.a});
  files.add_input({"B", options.b});
  if (!options.variance_file.empty()) files.add_input({"--variance", options.variance_file});
  files.add_output({"--diff", options.diff_file});
  check_image_output(options.diff_file);
  check_output_place(options.diff_file);
}

void write_difference(const CompareOptions& options, const CompareReport& report) {
  OutputSet outputs;
  TemporaryFile& file = outputs.create(options.diff_file);
  if (report.z_test) {
    double top = options.diff_scale.value_or(report.z_test->z_critical);
    write_false_color(file, report.z_test->abs_z, report.a.width, report.a.height, float(top));
  } else {
    double top = options.diff_scale.value_or(options.thresholds.fail);
    write_false_color(file, pixel_max_difference(report.a, report.b), report.a.width, report.a.height, float(top));
  }
  outputs.commit();
}

// Mixing an sRGB-encoded file with a linear one compares different encodings: say so.
void warn_about_encodings(const CompareReport& report) {
  const std::string &a = report.a.color_space, &b = report.b.color_space;
  if (!a.empty() && !b.empty() && a != b)
    std::cerr << "radiant compare: warning: " << report.a.path << " is " << a << " but "
              << report.b.path << " is " << b
              << "; the metrics compare the files' own encodings\n";
}

// ------------------------------------------------------------------------------- JSON output

void print_json(std::ostream& out, const CompareOptions& options, const CompareReport& report) {
  const CompareMetrics& m = report.metrics;
  const CompareThresholds& t = options.thresholds;
  Json j;
  j["a"] = report.a.path;
  j["b"] = report.b.path;
  j["width"] = report.a.width;
  j["height"] = report.a.height;
  j["channels"] = report.a.channel_names;
  j["mode"] = report.z_test ? "mc" : "threshold";
  j["metrics"] = {{"rmse", json_number(m.rmse)},
                  {"psnr", json_number(m.psnr)},
                  {"max_error", json_number(m.max_error)},
                  {"max_error_pixel", {m.max_x, m.max_y}},
                  {"max_error_channel", report.a.channel_names[m.max_channel]},
                  {"mean_error", json_number(m.mean_error)},
                  {"mean_relative_error", json_number(m.mean_relative_error)},
                  {"fail_pixels", m.fail_pixels},
                  {"fail_fraction", json_number(m.fail_fraction)},
                  {"warn_pixels", m.warn_pixels},
                  {"warn_fraction", json_number(m.warn_fraction)}};
  j["thresholds"] = {{"fail", json_number(t.fail)},
                     {"fail_percent", json_number(t.fail_percent)},
                     {"warn", json_number(t.warn)},
                     {"warn_percent", json_number(t.warn_percent)},
                     {"fail_relative", json_number(t.fail_relative)},
                     {"warn_relative", json_number(t.warn_relative)}};
  if (const auto& z = report.z_test)
    j["z_test"] = {{"alpha", json_number(options.z_test.alpha)},
                   {"alpha_corrected", json_number(z->alpha_corrected)},
                   {"z_critical", json_number(z->z_critical)},
                   {"tests", z->tests},
                   {"max_abs_z", json_number(z->max_abs_z)},
                   {"min_p_value", json_number(z->min_p_value)},
                   {"fail_pixels", z->fail_pixels},
                   {"fail_fraction", json_number(z->fail_fraction)},
                   {"allowed_fail_percent", json_number(options.z_test.allowed_fail_percent)},
                   {"epsilon", json_number(options.z_test.epsilon)},
                   {"bias_z", json_number(z->bias_z)},
                   {"bias_p_value", json_number(z->bias_p_value)},
                   {"bias_test", options.z_test.bias_test},
                   {"max_relative_deviation", json_number(options.z_test.max_relative_deviation)},
                   {"implausible_values", z->implausible_values}};
  else
    j["z_test"] = nullptr;
  j["nonfinite"] = report.nonfinite.empty() ? Json(nullptr) : Json(report.nonfinite);
  j["implausible_variance"] = report.implausible.empty() ? Json(nullptr) : Json(report.implausible);
  j["verdict"] = verdict_name(report.verdict);
  out << json_text(j, true);
}

// ------------------------------------------------------------------------------ table output

std::string percent(double fraction) {
  std::ostringstream text;
  text << fraction * 100 << "%";
  return text.str();
}

void print_table(std::ostream& out, const CompareOptions& options, const CompareReport& report) {
  const CompareMetrics& m = report.metrics;
  const CompareThresholds& t = options.thresholds;
  out << report.a.path << " vs " << report.b.path << ": " << report.a.width << "x"
      << report.a.height << ", channels";
  for (const std::string& name : report.a.channel_names) out << " " << name;
  out << "\n  RMSE                 " << m.rmse
      << "\n  PSNR                 " << m.psnr << " dB"
      << "\n  max error            " << m.max_error << " at (" << m.max_x << ", " << m.max_y
      << ") " << report.a.channel_names[m.max_channel]
      << "\n  mean error           " << m.mean_error
      << "\n  mean relative error  " << percent(m.mean_relative_error) << " (fail above "
      << percent(t.fail_relative) << ")"
      << "\n  pixels over " << t.fail << "    " << m.fail_pixels << " (" << percent(m.fail_fraction)
      << ", fail above " << t.fail_percent << "%)"
      << "\n  pixels over " << t.warn << "   " << m.warn_pixels << " (" << percent(m.warn_fraction)
      << ", warn above " << t.warn_percent << "%)\n";
  if (const auto& z = report.z_test)
    out << "  z-test               alpha " << options.z_test.alpha << ", Sidak level "
        << z->alpha_corrected << " (|z| > " << z->z_critical << ") over " << z->tests
        << " values\n  max |z|              " << z->max_abs_z
        << "\n  pixels failing z     " << z->fail_pixels << " (" << percent(z->fail_fraction)
        << ", fail above " << options.z_test.allowed_fail_percent << "%)"
        << "\n  bias z               " << z->bias_z << " (p " << z->bias_p_value
        << (options.z_test.bias_test ? ", fail below alpha)\n" : ", not tested: --mc-bias)\n");
  if (!report.nonfinite.empty())
    out << "  non-finite           " << report.nonfinite << ": fails whatever the thresholds\n";
  if (!report.implausible.empty())
    out << "  implausible variance " << report.implausible << ": fails whatever the difference\n";
  out << "verdict: " << verdict_name(report.verdict)
      << (report.z_test ? " (Monte Carlo z-test)\n" : " (thresholds)\n");
}

}  // namespace

int compare_main(int argc, char** argv) {
  CLI::App app{"Compare two images for CI: exit 0 pass (or warn), 1 fail, 2 error", "radiant compare"};
  app.footer(
      "\nExamples:\n"
      "  radiant render assets/first-render.scene -o golden.png --width 64 --threads 1\n"
      "  radiant render assets/first-render.scene -o new.png --width 64 --threads 2\n"
      "  radiant compare new.png golden.png                       # plain thresholds (docs/compare.md)\n"
      "  radiant compare new.png golden.png --diff diff.png       # and a false-color difference image\n"
      "  radiant render assets/cornell.gltf -o new.exr --width 64 --height 64 --spp 256 --seed 7 --aov variance\n"
      "  radiant compare new.exr golden/cornell-path.exr          # the z-test, with new.exr's variance\n"
      "  radiant compare new.exr golden/cornell-path.exr --json > report.json   # one JSON object for CI\n");
  CompareOptions options;
  add_options(app, options);
  std::optional<uint64_t> max_memory_bytes;
  try {
    parse_arguments(app, argc, argv);
    if (!options.max_memory.empty()) max_memory_bytes = parse_memory_limit("--max-memory", options.max_memory);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    std::cerr << "radiant compare: " << error.what() << "\n";
    return exit_usage;
  }
  try {
    if (!options.diff_file.empty()) check_difference_output(options);
    MemoryBudget budget = command_memory_budget(max_memory_bytes);
    CompareReport report = compare_files(options, budget);
    warn_about_encodings(report);
    if (!options.diff_file.empty()) write_difference(options, report);
    if (options.json) print_json(std::cout, options, report);
    else print_table(std::cout, options, report);
    // A report that did not arrive is an error, not a verdict (exit 1 would say "images differ").
    if (!std::cout.flush()) throw std::runtime_error(std::string("cannot write the report to standard output: ") + std::strerror(errno));
    return report.verdict == Verdict::fail ? exit_failure : exit_ok;
  } catch (const std::exception& error) {  // CompareError, and the difference image's errors
    std::cerr << "radiant compare: " << error.what() << "\n";
    return exit_usage;
  }
}

}  // namespace radiant::cli
