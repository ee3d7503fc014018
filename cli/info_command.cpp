// `radiant info SCENE [--json]`: scene statistics, warnings, and the effects it calls for.
#include <iostream>
#include <sstream>

#include "commands.h"
#include "load_scene.h"
#include "option_parsing.h"
#include "render/render.h"
#include "render_report.h"
#include "scene/effects.h"
#include "scene/scene_summary.h"

namespace radiant::cli {

namespace {

std::string vec3_json(vec3 v) {
  std::ostringstream o;
  o << "[" << v.x << ", " << v.y << ", " << v.z << "]";
  return o.str();
}

std::string info_json(const std::string& path, const SceneDesc& scene, const SceneSummary& s, const EffectSet& effects,
                      RenderMode auto_mode, const std::string& auto_reason) {
  std::ostringstream j;
  j << "{\n  \"scene\": \"" << json_escape(path) << "\",\n  \"name\": \"" << json_escape(scene.name) << "\",\n"
    << "  \"geometry\": {\"meshes\": " << s.meshes << ", \"instances\": " << s.instances << ", \"triangles\": " << s.triangles
    << ", \"instanced_triangles\": " << s.instanced_triangles << ", \"spheres\": " << s.spheres << ", \"planes\": " << s.planes
    << ", \"cylinders\": " << s.cylinders << ", \"tubes\": " << s.tubes << ", \"bytes\": " << s.geometry_bytes << "},\n"
    << "  \"materials\": " << s.materials << ", \"emissive_materials\": " << s.emissive_materials << ",\n"
    << "  \"textures\": {\"count\": " << s.textures << ", \"images\": " << s.images << ", \"bytes\": " << s.texture_bytes << "},\n"
    << "  \"lights\": {\"ambient\": " << s.ambient_lights << ", \"directional\": " << s.directional_lights
    << ", \"point\": " << s.point_lights << ", \"spot\": " << s.spot_lights << "},\n"
    << "  \"cameras\": " << s.cameras << ",\n";
  if (s.has_bounds) j << "  \"bounds\": {\"min\": " << vec3_json(s.bounds_lower) << ", \"max\": " << vec3_json(s.bounds_upper) << "},\n";
  else j << "  \"bounds\": null,\n";
  j << "  \"effects\": [";
  size_t reason = 0;
  bool first = true;
  for (const EffectInfo& info : effect_catalog()) {
    if (!effects.has(info.effect)) continue;
    j << (first ? "" : ",") << "\n    {\"effect\": \"" << info.name << "\", \"reason\": \"" << json_escape(effects.reasons[reason++]) << "\"}";
    first = false;
  }
  j << "\n  ],\n  \"auto_mode\": {\"mode\": \"" << mode_name(auto_mode) << "\", \"reason\": \"" << json_escape(auto_reason) << "\"},\n"
    << "  \"warnings\": [";
  for (size_t i = 0; i < s.warnings.size(); ++i) j << (i ? ", " : "") << "\"" << json_escape(s.warnings[i]) << "\"";
  j << "]\n}\n";
  return j.str();
}

void print_info(std::ostream& out, const std::string& path, const SceneDesc& scene, const SceneSummary& s,
                const EffectSet& effects, RenderMode auto_mode, const std::string& auto_reason) {
  out << path << (scene.name.empty() ? "" : " (" + scene.name + ")") << "\n"
      << "  geometry:  " << s.triangles << " triangles in " << s.meshes << " meshes, " << s.instances << " instances ("
      << s.instanced_triangles << " triangles placed); " << s.spheres << " spheres, " << s.planes << " planes, " << s.cylinders
      << " cylinders, " << s.tubes << " tubes; " << s.geometry_bytes / 1024 << " KiB\n"
      << "  materials: " << s.materials << " (" << s.emissive_materials << " emissive)\n"
      << "  textures:  " << s.textures << " using " << s.images << " images, " << s.texture_bytes / 1024 << " KiB\n"
      << "  lights:    " << s.point_lights << " point, " << s.spot_lights << " spot, " << s.directional_lights << " directional, "
      << s.ambient_lights << " ambient\n"
      << "  cameras:   " << s.cameras << (s.cameras ? "" : " (a framing camera will be used)") << "\n";
  if (s.has_bounds)
    out << "  bounds:    (" << s.bounds_lower.x << ", " << s.bounds_lower.y << ", " << s.bounds_lower.z << ") to ("
        << s.bounds_upper.x << ", " << s.bounds_upper.y << ", " << s.bounds_upper.z << ")\n";
  out << "  effects:\n";
  size_t reason = 0;
  for (const EffectInfo& info : effect_catalog())
    if (effects.has(info.effect)) out << "    " << info.name << ": " << effects.reasons[reason++] << "\n";
  out << "  auto mode: " << mode_name(auto_mode) << " (" << auto_reason << ")\n";
  for (const std::string& w : s.warnings) out << "  warning: " << w << "\n";
}

}  // namespace

int info_main(int argc, char** argv) {
  CLI::App app{"Scene statistics, warnings, and the effects the scene calls for."};
  std::string scene_path;
  bool json = false, allow_external = false;
  int gltf_scene = -1;
  app.add_option("SCENE", scene_path, "Scene file, or - for a .scene on standard input")->required();
  app.add_flag("--json", json, "Print one JSON object for scripts");
  app.add_option("--scene", gltf_scene, "glTF scene index");
  app.add_flag("--allow-external-files", allow_external, "Let scene files refer to files outside their folder");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "radiant info: " << e.what() << "\n";
    return exit_usage;
  }
  try {
    LoadOptions options;
    options.allow_external_files = allow_external;
    options.gltf_scene = gltf_scene;
    SceneDesc scene = load_scene(scene_path, options);
    SceneSummary summary = summarize_scene(scene);
    EffectSet effects = analyze_effects(scene);
    std::string reason;
    RenderMode auto_mode = choose_auto_mode(scene, reason);
    if (json) std::cout << info_json(scene_path, scene, summary, effects, auto_mode, reason);
    else print_info(std::cout, scene_path, scene, summary, effects, auto_mode, reason);
  } catch (const std::exception& e) {
    std::cerr << "radiant: " << e.what() << "\n";
    return exit_failure;
  }
  return exit_ok;
}

}  // namespace radiant::cli
