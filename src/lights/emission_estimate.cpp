#include "lights/emission_estimate.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "materials/surface.h"
#include "materials/texture_pyramid.h"

namespace radiant {

namespace {

// The image a material's emission reads, or nullptr when it is untextured (sample_texture then
// returns white: the emission itself).
const ImageDesc* emission_image(const SceneDesc& scene, const MaterialDesc& m) {
  const TextureRef& ref = m.emission_texture;
  if (is_black(m.emission) || !ref.valid() || ref.texcoord < 0 || ref.texcoord > 1) return nullptr;
  return texture_image(scene, ref);
}

int cells_along(int size) { return std::min(size, max_emission_cells); }

// An inclusive range of texels, or of cells, along one axis.
struct AxisRange {
  int lo, hi;
};

// The texels along one axis that lookups at coordinates in [a, b] can read (nearest: the texel
// holding x = coordinate * size; bilinear: the two whose centres surround x, so x +- 1/2), as one
// or two ranges. Returns their number. A little slack covers the float rounding of x in the
// lookup and of the coordinates interpolated across the triangle; a whole texel more would
// reach into the neighbouring cells of a texture atlas.
int axis_texels(float a, float b, int size, TextureWrap wrap, AxisRange out[2]) {
  out[0] = {0, size - 1};
  // Coordinates the lookup reduces to nonsense (reduce_coordinate) may read any texel.
  if (!std::isfinite(a) || !std::isfinite(b) || std::abs(a) > 1e6f || std::abs(b) > 1e6f) return 1;
  if (wrap == TextureWrap::clamp_to_edge) a = std::clamp(a, -1.0f, 2.0f), b = std::clamp(b, -1.0f, 2.0f);
  double x0 = double(a) * size - 0.5, x1 = double(b) * size + 0.5;
  double slack = 0.01 + 1e-6 * std::max(std::abs(x0), std::abs(x1));
  int64_t lo = int64_t(std::floor(x0 - slack)), hi = int64_t(std::floor(x1 + slack));
  if (hi - lo + 1 >= size) return 1;
  if (wrap == TextureWrap::clamp_to_edge) {  // within [-size - 1, 2 * size + 1]: an int
    out[0] = {wrap_index(int(lo), size, wrap), wrap_index(int(hi), size, wrap)};
    return 1;
  }
  // Shifted by whole periods of both repeating modes (2 * size) to start in [0, 2 * size).
  int64_t period = 2 * int64_t(size), shift = (lo >= 0 ? lo / period : -((-lo + period - 1) / period)) * period;
  int l = int(lo - shift), h = int(hi - shift);
  int wrapped_l = wrap_index(l, size, wrap), wrapped_h = wrap_index(h, size, wrap);
  if (l / size == h / size) {  // no edge of the image inside
    out[0] = {std::min(wrapped_l, wrapped_h), std::max(wrapped_l, wrapped_h)};
    return 1;
  }
  if (wrap == TextureWrap::repeat) {
    out[0] = {wrapped_l, size - 1}, out[1] = {0, wrapped_h};
    return 2;
  }
  // Mirrored: both sides of the edge fold back onto the same border texel.
  int border = wrap_index(h / size * size, size, wrap);
  out[0] = {std::min({wrapped_l, wrapped_h, border}), std::max({wrapped_l, wrapped_h, border})};
  return 1;
}

// The cells holding a texel range (cell c holds the texels t with t * cells / size == c).
AxisRange cells_of(AxisRange texels, int size, int cells) {
  return {int(int64_t(texels.lo) * cells / size), int(int64_t(texels.hi) * cells / size)};
}
// The first texel of cell c (c == cells: one past the last texel).
int64_t first_texel(int c, int size, int cells) { return (int64_t(c) * size + cells - 1) / cells; }

// Up to two cell ranges of one axis, merged when they meet (coarse cells at both image edges).
int axis_cells(const AxisRange texels[2], int ranges, int size, int cells, AxisRange out[2]) {
  for (int k = 0; k < ranges; ++k) out[k] = cells_of(texels[k], size, cells);
  if (ranges == 2 && out[1].hi >= out[0].lo) {
    out[0] = {0, cells - 1};
    return 1;
  }
  return ranges;
}

}  // namespace

uint64_t emission_estimate_bytes(const SceneDesc& scene) {
  std::vector<char> counted(scene.images.size(), 0);
  uint64_t bytes = 0, widest = 0;
  for (const MaterialDesc& m : scene.materials) {
    const ImageDesc* image = emission_image(scene, m);
    if (!image) continue;
    size_t index = size_t(image - scene.images.data());
    if (counted[index]) continue;
    counted[index] = 1;
    bytes += uint64_t(cells_along(image->width) + 1) * uint64_t(cells_along(image->height) + 1) * 3 * sizeof(double) +
             sizeof(EmissionEstimates::ImageSums);
    widest = std::max(widest, uint64_t(image->width));
  }
  // The image-to-table index and the column-to-cell map of the widest image, while building.
  if (bytes > 0) bytes += scene.images.size() * sizeof(int) + widest * sizeof(size_t);
  return bytes;
}

EmissionEstimates::EmissionEstimates(const SceneDesc& scene, MemoryBudget* budget)
    : scene_(&scene), sums_of_image_(scene.images.size(), -1) {
  memory_ = MemoryCharge(budget, emission_estimate_bytes(scene),
                         scene.source_path + ": the emission textures' light estimates");
  for (const MaterialDesc& m : scene.materials) {
    const ImageDesc* image = emission_image(scene, m);
    if (!image) continue;
    int& slot = sums_of_image_[size_t(image - scene.images.data())];
    if (slot >= 0) continue;
    slot = int(images_.size());
    ImageSums& table = images_.emplace_back();
    table.width = image->width, table.height = image->height;
    table.cells_x = cells_along(image->width), table.cells_y = cells_along(image->height);
    size_t row = size_t(table.cells_x + 1) * 3;
    table.sums.assign(row * size_t(table.cells_y + 1), 0.0);
    // Each cell's sum, stored at its lower-right corner; then the prefix sums in place. Texels
    // are read as texel_value reads them (8-bit ones as sRGB colour), a row at a time.
    std::vector<size_t> cell_of_column(size_t(image->width));
    for (int x = 0; x < image->width; ++x)
      cell_of_column[size_t(x)] = size_t(int64_t(x) * table.cells_x / image->width + 1) * 3;
    const std::array<float, 256>& srgb = srgb_to_linear_table();
    size_t channels = size_t(image->channels), step[3] = {0, channels < 3 ? 0u : 1u, channels < 3 ? 0u : 2u};
    for (int y = 0; y < image->height; ++y) {
      double* corner_row = &table.sums[size_t(int64_t(y) * table.cells_y / image->height + 1) * row];
      size_t first = size_t(y) * size_t(image->width) * channels;
      for (int x = 0; x < image->width; ++x) {
        double* cell = corner_row + cell_of_column[size_t(x)];
        size_t texel = first + size_t(x) * channels;
        for (int c = 0; c < 3; ++c) {
          float v = image->texels8.empty() ? image->texels_float[texel + step[c]] : srgb[image->texels8[texel + step[c]]];
          // Negative or NaN texels emit nothing; an infinite one stays finite here.
          cell[c] += v > 0 ? std::min(double(v), 1e30) : 0.0;
        }
      }
    }
    for (int cy = 1; cy <= table.cells_y; ++cy)
      for (int cx = 1; cx <= table.cells_x; ++cx)
        for (int c = 0; c < 3; ++c)
          table.sums[cy * row + cx * 3 + c] += table.sums[(cy - 1) * row + cx * 3 + c] +
                                               table.sums[cy * row + (cx - 1) * 3 + c] -
                                               table.sums[(cy - 1) * row + (cx - 1) * 3 + c];
  }
}

float EmissionEstimates::triangle_luminance(const MaterialDesc& material, const vec2 uv[3]) const {
  const ImageDesc* image = emission_image(*scene_, material);
  if (!image) return luminance(material.emission);
  const ImageSums& table = images_[size_t(sums_of_image_[size_t(image - scene_->images.data())])];
  const TextureRef& ref = material.emission_texture;
  const TextureDesc& texture = scene_->textures[size_t(ref.texture)];
  vec2 t[3] = {transform_uv(ref, uv[0]), transform_uv(ref, uv[1]), transform_uv(ref, uv[2])};
  // The coordinates' range along one axis; a NaN among them is passed on (min and max drop it).
  auto range = [](float a, float b, float c, float& lowest, float& highest) {
    bool finite = std::isfinite(a) && std::isfinite(b) && std::isfinite(c);
    lowest = finite ? std::min({a, b, c}) : std::nanf("");
    highest = finite ? std::max({a, b, c}) : std::nanf("");
  };
  float x0, x1, y0, y1;
  range(t[0].x, t[1].x, t[2].x, x0, x1);
  range(t[0].y, t[1].y, t[2].y, y0, y1);
  AxisRange texels_x[2], texels_y[2], cells_x[2], cells_y[2];
  int nx = axis_texels(x0, x1, table.width, texture.wrap_s, texels_x);
  int ny = axis_texels(y0, y1, table.height, texture.wrap_t, texels_y);
  nx = axis_cells(texels_x, nx, table.width, table.cells_x, cells_x);
  ny = axis_cells(texels_y, ny, table.height, table.cells_y, cells_y);
  size_t row = size_t(table.cells_x + 1) * 3;
  double sum[3] = {0, 0, 0}, texels = 0;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      AxisRange x = cells_x[i], y = cells_y[j];
      for (int c = 0; c < 3; ++c)
        sum[c] += table.sums[size_t(y.hi + 1) * row + size_t(x.hi + 1) * 3 + c] -
                  table.sums[size_t(y.lo) * row + size_t(x.hi + 1) * 3 + c] -
                  table.sums[size_t(y.hi + 1) * row + size_t(x.lo) * 3 + c] +
                  table.sums[size_t(y.lo) * row + size_t(x.lo) * 3 + c];
      texels += double(first_texel(x.hi + 1, table.width, table.cells_x) - first_texel(x.lo, table.width, table.cells_x)) *
                double(first_texel(y.hi + 1, table.height, table.cells_y) - first_texel(y.lo, table.height, table.cells_y));
    }
  // Prefix sums subtract: a box of black cells may come out a rounding error below zero.
  color3 mean = {float(std::max(sum[0], 0.0) / texels), float(std::max(sum[1], 0.0) / texels),
                 float(std::max(sum[2], 0.0) / texels)};
  return luminance(material.emission * mean);
}

}  // namespace radiant
