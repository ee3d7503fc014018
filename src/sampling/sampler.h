// Sample values as pure functions of (pixel, sample index, dimension, seed): the image never
// depends on thread count or tile order.
#pragma once

#include <cstdint>

#include "math/lane_isa.h"
#include "math/vec.h"
#include "scene/scene_desc.h"

namespace radiant {

// What identifies one sample of one pixel.
struct SampleContext {
  SamplerKind kind = SamplerKind::jittered;
  uint32_t pixel = 0;         // y * width + x
  uint32_t index = 0;         // sample index within the pixel
  uint32_t samples = 1;       // samples per pixel of the whole render (grid/jittered strata)
  uint32_t seed = 0;
};

// Position inside the pixel, in [0,1)^2. grid: cell centres; jittered: one random point per
// cell; random: independent; sobol: shuffled Owen-scrambled Sobol, the pair of dimension 0
// (sample_2d's, and draw_sobol_lanes' for dimension 0). One sample shoots through the centre for
// grid and jittered.
vec2 sample_pixel(const SampleContext& context);

// Whether a render of [0, A) samples can be extended later by [A, B) of a larger total: the
// sample positions of sobol and random do not depend on the total spp, those of grid and jittered
// (their strata) do.
constexpr bool sampler_extends(SamplerKind kind) { return kind == SamplerKind::sobol || kind == SamplerKind::random; }

// Grid and jittered pixel positions of `count` pixels at one sample index, drawn across SIMD
// lanes (math/lane_isa.h): (x[i], y[i]) is sample_pixel({kind, pixel[i], index, samples, seed})
// to the bit. `kind` is grid or jittered.
void draw_stratified_pixels(SamplerKind kind, uint32_t samples, uint32_t index, uint32_t seed, const uint32_t* pixel,
                            int count, float* x, float* y, LaneIsa isa = LaneIsa::best);

// The lens point of a thin-lens camera: a fixed pair far above every path vertex's block
// (integrators/path.cpp), so that a lens shifts no other random number.
constexpr uint32_t lens_dimension = 0xF0000000u;
// The time within the shutter of a camera ray (motion blur), beside the lens pair.
constexpr uint32_t time_dimension = 0xF0000002u;

// A camera ray's time in [0, 1) across the shutter, drawn from time_dimension and stratified
// over the pixel's samples: Sobol's own 1D points; for grid and jittered, one stratum of
// 1/samples per sample index in a per-pixel random order (grid at the strata's centres).
float sample_time(const SampleContext& context);

// A 1D / 2D value for `dimension` (>= 2; dimensions 0 and 1 are the pixel position). Sobol
// pads pairs of dimensions with independently shuffled and scrambled (0, 1) Sobol dimensions;
// the other samplers use independent random values.
float sample_1d(const SampleContext& context, uint32_t dimension);
vec2 sample_2d(const SampleContext& context, uint32_t dimension);

// Many pairs drawn at once, laid out one array per field so that the draw runs across them in
// SIMD (math/lane_isa.h): fill the first `count` lanes' inputs, call draw_sample_lanes, read x
// and y. Lane i's (x, y) is sample_2d({kind, pixel[i], index[i], _, seed[i]}, dimension[i]) to
// the bit (a 1D value is the pair's x, as sample_1d's), for every sampler: Sobol's shuffled
// and scrambled points, or the other samplers' hashes.
struct SampleLanes {
  static constexpr int capacity = 1280;
  alignas(32) uint32_t pixel[capacity], index[capacity], dimension[capacity], seed[capacity];
  alignas(32) float x[capacity], y[capacity];
  int count = 0;

  void add(const SampleContext& c, uint32_t d) {
    pixel[count] = c.pixel, index[count] = c.index, dimension[count] = d, seed[count] = c.seed;
    ++count;
  }
};
void draw_sample_lanes(SamplerKind kind, SampleLanes& lanes, LaneIsa isa = LaneIsa::best);

}  // namespace radiant
