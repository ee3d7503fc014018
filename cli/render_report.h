// What `render` tells the user afterwards: the one-line summary and the --stats JSON file.
#pragma once

#include <string>

#include "image/render_metadata.h"
#include "render/render.h"

namespace radiant::cli {

struct PhaseTimes {
  double load = 0, build = 0, render = 0, write = 0;
  double denoise = 0;  // --denoise's step, between the render and the write
};

// A frame of an animation (--frame, --frames): its number, how many times the command has read
// and parsed the scene file by then (1 for every frame of --frames: the file is read once), and
// whether its accelerator was built or updated from the previous frame's (render/prepare_frame.h).
struct FrameNote {
  long long frame = 0;
  int scene_reads = 0;
  bool accelerator_updated = false;
};

// "wrote out.png: 800x800, 81 spp (jittered), whitted, 12.3 s, 4.56 M rays/s"
std::string render_summary(const std::string& output, const RenderResult& result, const PhaseTimes& times);
// The --stats JSON document.
// With `frame`, it names the frame and counts the reads of the scene file.
std::string render_stats_json(const std::string& scene_path, const std::string& output, const RenderResult& result,
                              const PhaseTimes& times, const FrameNote* frame = nullptr);
// What the image of this render records about it (image/render_metadata.h): `command_line`
// made it from `scene_path` with `seed`.
RenderRecord render_record(const std::string& scene_path, const std::string& command_line, uint32_t seed,
                           const RenderResult& result);
// Why the image holds fewer samples than asked ("time limit reached at 51 of 100000 samples per
// pixel", "interrupted by SIGINT at 8 of 256 samples per pixel"), or "" for a complete render.
std::string partial_reason(const RenderResult& result);
// Peak resident memory of this process in bytes.
size_t peak_memory_bytes();

}  // namespace radiant::cli
