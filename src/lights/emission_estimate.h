// How bright an emissive triangle is where its emission texture lets it glow, for choosing
// lights by their power (lights/light_table.cpp): a mesh whose texture lights only some of its
// triangles (a screen, a facade's windows, a sign) should spend its light samples on those.
#pragma once

#include <cstdint>
#include <vector>

#include "math/vec.h"
#include "memory/memory_budget.h"
#include "scene/scene_desc.h"

namespace radiant {

// The most cells per axis of an emission texture's table: a texel box is rounded out to whole
// cells, so finer cells estimate small triangles better and cost memory (about 1.6 MB a texture).
constexpr int max_emission_cells = 256;

// Summed-area tables of the scene's emission textures, over a grid of cells.
class EmissionEstimates {
 public:
  // Charges `budget` (may be null) for the tables before building them; throws
  // MemoryLimitError when it refuses.
  EmissionEstimates(const SceneDesc& scene, MemoryBudget* budget);

  // The luminance of `material`'s mean emitted radiance over a triangle whose texture
  // coordinates (in the emission texture's set, as the mesh stores them) are `uv`. The mean is
  // taken over every texel a lookup anywhere on the triangle can read: the texel box around its
  // coordinates, widened by what bilinear filtering reaches and rounded out to whole cells. So
  // it is zero only when all of those texels are black: a triangle that can emit is never left
  // out. The luminance of the emission itself for an untextured material.
  float triangle_luminance(const MaterialDesc& material, const vec2 uv[3]) const;

  struct ImageSums {
    int width = 0, height = 0, cells_x = 0, cells_y = 0;
    std::vector<double> sums;  // (cells_y + 1) x (cells_x + 1) x 3: the sums above-left of each corner
  };

 private:
  const SceneDesc* scene_;
  std::vector<int> sums_of_image_;  // index into images_, or -1 for an image no emission reads
  std::vector<ImageSums> images_;
  MemoryCharge memory_;
};

// The bytes EmissionEstimates allocates for `scene`: three channels of sums per image that
// some emissive material reads as its emission texture, and what building them needs.
uint64_t emission_estimate_bytes(const SceneDesc& scene);

}  // namespace radiant
