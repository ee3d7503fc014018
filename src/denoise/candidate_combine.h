// How the denoiser picks among its candidate filters per pixel (the error-driven selection of
// NFOR): each candidate's error is estimated from its two filtered halves, the estimates are
// smoothed, each pixel takes the candidate of least error, and the choices are smoothed so that
// neighbouring pixels blend rather than switch.
#pragma once

#include <vector>

#include "denoise/denoise_input.h"
#include "denoise/regression.h"

namespace radiant {

// Each candidate's estimated squared error at each pixel, relative to the pixel's brightness: the
// variance its halves' difference shows, plus the squared bias its distance from the unfiltered
// image shows beyond the noise of that image, both averaged over 7x7 pixels.
std::vector<std::vector<float>> candidate_errors(const DenoiseInput& in, const std::vector<CandidateImages>& candidates);

// The denoised image: at each pixel the candidates' means (of both halves) blended by the
// 5x5-smoothed choice of the least error.
std::vector<color3> combine_candidates(const DenoiseInput& in, const std::vector<CandidateImages>& candidates,
                                       const std::vector<std::vector<float>>& errors);

}  // namespace radiant
