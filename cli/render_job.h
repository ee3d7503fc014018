// One render of a prepared scene to an image file, shared by `render` and `batch`.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "output/output_paths.h"
#include "render/render.h"
#include "render_report.h"
#include "watch_flags.h"

namespace radiant::cli {

struct RenderJob {
  RenderOptions options;
  std::string output;      // "-": standard output, in `format`
  std::string stats_path;  // "-": standard output
  std::string format = "png";  // the extension that names the format of `-o -`
  std::optional<uint64_t> max_memory_bytes;  // a batch render line's own --max-memory
  bool skip_existing = false;  // a shard already complete at `output` is not rendered again
  std::string shard_request_hash;  // of the command line, recorded in a shard (shard_request.h)
  std::string command_line;        // what asked for this render, recorded in the image
  bool write_metadata = true;      // --no-metadata: no record in the image, for identical bytes
  std::optional<FrameNote> frame;  // an animation frame, noted in the stats
  bool notes = true;  // say the framing camera, the mode and a missing light (once for --frames)
  // A batch line's moment of the scene's animation (--time, --frame): unset = the loaded scene.
  std::optional<double> animation_time;
  std::string animation;
  // --display-server and --serve: where each pass is shown, shared by the command's renders.
  Watchers watchers;
};

// A name whose extension names the image format: the output, or for `-o -` "-.FORMAT".
std::string image_format_name(const RenderJob& job);

// The job's outputs, named by their flags.
std::vector<NamedFile> render_job_outputs(const RenderJob& job);

// "scene.gltf: out of memory while rendering (...)": std::bad_alloc as one line naming the file and
// what was being done, and how --max-memory would have refused the work before it allocated.
std::string out_of_memory_message(const std::string& scene_path, const std::string& doing, const MemoryBudget& budget);

// What must hold before any work: -o names an image format (std::invalid_argument, a usage
// error, when not; it also loads the image writer) and every output can be created where it
// goes (std::runtime_error).
void check_render_job_outputs(const RenderJob& job);

// What a render prints before it starts, unless quiet: a framing camera, auto mode's choice
// and reason, and a scene that nothing lights (no light, emission or environment, flags included).
void print_render_notes(const std::string& scene_path, const PreparedScene& prepared, const ResolvedSettings& settings);

// Renders, writes the image (a shard file for --shard and --sample-range) and the stats and commits them together (neither replaces an
// existing file unless both were written), prints notes and the summary unless quiet. `times`
// carries the load time in and gets the rest filled. Throws on failure; std::invalid_argument
// means a bad setting (usage error). Moves `prepared` to the render origin of this view first
// (render/render_space.h).
void run_render_job(const std::string& scene_path, PreparedScene& prepared, const RenderJob& job, PhaseTimes& times);

}  // namespace radiant::cli
