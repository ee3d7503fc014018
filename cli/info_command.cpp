// `radiant info SCENE [--json]`: scene statistics, warnings, and the effects it calls for; and
// `radiant info IMAGE [--json]`: an image's size, channels and what radiant recorded in it.
#include <cstdio>
#include <iostream>

#include "commands.h"
#include "accel/light_enclosure.h"
#include "animation_flags.h"
#include "image_info.h"
#include "json_output.h"
#include "load_scene.h"
#include "option_parsing.h"
#include "render/render.h"
#include "render_report.h"
#include "scene/effects.h"
#include "scene/enum_names.h"
#include "scene/scene_summary.h"

namespace radiant::cli {

namespace {

// "1 cylinder", "2 meshes": a count with its noun in the number it needs.
std::string count_of(size_t count, const std::string& noun) {
  bool sibilant = noun.back() == 's' || noun.back() == 'h' || noun.back() == 'x';
  return std::to_string(count) + " " + noun + (count == 1 ? "" : sibilant ? "es" : "s");
}

// The counts that are not zero, joined by ", "; `none` when all are.
std::string nonzero_counts(const std::vector<std::pair<size_t, std::string>>& counts, const std::string& none) {
  std::string text;
  for (const auto& [count, noun] : counts)
    if (count) text += (text.empty() ? "" : ", ") + count_of(count, noun);
  return text.empty() ? none : text;
}

// "812 bytes", "1.4 KiB", "12.0 MiB": one decimal at every size, as a summary reads best.
std::string size_text(uint64_t bytes) {
  if (bytes < 1024) return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
  const char* units[] = {"KiB", "MiB", "GiB", "TiB"};
  double value = double(bytes) / 1024;
  int unit = 0;
  while (value >= 1024 && unit < 3) value /= 1024, ++unit;
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %s", value, units[unit]);
  return text;
}

// "2 s", "0.5 s": an animation's length.
std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%g s", seconds);
  return text;
}

std::string info_json(const std::string& path, const SceneDesc& scene, const SceneFileChoices& choices, const SceneSummary& s,
                      const EffectSet& effects, RenderMode auto_mode, const std::string& auto_reason) {
  Json j;
  j["scene"] = path;
  j["name"] = scene.name;
  j["geometry"] = {{"meshes", s.meshes},       {"instances", s.instances}, {"triangles", s.triangles},
                   {"instanced_triangles", s.instanced_triangles},         {"spheres", s.spheres},
                   {"planes", s.planes},       {"cylinders", s.cylinders}, {"tubes", s.tubes},
                   {"line_segments", s.line_segments}, {"points", s.points},
                   {"bytes", s.geometry_bytes}};
  j["materials"] = s.materials;
  j["emissive_materials"] = s.emissive_materials;
  j["textures"] = {{"count", s.textures}, {"images", s.images}, {"bytes", s.texture_bytes}};
  j["lights"] = {{"ambient", s.ambient_lights}, {"directional", s.directional_lights}, {"point", s.point_lights},
                 {"spot", s.spot_lights}};
  j["cameras"] = s.cameras;
  Json cameras = Json::array(), lights = Json::array();
  for (size_t i = 0; i < scene.cameras.size(); ++i)
    cameras.push_back({{"index", i}, {"name", scene.cameras[i].name}, {"projection", name_of(projection_names, scene.cameras[i].projection)}});
  for (size_t i = 0; i < scene.lights.size(); ++i)
    lights.push_back({{"index", i}, {"name", scene.lights[i].name}, {"kind", name_of(light_kind_names, scene.lights[i].kind)}});
  j["camera_list"] = cameras;
  j["light_list"] = lights;
  Json animations = Json::array();
  for (size_t i = 0; i < choices.animations.size(); ++i)
    animations.push_back({{"index", i}, {"name", choices.animations[i].name}, {"seconds", choices.animations[i].seconds}});
  j["animations"] = animations;
  j["material_variants"] = choices.material_variants;
  j["bounds"] = s.has_bounds ? Json{{"min", json_vec3(s.bounds_lower)}, {"max", json_vec3(s.bounds_upper)}} : Json(nullptr);
  Json list = Json::array();
  size_t reason = 0;
  for (const EffectInfo& info : effect_catalog())
    if (effects.has(info.effect)) list.push_back({{"effect", info.name}, {"reason", effects.reasons[reason++]}});
  j["effects"] = list;
  j["auto_mode"] = {{"mode", mode_name(auto_mode)}, {"reason", auto_reason}};
  j["warnings"] = s.warnings;
  return json_text(j);
}

void print_info(std::ostream& out, const std::string& path, const SceneDesc& scene, const SceneFileChoices& choices,
                const SceneSummary& s, const EffectSet& effects, RenderMode auto_mode, const std::string& auto_reason) {
  std::string shapes = nonzero_counts({{s.spheres, "sphere"}, {s.planes, "plane"}, {s.cylinders, "cylinder"}, {s.tubes, "tube"},
                                       {s.line_segments, "line segment"}, {s.points, "point"}},
                                      "");
  out << path << (scene.name.empty() ? "" : " (" + scene.name + ")") << "\n"
      << "  geometry:  " << count_of(s.triangles, "triangle") << " in " << count_of(s.meshes, "mesh") << ", "
      << count_of(s.instances, "instance") << " (" << s.instanced_triangles << " placed)" << (shapes.empty() ? "" : "; " + shapes)
      << "; " << size_text(s.geometry_bytes) << "\n"
      << "  materials: " << s.materials << (s.emissive_materials ? " (" + std::to_string(s.emissive_materials) + " emissive)" : "")
      << "\n"
      << "  textures:  "
      << (s.textures ? count_of(s.textures, "texture") + " using " + count_of(s.images, "image") + ", " + size_text(s.texture_bytes)
                     : "none")
      << "\n";
  // Each light, camera, animation and variant by index and name, as the flags take them.
  out << "  lights:    "
      << nonzero_counts({{s.point_lights, "point"}, {s.spot_lights, "spot"}, {s.directional_lights, "directional"},
                         {s.ambient_lights, "ambient"}},
                        "none")
      << "\n";
  for (size_t i = 0; i < scene.lights.size(); ++i)
    out << "    light " << i << (scene.lights[i].name.empty() ? "" : " '" + scene.lights[i].name + "'") << ": "
        << name_of(light_kind_names, scene.lights[i].kind) << "\n";
  out << "  cameras:   " << s.cameras << (s.cameras ? "" : " (a framing camera will be used)") << "\n";
  for (size_t i = 0; i < scene.cameras.size(); ++i)
    out << "    camera " << i << (scene.cameras[i].name.empty() ? "" : " '" + scene.cameras[i].name + "'") << ": "
        << name_of(projection_names, scene.cameras[i].projection) << "\n";
  if (!choices.animations.empty()) out << "  animations: " << choices.animations.size() << " (--animation NAME|INDEX)\n";
  for (size_t i = 0; i < choices.animations.size(); ++i)
    out << "    animation " << i << (choices.animations[i].name.empty() ? "" : " '" + choices.animations[i].name + "'")
        << ": " << seconds_text(choices.animations[i].seconds) << "\n";
  if (!choices.material_variants.empty())
    out << "  variants:  " << choices.material_variants.size() << " (--variant NAME)\n";
  for (size_t i = 0; i < choices.material_variants.size(); ++i)
    out << "    variant " << i << " '" << choices.material_variants[i] << "'\n";
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
  CLI::App app{"Scene statistics, warnings, and the effects the scene calls for; or an image's size, channels and "
               "the metadata radiant recorded in it (how it was made)."};
  app.footer(
      "\nExamples:\n"
      "  radiant info assets/showcase.scene                       # counts, bounds, lights, effects, auto mode\n"
      "  radiant info assets/models/turntable.gltf                # also its animations and material variants\n"
      "  radiant info assets/cornell.gltf --json | jq .warnings   # one JSON object for scripts\n"
      "  radiant info assets/cornell.gltf --scene 0               # a glTF scene of the file by index\n"
      "  cat assets/room-older-format.scene | radiant info -      # a .scene on standard input\n"
      "  radiant render assets/cornell.gltf -o cornell.png && radiant info cornell.png   # how radiant made it\n"
      "  radiant render assets/cornell.gltf -o s3.exr --shard 3/8 && radiant info s3.exr --json | jq .metadata\n");
  std::string scene_path;
  bool json = false, allow_external = false;
  int gltf_scene = -1;
  app.add_option("SCENE", scene_path, "Scene file, - for a .scene on standard input, or an image file")->required();
  app.add_flag("--json", json, "Print one JSON object for scripts");
  app.add_option("--scene", gltf_scene, "glTF scene index");
  app.add_flag("--allow-external-files", allow_external, "Let scene files refer to files outside their folder");
  // The moment a render would show, so that the effects (motion blur) are that render's.
  AnimationFlags animation;
  animation.bind(app);
  LoadOptions options;
  try {
    parse_arguments(app, argc, argv);
    animation.finish(options);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "radiant info: " << e.what() << "\n";
    return exit_usage;
  }
  try {
    if (is_image_path(scene_path)) {
      if (gltf_scene >= 0 || allow_external) {
        std::cerr << "radiant info: --scene and --allow-external-files are for scene files, not the image '" << scene_path
                  << "'\n";
        return exit_usage;
      }
      print_image_info(std::cout, scene_path, json);
      return exit_ok;
    }
    options.allow_external_files = allow_external;
    options.gltf_scene = gltf_scene;
    MemoryBudget budget = command_memory_budget(std::nullopt);
    options.budget = &budget;
    SceneFile file = read_scene_file(scene_path, options);
    SceneFileChoices choices = scene_file_choices(file);
    SceneDesc scene = scene_from_file(file, options);
    SceneSummary summary = summarize_scene(scene);
    for (std::string& warning : enclosed_light_warnings(scene)) summary.warnings.push_back(std::move(warning));
    EffectSet effects = analyze_effects(scene);
    std::string reason;
    // The plain command's environment: the file's own, or the studio when nothing lights it.
    bool environment = !is_black(scene.environment.color) || !scene.environment.map_path.empty() || !lights_itself(scene);
    RenderMode auto_mode = choose_auto_mode(scene, environment, reason);
    if (json) std::cout << info_json(scene_path, scene, choices, summary, effects, auto_mode, reason);
    else print_info(std::cout, scene_path, scene, choices, summary, effects, auto_mode, reason);
  } catch (const std::exception& e) {
    std::cerr << "radiant: " << e.what() << "\n";
    return exit_failure;
  }
  return exit_ok;
}

}  // namespace radiant::cli
