// How an image was made, recorded in the file itself (PNG text chunks, EXR header attributes),
// so that a CI artefact says which radiant, command, scene and settings made it. The keys PNG
// defines are used where they fit (Software, Comment); the rest are radiant's own (docs/cli.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "image/image_io_module.h"

namespace radiant {

struct RenderRecord {
  std::string version;       // radiant's ("Software": "radiant VERSION")
  std::string command_line;  // the command that made the image ("Comment")
  std::string scene;         // the scene file as given
  std::string mode;          // the integrator that ran (auto resolved)
  std::string sampler;
  uint32_t spp = 0, seed = 0;
  double render_seconds = 0;  // rendering only: loading, building and writing are not included
  uint64_t rays = 0;          // every ray traced, of any kind
  bool denoised = false;      // the colour went through the denoiser ("radiant:denoised")
  bool operator==(const RenderRecord&) const = default;
};

// The record as file attributes, rays per second included (rays / render_seconds).
ImageMetadata render_metadata(const RenderRecord& record);

// The record in a file's attributes; nullopt when they hold none (no "Software" naming radiant:
// a foreign image, or one written with --no-metadata). Throws std::runtime_error naming the
// attribute that is missing or malformed.
std::optional<RenderRecord> parse_render_metadata(const ImageMetadata& metadata);

// One record for several that made one image together (the shards of a merge): the first one's
// settings, the render times and rays summed.
RenderRecord combined_record(const std::vector<RenderRecord>& records);

// The attributes of `metadata` that radiant wrote: "Software" when it names radiant, "Comment"
// beside it, and every "radiant:" one. Empty for a foreign image.
ImageMetadata radiant_attributes(const ImageMetadata& metadata);

// Appends each attribute of `extra` whose name `metadata` does not hold yet.
void add_missing_attributes(ImageMetadata& metadata, const ImageMetadata& extra);

// The value of attribute `name`, or nullopt.
std::optional<std::string> find_attribute(const ImageMetadata& metadata, const std::string& name);

}  // namespace radiant
