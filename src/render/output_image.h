// The film as an output image: its channels (colour, alpha, AOVs) and what making it costs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "film/film.h"
#include "image/image_writer.h"
#include "memory/memory_budget.h"

namespace radiant {

// An AOV --aov can name, and the channels it adds to the image after R, G, B (and A).
struct AovLayout {
  const char* name;
  const char* channels[6];  // the first `channel_count`
  int channel_count;
};
inline constexpr AovLayout aov_layouts[] = {
    {"albedo", {"albedo.R", "albedo.G", "albedo.B"}, 3},
    {"normal", {"N.X", "N.Y", "N.Z"}, 3},
    {"depth", {"Z"}, 1},
    {"variance", {"variance.R", "variance.G", "variance.B"}, 3},
    {"spp", {"spp"}, 1},
    {"noisy", {"noisy.R", "noisy.G", "noisy.B"}, 3},
    {"halves", {"even.R", "even.G", "even.B", "odd.R", "odd.G", "odd.B"}, 6},
};
// The AOV named `name`, or null.
inline const AovLayout* find_aov(const std::string& name) {
  for (const AovLayout& aov : aov_layouts)
    if (name == aov.name) return &aov;
  return nullptr;
}

// What a render of `width` x `height` pixels with `channels` output channels allocates per
// image: the film (with AOV sums when `with_aovs`, coverage sums when `with_alpha`), the sample
// counts and activity masks, the output image and its 8-bit conversion for PNG.
uint64_t render_image_bytes(int width, int height, size_t channels, bool with_aovs, bool with_alpha,
                            bool with_halves = false);

// Whether `aovs` names `name`.
bool wants_aov(const std::vector<std::string>& aovs, const std::string& name);

// The channels film_to_image makes: R, G, B, A when `with_alpha`, then those of each AOV
// ("albedo.R", "N.X", "Z", "noisy.R", "even.R" ... "odd.B", ...).
std::vector<std::string> output_channel_names(const std::vector<std::string>& aovs, bool with_alpha);

// The film as an image with the requested AOV channels (a cropped render's film is the window).
// A film with coverage sums gives an A channel: R, G, B are then associated (premultiplied) by
// it already, the background having added nothing.
OutputImage film_to_image(const Film& film, const std::vector<std::string>& aovs);

}  // namespace radiant
