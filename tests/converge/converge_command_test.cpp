// `radiant converge` as scripts drive it: the files it writes, their shape, and its usage errors.
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {


std::vector<std::vector<std::string>> read_csv(const fs::path& file) {
  std::vector<std::vector<std::string>> rows;
  std::stringstream in(read_bytes(file));
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> row;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(cell);
    rows.push_back(row);
  }
  return rows;
}

bool is_number(const std::string& text) {
  size_t used = 0;
  try {
    std::stod(text, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == text.size();
}

}  // namespace

TEST_CASE("converge cli: --denoise adds a denoised ladder, less error at 16 spp, and the time to the raw ladder's last error") {
  ScratchDir dir("converge-denoise");
  CommandResult r = run_radiant("converge " + quoted(source_path("assets/cornell.gltf")) +
                                " --width 32 --height 32 --spp-ladder 4,16 --reference-spp 256 --mode path --denoise" +
                                " --out " + quoted(dir.path));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  auto rows = read_csv(dir.file("converge.csv"));
  REQUIRE(rows.size() == 5);
  CHECK(rows[1][0] == "path");
  CHECK(rows[3][0] == "path+denoise");
  CHECK(rows[4][3] == "16");
  CHECK(std::stod(rows[4][6]) < std::stod(rows[2][6]));  // denoised 16 spp against raw 16 spp, RMSE
  // Without --target-error both series are asked for the raw ladder's last RMSE.
  CHECK(r.out.find("path: RMSE = ") != std::string::npos);
  CHECK(r.out.find("path+denoise: RMSE = ") != std::string::npos);
  CHECK(r.out.find("RMSE " + rows[2][6].substr(0, 4)) != std::string::npos);
  nlohmann::json report = nlohmann::json::parse(read_bytes(dir.file("converge.json")));
  CHECK(report["series"][1]["steps"][1]["denoise_seconds"].get<double>() > 0);
  CHECK(report["series"][0]["steps"][1]["denoise_seconds"].get<double>() == 0);
  CommandResult both = run_radiant("converge " + quoted(source_path("assets/cornell.gltf")) +
                                   " --supersampling --denoise --out " + quoted(dir.path));
  CHECK(both.exit_code == 2);
  CHECK(both.err.find("--denoise: adds denoised ladders of modes: not with --supersampling") != std::string::npos);
}

TEST_CASE("converge cli: path and naive ladders write a well-formed CSV and JSON, one row per step") {
  ScratchDir dir("converge-ladder");
  CommandResult r = run_radiant("converge " + quoted(source_path("assets/cornell.gltf")) +
                                " --width 24 --height 24 --spp-ladder 1,2,4 --reference-spp 32 --mode path,naive" +
                                " --target-error 0.01 --out " + quoted(dir.path));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("reference: path, 32 spp") != std::string::npos);
  CHECK(r.out.find("path: RMSE = ") != std::string::npos);
  CHECK(r.out.find("RMSE 0.01 needs ~") != std::string::npos);

  auto rows = read_csv(dir.file("converge.csv"));
  REQUIRE(rows.size() == 7);
  CHECK(rows[0] == std::vector<std::string>{"series", "mode", "sampler", "spp", "seconds", "rays", "rmse",
                                            "relative_mse", "psnr", "edge_rmse", "time_multiple"});
  for (size_t i = 1; i < rows.size(); ++i) {
    REQUIRE(rows[i].size() == 11);
    CHECK(rows[i][0] == (i <= 3 ? "path" : "naive"));
    for (size_t c = 3; c < 11; ++c) CHECK_MESSAGE(is_number(rows[i][c]), rows[i][c]);
  }
  CHECK(rows[1][3] == "1");
  CHECK(rows[3][3] == "4");
  CHECK(rows[1][10] == "1");  // the 1-spp step is the time unit

  std::string json = read_bytes(dir.file("converge.json"));
  nlohmann::json report = nlohmann::json::parse(json);  // throws, failing the test, unless valid
  CHECK(report["kind"] == "ladder");
  CHECK(report["references"][0]["mode"] == "path");
  CHECK(report["references"][0]["file"] == "");
  CHECK(report["references"][0]["spp"] == 32);
  // What the chart records about how it was made.
  nlohmann::json metadata = report["metadata"];
  CHECK(metadata["Software"] == "radiant " RADIANT_VERSION);
  CHECK(metadata["Comment"].get<std::string>().rfind("radiant converge " + source_path("assets/cornell.gltf").string(), 0) == 0);
  CHECK(metadata["radiant:mode"] == "path,naive");
  CHECK(metadata["radiant:spp"] == "1,2,4");
  CHECK(metadata["radiant:seed"] == "0");
  CHECK(std::stod(metadata["radiant:render_seconds"].get<std::string>()) > 0);
  if (fs::exists(dir.file("converge.png"))) {
    CHECK(read_bytes(dir.file("converge.png")).substr(1, 3) == "PNG");
    CHECK(image_attribute(dir.file("converge.png"), "Software") == "radiant " RADIANT_VERSION);
    CHECK(image_attribute(dir.file("converge.png"), "radiant:spp") == "1,2,4");
  } else {
    CHECK(r.err.find("warning: no chart") != std::string::npos);
  }
}

TEST_CASE("converge cli: --supersampling measures each sampler at edges, in time multiples of 1 spp") {
  ScratchDir dir("converge-supersampling");
  CommandResult r = run_radiant("converge " + quoted(source_path("assets/showcase.scene")) +
                                " --supersampling --width 32 --height 18 --spp-ladder 1,9 --reference-spp 64 --quiet --out " +
                                quoted(dir.path));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.empty());
  auto rows = read_csv(dir.file("supersampling.csv"));
  REQUIRE(rows.size() == 9);
  const char* samplers[] = {"grid", "random", "jittered", "sobol"};
  for (size_t i = 1; i < rows.size(); ++i) {
    CHECK(rows[i][0] == samplers[(i - 1) / 2]);
    CHECK(rows[i][1] == "whitted");
    CHECK(std::stod(rows[i][9]) > 0);  // edge RMSE
  }
  CHECK(rows[1][10] == "1");
  CHECK(std::stod(rows[2][9]) < std::stod(rows[1][9]));  // 9 grid samples beat one at the edges
  CHECK_NOTHROW(nlohmann::json::parse(read_bytes(dir.file("supersampling.json"))));
}

TEST_CASE("converge cli: usage errors exit 2 with one line, a missing scene exits 1") {
  std::string cornell = quoted(source_path("assets/cornell.gltf"));
  CommandResult bad_ladder = run_radiant("converge " + cornell + " --spp-ladder 1,x");
  CHECK(bad_ladder.exit_code == 2);
  CHECK(bad_ladder.err == "radiant converge: --spp-ladder: 'x' is not a sample count (1 to 16777216)\n");
  CommandResult two_modes = run_radiant("converge " + cornell + " --supersampling --mode path,whitted");
  CHECK(two_modes.exit_code == 2);
  CHECK(two_modes.err == "radiant converge: --mode: --supersampling compares samplers of one mode\n");
  CommandResult bad_mode = run_radiant("converge " + cornell + " --mode path,fast");
  CHECK(bad_mode.exit_code == 2);
  CHECK(bad_mode.err.find("unknown mode 'fast'") != std::string::npos);
  CommandResult missing = run_radiant("converge /nonexistent/scene.gltf --spp-ladder 1");
  CHECK(missing.exit_code == 1);
  CHECK(missing.err.rfind("radiant: ", 0) == 0);
  CHECK(std::count(missing.err.begin(), missing.err.end(), '\n') == 1);
}

TEST_CASE("converge cli: --reference measures against a given EXR, takes its size, and refuses another size") {
  ScratchDir dir("converge-reference");
  std::string cornell = quoted(source_path("assets/cornell.gltf"));
  fs::path reference = dir.file("reference.exr");
  REQUIRE(run_radiant("render " + cornell + " -o " + quoted(reference) + " --width 20 --height 16 --spp 64 --quiet --seed 7")
              .exit_code == 0);
  CommandResult r = run_radiant("converge " + cornell + " --reference " + quoted(reference) + " --spp-ladder 1,4 --out " +
                                quoted(dir.path));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("(20x16)") != std::string::npos);
  CHECK(r.out.find("reference: " + reference.string()) != std::string::npos);
  auto rows = read_csv(dir.file("converge.csv"));
  REQUIRE(rows.size() == 3);
  CHECK(std::stod(rows[2][6]) < std::stod(rows[1][6]));  // 4 spp is closer to it than 1

  CommandResult wrong = run_radiant("converge " + cornell + " --reference " + quoted(reference) +
                                    " --width 32 --height 32 --spp-ladder 1 --out " + quoted(dir.path));
  CHECK(wrong.exit_code == 2);
  CHECK(wrong.err == "radiant converge: --reference " + reference.string() + " is 20x16 but the renders are 32x32\n");
  CommandResult mixed = run_radiant("converge " + cornell + " --reference " + quoted(reference) +
                                    " --mode path,whitted --spp-ladder 1 --out " + quoted(dir.path));
  CHECK(mixed.exit_code == 2);
  CHECK(mixed.err.find("Whitted and path/naive converge to different ones") != std::string::npos);
}

TEST_CASE("converge cli: --supersampling says what each step costs and buys in a sentence") {
  ScratchDir dir("converge-sentence");
  CommandResult r = run_radiant("converge " + quoted(source_path("assets/showcase.scene")) +
                                " --supersampling --width 32 --height 18 --spp-ladder 1,9 --reference-spp 64 --samplers grid --out " +
                                quoted(dir.path));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  auto rows = read_csv(dir.file("supersampling.csv"));
  REQUIRE(rows.size() == 3);
  // The sentence carries the table's own numbers: the time multiple and the edge error as a share of 1 spp's.
  size_t at = r.out.find("grid: 9 samples per pixel cost ");
  REQUIRE(at != std::string::npos);
  double multiple = 0, percent = 0;
  REQUIRE(std::sscanf(r.out.c_str() + at, "grid: 9 samples per pixel cost %lfx the time of one and cut edge error to %lf%%",
                      &multiple, &percent) == 2);
  double table_multiple = std::stod(rows[2][10]);
  CHECK(std::abs(multiple - table_multiple) <= (table_multiple < 10 ? 0.06 : 0.51));  // one decimal below 10x, none above
  CHECK(percent == doctest::Approx(100 * std::stod(rows[2][9]) / std::stod(rows[1][9])).epsilon(0.05));
}
