#include "option_parsing.h"

#include <limits>

#include "environment_flags.h"
#include "image/view_transform.h"
#include "lights/light_table.h"
#include "render/render.h"
#include "sampling/pixel_filter.h"
#include "scene/coordinate_range.h"

namespace radiant::cli {

void RenderFlags::bind(CLI::App& app, bool image_flags) {
  if (image_flags) {
    app.add_option("--width", width, "Image width in pixels (default: from the scene or camera)")->check(CLI::Range(1, 65536));
    app.add_option("--height", height, "Image height in pixels")->check(CLI::Range(1, 65536));
    app.add_option("--spp", spp, "Samples per pixel (the maximum with --noise-threshold)")->check(CLI::Range(1, 1 << 24));
    app.add_option("--exposure", options.exposure, "Exposure in stops for PNG, TIFF, JPEG... (EXR stays linear)")
        ->check(number_in(-64, 64));
    app.add_option("--view", view, "View transform of PNG, TIFF, JPEG...: standard (sRGB), linear, filmic, agx, neutral (Khronos PBR Neutral) or aces");
    app.add_option("--bit-depth", options.bit_depth, "8 or 16 bits per channel for PNG and TIFF")
        ->check(CLI::IsMember({8, 16}));
    app.add_flag("--half", options.half_float, "EXR with 16-bit half floats instead of 32-bit");
    app.add_flag("--no-metadata", no_metadata,
                 "Record nothing about the render in the image (version, command, times...): the same render "
                 "then writes the same bytes");
    app.add_flag("--denoise", options.denoise,
                 "Denoise the image (feature-guided regression on albedo, normal and depth) before it is written");
    app.add_flag("--transparent", transparent,
                 "RGBA with alpha = coverage of geometry; the background is not seen but still lights the scene "
                 "(EXR premultiplied, PNG/TIFF straight alpha)");
  }
  app.add_option("--mode", mode, "Integrator: whitted, path, naive or auto (default auto)");
  app.add_option("--max-depth", max_depth, "Surface interactions that gather light (1 = direct only)")->check(CLI::Range(1, 1000));
  app.add_option("--indirect-paths", indirect_paths,
                 "Paths each camera sample sends on from its first hit (path tracing; default 1): its direct light "
                 "is taken once, its bounce this many times")
      ->check(CLI::Range(1, max_indirect_paths));
  app.add_option("--clamp-direct", options.clamp_direct,
                 "Path tracing: the most a sample's light from its first hit may add, per channel (0 = off; "
                 "cuts fireflies, darkens bright light)")
      ->check(number_in(0, std::numeric_limits<float>::max()));
  app.add_option("--clamp-indirect", options.clamp_indirect,
                 "Path tracing: the most each bounce's light may add to a sample, per channel (0 = off; cuts "
                 "fireflies, darkens bright indirect light)")
      ->check(number_in(0, std::numeric_limits<float>::max()));
  app.add_option("--threads", options.threads, "Worker threads (default: all cores); never changes the image")->check(CLI::Range(0, 1024));
  app.add_option("--seed", options.seed, "Random seed");
  app.add_option("--sampler", sampler, "grid, random, jittered (Whitted default) or sobol (path default)");
  app.add_option("--filter", filter, "Pixel filter: box (default), triangle, gaussian, mitchell or blackman-harris");
  app.add_option("--filter-width", filter_width,
                 "The filter's full width in pixels (default: box 1, gaussian 3, triangle, mitchell, blackman-harris 4)")
      ->check(positive_number(max_filter_width));
  app.add_option("--light-sampler", light_sampler,
                 "How the path tracer chooses a light: power, bvh (by estimated contribution) or auto (bvh from " +
                     std::to_string(light_bvh_min_lights) + " lights with a position; default)");
  app.add_option("--camera", options.camera, "Camera name or index (default: the first)");
  app.add_option("--scene", gltf_scene, "glTF scene index (default: the file's default scene)")->check(CLI::NonNegativeNumber);
  app.add_option("--variant", variant, "glTF material variant by name (KHR_materials_variants)");
  app.add_option("--env-color", env_color, "Uniform environment radiance R,G,B (linear)");
  app.add_option("--env", env,
                 "Environment: studio (the default for files with no light of their own), white, none, or an "
                 "equirectangular map (.exr, .hdr)");
  app.add_option("--env-intensity", env_intensity, "Multiplies the environment's radiance (default 1)")
      ->check(number_in(0, 1e6));
  app.add_option("--env-rotation", env_rotation,
                 "Turns the environment about the up axis, in degrees, counterclockwise seen from above (at 0 "
                 "the map's centre faces +X, as in Blender and three.js)")
      ->check(number_in(-36000, 36000));
  app.add_option("--background", background,
                 "What the camera sees behind the scene: blur (the environment blurred; default), env, "
                 "transparent or color:R,G,B");
  app.add_option("--look-from", look_from, "Camera position X,Y,Z");
  app.add_option("--look-at", look_at, "Point the camera looks at X,Y,Z");
  app.add_option("--up", up,
                 "The scene's up: an axis (+Z for z-up files) or X,Y,Z; turns the framing camera and the "
                 "environment, and is the up of a camera placed by --look-from/--look-at");
  app.add_option("--orbit", orbit,
                 "AZIMUTH,ELEVATION[,DISTANCE]: the framing camera turned about the model in degrees, and "
                 "its distance as a multiple of the framing one");
  app.add_option("--fov", fov, "Vertical field of view in degrees (a fisheye's whole one, up to 360)")
      ->check(positive_number(360));
  app.add_option("--camera-type", camera_type,
                 "perspective, orthographic (framing the scene unless placed by the flags), equirect (360 degrees) or fisheye");
  app.add_option("--ortho-height", ortho_height, "An orthographic view's full height in scene units (default: the scene's)")
      ->check(positive_number(max_scene_coordinate));
  app.add_option("--lens-radius", lens_radius, "Thin-lens aperture radius in scene units (0 = pinhole)")
      ->check(number_in(0, max_scene_coordinate));
  app.add_option("--focus-distance", focus_distance, "Distance in focus along the view (default: to --look-at)")
      ->check(positive_number(max_scene_coordinate));
  app.add_option("--blades", blades, "Aperture blades: a polygonal bokeh (0 = round)")->check(CLI::Range(0, 64));
  app.add_option("--texture-filter", texture_filter,
                 "point (nearest texel), bilinear (full resolution) or trilinear (mip-mapped by the pixel's "
                 "footprint; default)");
  app.add_option("--line-width", line_width,
                 "Width of lines and points without one of their own: pixels at their distance (default 1), or "
                 "world units with a trailing m (0.01m)");
  app.add_option("--batching", batching,
                 "How paths share ray tracing: all (paths advance together, every ray in streams; default), "
                 "camera (a tile's camera rays as packets, then each path alone) or none; the image is the same");
  app.add_option("--effects", options.effects, "Switch effects off/on: e.g. -shadows,-indirect, or 'all' (generic integrator)");
  app.add_flag("--allow-external-files", allow_external_files, "Let scene files refer to files outside their folder");
  app.add_option("--max-memory", max_memory,
                 "Memory cap in GiB for loading and rendering: work that would need more is refused before it "
                 "allocates (default 1/4 of RAM)");
  log.bind(app);
}

void RenderFlags::finish() {
  if (width) options.width = width;
  if (height) options.height = height;
  if (spp) options.spp = spp;
  if (max_depth) options.max_depth = max_depth;
  if (indirect_paths) options.indirect_paths = indirect_paths;
  if (!mode.empty()) options.mode = parse_mode("--mode", mode);
  if (!sampler.empty()) options.sampler = parse_sampler("--sampler", sampler);
  if (!view.empty()) {
    try {
      options.view = parse_view_transform(view);
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError("--view", e.what());
    }
  }
  if (transparent) options.transparent = true;
  if (!filter.empty()) {
    try {
      options.filter = parse_pixel_filter(filter);
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError("--filter", e.what());
    }
  }
  if (filter_width > 0) options.filter_width = filter_width;
  if (!texture_filter.empty()) options.texture_filter = parse_texture_filter("--texture-filter", texture_filter);
  if (!batching.empty()) options.path_batching = parse_batching("--batching", batching);
  if (!line_width.empty()) options.line_width = parse_line_width("--line-width", line_width);
  if (!light_sampler.empty()) options.light_sampler = parse_light_sampler("--light-sampler", light_sampler);
  if (!env_color.empty()) {
    vec3 c = parse_vec3("--env-color", env_color);
    if (min_component(c) < 0) throw CLI::ValidationError("--env-color", "radiance cannot be negative");
    options.env_color = c;
  }
  if (!crop.empty()) options.crop = parse_window("--crop", crop);
  if (!shard.empty()) {
    if (!crop.empty() || !sample_range.empty())
      throw CLI::ValidationError("--shard", "takes its region and samples itself: not with --crop or --sample-range");
    options.shard = parse_shard("--shard", shard);
    if (!split.empty()) options.shard->split = parse_split("--split", split);
  } else if (!split.empty()) {
    throw CLI::ValidationError("--split", "needs --shard I/K");
  }
  if (!sample_range.empty()) options.sample_range = parse_sample_range("--sample-range", sample_range);
  if (!aovs.empty()) options.aovs = parse_aovs("--aov", aovs);
  if (wants_aov(options.aovs, "noisy") && !options.denoise)
    throw CLI::ValidationError("--aov", "noisy is the image before denoising: it needs --denoise");
  if (options.denoise && (!shard.empty() || !sample_range.empty()))
    throw CLI::ValidationError("--denoise", "is a step after merge: not with --shard or --sample-range");
  if (!look_from.empty()) options.camera_override.look_from = parse_vec3("--look-from", look_from);
  if (!look_at.empty()) options.camera_override.look_at = parse_vec3("--look-at", look_at);
  if (!up.empty()) {
    options.world_up = parse_up("--up", up);
    // A file's camera keeps its own roll; a camera placed by the flags stands on this up.
    if (!look_from.empty() || !look_at.empty()) options.camera_override.up = options.world_up;
  }
  if (!orbit.empty()) options.orbit = parse_orbit("--orbit", orbit);
  if (!env.empty()) parse_environment_choice(env, options);
  options.env_intensity = env_intensity;
  options.env_rotation_degrees = env_rotation;
  if (!background.empty()) {
    parse_background(background, options);
    if (transparent && options.background != BackgroundKind::transparent)
      throw CLI::ValidationError("--background", "contradicts --transparent");
  }
  if (fov != 0) options.camera_override.fov_degrees = fov;
  if (ortho_height > 0) options.camera_override.ortho_height = ortho_height;
  if (!camera_type.empty()) options.camera_override.projection = parse_camera_type("--camera-type", camera_type);
  if (lens_radius >= 0) options.camera_override.lens_radius = lens_radius;
  if (focus_distance > 0) options.camera_override.focus_distance = focus_distance;
  if (blades == 1 || blades == 2) throw CLI::ValidationError("--blades", "an aperture needs 0 (round) or at least 3 blades");
  if (blades >= 0) options.camera_override.aperture_blades = blades;
  if (!max_memory.empty()) max_memory_bytes = parse_memory_limit("--max-memory", max_memory);
  LogLevel level = log.level();
  options.quiet = !shows(level, LogLevel::info);
  options.quiet_warnings = !shows(level, LogLevel::warning);
}

MemoryBudget command_memory_budget(const std::optional<uint64_t>& max_memory_bytes) {
  if (max_memory_bytes) return MemoryBudget(*max_memory_bytes, "--max-memory");
  return MemoryBudget(default_memory_limit(), default_memory_limit_source);
}

MemoryBudget RenderFlags::memory_budget() const { return command_memory_budget(max_memory_bytes); }

}  // namespace radiant::cli
