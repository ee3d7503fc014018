// Damaged glTF and GLB files: every one either loads or fails with LoadError; never a crash,
// a hang, or another exception type. Fixed seed, a few hundred cases each.
#include <doctest/doctest.h>


#include <cstdint>

#include "loaders/gltf_builder.h"
#include "load_scene.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// A small deterministic generator (the standard distributions differ between libraries).
struct Random {
  uint64_t state;
  uint32_t next() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return uint32_t(state >> 33);
  }
  size_t below(size_t n) { return n == 0 ? 0 : next() % n; }
};

std::string png_bytes(const ScratchDir& dir) {
  auto path = dir.file("t.png");
  write_texel_bytes(path, 2, 2, 3, {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255});
  return read_bytes(path);
}

// A file that uses most of the loader: two primitives, strides, sparse, texture, camera, light.
GltfBuilder rich_builder(const std::string& png, std::string& body) {
  GltfBuilder b = quad_builder();
  b.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
  b.floats({0, 0, 1, 0, 1, 1, 0, 1}, "VEC2", 2);
  int image_view = b.view(png);
  int sparse_indices = b.view(GltfBuilder::bytes_of(std::vector<uint16_t>{1}));
  int sparse_values = b.view(GltfBuilder::bytes_of(std::vector<float>{2, 0, 0}));
  b.accessor(0, 5126, 4, "VEC3", ",\"sparse\":{\"count\":1,\"indices\":{\"bufferView\":" +
                                    std::to_string(sparse_indices) + ",\"componentType\":5123},\"values\":{"
                                    "\"bufferView\":" + std::to_string(sparse_values) + "}}");
  body = "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":2,\"TEXCOORD_0\":3},\"indices\":1,"
         "\"material\":0},{\"attributes\":{\"POSITION\":4},\"mode\":6}]}],"
         "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}},\"normalTexture\":{\"index\":0},"
         "\"emissiveFactor\":[1,1,1]}],"
         "\"textures\":[{\"source\":0,\"sampler\":0}],\"samplers\":[{\"magFilter\":9728}],"
         "\"images\":[{\"bufferView\":" + std::to_string(image_view) + ",\"mimeType\":\"image/png\"}],"
         "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.7,\"znear\":0.1}}],"
         "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[{\"type\":\"spot\",\"intensity\":5,\"spot\":{\"outerConeAngle\":0.5}}]}},"
         "\"nodes\":[{\"mesh\":0,\"children\":[1,2]},{\"camera\":0,\"translation\":[0,0,5]},"
         "{\"matrix\":[-1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],\"mesh\":0,"
         "\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}}],"
         "\"scene\":0,\"scenes\":[{\"nodes\":[0]}]";
  return b;
}

const char* replacements[] = {"0", "1", "-1", "2", "3", "7", "255", "65536", "4294967295", "-2147483649",
                              "1e308", "1e39", "2.5", "-0", "18446744073709551615", "99999999999999999999"};
const char* type_names[] = {"\"SCALAR\"", "\"VEC2\"", "\"VEC3\"", "\"VEC4\"", "\"MAT4\"", "\"BAD\"", "5", "null"};

// One damage: truncate, flip bytes, change a number, a type name, or a bracket.
std::string mutate(const std::string& original, Random& random, bool binary) {
  std::string text = original;
  switch (random.below(binary ? 4 : 5)) {
    case 0: text.resize(random.below(text.size())); break;
    case 1:
      for (int flips = 1 + int(random.below(4)); flips > 0; --flips)
        text[random.below(text.size())] ^= char(1 << random.below(8));
      break;
    case 2: {
      std::vector<size_t> numbers;
      for (size_t i = 0; i < text.size(); ++i)
        if (std::isdigit((unsigned char)text[i]) && (i == 0 || !std::isalnum((unsigned char)text[i - 1])) &&
            (i == 0 || text[i - 1] != '.'))
          numbers.push_back(i);
      if (numbers.empty()) break;
      size_t start = numbers[random.below(numbers.size())], end = start;
      while (end < text.size() && (std::isdigit((unsigned char)text[end]) || text[end] == '.')) ++end;
      std::string with = replacements[random.below(std::size(replacements))];
      if (binary) with.resize(std::min(with.size(), end - start), ' ');  // keep the GLB chunk lengths
      if (binary) with.append(end - start - with.size(), ' ');
      text.replace(start, end - start, with);
      break;
    }
    case 3: {
      size_t at = text.find("\"VEC", random.below(text.size()));
      if (at == std::string::npos) at = text.find("\"SCALAR\"");
      if (at == std::string::npos) break;
      size_t end = text.find('"', at + 1) + 1;
      std::string with = type_names[random.below(std::size(type_names))];
      if (binary) with.resize(end - at, ' ');
      text.replace(at, end - at, with);
      break;
    }
    default: {
      size_t at = text.find_first_of("[]{}", random.below(text.size()));
      if (at != std::string::npos) text[at] = "[]{},"[random.below(5)];
    }
  }
  return text;
}

// Loads every mutation in-process; counts the outcomes.
void survive_mutations(const std::string& original, const std::string& name, uint64_t seed, int cases) {
  ScratchDir dir("gltf-mutation");
  LoadOptions options;
  options.max_memory_bytes = size_t(64) << 20;  // keeps refused giants cheap
  Random random{seed};
  int loaded = 0, refused = 0;
  for (int i = 0; i < cases; ++i) {
    std::string path = dir.write(name, mutate(original, random, name.ends_with(".glb"))).string();
    try {
      load_scene(path, options);
      ++loaded;
    } catch (const LoadError& error) {
      CHECK(std::string(error.what()).find('\n') == std::string::npos);
      ++refused;
    } catch (const std::exception& error) {
      FAIL("case " << i << ": unexpected exception " << error.what());
    }
  }
  CHECK(loaded + refused == cases);
  CHECK(loaded > 0);
  CHECK(refused > cases / 4);
}

}  // namespace

TEST_CASE("gltf mutation: damaged .gltf files load or fail with LoadError") {
  ScratchDir dir("gltf-mutation-source");
  std::string body;
  GltfBuilder b = rich_builder(png_bytes(dir), body);
  std::string original = b.gltf(body);
  REQUIRE(load_scene(dir.write("ok.gltf", original).string()).meshes.size() == 4);  // 2 + 2 mirrored
  survive_mutations(original, "m.gltf", 12345, 400);
}

TEST_CASE("gltf mutation: damaged .glb files load or fail with LoadError") {
  ScratchDir dir("gltf-mutation-source");
  std::string body;
  GltfBuilder b = rich_builder(png_bytes(dir), body);
  std::string original = b.glb(body);
  REQUIRE(load_scene(dir.write("ok.glb", original).string()).cameras.size() == 1);
  survive_mutations(original, "m.glb", 67890, 400);
}
