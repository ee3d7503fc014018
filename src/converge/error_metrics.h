// How far a render is from a reference: RMSE, relative MSE, PSNR and the error at edges, built
// on the image comparison library (docs/accuracy.md gives every formula).
#pragma once

#include <cstdint>
#include <vector>

#include "film/film.h"
#include "image/compare.h"

namespace radiant {

struct ErrorMetrics {
  double rmse = 0;          // root mean squared error over pixels × RGB (compute_metrics)
  double relative_mse = 0;  // mean over pixels × RGB of (a−b)² / (b² + 0.01)
  double psnr = 0;          // 20·log10(1 / rmse), peak value 1
  double edge_rmse = 0;     // RMSE over the edge pixels only (0 without an edge mask)
};

// Linear colours, one per pixel of a `width` x `height` image, as a comparable image; `srgb`
// encodes them (clamped to [0,1]) to compare against an 8-bit reference, which reads back
// sRGB-encoded.
CompareImage colors_to_compare_image(const std::vector<color3>& colors, int width, int height, bool srgb);

// The film's mean radiance as colors_to_compare_image makes it.
CompareImage film_to_compare_image(const Film& film, bool srgb);

// Mean over values of (a−b)² / (b² + 0.01), `b` being the reference (Rousselle et al. 2011,
// Mitsuba's relMSE): the 0.01 keeps dark pixels from dominating.
double relative_mse(const CompareImage& image, const CompareImage& reference);

// Pixels where the reference has edges: the `fraction` of pixels with the largest Sobel
// gradient magnitude of luminance (ties at the cut included). 1 marks an edge pixel.
std::vector<uint8_t> edge_mask(const CompareImage& reference, double fraction);

// RMSE over the values of the pixels the mask marks (0 when it marks none).
double masked_rmse(const CompareImage& image, const CompareImage& reference, const std::vector<uint8_t>& mask);

// Every metric of `image` against `reference`; `edges` may be empty (edge_rmse stays 0).
// Throws CompareError when the sizes differ.
ErrorMetrics measure_error(const CompareImage& image, const CompareImage& reference, const std::vector<uint8_t>& edges);

}  // namespace radiant
