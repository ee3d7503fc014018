#include "gltf/gltf_declarations.h"

#include <cctype>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>

#include "gltf/gltf_index_fields.h"
#include "message_text.h"
#include "scene/load_error.h"

namespace radiant {

// ---------------------------------------------------------------- a minimal JSON reader

namespace {

// The parts of the document the declarations need; everything else is checked and counted only.
struct JsonValue {
  enum class Kind { null, boolean, number, string, array, object } kind = Kind::null;
  double number = 0;
  std::string text;
  std::vector<JsonValue> items;
  std::map<std::string, JsonValue> members;
};

// Paths whose values are kept ("buffers[].uri": the uri member of any element of buffers).
bool is_kept(const std::string& path) {
  static const char* kept[] = {"",           "buffers",     "buffers[]", "buffers[].byteLength", "buffers[].uri",
                               "images",     "images[]",    "images[].uri", "extensionsRequired",
                               "extensionsRequired[]", "asset", "asset.version"};
  for (const char* k : kept)
    if (path == k) return true;
  return false;
}

// Arrays whose elements tinygltf turns into structs of their own, counted for the memory charge.
bool is_counted(const std::string& path) {
  static const char* counted[] = {"accessors", "animations", "buffers",  "bufferViews",          "cameras",
                                  "images",    "materials",  "meshes",   "nodes",                "samplers",
                                  "scenes",    "skins",      "textures", "meshes[].primitives", "animations[].channels",
                                  "animations[].samplers",   "extensions.KHR_lights_punctual.lights"};
  for (const char* c : counted)
    if (path == c) return true;
  return false;
}

// "meshes[].primitives" -> "meshes.primitives".
std::string count_key(std::string path) {
  for (size_t at; (at = path.find("[]")) != std::string::npos;) path.erase(at, 2);
  return path;
}

// Recursive descent with a depth limit, so hostile nesting cannot overflow the stack. Paths are
// followed only near the root, where everything kept or counted lives. Counting keeps nothing;
// reading the declarations keeps the values at is_kept paths.
struct JsonReader {
  const std::string& in;
  const std::string& file;
  bool keeping;
  GltfJsonCounts counts;
  // Whether numbers are checked against what their member holds (gltf_index_fields.h), and the
  // full path followed for that: its steps, and the text that names it ("nodes[3].camera").
  bool checking_numbers = false;
  std::vector<JsonStep> steps;
  std::string location;
  size_t at = 0;
  static constexpr int max_depth = 128;
  static constexpr int path_depth = 4;
  static constexpr size_t longest_path_key = 64;
  inline static const std::string deep = "*";  // below path_depth: nothing kept or counted

  [[noreturn]] void fail(const std::string& message) const {
    throw LoadError(file + ": invalid JSON at byte " + std::to_string(at) + ": " + message);
  }
  void skip_space() {
    while (at < in.size() && (in[at] == ' ' || in[at] == '\t' || in[at] == '\n' || in[at] == '\r')) ++at;
  }
  bool take(char c) {
    skip_space();
    if (at < in.size() && in[at] == c) return ++at, true;
    return false;
  }
  void expect(char c) {
    if (!take(c)) fail(std::string("expected '") + c + "'");
  }
  std::string child_path(const std::string& path, int depth, const std::string& name) const {
    if (depth + 1 >= path_depth || path == deep) return deep;
    return path + name;
  }

  JsonValue value(int depth, const std::string& path) {
    if (depth > max_depth) fail("nested too deeply");
    skip_space();
    if (at >= in.size()) fail("unexpected end");
    ++counts.values;
    bool keep = keeping && path != deep && is_kept(path);
    JsonValue v;
    char c = in[at];
    if (c == '{') {
      v.kind = JsonValue::Kind::object;
      ++at;
      if (take('}')) return v;
      do {
        skip_space();
        ++counts.values;  // a member name is a string tinygltf keeps too
        size_t key_start = at;
        skip_string();
        size_t key_length = at - key_start - 2;
        std::string key;
        if (path != deep && key_length <= longest_path_key) key = in.substr(key_start + 1, key_length);
        expect(':');
        std::string member_path = child_path(path, depth, (path.empty() ? "" : ".") + key);
        size_t location_length = location.size();
        if (checking_numbers) {
          std::string name = key_length <= longest_path_key ? in.substr(key_start + 1, key_length) : "...";
          location += (location.empty() ? "" : ".") + name;
          steps.push_back({std::move(name), false});
        }
        JsonValue member = value(depth + 1, member_path);
        if (checking_numbers) steps.pop_back(), location.resize(location_length);
        if (keep && is_kept(member_path)) v.members[key] = std::move(member);
      } while (take(','));
      expect('}');
    } else if (c == '[') {
      v.kind = JsonValue::Kind::array;
      ++at;
      if (take(']')) return v;
      std::string item_path = child_path(path, depth, "[]");
      uint64_t items = 0;
      do {
        size_t location_length = location.size();
        if (checking_numbers) {
          location += "[" + std::to_string(items) + "]";
          steps.push_back({steps.empty() ? "" : steps.back().name, true});
        }
        JsonValue item = value(depth + 1, item_path);
        if (checking_numbers) steps.pop_back(), location.resize(location_length);
        ++items;
        if (keep) v.items.push_back(std::move(item));
      } while (take(','));
      expect(']');
      if (path != deep && is_counted(path)) counts.elements[count_key(path)] += items;
    } else if (c == '"') {
      v.kind = JsonValue::Kind::string;
      if (keep) v.text = string();
      else skip_string();
    } else if (literal("true") || literal("false")) {
      v.kind = JsonValue::Kind::boolean;
    } else if (literal("null")) {
    } else {
      v.kind = JsonValue::Kind::number;
      v.number = number(keep);
    }
    return v;
  }
  bool literal(const char* word) {
    size_t n = std::strlen(word);
    if (in.compare(at, n, word) != 0) return false;
    at += n;
    return true;
  }
  double number(bool keep) {
    size_t start = at;
    while (at < in.size() && std::strchr("+-0123456789.eE", in[at])) ++at;
    if (start == at) fail("unexpected character");
    if (checking_numbers) {
      std::string problem = gltf_number_problem(gltf_number_kind(steps), std::string_view(in).substr(start, at - start));
      if (!problem.empty()) throw LoadError(file + ": " + (location.empty() ? "" : location + ": ") + problem);
    }
    return keep ? std::strtod(in.substr(start, at - start).c_str(), nullptr) : 0;
  }
  // Escapes are decoded as tinygltf decodes them, so that URIs compare equal to the ones it asks
  // for; a malformed \\u escape is kept as written (tinygltf refuses the file then).
  std::string string() {
    if (at >= in.size() || in[at] != '"') fail("expected a string");
    std::string out;
    for (++at; at < in.size() && in[at] != '"'; ++at) {
      if (in[at] != '\\' || at + 1 >= in.size()) {
        out += in[at];
        continue;
      }
      char e = in[++at];
      switch (e) {
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': unicode_escape(out); break;
        default: out += e;
      }
    }
    if (at >= in.size()) fail("unterminated string");
    ++at;
    return out;
  }
  // After "\\u" (at on the 'u'): the code point as UTF-8, surrogate pairs joined.
  void unicode_escape(std::string& out) {
    uint32_t code = 0;
    if (!hex4(at + 1, code)) {
      out += "\\u";
      return;
    }
    at += 4;
    uint32_t low = 0;
    if (code >= 0xD800 && code < 0xDC00 && in.compare(at + 1, 2, "\\u") == 0 && hex4(at + 3, low) &&
        low >= 0xDC00 && low < 0xE000) {
      code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
      at += 6;
    }
    if (code < 0x80) {
      out += char(code);
    } else if (code < 0x800) {
      out += char(0xC0 | (code >> 6)), out += char(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      out += char(0xE0 | (code >> 12)), out += char(0x80 | ((code >> 6) & 0x3F)), out += char(0x80 | (code & 0x3F));
    } else {
      out += char(0xF0 | (code >> 18)), out += char(0x80 | ((code >> 12) & 0x3F));
      out += char(0x80 | ((code >> 6) & 0x3F)), out += char(0x80 | (code & 0x3F));
    }
  }
  // Four hex digits at `from`.
  bool hex4(size_t from, uint32_t& code) const {
    if (from + 4 > in.size()) return false;
    code = 0;
    for (size_t i = from; i < from + 4; ++i) {
      int digit = std::isdigit((unsigned char)in[i]) ? in[i] - '0'
                  : std::isxdigit((unsigned char)in[i]) ? std::tolower((unsigned char)in[i]) - 'a' + 10
                                                        : -1;
      if (digit < 0) return false;
      code = code * 16 + uint32_t(digit);
    }
    return true;
  }
  // A string passed over without copying it (a data URI may be most of the file).
  void skip_string() {
    if (at >= in.size() || in[at] != '"') fail("expected a string");
    for (++at; at < in.size() && in[at] != '"'; ++at)
      if (in[at] == '\\' && at + 1 < in.size()) ++at;
    if (at >= in.size()) fail("unterminated string");
    ++at;
  }
};

const JsonValue* member(const JsonValue& object, const std::string& key) {
  auto it = object.members.find(key);
  return it == object.members.end() ? nullptr : &it->second;
}

// The URIs of an array's elements, data URIs shortened to data_uri_marker.
std::vector<std::string> uris_of(const JsonValue* array) {
  std::vector<std::string> uris;
  if (!array) return uris;
  for (const JsonValue& item : array->items) {
    const JsonValue* uri = member(item, "uri");
    std::string text = uri ? uri->text : "";
    uris.push_back(text.rfind(data_uri_marker, 0) == 0 ? data_uri_marker : text);
  }
  return uris;
}

// glTF 2.x only: a 1.0 file parses as JSON but means something else (objects instead of arrays).
void check_version(const JsonValue& root, const std::string& file) {
  const JsonValue* asset = member(root, "asset");
  const JsonValue* version = asset ? member(*asset, "version") : nullptr;
  if (!version || version->kind != JsonValue::Kind::string) return;  // tinygltf reports a missing one
  if (version->text.compare(0, 2, "2.") != 0)
    throw LoadError(file + ": asset.version: glTF " + escaped(version->text) +
                    " is not supported (radiant reads glTF 2.x)");
}

}  // namespace

// The document's root value, kept where `keeping` and the path say so.
static JsonValue read_json(JsonReader& reader) {
  if (reader.in.compare(0, 3, "\xEF\xBB\xBF") == 0) reader.at = 3;  // a UTF-8 byte order mark, as tinygltf allows
  return reader.value(0, "");
}

GltfJsonCounts count_gltf_json(const std::string& json, const std::string& file) {
  JsonReader reader{json, file, false, {}};
  reader.checking_numbers = true;
  read_json(reader);
  return reader.counts;
}

GltfDeclarations read_gltf_declarations(const std::string& json, const std::string& file) {
  GltfDeclarations out;
  JsonReader reader{json, file, true, {}};
  JsonValue root = read_json(reader);
  check_version(root, file);
  if (const JsonValue* buffers = member(root, "buffers")) {
    for (size_t i = 0; i < buffers->items.size(); ++i) {
      const JsonValue* length = member(buffers->items[i], "byteLength");
      double bytes = length ? length->number : 0;
      if (!(bytes >= 0 && bytes < 1.8e19))
        throw LoadError(file + ": buffers[" + std::to_string(i) + "].byteLength: invalid size");
      out.buffer_byte_lengths.push_back(uint64_t(bytes));
    }
  }
  out.buffer_uris = uris_of(member(root, "buffers"));
  out.image_uris = uris_of(member(root, "images"));
  if (const JsonValue* required = member(root, "extensionsRequired"))
    for (const JsonValue& name : required->items) out.extensions_required.push_back(name.text);
  return out;
}

// ---------------------------------------------------------------- GLB container

static uint32_t read_u32(const std::string& bytes, size_t offset) {
  uint32_t v = 0;
  std::memcpy(&v, bytes.data() + offset, 4);
  return v;  // GLB is little-endian, as is every platform radiant builds on
}

std::string glb_json_chunk(const std::string& bytes, const std::string& file) {
  if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0)
    throw LoadError(file + ": not a GLB file (bad header)");
  if (uint32_t version = read_u32(bytes, 4); version != 2)
    throw LoadError(file + ": GLB version " + std::to_string(version) + " is not supported (radiant reads glTF 2.x)");
  uint32_t chunk_length = read_u32(bytes, 12), chunk_type = read_u32(bytes, 16);
  if (chunk_type != 0x4E4F534Au || chunk_length > bytes.size() - 20)
    throw LoadError(file + ": GLB: the first chunk is not a complete JSON chunk");
  return bytes.substr(20, chunk_length);
}

std::string glb_with_json_chunk(const std::string& bytes, std::string json) {
  uint32_t old_length = read_u32(bytes, 12);
  while (json.size() % 4) json += ' ';
  std::string rest = bytes.substr(20 + size_t(old_length));
  auto u32 = [](uint64_t v) {
    uint32_t value = uint32_t(v);
    return std::string(reinterpret_cast<const char*>(&value), 4);
  };
  return "glTF" + u32(2) + u32(20 + json.size() + rest.size()) + u32(json.size()) + "JSON" + json + rest;
}

}  // namespace radiant
