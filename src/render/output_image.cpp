#include "render/output_image.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace radiant {

bool wants_aov(const std::vector<std::string>& aovs, const std::string& name) {
  return std::find(aovs.begin(), aovs.end(), name) != aovs.end();
}

uint64_t render_image_bytes(int width, int height, size_t channels, bool with_aovs, bool with_alpha, bool with_halves) {
  // A film pixel (with its AOV, coverage and half-image sums when kept), a sample count and two
  // activity bytes (adaptive sampling's verdict on the pixel and on its neighbourhood); the
  // output image's floats; for 8-bit formats three more floats a pixel (four with alpha) and
  // three bytes a channel: the PNG encoder's filtered rows, its compressed pieces and the file
  // they make (deflate's output exceeds its input by a fraction of a percent at most, which the
  // pixel's other bytes cover).
  uint64_t display_channels = with_alpha ? 4 : 3;
  uint64_t per_pixel = film_pixel_bytes(with_aovs, with_alpha, with_halves) + sizeof(uint32_t) + 2 + channels * sizeof(float) +
                       display_channels * (sizeof(float) + 3);
  return saturating_multiply(uint64_t(std::max(width, 0)) * uint64_t(std::max(height, 0)), per_pixel);
}

std::vector<std::string> output_channel_names(const std::vector<std::string>& aovs, bool with_alpha) {
  std::vector<std::string> channels = {"R", "G", "B"};
  if (with_alpha) channels.push_back("A");
  for (const std::string& name : aovs)
    if (const AovLayout* aov = find_aov(name)) channels.insert(channels.end(), aov->channels, aov->channels + aov->channel_count);
  return channels;
}

OutputImage film_to_image(const Film& film, const std::vector<std::string>& aovs) {
  OutputImage image;
  image.width = film.width;
  image.height = film.height;
  image.x = film.x, image.y = film.y;
  image.full_width = film.full_width, image.full_height = film.full_height;
  bool with_alpha = !film.alpha.empty();
  image.channels = output_channel_names(aovs, with_alpha);
  size_t stride = image.channels.size();
  image.pixels.resize(size_t(film.width) * film.height * stride);
  // Each pixel's exact sums resolved on every thread: a large image's resolve would otherwise be
  // a serial tail after the render.
  tbb::parallel_for(size_t(0), film.pixels.size(), [&](size_t i) {
    const FilmPixel& p = film.pixels[i];
    float* out = &image.pixels[i * stride];
    color3 mean = pixel_mean(p);
    *out++ = mean.x, *out++ = mean.y, *out++ = mean.z;
    if (with_alpha) *out++ = pixel_alpha(film, i);
    static const FilmAovs no_aovs;  // a film made without AOV sums gives black AOVs
    const FilmAovs& a = film.aovs.empty() ? no_aovs : film.aovs[i];
    for (const std::string& aov : aovs) {
      if (aov == "albedo") {
        color3 albedo = pixel_albedo(p, a);
        *out++ = albedo.x, *out++ = albedo.y, *out++ = albedo.z;
      } else if (aov == "normal") {
        vec3 normal = pixel_normal(a);
        *out++ = normal.x, *out++ = normal.y, *out++ = normal.z;
      } else if (aov == "depth") *out++ = pixel_depth(p, a);
      else if (aov == "variance") {
        color3 v = pixel_mean_variance(p);
        *out++ = v.x, *out++ = v.y, *out++ = v.z;
      } else if (aov == "spp") *out++ = float(p.samples);
      else if (aov == "noisy") *out++ = mean.x, *out++ = mean.y, *out++ = mean.z;
      else if (aov == "halves") {
        color3 even = mean, odd = mean;  // a film without halves: both are the whole pixel
        if (!film.odd_half.empty()) pixel_half_means(p, film.odd_half[i], even, odd);
        for (int k = 0; k < 3; ++k) *out++ = even[k];
        for (int k = 0; k < 3; ++k) *out++ = odd[k];
      }
    }
  });
  return image;
}

}  // namespace radiant
