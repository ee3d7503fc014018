// Pixel reconstruction filters by filter importance sampling, as pbrt-v4 does: a pixel's samples
// are placed by the filter's own distribution instead of being splatted into the neighbours, so
// every pixel stays a sum over its own samples (tiles, sample ranges and shards merge exactly).
//
// Box and triangle are sampled exactly (weight 1). Gaussian, Mitchell and Blackman-Harris are
// tabulated as pbrt-v4's FilterSampler does, 32 cells per pixel of radius, |f| at each cell's
// centre as a piecewise-constant density; they are separable, so the 2D table is the product of
// one 1D table per axis, sampled axis by axis. A sample's weight is f / pdf, normalised so that
// its mean is 1: exactly 1 for every filter but Mitchell, whose weights are ±1 / (1 - 2m) per
// axis (m its negative lobes' share of the integral of |f|), negative in those lobes. One
// magnitude per filter is what lets the film keep pbrt-v4's weighted mean sum(w L) / sum(w) as
// sum(±L) / (samples - 2 negative samples) (src/film/film.h).
#pragma once

#include <string>
#include <vector>

#include "math/vec.h"
#include "sampling/distribution.h"
#include "scene/scene_desc.h"

namespace radiant {

// A filter ready to sample: its kind, radius (pixels) and, when tabulated, the 1D table of each
// axis with each cell's weight.
struct PixelFilter {
  PixelFilterKind kind = PixelFilterKind::box;
  float radius = 0.5f;
  Distribution1D table;             // |f| over [-radius, radius] (gaussian, mitchell, blackman-harris)
  std::vector<float> cell_weights;  // each cell's f / pdf, normalised
};

// Where a sample lies in its pixel, from the pixel's top-left corner ((0.5, 0.5) is its centre,
// and a filter wider than the box reaches into the neighbours), and its weight.
struct FilterSample {
  vec2 position;
  float weight = 1;
};

// pbrt-v4's default radius of each filter (box 0.5, triangle 2, gaussian 1.5, mitchell 2) and
// Blackman-Harris's 2 (Sunflow's; Cycles' default of 1.5 pixels is --filter-width 3).
float default_filter_radius(PixelFilterKind kind);
// The filter of `kind` with `radius` in (0, max_filter_width / 2], tabulated when it needs to be.
PixelFilter make_pixel_filter(PixelFilterKind kind, float radius);

// The continuous 1D filter (unnormalised) at offset x from the pixel centre: the 2D filter is
// eval_filter_1d(x) * eval_filter_1d(y). Gaussian sigma 0.5, Mitchell B = C = 1/3 (pbrt-v4).
float eval_filter_1d(PixelFilterKind kind, float radius, float x);

// The sample for the pixel-sample pair `u` in [0, 1)^2; box of radius 0.5 returns `u` itself.
FilterSample sample_filter(const PixelFilter& filter, vec2 u);
// The density of sample_filter's position along one axis at offset x from the pixel centre.
float sample_filter_pdf_1d(const PixelFilter& filter, float x);

// "box", "triangle", "gaussian", "mitchell", "blackman-harris"; parse throws
// std::invalid_argument naming the choices.
const char* pixel_filter_name(PixelFilterKind kind);
PixelFilterKind parse_pixel_filter(const std::string& name);

}  // namespace radiant
