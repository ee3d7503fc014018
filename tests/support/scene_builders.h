// Small scenes built in code for analytic tests: no file format in between.
#pragma once

#include "render/render.h"
#include "scene/scene_desc.h"

namespace radiant::test {

// Adds a Phong material with diffuse reflectance `kd` and returns its index.
int add_diffuse(SceneDesc& scene, color3 kd);
int add_material(SceneDesc& scene, const MaterialDesc& material);
void add_sphere(SceneDesc& scene, vec3 center, float radius, int material);
void add_plane(SceneDesc& scene, vec3 point, vec3 normal, int material);
// A quad as a two-triangle mesh with an identity instance (normal = (b - a) x (c - a)).
void add_quad(SceneDesc& scene, vec3 a, vec3 b, vec3 c, vec3 d, int material);
LightDesc point_light(vec3 position, color3 intensity, float kc = 0, float kl = 0, float kq = 1);
// Orthographic camera at `position` looking along `forward`, view `height` tall.
CameraDesc ortho_camera(vec3 position, vec3 forward, vec3 up, float height);
CameraDesc perspective_camera(vec3 position, vec3 forward, vec3 up, float vfov_degrees);

// Renders in-process and returns the result.
RenderResult render_scene(const SceneDesc& scene, const RenderOptions& options);

}  // namespace radiant::test
