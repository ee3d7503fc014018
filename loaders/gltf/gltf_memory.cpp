#include "gltf/gltf_memory.h"

#include <tiny_gltf.h>

#include <utility>

#include "memory/memory_budget.h"

namespace radiant {

namespace {

constexpr uint64_t bytes_per_json_value = 256;  // measured: 190 for numbers, 283 for one-member objects
constexpr uint64_t struct_overhead = 2;         // measured: a Material of 2144 bytes costs 3.8 KB

// sizeof the struct tinygltf makes of each element of a counted array.
const std::pair<const char*, uint64_t> element_sizes[] = {
    {"accessors", sizeof(tinygltf::Accessor)},
    {"animations", sizeof(tinygltf::Animation)},
    {"animations.channels", sizeof(tinygltf::AnimationChannel)},
    {"animations.samplers", sizeof(tinygltf::AnimationSampler)},
    {"buffers", sizeof(tinygltf::Buffer)},
    {"bufferViews", sizeof(tinygltf::BufferView)},
    {"cameras", sizeof(tinygltf::Camera)},
    {"extensions.KHR_lights_punctual.lights", sizeof(tinygltf::Light)},
    {"images", sizeof(tinygltf::Image)},
    {"materials", sizeof(tinygltf::Material)},
    {"meshes", sizeof(tinygltf::Mesh)},
    {"meshes.primitives", sizeof(tinygltf::Primitive)},
    {"nodes", sizeof(tinygltf::Node)},
    {"samplers", sizeof(tinygltf::Sampler)},
    {"scenes", sizeof(tinygltf::Scene)},
    {"skins", sizeof(tinygltf::Skin)},
    {"textures", sizeof(tinygltf::Texture)},
};

}  // namespace

uint64_t gltf_model_bytes(const GltfJsonCounts& counts, uint64_t json_bytes) {
  uint64_t bytes = saturating_add(saturating_multiply(counts.values, bytes_per_json_value),
                                  saturating_multiply(json_bytes, 2));
  for (const auto& [path, size] : element_sizes) {
    auto count = counts.elements.find(path);
    if (count != counts.elements.end())
      bytes = saturating_add(bytes, saturating_multiply(count->second, struct_overhead * size));
  }
  return bytes;
}

uint64_t gltf_image_decode_bytes(int width, int height, int bytes_per_channel) {
  constexpr uint64_t copies = 4;  // stb's planes, stb's output, tinygltf's image, radiant's texels
  uint64_t pixels = saturating_multiply(uint64_t(width), uint64_t(height));
  return saturating_multiply(pixels, copies * 4 * uint64_t(bytes_per_channel));
}

}  // namespace radiant
