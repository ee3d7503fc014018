// One render of a prepared scene to an image file, shared by `render` and `batch`.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "render/render.h"
#include "render_report.h"

namespace radiant::cli {

struct RenderJob {
  RenderOptions options;
  std::string output;
  std::string stats_path;
  std::optional<uint64_t> max_memory_bytes;  // a batch render line's own --max-memory
};

// Renders, writes the image (atomically) and the stats, prints notes and the summary unless
// quiet. `times` carries the load time in and gets the rest filled. Throws on failure;
// std::invalid_argument means a bad setting (usage error).
void run_render_job(const std::string& scene_path, const PreparedScene& prepared, const RenderJob& job, PhaseTimes& times);

// "scene.gltf: out of memory while rendering (...)": std::bad_alloc as one line naming the file and
// what was being done, and how --max-memory would have refused the work before it allocated.
std::string out_of_memory_message(const std::string& scene_path, const std::string& doing, const MemoryBudget& budget);

// Writes `text` to `path` through a temporary file and a rename.
void write_text_file_atomically(const std::string& path, const std::string& text);

}  // namespace radiant::cli
