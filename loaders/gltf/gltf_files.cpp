#include "gltf/gltf_files.h"

#include <fstream>

#include "file_access.h"
#include "gltf/gltf_context.h"
#include "gltf/gltf_memory.h"
#include "message_text.h"

namespace radiant {

namespace fs = std::filesystem;

static std::string percent_decoded(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit((unsigned char)uri[i + 1]) &&
        std::isxdigit((unsigned char)uri[i + 2])) {
      out += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

// The JSON path of the element whose URI tinygltf asks for ("images[0].uri"), or "".
static std::string element_of(const GltfFileAccess& access, const std::string& uri) {
  auto find = [&](const std::vector<std::string>& uris, const char* name) -> std::string {
    for (size_t i = 0; i < uris.size(); ++i)
      if (uris[i] == uri || percent_decoded(uris[i]) == uri) return element(name, i) + ".uri";
    return "";
  };
  std::string where = find(access.declarations->buffer_uris, "buffers");
  return where.empty() ? find(access.declarations->image_uris, "images") : where;
}

// "file.gltf: images[0].uri", for messages about `uri`.
static std::string where_of(const GltfFileAccess& access, const std::string& uri) {
  std::string element = element_of(access, uri);
  return access.file + ": " + (element.empty() ? "uri '" + escaped(uri) + "'" : element);
}

static void refuse(GltfFileAccess& access, const std::string& message) {
  if (access.error.empty()) access.error = message;
}

// "file.gltf: images[0].uri 'x.png'": the element that asked for `path` and its URI, for messages.
static std::string label_of(const GltfFileAccess& access, const std::string& path) {
  auto uri = access.uri_of_path.find(path);
  if (uri == access.uri_of_path.end()) return access.file + ": '" + escaped(path) + "'";
  std::string element = element_of(access, uri->second);
  return access.file + ": " + (element.empty() ? "" : element + " ") + "'" + escaped(uri->second) + "'";
}

// A missing, folder or FIFO file is refused here, so that the message says which.
static bool file_exists(const std::string& path, void* user) {
  auto& access = *static_cast<GltfFileAccess*>(user);
  if (path.empty()) return false;
  try {
    check_input_file(path, label_of(access, path), *access.options);
    return true;
  } catch (const LoadError& error) {
    refuse(access, error.what());
    return false;
  }
}

// tinygltf asks for "<uri>" (base dir "") and then "./<uri>"; both resolve inside the scene folder.
static std::string expand_file_path(const std::string& path, void* user) {
  auto& access = *static_cast<GltfFileAccess*>(user);
  std::string uri = path.rfind("./", 0) == 0 ? path.substr(2) : path;
  try {
    std::string resolved =
        resolve_inside(access.base_dir, uri, access.options->allow_external_files, where_of(access, uri)).string();
    access.uri_of_path[resolved] = uri;
    return resolved;
  } catch (const LoadError& error) {
    refuse(access, error.what());
    return "";
  }
}

static bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                            void* user) {
  auto& access = *static_cast<GltfFileAccess*>(user);
  try {
    std::string label = label_of(access, path);
    uint64_t size = check_input_file(path, label, *access.options);
    charge_load(*access.options, size, label);
    std::ifstream in(path, std::ios::binary);
    out->resize(size);
    if (!in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size))) throw LoadError(label + ": read failed");
    return true;
  } catch (const LoadError& error) {
    refuse(access, error.what());
    return *err = error.what(), false;
  }
}

static bool write_whole_file(std::string* err, const std::string&, const std::vector<unsigned char>&,
                             void*) {
  *err = "radiant never writes glTF files";
  return false;
}

// ---------------------------------------------------------------- images

static uint32_t big_endian(const unsigned char* p, int bytes) {
  uint32_t v = 0;
  for (int i = 0; i < bytes; ++i) v = (v << 8) | p[i];
  return v;
}

bool read_image_header(const unsigned char* bytes, size_t size, int& width, int& height,
                       int& bytes_per_channel) {
  static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (size >= 25 && std::equal(png, png + 8, bytes) && std::equal(bytes + 12, bytes + 16, "IHDR")) {
    width = int(std::min<uint32_t>(big_endian(bytes + 16, 4), 1u << 30));
    height = int(std::min<uint32_t>(big_endian(bytes + 20, 4), 1u << 30));
    bytes_per_channel = bytes[24] == 16 ? 2 : 1;
    return true;
  }
  if (size < 4 || bytes[0] != 0xFF || bytes[1] != 0xD8) return false;
  // JPEG: walk the segments up to the first start-of-frame marker.
  for (size_t at = 2; at + 9 < size;) {
    if (bytes[at] != 0xFF) return false;
    unsigned char marker = bytes[at + 1];
    if (marker == 0xFF) { ++at; continue; }
    bool start_of_frame = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 &&
                          marker != 0xCC;
    if (start_of_frame) {
      height = int(big_endian(bytes + at + 5, 2));
      width = int(big_endian(bytes + at + 7, 2));
      bytes_per_channel = bytes[at + 4] > 8 ? 2 : 1;
      return true;
    }
    if ((marker >= 0xD0 && marker <= 0xD9) || marker == 0x01) { at += 2; continue; }
    at += 2 + big_endian(bytes + at + 2, 2);
  }
  return false;
}

// True at a marker that ends entropy-coded data: 0xFF followed by neither a stuffed 0x00 nor a
// restart marker.
static bool ends_scan(const unsigned char* p) { return p[0] == 0xFF && p[1] != 0x00 && (p[1] < 0xD0 || p[1] > 0xD7); }

bool jpeg_is_complete(const unsigned char* bytes, size_t size) {
  // Walk the marker segments; after a start of scan, pass its entropy-coded data up to the next
  // marker. Progressive files have several scans; the end-of-image marker follows the last.
  size_t at = 2;
  while (at + 1 < size) {
    if (bytes[at] != 0xFF) return false;
    unsigned char marker = bytes[at + 1];
    if (marker == 0xD9) return true;
    if (marker == 0xFF) { ++at; continue; }
    if ((marker >= 0xD0 && marker <= 0xD7) || marker == 0x01) { at += 2; continue; }
    if (at + 3 >= size) return false;
    at += 2 + big_endian(bytes + at + 2, 2);
    if (marker != 0xDA) continue;
    while (at + 1 < size && !ends_scan(bytes + at)) ++at;
  }
  return false;
}

// The MIME type of a WebP or KTX2 image (which stb_image cannot decode), else "".
static std::string image_format_beyond_stb(const unsigned char* bytes, size_t size) {
  static const unsigned char ktx2[12] = {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'};
  if (size >= 12 && std::equal(bytes, bytes + 4, "RIFF") && std::equal(bytes + 8, bytes + 12, "WEBP")) return "image/webp";
  if (size >= 12 && std::equal(ktx2, ktx2 + 12, bytes)) return "image/ktx2";
  return "";
}

// Charges the decoding against the memory budget, then decodes with tinygltf's stb_image.
// WebP and KTX2 images are left undecoded, marked by their MIME type: the textures decide
// whether they are read or a PNG/JPEG fallback is (gltf_materials.cpp).
static bool decode_image(GltfFileAccess& access, tinygltf::Image* image, int index, std::string* err,
                         std::string* warn, const unsigned char* bytes, size_t size) {
  std::string where = access.file + ": " + element("images", size_t(index));
  std::string deferred = image_format_beyond_stb(bytes, size);
  if (!deferred.empty()) {
    image->mimeType = deferred;
    return true;
  }
  int width = 0, height = 0, bytes_per_channel = 1;
  if (size == 0 || size > 0x7fffffff || !read_image_header(bytes, size, width, height, bytes_per_channel)) {
    refuse(access, where + ": not a PNG or JPEG image");
    return false;
  }
  uint64_t needed = gltf_image_decode_bytes(width, height, bytes_per_channel);
  MemoryBudget& budget = *access.options->budget;
  if (!budget.try_charge(needed)) {
    refuse(access,
           budget.refusal(needed, where + ": a " + std::to_string(width) + "x" + std::to_string(height) + " image"));
    return false;
  }
  if (bytes[0] == 0xFF && !jpeg_is_complete(bytes, size)) {
    refuse(access, where + ": the JPEG data is truncated (no end-of-image marker after its scan)");
    return false;
  }
  // Same layout as tinygltf's LoadImageDataOption, which only its implementation declares.
  struct { bool preserve_channels = true; } keep_channels;
  if (tinygltf::LoadImageData(image, index, err, warn, 0, 0, bytes, int(size), &keep_channels)) return true;
  refuse(access, where + ": the image could not be decoded");
  return false;
}

// tinygltf 2.7 passes bufferView images without checking the view against its buffer, so those
// wait for decode_buffer_view_images; files (read by read_whole_file) and data URIs are safe.
static bool load_image(tinygltf::Image* image, const int index, std::string* err, std::string* warn,
                       int, int, const unsigned char* bytes, int size, void* user) {
  auto& access = *static_cast<GltfFileAccess*>(user);
  if (image->bufferView >= 0) return true;
  return decode_image(access, image, index, err, warn, bytes, size_t(std::max(size, 0)));
}

void decode_buffer_view_images(tinygltf::Model& model, GltfFileAccess& access) {
  for (size_t i = 0; i < model.images.size(); ++i) {
    tinygltf::Image& image = model.images[i];
    if (image.bufferView < 0) continue;
    std::string where = access.file + ": " + element("images", i) + ".bufferView";
    if (size_t(image.bufferView) >= model.bufferViews.size())
      throw LoadError(where + ": bufferView " + std::to_string(image.bufferView) + " out of range");
    const tinygltf::BufferView& view = model.bufferViews[image.bufferView];
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
      throw LoadError(where + ": buffer " + std::to_string(view.buffer) + " out of range");
    const std::vector<unsigned char>& data = model.buffers[view.buffer].data;
    if (view.byteLength > data.size() || view.byteOffset > data.size() - view.byteLength)
      throw LoadError(where + ": " + element("bufferViews", size_t(image.bufferView)) + " runs past the end of " +
                      element("buffers", size_t(view.buffer)));
    std::string error, warning;
    if (!decode_image(access, &image, int(i), &error, &warning, data.data() + view.byteOffset, view.byteLength))
      throw LoadError(access.error);
  }
}

void install_file_access(tinygltf::TinyGLTF& gltf, GltfFileAccess& access) {
  gltf.SetFsCallbacks({&file_exists, &expand_file_path, &read_whole_file, &write_whole_file, &access});
  gltf.SetImageLoader(&load_image, &access);
  gltf.SetPreserveImageChannels(true);
}

}  // namespace radiant
