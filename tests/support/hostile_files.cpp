#include "support/hostile_files.h"

#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include "loaders/gltf_builder.h"
#include "support/test_support.h"

namespace radiant::test {

namespace {

const char* placed_mesh = "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
                          "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0";

std::string triangle_gltf(const std::string& extra_members) {
  GltfBuilder b;
  b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
  return b.gltf(std::string(placed_mesh) + extra_members);
}

}  // namespace

std::string sparse_positions_gltf(size_t count) {
  GltfBuilder b;
  int indices = b.view(GltfBuilder::bytes_of(std::vector<uint32_t>{0}));
  int values = b.view(GltfBuilder::bytes_of(std::vector<float>{1, 2, 3}));
  b.accessor(-1, 5126, count, "VEC3",
             ",\"sparse\":{\"count\":1,\"indices\":{\"bufferView\":" + std::to_string(indices) +
                 ",\"componentType\":5125},\"values\":{\"bufferView\":" + std::to_string(values) + "}}");
  return b.gltf(placed_mesh);
}

std::string gltf_with_extras(size_t values) {
  std::string zeros;
  zeros.reserve(values * 2);
  for (size_t i = 0; i < values; ++i) zeros += i ? ",0" : "0";
  return triangle_gltf(",\"extras\":[" + zeros + "]");
}

std::string mtl_with_materials(size_t materials) {
  std::string text;
  for (size_t i = 0; i < materials; ++i) text += "newmtl m" + std::to_string(i) + "\nKd 1 1 1\n";
  return text;
}

std::string obj_using_mtl(const std::string& mtl_name, const std::string& material) {
  return "mtllib " + mtl_name + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl " + material + "\nf 1 2 3\n";
}

std::string obj_with_faces(size_t faces) {
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  text.reserve(text.size() + faces * 8);
  for (size_t i = 0; i < faces; ++i) text += "f 1 2 3\n";
  return text;
}

std::string scene_with_words(size_t lines, size_t words) {
  std::string line = "p";
  line.reserve(words * 2 + 2);
  for (size_t i = 0; i < words; ++i) line += " 1";
  std::string text = "@sphere\n";
  for (size_t i = 0; i < lines; ++i) text += line + "\n";
  return text;
}

std::string truncated_jpeg(const std::filesystem::path& scratch_folder, int width, int height) {
  std::mt19937 random(7);
  std::vector<float> noise(64 * 64);
  for (float& v : noise) v = float(random() % 256) / 255;
  std::filesystem::path source = scratch_folder / "noise-source.jpg";
  write_test_image(source, 64, 64, {"Y"}, noise);
  std::string bytes = read_bytes(source);
  std::filesystem::remove(source);
  size_t frame = bytes.find("\xFF\xC0"), scan = bytes.find("\xFF\xDA");
  if (frame == std::string::npos || scan == std::string::npos || scan + 400 > bytes.size())
    throw std::runtime_error("unexpected JPEG layout from the OpenImageIO module");
  bytes[frame + 5] = char(height >> 8), bytes[frame + 6] = char(height & 255);
  bytes[frame + 7] = char(width >> 8), bytes[frame + 8] = char(width & 255);
  return bytes.substr(0, scan + 300);  // the scan header and part of the compressed data
}

std::string gltf_textured_triangle(const std::string& image_uri) {
  GltfBuilder b;
  b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
  b.floats({0, 0, 1, 0, 0, 1}, "VEC2", 2);
  return b.gltf(
      "\"images\":[{\"uri\":\"" + image_uri + "\"}],\"textures\":[{\"source\":0}],"
      "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}}}],"
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":1},\"material\":0}]}],"
      "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0");
}

std::string obj_textured_triangle(const std::string& mtl_name, const std::string& image_name, std::string& mtl) {
  mtl = "newmtl t\nKd 1 1 1\nmap_Kd " + image_name + "\n";
  return "mtllib " + mtl_name + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl t\nf 1/1 2/2 3/3\n";
}

std::string hdr_header_only(int width, int height) {
  return "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(height) + " +X " + std::to_string(width) + "\n";
}

}  // namespace radiant::test
