// The .scene loader on damaged input: every outcome is a scene or one LoadError naming a place.
#include <doctest/doctest.h>

#include <random>
#include <sstream>

#include "load_scene.h"
#include "loaders/scene_format_test_support.h"
#include "support/test_support.h"

using namespace radiant;

// The words of `text` split on whitespace, newlines kept as their own words.
static std::vector<std::string> words_of(const std::string& text) {
  std::vector<std::string> words;
  std::string word;
  for (char c : text) {
    if (c == ' ' || c == '\n') {
      if (!word.empty()) words.push_back(word);
      if (c == '\n') words.push_back("\n");
      word.clear();
    } else {
      word += c;
    }
  }
  if (!word.empty()) words.push_back(word);
  return words;
}

TEST_CASE("damaged copies of the showcase load or fail with file:line:col, never anything else") {
  std::string original = test::read_bytes(test::source_path("assets/showcase.scene"));
  std::vector<std::string> words = words_of(original);
  const std::vector<std::string> junk = {"@sphere", "@light", "nan", "-1", "0", "1e39", "#", "@", "kd", "\n", "x"};
  std::mt19937 random(12345);
  int loaded = 0, failed = 0;
  for (int attempt = 0; attempt < 300; ++attempt) {
    std::vector<std::string> damaged = words;
    for (int edit = 0; edit < 3; ++edit) {
      size_t at = random() % damaged.size();
      switch (random() % 3) {
        case 0: damaged.erase(damaged.begin() + long(at)); break;
        case 1: damaged.insert(damaged.begin() + long(at), junk[random() % junk.size()]); break;
        default: damaged[at] = junk[random() % junk.size()]; break;
      }
    }
    std::string text;
    for (const std::string& word : damaged) text += word == "\n" ? "\n" : word + " ";
    std::string message = test::scene_text_error(text);
    if (message == "(loaded)") {
      ++loaded;
    } else {
      ++failed;
      CAPTURE(text);
      CHECK(message.rfind("t.scene:", 0) == 0);
      CHECK(message.find('\n') == std::string::npos);
    }
  }
  CHECK(failed > 100);  // the damage is real: most copies are rejected
}

TEST_CASE("load_scene routes .scene files to this loader and records the source path") {
  std::string path = test::source_path("assets/first-render.scene").string();
  SceneDesc scene = load_scene(path);
  CHECK(scene.source_path == path);
  CHECK(scene.name == "first render");
  CHECK(scene.shapes.size() == 1);
}
