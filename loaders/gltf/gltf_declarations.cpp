#include "gltf/gltf_declarations.h"

#include <cctype>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>

#include "load_scene.h"

namespace radiant {

// ---------------------------------------------------------------- a minimal JSON reader

namespace {

struct JsonValue {
  enum class Kind { null, boolean, number, string, array, object } kind = Kind::null;
  double number = 0;
  std::string text;
  std::vector<JsonValue> items;
  std::map<std::string, JsonValue> members;
};

// Recursive descent with a depth limit, so hostile nesting cannot overflow the stack.
struct JsonReader {
  const std::string& in;
  const std::string& file;
  size_t at = 0;
  static constexpr int max_depth = 128;

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

  JsonValue value(int depth) {
    if (depth > max_depth) fail("nested too deeply");
    skip_space();
    if (at >= in.size()) fail("unexpected end");
    JsonValue v;
    char c = in[at];
    if (c == '{') {
      v.kind = JsonValue::Kind::object;
      ++at;
      if (take('}')) return v;
      do {
        skip_space();
        std::string key = string();
        expect(':');
        v.members[key] = value(depth + 1);
      } while (take(','));
      expect('}');
    } else if (c == '[') {
      v.kind = JsonValue::Kind::array;
      ++at;
      if (take(']')) return v;
      do v.items.push_back(value(depth + 1));
      while (take(','));
      expect(']');
    } else if (c == '"') {
      v.kind = JsonValue::Kind::string;
      v.text = string();
    } else if (literal("true") || literal("false")) {
      v.kind = JsonValue::Kind::boolean;
    } else if (literal("null")) {
    } else {
      v.kind = JsonValue::Kind::number;
      v.number = number();
    }
    return v;
  }
  bool literal(const char* word) {
    size_t n = std::strlen(word);
    if (in.compare(at, n, word) != 0) return false;
    at += n;
    return true;
  }
  double number() {
    size_t start = at;
    while (at < in.size() && std::strchr("+-0123456789.eE", in[at])) ++at;
    if (start == at) fail("unexpected character");
    return std::strtod(in.substr(start, at - start).c_str(), nullptr);
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
};

const JsonValue* member(const JsonValue& object, const std::string& key) {
  auto it = object.members.find(key);
  return it == object.members.end() ? nullptr : &it->second;
}

std::vector<std::string> uris_of(const JsonValue* array) {
  std::vector<std::string> uris;
  if (!array) return uris;
  for (const JsonValue& item : array->items) {
    const JsonValue* uri = member(item, "uri");
    uris.push_back(uri ? uri->text : "");
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

GltfDeclarations read_gltf_declarations(const std::string& json, const std::string& file) {
  JsonReader reader{json, file};
  if (json.compare(0, 3, "\xEF\xBB\xBF") == 0) reader.at = 3;  // a UTF-8 byte order mark, as tinygltf allows
  JsonValue root = reader.value(0);
  check_version(root, file);
  GltfDeclarations out;
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

}  // namespace radiant
