// `radiant merge SHARD... -o OUT`: the shards of one render, checked to belong together and to
// cover the image x [0, spp) exactly once, added exactly and written like `render` writes.
#include <algorithm>
#include <iostream>

#include "command_line.h"
#include "commands.h"
#include "film/shard_merge.h"
#include "image/image_io.h"
#include "image/render_metadata.h"
#include "option_parsing.h"
#include "output/output_paths.h"
#include "output/output_set.h"
#include "render/render.h"

namespace radiant::cli {

namespace {

const char* merge_examples =
    "\nExamples:\n"
    "  for i in 0 1 2 3; do radiant render assets/cornell.gltf -o shard-$i.exr --shard $i/4; done\n"
    "  radiant merge shard-*.exr -o image.exr\n"
    "  radiant merge shard-*.exr -o image.png\n"
    "  radiant merge shard-0.exr shard-1.exr -o half.exr --keep-accum   # one shard again, for a later merge\n"
    "  for i in 0 1; do radiant render assets/cornell.gltf -o d-$i.exr --shard $i/2 --aov albedo,normal,depth,halves,variance; done\n"
    "  radiant merge d-*.exr -o merged.exr && radiant denoise merged.exr -o clean.png   # denoised after the merge\n";

// What the merged image records: the shards' render (their settings, the merged spp, their render
// times and rays summed, the first one's command line) and how many were merged. Shards rendered
// with --no-metadata record no render: then only the settings every shard holds.
ImageMetadata merged_metadata(const std::vector<NamedShard>& shards, const ShardInfo& merged,
                              const std::string& command_line, MemoryBudget& budget) {
  std::vector<RenderRecord> records;
  for (const NamedShard& shard : shards) {
    std::optional<RenderRecord> record;
    try {
      record = parse_render_metadata(read_image_header(shard.path, &budget).metadata);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(shard.path + ": " + e.what());
    }
    if (record) records.push_back(*record);
  }
  ImageMetadata metadata;
  if (records.size() == shards.size()) {
    RenderRecord record = combined_record(records);
    record.version = RADIANT_VERSION;
    record.command_line = command_line;
    record.spp = merged.spp;
    metadata = render_metadata(record);
    metadata.emplace_back("radiant:shard_command", records.front().command_line);
  } else {
    metadata = {{"Software", "radiant " RADIANT_VERSION},
                {"Comment", command_line},
                {"radiant:sampler", merged.sampler},
                {"radiant:spp", std::to_string(merged.spp)},
                {"radiant:seed", std::to_string(merged.seed)}};
  }
  metadata.emplace_back("radiant:shards", std::to_string(shards.size()));
  return metadata;
}

// Reads, checks and adds the shards; writes `output` (and nothing when anything fails) with
// `command_line` recorded in it unless `metadata` is false.
void merge_shards(const std::vector<std::string>& paths, const std::string& output, bool keep_accum, bool quiet,
                  const std::string& command_line, bool metadata, MemoryBudget& budget) {
  std::vector<NamedShard> shards;
  for (const std::string& path : paths) shards.push_back({path, read_shard_info(path, &budget)});
  ShardInfo merged = check_shards(shards, !keep_accum);
  if (merged.transparent && !keep_accum && !stores_alpha(output))
    throw std::runtime_error("the shards are of a --transparent render: -o needs an output with alpha: PNG, TIFF or EXR "
                             "(got '" + output + "')");
  bool with_aovs = !merged.aovs.empty();
  bool with_halves = std::find(merged.aovs.begin(), merged.aovs.end(), "halves") != merged.aovs.end();
  int width = merged.x1 - merged.x0, height = merged.y1 - merged.y0;
  size_t channels = output_channel_names(merged.aovs, merged.transparent).size();
  MemoryCharge image_memory(&budget, render_image_bytes(width, height, channels, with_aovs, merged.transparent, with_halves),
                            output + ": the merged " + std::to_string(width) + "x" + std::to_string(height) + " film and image");
  Film film = make_film(width, height, with_aovs, merged.transparent, with_halves);
  film.x = merged.x0, film.y = merged.y0, film.full_width = merged.full_width, film.full_height = merged.full_height;
  for (const NamedShard& shard : shards) add_shard(film, read_shard_film(shard.path, shard.info, &budget).film);
  ImageMetadata record = metadata ? merged_metadata(shards, merged, command_line, budget) : ImageMetadata{};
  OutputSet outputs;
  if (keep_accum) {
    write_shard(outputs.create(output), film, merged, record, &budget);
  } else {
    OutputImage image = film_to_image(film, merged.aovs);
    image.metadata = record;
    image.display = merged.display;  // as the one render would have written it
    image.bit_depth = merged.bit_depth;
    image.half = merged.half;
    write_image(outputs.create(output), image);
  }
  outputs.commit();
  if (!quiet)
    std::cerr << "radiant: merged " << shards.size() << " shards into " << output << " (" << width << "x" << height
              << ", " << merged.spp << " spp)\n";
}

}  // namespace

int merge_main(int argc, char** argv) {
  CLI::App app{"Merge shards (radiant render --shard/--sample-range) into the image one render makes."};
  app.footer(merge_examples);
  std::vector<std::string> paths;
  std::string output, max_memory;
  bool keep_accum = false, no_metadata = false;
  LogLevelFlags log;
  app.add_option("SHARD", paths, "Shard EXR files of one render")->required();
  app.add_option("-o,--output", output, "Output image (.png, .exr, ...), or a shard EXR with --keep-accum")->required();
  app.add_flag("--keep-accum", keep_accum,
               "Write the exact accumulators as one shard for a later merge: the shards then need cover only their "
               "bounding region and sample range, exactly once");
  app.add_option("--max-memory", max_memory, "Memory cap in GiB (default 1/4 of RAM)");
  app.add_flag("--no-metadata", no_metadata,
               "Record nothing about the render in the image: the same shards then merge to the same bytes");
  log.bind(app);
  std::optional<uint64_t> max_memory_bytes;
  bool quiet = false;
  try {
    app.parse(argc, argv);
    if (!max_memory.empty()) max_memory_bytes = parse_memory_limit("--max-memory", max_memory);
    quiet = !shows(log.level(), LogLevel::info);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "radiant merge: " << e.what() << "\n";
    return exit_usage;
  }
  MemoryBudget budget = command_memory_budget(max_memory_bytes);
  try {
    if (keep_accum && !is_exr_format(output))
      throw std::invalid_argument("--keep-accum writes a shard EXR: -o must end in .exr (got '" + output + "')");
    DistinctFiles files;
    for (const std::string& path : paths) files.add_input({"a shard", path});
    files.add_output({"-o", output});
    check_image_output(output);
  } catch (const std::invalid_argument& e) {
    std::cerr << "radiant merge: " << e.what() << "\n";
    return exit_usage;
  }
  try {
    check_output_place(output);
    merge_shards(paths, output, keep_accum, quiet, command_line_text(argc, argv), !no_metadata, budget);
  } catch (const std::exception& e) {
    std::cerr << "radiant: " << e.what() << "\n";
    return exit_failure;
  }
  return exit_ok;
}

}  // namespace radiant::cli
