#include "obj/obj_messages.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "message_text.h"

namespace radiant {

namespace {

// tinyobjloader's messages that carry a line number, reworded. `line` is the capture group of
// the number; `$n` in `message` are the pattern's groups.
struct Rewrite {
  std::regex pattern;
  int line;
  const char* message;
};

const std::vector<Rewrite>& rewrites() {
  static const std::vector<Rewrite> table = {
      {std::regex(R"(Failed parse `([flp])' line.* line (\d+)\.?\)?)"), 2,
       "$1: an index is 0 or not a number (OBJ indices start at 1)"},
      {std::regex(R"(Failed parse `vw' line.* line (\d+)\.?\)?)"), 1, "vw: a joint id is negative"},
      {std::regex(R"(Looks like empty filename for mtllib.*\(line (\d+)\.?\))"), 1,
       "mtllib names no file; the default material is used"},
      {std::regex(R"(Empty group name\. line: (\d+))"), 1, "g without a name"},
      {std::regex(R"re(Both `d` and `Tr` parameters defined for "(.*)"\..*\(line (\d+) in \.mtl\.\))re"), 2,
       "material '$1' sets both d and Tr; d is used"},
  };
  return table;
}

// tinyobjloader checks the largest index once the file is read and names its last line; the
// faces are checked by radiant with their place, lines and points are not rendered.
const std::regex index_bounds(R"((Vertex|Vertex normal|Vertex texcoord) indices out of bounds \(line \d+\.\))");
const std::regex unknown_material(R"(material \[ '(.*)' \] not found in \.mtl)");
const std::regex any_line(R"(\s*\(?\bline:? (\d+)[^)]*\)?\.?$)");

std::string trimmed(const std::string& text) {
  size_t first = text.find_first_not_of(" \t\r.");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") + 1 - first);
}


std::string at_line(const std::string& file, const std::string& line) { return file + ":" + line + ": "; }

}  // namespace

std::vector<FaceStatement> face_statements(const std::string& path) {
  std::ifstream in(path);
  std::vector<FaceStatement> faces;
  std::string text;
  for (size_t line = 1; std::getline(in, text); ++line) {
    std::istringstream tokens(text);
    std::string keyword, corner;
    int corners = 0;
    if (!(tokens >> keyword) || keyword != "f") continue;
    while (tokens >> corner) ++corners;
    faces.push_back({line, text, corners});
  }
  return faces;
}

std::vector<std::string> placed_messages(const std::string& text, const ObjMessageSource& source) {
  std::vector<std::string> placed;
  std::map<std::string, bool> unknown_reported;  // one message per unknown material name
  size_t usemtl_cursor = 0;  // tinyobjloader reports unknown materials in file order
  size_t short_faces = 0;
  std::istringstream lines(text);
  std::string raw;
  std::smatch match;
  while (std::getline(lines, raw)) {
    std::string message = trimmed(raw);
    if (message.empty()) continue;
    if (message.rfind("Failed to load material file(s)", 0) == 0) continue;  // the reader named the file
    if (message.rfind("Degenerated face found", 0) == 0) {
      ++short_faces;
      continue;
    }
    if (std::regex_match(message, match, unknown_material)) {
      std::string name = decode_material_name(match[1].str());
      if (!source.report_unknown_materials || !unknown_reported.emplace(name, true).second) continue;
      std::string place = source.file + ": ";
      if (source.usemtl_lines) {
        const auto& usemtl = *source.usemtl_lines;
        while (usemtl_cursor < usemtl.size() && usemtl[usemtl_cursor].name != name) ++usemtl_cursor;
        if (usemtl_cursor < usemtl.size()) place = at_line(source.file, std::to_string(usemtl[usemtl_cursor].line));
      }
      placed.push_back(place + "usemtl '" + escaped(name) +
                       "': no material of that name in the MTL files; its faces get the default material");
      continue;
    }
    if (std::regex_match(message, index_bounds)) {
      placed.push_back(source.file + ": " + std::regex_replace(message, any_line, ""));
      continue;
    }
    bool rewritten = false;
    for (const Rewrite& rewrite : rewrites()) {
      if (!std::regex_match(message, match, rewrite.pattern)) continue;
      std::string reworded = match.format(rewrite.message);
      if (reworded.find('%') != std::string::npos) reworded = decode_material_name(reworded);
      placed.push_back(at_line(source.file, match[rewrite.line].str()) + reworded);
      rewritten = true;
      break;
    }
    if (rewritten) continue;
    if (std::regex_search(message, match, any_line))
      placed.push_back(at_line(source.file, match[1].str()) + std::regex_replace(message, any_line, ""));
    else
      placed.push_back(source.file + ": " + message);
  }
  if (short_faces > 0) {
    std::vector<FaceStatement> faces = face_statements(source.file);
    auto first = std::find_if(faces.begin(), faces.end(), [](const FaceStatement& f) { return f.corners < 3; });
    std::string place = first == faces.end() ? source.file + ": " : at_line(source.file, std::to_string(first->line));
    placed.push_back(place + std::to_string(short_faces) + " faces with fewer than 3 corners are skipped" +
                     (short_faces > 1 ? " (this one first)" : ""));
  }
  return placed;
}

}  // namespace radiant
