#include "render/prepared_scene.h"

#include <chrono>
#include <optional>

#include "accel/accel_memory.h"
#include "render/camera.h"
#include "scene/effects.h"
#include "scene/scene_motion.h"

namespace radiant {

namespace {

// The image's width / height as a camera without an aspect of its own will see it (1 when the
// size comes from the default).
float image_aspect(const SceneSettings& settings, const RenderOptions& options) {
  // One side from the flags keeps the scene's shape (resolve_settings).
  bool flags = options.width && options.height;
  std::optional<int> width = flags ? options.width : settings.width;
  std::optional<int> height = flags ? options.height : settings.height;
  return width && height && *width > 0 && *height > 0 ? float(*width) / float(*height) : 1.0f;
}

}  // namespace

void build_accel(PreparedScene& prepared) {
  prepared.accel.reset();
  prepared.accel_memory = MemoryCharge();
  prepared.accel_memory = MemoryCharge(prepared.budget, accel_build_bytes(*prepared.scene),
                                       prepared.scene->source_path + ": the accelerator");
  auto start = std::chrono::steady_clock::now();
  prepared.accel = build_scene_accel(*prepared.scene, prepared.layout, prepared.stroke_sizing);
  prepared.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

CameraDesc world_view_camera(const PreparedScene& prepared, const RenderOptions& options, bool& framed) {
  return world_view_camera(prepared.world, prepared.scene->settings, options, framed);
}

CameraDesc world_view_camera(const WorldPlacement& world, const SceneSettings& settings, const RenderOptions& options,
                             bool& framed) {
  CameraDesc framing;
  framing.name = "framing";
  vec3 up = options.world_up ? normalize(*options.world_up) : vec3{0, 1, 0};
  if (world.has_framing_box)
    framing = frame_box(world.framing_lower, world.framing_upper, image_aspect(settings, options), up,
                        options.orbit.value_or(Orbit{}));
  // --orbit turns the framing camera, which it takes unless another is named.
  std::string which = options.orbit && options.camera.empty() ? framing_camera_name : options.camera;
  CameraDesc camera = select_camera(world.cameras, framing, which, framed);
  if (options.orbit && !framed)
    throw std::invalid_argument("--orbit turns the framing camera: leave out --camera, or give --camera frame");
  bool made_orthographic = camera.projection != Projection::orthographic &&
                           options.camera_override.projection == Projection::orthographic;
  apply_camera_override(camera, options.camera_override);
  // A view turned orthographic by the flags shows the whole scene, as the framing camera does.
  if (made_orthographic && world.has_framing_box)
    frame_orthographic(camera, world.framing_lower, world.framing_upper, image_aspect(settings, options),
                       options.camera_override.look_from.has_value(), options.camera_override.ortho_height.has_value());
  // A camera placed entirely by the flags is not a framing camera.
  if (options.camera_override.look_from && options.camera_override.look_at) framed = false;
  return camera;
}

// How the view of `options` sizes the prepared scene's lines and points.
static StrokeSizing view_stroke_sizing(const PreparedScene& prepared, const RenderOptions& options) {
  if (prepared.scene->strokes.empty() || !options.line_width.in_pixels) return {options.line_width, {}};
  bool framed = false;
  CameraDesc camera = world_view_camera(prepared, options, framed);
  int height = resolved_image_height(options, *prepared.scene, camera);
  return stroke_sizing_in_pixels(options.line_width, camera, height, prepared.origin);
}

PreparedScene prepare_scene(SceneDesc scene, const RenderOptions& options, AccelLayout layout) {
  // Without motion blur the scene holds still at the rendered time.
  if (!(apply_effects_override(effect_motion_blur, options.effects) & effect_motion_blur)) drop_motion(scene);
  PreparedScene prepared;
  prepared.budget = options.memory;
  prepared.layout = layout;
  prepared.world = record_world_placement(scene);
  prepared.scene = std::make_unique<SceneDesc>(std::move(scene));
  bool framed = false;
  prepared.origin = choose_render_origin(prepared.world, world_view_camera(prepared, options, framed).position);
  place_at_render_origin(*prepared.scene, prepared.world, prepared.origin);
  prepared.stroke_sizing = view_stroke_sizing(prepared, options);
  build_accel(prepared);
  prepared.effects = analyze_effects(*prepared.scene);
  if (options.texture_filter == TextureFilterMode::trilinear)
    prepared.texture_pyramids = std::make_unique<TexturePyramids>(build_texture_pyramids(*prepared.scene, options.memory));
  return prepared;
}

double prepare_view(PreparedScene& prepared, const RenderOptions& options) {
  bool framed = false;
  dvec3 origin = choose_render_origin(prepared.world, world_view_camera(prepared, options, framed).position);
  bool moved = origin.x != prepared.origin.x || origin.y != prepared.origin.y || origin.z != prepared.origin.z;
  if (moved) {
    prepared.origin = origin;
    place_at_render_origin(*prepared.scene, prepared.world, origin);
  }
  // Lines and points a number of pixels wide follow the view.
  StrokeSizing sizing = view_stroke_sizing(prepared, options);
  if (!moved && same_sizing(sizing, prepared.stroke_sizing)) return 0;
  prepared.stroke_sizing = sizing;
  build_accel(prepared);
  return prepared.build_seconds;
}

}  // namespace radiant
