// `--mode auto`: Whitted when it gives the answer the path tracer would converge to.
#include <string>

#include "render/render.h"

namespace radiant {

namespace {

bool is_emissive(const SceneDesc& scene, int material) {
  return material >= 0 && !is_black(scene.materials[material].emission);
}

}  // namespace

RenderMode choose_auto_mode(const SceneDesc& scene, bool environment, std::string& reason) {
  for (const LightDesc& l : scene.lights)
    if (l.kind == LightKind::ambient) {
      reason = "the scene has ambient light, which only the Whitted model defines";
      return RenderMode::whitted;
    }
  if (environment) {
    reason = "the background lights the scene (environment light needs the path tracer)";
    return RenderMode::path;
  }
  size_t objects = scene.shapes.size() + scene.instances.size() + scene.strokes.size();
  bool single_convex = scene.instances.empty() && scene.strokes.empty() && scene.shapes.size() == 1 &&
                       scene.shapes[0].kind != ShapeKind::tube && scene.shapes[0].kind != ShapeKind::cylinder;
  if (objects > 1 || !scene.instances.empty()) {
    for (const ShapeDesc& s : scene.shapes)
      if (is_emissive(scene, s.material)) {
        reason = "emissive surfaces light other objects (area lights need the path tracer)";
        return RenderMode::path;
      }
    for (const InstanceDesc& i : scene.instances)
      if (is_emissive(scene, scene.meshes[i.mesh].material)) {
        reason = "emissive surfaces light other objects (area lights need the path tracer)";
        return RenderMode::path;
      }
  }
  if (!single_convex) {
    reason = "light can bounce between surfaces (indirect light needs the path tracer)";
    return RenderMode::path;
  }
  // One convex object: it cannot light itself, so what it shows is its own emission and the
  // direct light of the delta lights, which the Whitted model computes exactly.
  if (!scene.lights.empty())
    reason = "one convex object lit only by point, spot or directional lights: no indirect light exists";
  else if (is_emissive(scene, scene.shapes[0].material))
    reason = "one convex emissive object and no other light: it shows only its own emission";
  else
    reason = "nothing emits light: the image is black in every mode";
  return RenderMode::whitted;
}

}  // namespace radiant
