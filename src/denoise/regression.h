// The denoiser's candidate filters (after Bitterli et al. 2016, "Nonlinearly Weighted First-order
// Regression for Denoising Monte Carlo Renderings"): at each pixel, a weighted least-squares fit
// of colour as an affine function of the features over a window of neighbours, read at the
// pixel's own features. The weights are NL-means weights on the colour (Rousselle et al. 2012),
// each candidate with its own bandwidth: a small one trusts the colour and keeps what the
// features miss (shadow edges), a large one leans on the features and removes more noise.
#pragma once

#include <cstdint>
#include <vector>

#include "denoise/denoise_input.h"
#include "denoise/feature_prefilter.h"

namespace radiant {

constexpr int denoise_window_radius = 5;  // neighbours within 5 pixels each way: an 11x11 window
constexpr int denoise_patch_radius = 1;   // NL-means compares 3x3 patches
constexpr int denoise_tile_size = 16;     // the regression works on 16x16 tiles, one per task

// One candidate's result: the even and the odd half image, each fitted on its own samples (the
// weights, from the whole image, are shared), so that their difference shows the noise the
// candidate leaves.
struct CandidateImages {
  std::vector<color3> even, odd;
};

// The candidates of `bandwidths` (NL-means k, at least 0.5), fitted on `in`'s halves with `variance` (the
// variance of the whole image's mean, smoothed) for the weights. Tile-parallel on the calling
// task arena's threads; every pixel's result depends on its neighbours only, never on the
// tiling or thread count.
std::vector<CandidateImages> regress_candidates(const DenoiseInput& in, const std::vector<color3>& variance,
                                                const DenoiseFeatures& features, const std::vector<float>& bandwidths);

// Bytes one task's workspace takes for `candidates` candidates.
uint64_t regression_workspace_bytes(int candidates);

}  // namespace radiant
