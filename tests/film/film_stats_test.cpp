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

TEST_CASE("adaptive sampling's mask: the pixels above the threshold and their neighbours, counted") {
  Film film = noisy_film();
  float threshold = 0.3f;
  auto above = [&](int x, int y) { return pixel_relative_error(film.at(x, y)) > threshold; };
  size_t expected_own = 0, expected_active = 0;
  std::vector<uint8_t> expected(film.pixels.size());
  for (int y = 0; y < film.height; ++y)
    for (int x = 0; x < film.width; ++x) {
      expected_own += above(x, y);
      bool any = false;
      for (int ny = y - 1; ny <= y + 1; ++ny)
        for (int nx = x - 1; nx <= x + 1; ++nx)
          any |= nx >= 0 && ny >= 0 && nx < film.width && ny < film.height && above(nx, ny);
      expected[size_t(y) * film.width + x] = any;
      expected_active += any;
    }
  REQUIRE(expected_own > 0);
  REQUIRE(expected_active < film.pixels.size());
  CHECK(expected_active > expected_own);
  std::vector<uint8_t> own = {7}, active = {7};
  size_t marked = 0;
  tbb::task_arena(4).execute([&] { marked = mark_unconverged_pixels(film, threshold, own, active); });
  CHECK(marked == expected_active);
  REQUIRE(active.size() == film.pixels.size());
  REQUIRE(own.size() == film.pixels.size());
  size_t wrong = 0;
  for (size_t i = 0; i < active.size(); ++i) wrong += active[i] != expected[i] || own[i] != (pixel_relative_error(film.pixels[i]) > threshold);
  CHECK(wrong == 0);
}

TEST_CASE("adaptive sampling's mask: a pixel whose samples all missed the light stays active among noisy neighbours") {
  // 3x3 pixels of 8 samples: the centre's are all black (zero variance, zero error), the rest
  // alternate 0 and 1 (relative error 0.38).
  Film film = make_film(3, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x)
      for (int s = 0; s < 8; ++s) {
        float v = x == 1 && y == 1 ? 0.0f : float(s % 2);
        add_sample(film.at(x, y), {v, v, v});
      }
  REQUIRE(pixel_relative_error(film.at(1, 1)) == 0);
  std::vector<uint8_t> own, active;
  CHECK(mark_unconverged_pixels(film, 0.05f, own, active) == 9);
  CHECK(own[4] == 0);
  CHECK(active[4] == 1);
}
