// EXT_meshopt_compression: bufferViews encoded with meshoptimizer's own encoder load to exactly
// the values of the uncompressed file, in every mode and filter.
#include <doctest/doctest.h>

#include <meshoptimizer.h>

#include <cmath>

#include "load_scene.h"
#include "loaders/gltf_builder.h"
#include "support/load_errors.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// A bumpy 4 x 4 grid of quads as the streams a glTF holds: float positions, octahedral-encoded
// 16-bit normals (the OCTAHEDRAL filter's input), exponent-encoded texcoords (EXPONENTIAL's),
// 32 triangles.
struct GridStreams {
  static constexpr size_t points = 25;
  std::vector<float> positions;
  std::vector<int16_t> normals;   // 4 per point, stride 8
  std::vector<uint32_t> texcoords;  // 2 per point, stride 8
  std::vector<uint32_t> indices;
};

GridStreams grid_streams() {
  GridStreams g;
  std::vector<float> normals, texcoords;
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) {
      g.positions.insert(g.positions.end(), {float(i), float(j), 0.25f * float((i * j) % 3)});
      float x = 0.1f * float(i), y = 0.1f * float(j), length = std::sqrt(x * x + y * y + 1);
      normals.insert(normals.end(), {x / length, y / length, 1 / length, 0});
      texcoords.insert(texcoords.end(), {float(i) / 3, float(j) / 7});
    }
  g.normals.resize(GridStreams::points * 4);
  meshopt_encodeFilterOct(g.normals.data(), GridStreams::points, 8, 16, normals.data());
  g.texcoords.resize(GridStreams::points * 2);
  meshopt_encodeFilterExp(g.texcoords.data(), GridStreams::points, 8, 15, texcoords.data());
  for (uint32_t i = 0; i < 4; ++i)
    for (uint32_t j = 0; j < 4; ++j) {
      uint32_t a = i * 5 + j, b = a + 5;
      g.indices.insert(g.indices.end(), {a, b, b + 1, a, b + 1, a + 1});
    }
  return g;
}

template <typename T>
std::string bytes_of(const std::vector<T>& values) {
  return GltfBuilder::bytes_of(values);
}

// `encoded` after the decoder's filter, as the uncompressed file stores it.
std::string filtered(std::string encoded, const std::string& filter, size_t count, size_t stride) {
  if (filter == "OCTAHEDRAL") meshopt_decodeFilterOct(encoded.data(), count, stride);
  if (filter == "QUATERNION") meshopt_decodeFilterQuat(encoded.data(), count, stride);
  if (filter == "EXPONENTIAL") meshopt_decodeFilterExp(encoded.data(), count, stride);
  return encoded;
}

// How the glTF files of a test are written: compressed or not, and how.
struct Encoding {
  bool compressed = true;
  std::string index_mode = "TRIANGLES";  // or INDICES
  size_t truncate = 0;                   // bytes cut from the end of the position stream
  uint64_t position_count = 0;           // a declared count other than the real one (0 = real)
};

// Adds `raw` (`count` elements of `stride` bytes) as a bufferView: plain over buffer 0, or
// meshopt-encoded in buffer 0 with its uncompressed layout in the fallback buffer 1.
int add_view(GltfBuilder& b, uint64_t& fallback_bytes, const std::string& raw, size_t count, size_t stride,
             const std::string& mode, const std::string& filter, const Encoding& e, bool with_stride,
             uint64_t declared_count = 0) {
  if (!e.compressed) return b.view(filter == "NONE" ? raw : filtered(raw, filter, count, stride), with_stride ? int(stride) : 0);
  std::vector<unsigned char> encoded;
  if (mode == "ATTRIBUTES") {
    encoded.resize(meshopt_encodeVertexBufferBound(count, stride));
    encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), raw.data(), count, stride));
  } else {
    std::vector<uint32_t> indices(count);
    for (size_t i = 0; i < count; ++i)
      indices[i] = stride == 2 ? reinterpret_cast<const uint16_t*>(raw.data())[i] : reinterpret_cast<const uint32_t*>(raw.data())[i];
    encoded.resize(mode == "TRIANGLES" ? meshopt_encodeIndexBufferBound(count, GridStreams::points)
                                       : meshopt_encodeIndexSequenceBound(count, GridStreams::points));
    encoded.resize(mode == "TRIANGLES" ? meshopt_encodeIndexBuffer(encoded.data(), encoded.size(), indices.data(), count)
                                       : meshopt_encodeIndexSequence(encoded.data(), encoded.size(), indices.data(), count));
  }
  REQUIRE(!encoded.empty());
  std::string bytes(encoded.begin(), encoded.end());
  if (mode == "ATTRIBUTES" && e.truncate) bytes.resize(bytes.size() - e.truncate);
  int view = b.view(bytes);
  size_t at = b.bin.size() - bytes.size();
  uint64_t elements = declared_count ? declared_count : count;
  b.views[size_t(view)] = "{\"buffer\":1,\"byteOffset\":" + std::to_string(fallback_bytes) +
                          ",\"byteLength\":" + std::to_string(elements * stride) +
                          (with_stride ? ",\"byteStride\":" + std::to_string(stride) : "") +
                          ",\"extensions\":{\"EXT_meshopt_compression\":{\"buffer\":0,\"byteOffset\":" +
                          std::to_string(at) + ",\"byteLength\":" + std::to_string(bytes.size()) +
                          ",\"byteStride\":" + std::to_string(stride) + ",\"count\":" + std::to_string(elements) +
                          ",\"mode\":\"" + mode + "\"" + (filter == "NONE" ? "" : ",\"filter\":\"" + filter + "\"") + "}}}";
  fallback_bytes += (elements * stride + 3) / 4 * 4;
  return view;
}

// The grid as a glTF document (or GLB), with a rotation animation whose quaternions take the
// QUATERNION filter.
GltfBuilder grid_builder(const Encoding& e, std::string& body) {
  GridStreams g = grid_streams();
  GltfBuilder b;
  uint64_t fallback = 0;
  size_t n = GridStreams::points;
  int position = add_view(b, fallback, bytes_of(g.positions), n, 12, "ATTRIBUTES", "NONE", e, true, e.position_count);
  int normal = add_view(b, fallback, bytes_of(g.normals), n, 8, "ATTRIBUTES", "OCTAHEDRAL", e, true);
  int texcoord = add_view(b, fallback, bytes_of(g.texcoords), n, 8, "ATTRIBUTES", "EXPONENTIAL", e, true);
  std::vector<uint16_t> short_indices(g.indices.begin(), g.indices.end());
  bool sequence = e.index_mode == "INDICES";
  int index = add_view(b, fallback, sequence ? bytes_of(g.indices) : bytes_of(short_indices), g.indices.size(),
                       sequence ? 4 : 2, e.index_mode, "NONE", e, false);
  std::vector<float> times = {0, 1, 2}, quaternions;
  for (float angle : {0.0f, 0.7f, 2.1f}) quaternions.insert(quaternions.end(), {0, std::sin(angle / 2), 0, std::cos(angle / 2)});
  std::vector<int16_t> encoded_quaternions(12);
  meshopt_encodeFilterQuat(encoded_quaternions.data(), 3, 8, 12, quaternions.data());
  int time = add_view(b, fallback, bytes_of(times), 3, 4, "ATTRIBUTES", "NONE", e, false);
  int rotation = add_view(b, fallback, bytes_of(encoded_quaternions), 3, 8, "ATTRIBUTES", "QUATERNION", e, false);
  b.accessor(position, 5126, e.position_count ? e.position_count : n, "VEC3");
  b.accessor(normal, 5122, n, "VEC3", ",\"normalized\":true");
  b.accessor(texcoord, 5126, n, "VEC2");
  b.accessor(index, sequence ? 5125 : 5123, g.indices.size(), "SCALAR");
  b.accessor(time, 5126, 3, "SCALAR", ",\"min\":[0],\"max\":[2]");
  b.accessor(rotation, 5122, 3, "VEC4", ",\"normalized\":true");
  if (e.compressed)
    b.more_buffers.push_back("{\"byteLength\":" + std::to_string(fallback) +
                             ",\"extensions\":{\"EXT_meshopt_compression\":{\"fallback\":true}}}");
  body = std::string(e.compressed ? "\"extensionsUsed\":[\"EXT_meshopt_compression\",\"KHR_mesh_quantization\"],"
                                    "\"extensionsRequired\":[\"EXT_meshopt_compression\",\"KHR_mesh_quantization\"],"
                                  : "\"extensionsUsed\":[\"KHR_mesh_quantization\"],"
                                    "\"extensionsRequired\":[\"KHR_mesh_quantization\"],") +
         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2},\"indices\":3}]}],"
         "\"animations\":[{\"samplers\":[{\"input\":4,\"output\":5}],"
         "\"channels\":[{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"rotation\"}}]}],"
         "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0";
  return b;
}

std::string grid_gltf(const Encoding& e) {
  std::string body;
  GltfBuilder b = grid_builder(e, body);
  return b.gltf(body);
}

std::string grid_glb(const Encoding& e) {
  std::string body;
  GltfBuilder b = grid_builder(e, body);
  return b.glb(body);
}

// The scene at 1.5 s, between the rotation keys, so that the quaternions are read.
SceneDesc load_between_keys(const std::filesystem::path& file) {
  LoadOptions options;
  options.animation_time = 1.5;
  return load_scene(file.string(), options);
}

bool same_texcoords(const std::vector<vec2>& a, const std::vector<vec2>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].x != b[i].x || a[i].y != b[i].y) return false;
  return true;
}

bool same_matrix(const mat4& a, const mat4& b) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      if (a.m[r][c] != b.m[r][c]) return false;
  return true;
}

void check_same_mesh(const SceneDesc& a, const SceneDesc& b) {
  REQUIRE(a.meshes.size() == 1);
  REQUIRE(b.meshes.size() == 1);
  CHECK(a.meshes[0].positions.size() == GridStreams::points);
  CHECK(a.meshes[0].indices.size() == 96);
  CHECK(a.meshes[0].positions == b.meshes[0].positions);
  CHECK(a.meshes[0].normals == b.meshes[0].normals);
  CHECK(same_texcoords(a.meshes[0].texcoords0, b.meshes[0].texcoords0));
  CHECK(a.meshes[0].indices == b.meshes[0].indices);
  REQUIRE(a.instances.size() == 1);
  REQUIRE(b.instances.size() == 1);
  CHECK(same_matrix(a.instances[0].transform, b.instances[0].transform));
}

}  // namespace

TEST_CASE("gltf meshopt: every mode and filter decodes to exactly the uncompressed file's values") {
  ScratchDir dir("gltf-meshopt");
  Encoding plain;
  plain.compressed = false;
  SceneDesc expected = load_between_keys(dir.write("plain.gltf", grid_gltf(plain)));
  REQUIRE(expected.instances.size() == 1);
  CHECK(!same_matrix(expected.instances[0].transform, mat4{}));  // the animation turned it
  Encoding triangles;
  SceneDesc from_gltf = load_between_keys(dir.write("triangles.gltf", grid_gltf(triangles)));
  check_same_mesh(from_gltf, expected);
  CHECK(from_gltf.warnings == expected.warnings);  // the extension is not "unsupported"
  // In a GLB the fallback buffer is buffer 1, without data: it is not the binary chunk.
  check_same_mesh(load_between_keys(dir.write("triangles.glb", grid_glb(triangles))), expected);
  Encoding sequence;
  sequence.index_mode = "INDICES";
  plain.index_mode = "INDICES";
  SceneDesc expected_sequence = load_between_keys(dir.write("plain-sequence.gltf", grid_gltf(plain)));
  check_same_mesh(load_between_keys(dir.write("sequence.gltf", grid_gltf(sequence))), expected_sequence);
}

TEST_CASE("gltf meshopt: the compressed file renders the same pixels as the uncompressed one") {
  ScratchDir dir("gltf-meshopt-render");
  Encoding plain;
  plain.compressed = false;
  std::string flags = " --width 16 --height 16 --spp 2 --env-color 1,1,1 --quiet --time 1.5 -o ";
  CommandResult a = run_radiant("render " + quoted(dir.write("plain.gltf", grid_gltf(plain))) + flags + quoted(dir.path / "plain.png"));
  CommandResult b = run_radiant("render " + quoted(dir.write("packed.glb", grid_glb(Encoding{}))) + flags + quoted(dir.path / "packed.png"));
  REQUIRE(a.exit_code == 0);
  REQUIRE(b.exit_code == 0);
  TestImage image = read_image(dir.path / "plain.png");
  float sum = 0;
  for (float v : image.pixels) sum += v;
  CHECK(sum > 0);  // the grid is seen
  CHECK(same_pixels(dir.path / "plain.png", dir.path / "packed.png"));
}

TEST_CASE("gltf meshopt: a truncated stream, bad fields and a count over the budget are errors naming the bufferView") {
  ScratchDir dir("gltf-meshopt-errors");
  std::string at = "bufferViews[0].extensions.EXT_meshopt_compression";
  Encoding truncated;
  truncated.truncate = 8;
  CHECK(load_error(dir, dir.write("truncated.gltf", grid_gltf(truncated)))
            .rfind("truncated.gltf: " + at + ": cannot decode the ATTRIBUTES data: it is malformed or truncated", 0) == 0);
  std::string good = grid_gltf(Encoding{});
  auto with = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    size_t found = text.find(from);
    REQUIRE(found != std::string::npos);
    return text.replace(found, from.size(), to);
  };
  CHECK(load_error(dir, dir.write("mode.gltf", with("\"mode\":\"ATTRIBUTES\"", "\"mode\":\"VERTICES\""))) ==
        "mode.gltf: " + at + ".mode: expected ATTRIBUTES, TRIANGLES or INDICES, found 'VERTICES'");
  CHECK(load_error(dir, dir.write("stride.gltf", with("\"byteStride\":12,\"count\"", "\"byteStride\":6,\"count\""))) ==
        "stride.gltf: " + at + ".byteStride: ATTRIBUTES needs a multiple of 4 up to 256, found 6");
  CHECK(load_error(dir, dir.write("filter.gltf", with("\"mode\":\"ATTRIBUTES\"}", "\"mode\":\"ATTRIBUTES\",\"filter\":\"OCTAHEDRAL\"}"))) ==
        "filter.gltf: " + at + ".filter: OCTAHEDRAL does not take a byteStride of 12");
  // 2^28 positions declared consistently (4 GiB decoded): refused by the budget before decoding.
  Encoding huge;
  huge.position_count = uint64_t(1) << 28;
  LoadOptions limited;
  limited.max_memory_bytes = size_t(64) << 20;
  std::string message = load_error(dir, dir.write("huge.gltf", grid_gltf(huge)), limited);
  CHECK(message.rfind("huge.gltf: " + at + ": decoding 268435456 elements of 12 bytes", 0) == 0);
  CHECK(message.find("over the memory limit of 64.0 MiB") != std::string::npos);
}
