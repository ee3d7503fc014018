// Mip-map pyramids of the scene's textures: each image halved again and again down to 1x1,
// box-filtered in linear values, so that a lookup can read the level whose texels match a
// pixel's footprint (docs/materials.md, "Texture filtering").
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "memory/memory_budget.h"
#include "scene/scene_desc.h"

namespace radiant {

// One level below full resolution: linear texel values (sRGB decoded for a colour use).
struct MipLevel {
  int width = 0, height = 0, channels = 0;
  std::vector<float> texels;  // `channels` per texel, rows from the top
};

// Levels 1, 2, ... of one image read one way; level 0 is the ImageDesc itself.
struct ImagePyramid {
  std::vector<MipLevel> levels;
};

struct TexturePyramids {
  // Indexed by image * 2 + (1 when an 8-bit image is read as sRGB colour): the decoding comes
  // before the averaging, so the two uses of one image average differently.
  std::vector<ImagePyramid> by_use;
  MemoryCharge memory;
  // The pyramid of `image` read with `srgb`, or nullptr when the scene never reads it so.
  const ImagePyramid* find(int image, bool srgb) const;
};

// The bytes build_texture_pyramids allocates for `scene` (every image some material slot reads).
uint64_t texture_pyramid_bytes(const SceneDesc& scene);

// Builds the pyramid of every image a material slot reads, charging `budget` (may be null) for
// all of them first; throws MemoryLimitError when it refuses.
TexturePyramids build_texture_pyramids(const SceneDesc& scene, MemoryBudget* budget);

// Whether the pyramids built for `built_for` are those of `scene` too: the same images, bit for
// bit, read the same ways (an animation's next frame, whose textures do not change).
bool pyramids_serve(const SceneDesc& built_for, const SceneDesc& scene);

// The 256 sRGB-encoded byte values decoded to linear once (IEC 61966-2-1 curve).
const std::array<float, 256>& srgb_to_linear_table();

// Channel `c` of texel (x, y) of `image` as a linear value (8-bit colour through the sRGB curve
// when `srgb`, alpha never); the decoding every lookup of level 0 uses.
float texel_value(const ImageDesc& image, int x, int y, int c, bool srgb);

// The sizes below `width` x `height`: each halved (rounded down, at least 1) until 1x1.
std::vector<std::pair<int, int>> mip_level_sizes(int width, int height);

// Level 1 of `image` read with `srgb`, then each next level from the one before: every texel the
// area-weighted mean of the texels it covers (the mean of a 2x2 block for even sizes).
ImagePyramid build_image_pyramid(const ImageDesc& image, bool srgb);

// The level a footprint calls for: log2 of the longer of the footprint's two axes in texels of
// level 0 (OpenGL's rho), 0 when it is at most one texel, at most `max_level`. `duv_dx` and
// `duv_dy` are the change of uv across one pixel in x and in y.
float mip_level_for(vec2 duv_dx, vec2 duv_dy, int width, int height, int max_level);

}  // namespace radiant
