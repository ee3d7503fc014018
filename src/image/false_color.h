// False-color images of a per-pixel magnitude, for looking at where two images differ.
#pragma once

#include <string>
#include <vector>

#include "math/vec.h"

namespace radiant {

// The black→red→yellow→white ramp at t in [0,1] (clamped; NaN maps to white): brightness grows
// with t, so the largest errors stand out even in grayscale print.
color3 false_color(float t);

// Writes `magnitude` (width×height, row-major) as an RGB false-color image with `top` mapping to
// white, to `path` (any OIIO format, by extension) through a temporary file in the same folder
// renamed into place, so a failed write leaves nothing behind. Throws CompareError.
void write_false_color(const std::string& path, const std::vector<float>& magnitude, int width,
                       int height, float top);

}  // namespace radiant
