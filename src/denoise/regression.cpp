#include "denoise/regression.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>

#include "math/lane_isa.h"

namespace radiant {

namespace {

constexpr int unknowns = 1 + denoise_feature_count;               // intercept and one slope a feature
constexpr int normal_terms = unknowns * (unknowns + 1) / 2;       // the symmetric matrix's upper half
constexpr int right_terms = unknowns * 3;                         // per half: each unknown x R, G, B
constexpr int tile_pixels = denoise_tile_size * denoise_tile_size;
constexpr int margin_side = denoise_tile_size + 2 * denoise_patch_radius;
// A slope costs this fraction of the window's weight times its square: features that barely vary
// in a window (a flat albedo) get no slope fitted to the colour's noise.
constexpr double ridge = 1e-4;
// NL-means distances are cut here: the weight e^-20 is nothing beside the pixel's own 1, and the
// cut keeps exp_negative's argument within its range for bandwidths down to 0.5.
constexpr float farthest_patch_distance = 20;
constexpr float smallest_bandwidth = 0.5f;

constexpr int halo_reach = denoise_window_radius + denoise_patch_radius;
constexpr int halo_side = denoise_tile_size + 2 * halo_reach;  // the pixels a tile's fits read
constexpr int halo_pixels = halo_side * halo_side;
// The planes of the halo: colour and its variance (for the weights), the halves, the features.
constexpr int halo_planes = 12 + denoise_feature_count;

// Sums of one task's tile, one plane per term, pixels innermost (the loops over pixels vectorise).
struct Workspace {
  std::vector<float> normal;       // candidates x normal_terms x tile_pixels
  std::vector<float> even, odd;    // candidates x right_terms x tile_pixels
  std::vector<float> halo;         // halo_planes x halo_pixels: the image around the tile, edges clamped
  std::vector<float> patch_terms;  // margin_side^2: the NL-means term of each pixel around the tile
  std::vector<float> distance, inside;  // tile_pixels each
  std::vector<float> x;            // unknowns x tile_pixels: 1 and the feature differences
  std::vector<float> weighted_x;   // unknowns x tile_pixels: x times one candidate's weight
  std::vector<float> y_even, y_odd;  // 3 x tile_pixels: the neighbour's colour in each half
};

int clamp_index(int v, int size) { return std::clamp(v, 0, size - 1); }

// exp(-x) for 0 <= x <= 87, to about 2e-5 relative, in plain arithmetic without branches that
// vectorises (the library's exp was a third of the denoiser's time) and gives the same bits
// everywhere.
[[gnu::always_inline]] inline float exp_negative(float x) {
  float y = -x * 1.44269504f;  // exp(-x) = 2^y, y >= -125.6
  int whole = int(y);                              // toward zero: y - whole is in (-1, 0]
  float z = (y - float(whole)) * 0.693147181f;     // 2^(y - whole) = e^z, z in (-0.7, 0]
  float e = 1 + z * (1 + z * (0.5f + z * (1.0f / 6 + z * (1.0f / 24 + z * (1.0f / 120 + z * (1.0f / 720))))));
  return e * std::bit_cast<float>(uint32_t(whole + 127) << 23);
}

// Solves the candidate's normal equations at one pixel for both halves and keeps the
// intercepts: the fitted colour at the pixel's own features. Only the intercept is wanted, so one
// solve, A u = e0, serves every right side: the intercept is u . b. A window whose fit is
// singular (all weight on one pixel) gives its weighted mean.
void solve_pixel(const float* normal, const float* even, const float* odd, int stride, color3& even_out,
                 color3& odd_out) {
  double a[unknowns][unknowns];
  for (int r = 0, t = 0; r < unknowns; ++r)
    for (int c = r; c < unknowns; ++c, ++t) a[r][c] = a[c][r] = normal[t * stride];
  double weight = a[0][0];
  for (int r = 1; r < unknowns; ++r) a[r][r] += ridge * weight;
  // Cholesky: a = L L^T, L kept in a's lower half.
  bool singular = !(weight > 0);
  for (int j = 0; j < unknowns && !singular; ++j) {
    double d = a[j][j];
    for (int k = 0; k < j; ++k) d -= a[j][k] * a[j][k];
    if (!(d > 1e-12 * weight)) {
      singular = true;
      break;
    }
    a[j][j] = std::sqrt(d);
    for (int i = j + 1; i < unknowns; ++i) {
      double s = a[i][j];
      for (int k = 0; k < j; ++k) s -= a[i][k] * a[j][k];
      a[i][j] = s / a[j][j];
    }
  }
  double u[unknowns] = {};
  if (!singular) {
    double z[unknowns];
    for (int i = 0; i < unknowns; ++i) {
      double v = i == 0 ? 1.0 : 0.0;
      for (int k = 0; k < i; ++k) v -= a[i][k] * z[k];
      z[i] = v / a[i][i];
    }
    for (int i = unknowns - 1; i >= 0; --i) {
      double v = z[i];
      for (int k = i + 1; k < unknowns; ++k) v -= a[k][i] * u[k];
      u[i] = v / a[i][i];
    }
  } else if (weight > 0) {
    u[0] = 1 / weight;  // the weighted mean: the intercept alone
  }
  const float* rights[2] = {even, odd};
  color3* outs[2] = {&even_out, &odd_out};
  for (int h = 0; h < 2; ++h)
    for (int c = 0; c < 3; ++c) {
      double v = 0;
      for (int i = 0; i < unknowns; ++i) v += u[i] * rights[h][(i * 3 + c) * stride];
      (*outs[h])[c] = float(v);
    }
}

// The weighted products of one offset's neighbours added to a tile's sums: x x^T and x y for both
// halves, one plane per term, pixels innermost, weighted by the NL-means weights of `distance`
// at bandwidth 1 / sqrt(inverse_k2) (x's first plane is 1). Without fused multiply-adds either
// way, so the AVX2 copy gives the baseline's bits (math/lane_isa.h).
[[gnu::always_inline]] inline void add_products_body(const float* distance, const float* inside, float inverse_k2,
                                                     const float* x, const float* y_even, const float* y_odd,
                                                     float* weighted_x, float* normal, float* even, float* odd) {
  for (int t = 0; t < tile_pixels; ++t) weighted_x[t] = inside[t] * exp_negative(distance[t] * inverse_k2);
  for (int a = 1; a < unknowns; ++a)
    for (int t = 0; t < tile_pixels; ++t) weighted_x[a * tile_pixels + t] = weighted_x[t] * x[a * tile_pixels + t];
  for (int a = 0, term = 0; a < unknowns; ++a) {
    const float* wxa = &weighted_x[a * tile_pixels];
    for (int b = a; b < unknowns; ++b, ++term) {
      const float* xb = &x[b * tile_pixels];
      float* sum = normal + term * tile_pixels;
      for (int t = 0; t < tile_pixels; ++t) sum[t] += wxa[t] * xb[t];
    }
    for (int c = 0; c < 3; ++c) {
      const float* ye = &y_even[c * tile_pixels];
      const float* yo = &y_odd[c * tile_pixels];
      float* sum_even = even + (a * 3 + c) * tile_pixels;
      float* sum_odd = odd + (a * 3 + c) * tile_pixels;
      for (int t = 0; t < tile_pixels; ++t) {
        sum_even[t] += wxa[t] * ye[t];
        sum_odd[t] += wxa[t] * yo[t];
      }
    }
  }
}

void add_products(const float* distance, const float* inside, float inverse_k2, const float* x, const float* y_even,
                  const float* y_odd, float* weighted_x, float* normal, float* even, float* odd) {
  add_products_body(distance, inside, inverse_k2, x, y_even, y_odd, weighted_x, normal, even, odd);
}

__attribute__((target("avx2"))) void add_products_avx2(const float* distance, const float* inside, float inverse_k2,
                                                       const float* x, const float* y_even, const float* y_odd,
                                                       float* weighted_x, float* normal, float* even, float* odd) {
  add_products_body(distance, inside, inverse_k2, x, y_even, y_odd, weighted_x, normal, even, odd);
}

struct TileRegression {
  const DenoiseInput& in;
  const std::vector<color3>& variance;
  const DenoiseFeatures& features;
  const std::vector<float>& bandwidths;
  std::vector<CandidateImages>& out;

  // Copies the image around the tile into the halo planes, coordinates clamped to the image.
  void fill_halo(Workspace& w, int x0, int y0) const {
    for (int hy = 0; hy < halo_side; ++hy)
      for (int hx = 0; hx < halo_side; ++hx) {
        size_t i = size_t(clamp_index(y0 - halo_reach + hy, in.height)) * in.width +
                   clamp_index(x0 - halo_reach + hx, in.width);
        float* h = &w.halo[hy * halo_side + hx];
        for (int c = 0; c < 3; ++c) {
          h[c * halo_pixels] = in.color[i][c];
          h[(3 + c) * halo_pixels] = variance[i][c];
          h[(6 + c) * halo_pixels] = in.even[i][c];
          h[(9 + c) * halo_pixels] = in.odd[i][c];
        }
        for (int k = 0; k < denoise_feature_count; ++k) h[(12 + k) * halo_pixels] = features.planes[k][i];
      }
  }

  // Rousselle et al.'s per-pixel NL-means term of each pixel around the tile and its neighbour
  // at (dx, dy): the squared colour difference less what noise alone explains, over their
  // variances. A patch's mean of it is the NL-means distance.
  void patch_terms(Workspace& w, int dx, int dy, int tw, int th) const {
    constexpr int pr = denoise_patch_radius, r = denoise_window_radius;
    const float* halo = w.halo.data();
    for (int my = 0; my < th + 2 * pr; ++my) {
      const float* p = halo + (my + r) * halo_side + r;
      const float* q = p + dy * halo_side + dx;
      float* out = &w.patch_terms[my * margin_side];
      for (int mx = 0; mx < tw + 2 * pr; ++mx) out[mx] = 0;
      for (int c = 0; c < 3; ++c) {
        const float *up = p + c * halo_pixels, *uq = q + c * halo_pixels;
        const float *vp = p + (3 + c) * halo_pixels, *vq = q + (3 + c) * halo_pixels;
        for (int mx = 0; mx < tw + 2 * pr; ++mx) {
          float d = up[mx] - uq[mx];
          out[mx] += (d * d - (vp[mx] + std::min(vp[mx], vq[mx]))) / (1e-10f + vp[mx] + vq[mx]) * (1.0f / 3);
        }
      }
    }
  }

  void run(Workspace& w, int x0, int y0) const {
    int width = in.width, height = in.height;
    int tw = std::min(denoise_tile_size, width - x0), th = std::min(denoise_tile_size, height - y0);
    int candidates = int(bandwidths.size());
    std::fill(w.normal.begin(), w.normal.end(), 0.0f);
    std::fill(w.even.begin(), w.even.end(), 0.0f);
    std::fill(w.odd.begin(), w.odd.end(), 0.0f);
    fill_halo(w, x0, y0);
    constexpr int r = denoise_window_radius, pr = denoise_patch_radius;
    constexpr float patch_area = (2 * pr + 1) * (2 * pr + 1);
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        patch_terms(w, dx, dy, tw, th);
        for (int ty = 0; ty < th; ++ty) {
          int ny = y0 + ty + dy;
          bool row_inside = ny >= 0 && ny < height;
          const float* p = w.halo.data() + (ty + halo_reach) * halo_side + halo_reach;
          const float* q = p + dy * halo_side + dx;
          int t0 = ty * denoise_tile_size;
          for (int tx = 0; tx < tw; ++tx) {
            float sum = 0;
            for (int py = 0; py <= 2 * pr; ++py)
              for (int px = 0; px <= 2 * pr; ++px) sum += w.patch_terms[(ty + py) * margin_side + tx + px];
            w.distance[t0 + tx] = std::clamp(sum * (1 / patch_area), 0.0f, farthest_patch_distance);
            int nx = x0 + tx + dx;
            w.inside[t0 + tx] = row_inside && nx >= 0 && nx < width ? 1.0f : 0.0f;
            w.x[t0 + tx] = 1;
          }
          for (int k = 0; k < denoise_feature_count; ++k) {
            const float *fp = p + (12 + k) * halo_pixels, *fq = q + (12 + k) * halo_pixels;
            float* dk = &w.x[(1 + k) * tile_pixels + t0];
            for (int tx = 0; tx < tw; ++tx) dk[tx] = fq[tx] - fp[tx];
          }
          for (int c = 0; c < 3; ++c)
            for (int tx = 0; tx < tw; ++tx) {
              w.y_even[c * tile_pixels + t0 + tx] = q[(6 + c) * halo_pixels + tx];
              w.y_odd[c * tile_pixels + t0 + tx] = q[(9 + c) * halo_pixels + tx];
            }
        }
        for (int cand = 0; cand < candidates; ++cand) accumulate(w, cand);
      }
    for (int cand = 0; cand < candidates; ++cand)
      for (int ty = 0; ty < th; ++ty)
        for (int tx = 0; tx < tw; ++tx) {
          int t = ty * denoise_tile_size + tx;
          size_t p = size_t(y0 + ty) * width + x0 + tx;
          solve_pixel(&w.normal[size_t(cand) * normal_terms * tile_pixels + t],
                      &w.even[size_t(cand) * right_terms * tile_pixels + t],
                      &w.odd[size_t(cand) * right_terms * tile_pixels + t], tile_pixels, out[cand].even[p],
                      out[cand].odd[p]);
        }
  }

  // Adds this offset's neighbours, weighted for candidate `cand`, to its normal equations.
  void accumulate(Workspace& w, int cand) const {
    float bandwidth = std::max(bandwidths[cand], smallest_bandwidth);
    float inverse_k2 = 1 / (bandwidth * bandwidth);
    float* normal = &w.normal[size_t(cand) * normal_terms * tile_pixels];
    float* even = &w.even[size_t(cand) * right_terms * tile_pixels];
    float* odd = &w.odd[size_t(cand) * right_terms * tile_pixels];
    if (resolve_lane_isa(LaneIsa::best) == LaneIsa::avx2)
      add_products_avx2(w.distance.data(), w.inside.data(), inverse_k2, w.x.data(), w.y_even.data(), w.y_odd.data(),
                        w.weighted_x.data(), normal, even, odd);
    else
      add_products(w.distance.data(), w.inside.data(), inverse_k2, w.x.data(), w.y_even.data(), w.y_odd.data(),
                   w.weighted_x.data(), normal, even, odd);
  }
};

}  // namespace

uint64_t regression_workspace_bytes(int candidates) {
  return sizeof(float) * (uint64_t(candidates) * (normal_terms + 2 * right_terms) * tile_pixels +
                          halo_planes * halo_pixels + margin_side * margin_side + (2 + 2 * unknowns + 6) * tile_pixels);
}

std::vector<CandidateImages> regress_candidates(const DenoiseInput& in, const std::vector<color3>& variance,
                                                const DenoiseFeatures& features, const std::vector<float>& bandwidths) {
  size_t count = size_t(in.width) * in.height;
  std::vector<CandidateImages> out(bandwidths.size());
  for (CandidateImages& c : out) c.even.resize(count), c.odd.resize(count);
  size_t candidates = bandwidths.size();
  tbb::enumerable_thread_specific<Workspace> workspaces([&] {
    Workspace w;
    w.normal.resize(candidates * normal_terms * tile_pixels);
    w.even.resize(candidates * right_terms * tile_pixels);
    w.odd.resize(candidates * right_terms * tile_pixels);
    w.halo.resize(size_t(halo_planes) * halo_pixels);
    w.patch_terms.resize(margin_side * margin_side);
    w.distance.resize(tile_pixels, 0.0f), w.inside.resize(tile_pixels, 0.0f);
    w.x.resize(unknowns * tile_pixels, 0.0f), w.weighted_x.resize(unknowns * tile_pixels, 0.0f);
    w.y_even.resize(3 * tile_pixels, 0.0f), w.y_odd.resize(3 * tile_pixels, 0.0f);
    return w;
  });
  TileRegression regression{in, variance, features, bandwidths, out};
  int tiles_x = (in.width + denoise_tile_size - 1) / denoise_tile_size;
  int tiles_y = (in.height + denoise_tile_size - 1) / denoise_tile_size;
  tbb::parallel_for(0, tiles_x * tiles_y, [&](int tile) {
    regression.run(workspaces.local(), (tile % tiles_x) * denoise_tile_size, (tile / tiles_x) * denoise_tile_size);
  });
  return out;
}

}  // namespace radiant
