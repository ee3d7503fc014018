// False-color images of a per-pixel magnitude, for looking at where two images differ.
#pragma once

#include <string>
#include <vector>

#include "math/vec.h"
#include "output/temporary_file.h"

namespace radiant {

// The black→red→yellow→white ramp at t in [0,1] (clamped; NaN maps to white): brightness grows
// with t, so the largest errors stand out even in grayscale print.
color3 false_color(float t);

// Writes `magnitude` (width×height, row-major) as an RGB false-color image with `top` mapping to
// white, to `file` (any format radiant writes, by its target's extension: half float in EXR,
// else 8 bits). Throws std::runtime_error naming the target.
void write_false_color(TemporaryFile& file, const std::vector<float>& magnitude, int width, int height,
                       float top);

}  // namespace radiant
