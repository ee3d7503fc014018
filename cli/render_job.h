// One render of a prepared scene to an image file, shared by `render` and `batch`.
#pragma once

#include <string>

#include "render/render.h"
#include "render_report.h"

namespace radiant::cli {

struct RenderJob {
  RenderOptions options;
  std::string output;
  std::string stats_path;
};

// Renders, writes the image (atomically) and the stats, prints notes and the summary unless
// quiet. `times` carries the load time in and gets the rest filled. Throws on failure;
// std::invalid_argument means a bad setting (usage error). Moves `prepared` to the render origin
// of this view first (render/render_space.h).
void run_render_job(const std::string& scene_path, PreparedScene& prepared, const RenderJob& job, PhaseTimes& times);

// Writes `text` to `path` through a temporary file and a rename.
void write_text_file_atomically(const std::string& path, const std::string& text);

}  // namespace radiant::cli
