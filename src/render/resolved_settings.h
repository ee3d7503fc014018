// A render's settings once the flags, the scene file and the defaults are combined.
#pragma once

#include <cstdint>
#include <string>

#include "lights/light_table.h"
#include "render/render_options.h"
#include "scene/scene_desc.h"

namespace radiant {

// Settings after combining flags, the scene file's settings and the defaults.
struct ResolvedSettings {
  int width = 0, height = 0, spp = 1, max_depth = 1;
  int indirect_paths = 1;  // paths from each camera sample's first hit (path and naive modes)
  RenderMode mode = RenderMode::path;
  std::string mode_reason;  // why auto picked the mode ("" when given)
  SamplerKind sampler = SamplerKind::jittered;
  ViewTransform view = ViewTransform::standard;
  bool transparent = false;  // RGBA with coverage as alpha, the background not seen
  PixelFilterKind filter = PixelFilterKind::box;
  float filter_radius = 0.5f;  // pixels: half the filter's width
  LightSampler light_sampler = LightSampler::power;  // as the light table resolved `automatic`
  CameraDesc camera;
  bool camera_framed = false;  // no camera in the file: one frames the scene
  EnvironmentSpec environment;  // what lights the scene from afar
  // The environment was chosen because the scene has no light of its own.
  bool default_environment = false;
  vec3 world_up = {0, 1, 0};
  BackgroundKind background = BackgroundKind::blur;
  color3 background_color;
  uint32_t effects = 0;          // what runs: the scene's effects after --effects
  uint32_t compiled_variant = 0; // the compiled effect set that runs them
  PixelWindow window;
  SampleRange samples;  // the sample indices of each pixel this render takes, of [0, spp)
};

}  // namespace radiant
