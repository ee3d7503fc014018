// The film's statistics and its adaptive-sampling mask: the numbers a serial pass over the
// pixels gives, the same on one thread and on four, and the film made on many threads empty.
#include <doctest/doctest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <random>

#include "film/film_stats.h"

using namespace radiant;

namespace {

// A film whose pixel i took 2 + i % 7 samples (10 000 pixels: several blocks), of noisy gray.
Film noisy_film() {
  Film film = make_film(125, 80);
  std::mt19937 random(3);
  std::uniform_real_distribution<float> value(0.0f, 2.0f);
  for (size_t i = 0; i < film.pixels.size(); ++i)
    for (size_t s = 0; s < 2 + i % 7; ++s) {
      float v = value(random);
      add_sample(film.pixels[i], {v, v, v});
    }
  return film;
}

}  // namespace

TEST_CASE("film: made on many threads, every pixel empty") {
  Film film;
  tbb::task_arena(4).execute([&] { film = make_film(300, 200, true, true); });
  REQUIRE(film.pixels.size() == 60000);
  REQUIRE(film.aovs.size() == 60000);
  REQUIRE(film.alpha.size() == 60000);
  size_t wrong = 0;
  for (size_t i = 0; i < film.pixels.size(); ++i)
    wrong += !(film.pixels[i].samples == 0 && film.pixels[i].sum[1] == ExactSum() && film.aovs[i].depth == ExactSum() &&
               film.alpha[i] == ExactSum() && pixel_mean(film.pixels[i]) == color3{0, 0, 0});
  CHECK(wrong == 0);
}

TEST_CASE("film statistics: a serial pass's counts and quantiles, and one error sum for any thread count") {
  Film film = noisy_film();
  std::vector<uint32_t> counts;
  uint64_t samples = 0;
  double error_sum = 0;
  for (const FilmPixel& p : film.pixels) {
    counts.push_back(p.samples), samples += p.samples;
    error_sum += pixel_relative_error(p);  // every pixel has two samples or more: all finite
  }
  std::sort(counts.begin(), counts.end());
  FilmSampleStats one, four;
  tbb::task_arena(1).execute([&] { one = film_sample_stats(film); });
  tbb::task_arena(4).execute([&] { four = film_sample_stats(film); });
  CHECK(one.samples == samples);
  CHECK(one.min_pixel_samples == 2);
  CHECK(one.max_pixel_samples == 8);
  CHECK(one.median_pixel_samples == counts[size_t(0.5 * double(counts.size() - 1))]);
  CHECK(one.p90_pixel_samples == counts[size_t(0.9 * double(counts.size() - 1))]);
  CHECK(one.mean_relative_error == doctest::Approx(error_sum / double(film.pixels.size())).epsilon(1e-6));
  CHECK(one.mean_relative_error > 0);
  CHECK(std::bit_cast<uint32_t>(one.mean_relative_error) == std::bit_cast<uint32_t>(four.mean_relative_error));
  CHECK(one.median_pixel_samples == four.median_pixel_samples);
  CHECK(one.p90_pixel_samples == four.p90_pixel_samples);
}

TEST_CASE("film statistics: equal sample counts give every quantile that count, and one sample no error") {
  Film film = make_film(40, 30);
  for (FilmPixel& p : film.pixels) add_sample(p, {1, 1, 1});
  FilmSampleStats stats = film_sample_stats(film);
  CHECK(stats.samples == 1200);
  CHECK(stats.min_pixel_samples == 1);
  CHECK(stats.median_pixel_samples == 1);
  CHECK(stats.p90_pixel_samples == 1);
  CHECK(stats.max_pixel_samples == 1);
  CHECK(stats.mean_relative_error == 0);
}

TEST_CASE("adaptive sampling's mask: the pixels above the threshold, counted") {
  Film film = noisy_film();
  float threshold = 0.3f;
  size_t expected = 0;
  for (const FilmPixel& p : film.pixels) expected += pixel_relative_error(p) > threshold;
  REQUIRE(expected > 0);
  REQUIRE(expected < film.pixels.size());
  std::vector<uint8_t> active = {7};
  size_t marked = 0;
  tbb::task_arena(4).execute([&] { marked = mark_unconverged_pixels(film, threshold, active); });
  CHECK(marked == expected);
  REQUIRE(active.size() == film.pixels.size());
  size_t wrong = 0;
  for (size_t i = 0; i < active.size(); ++i) wrong += active[i] != (pixel_relative_error(film.pixels[i]) > threshold);
  CHECK(wrong == 0);
}
