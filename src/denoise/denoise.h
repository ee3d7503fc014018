// The feature-guided denoiser: from a linear image, its two half images, its variance and its
// first-hit features (denoise_input.h), a linear image with the noise removed. It runs before
// the view transform, after a render or a shard merge (docs/denoise.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "denoise/denoise_input.h"
#include "memory/memory_budget.h"

namespace radiant {

// The denoised colour, one per pixel of `in`. Runs on the calling task arena's threads and gives
// the same bits for any thread count. Its memory (and its input's) is charged by charge_denoise.
std::vector<color3> denoise(const DenoiseInput& in);

// Charges `budget` (none when null) for denoising a `width` x `height` image on the calling task
// arena's threads, its input included: call it before making the input. Throws MemoryLimitError
// naming `what` (the image) when the budget refuses.
MemoryCharge charge_denoise(MemoryBudget* budget, int width, int height, const std::string& what);

// The film's image denoised, charged to `budget` first (the film needs AOV sums and halves).
std::vector<color3> denoise_film(const Film& film, MemoryBudget* budget, const std::string& what);

// The bytes denoise() holds for a `width` x `height` image on `threads` threads, its input
// included.
uint64_t denoise_bytes(int width, int height, int threads);

}  // namespace radiant
