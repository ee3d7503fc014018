// Whitted mode against closed-form pixel values (internal units: kd/pi * I * cos / attenuation).
#include <doctest/doctest.h>

#include <cmath>

#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// A plane y = 0 seen from above by an orthographic camera covering [-2, 2]^2 on 8x8 pixels.
SceneDesc lit_plane(int material_kd_index_out[1], color3 kd) {
  SceneDesc scene;
  material_kd_index_out[0] = add_diffuse(scene, kd);
  add_plane(scene, {0, 0, 0}, {0, 1, 0}, material_kd_index_out[0]);
  scene.cameras.push_back(ortho_camera({0, 5, 0}, {0, -1, 0}, {0, 0, -1}, 4));
  return scene;
}

RenderOptions one_sample_whitted() {
  RenderOptions o;
  o.width = 8;
  o.height = 8;
  o.spp = 1;
  o.mode = RenderMode::whitted;
  return o;
}

// World position on the plane seen through the centre of pixel (x, y).
vec3 plane_point(int x, int y) { return {-2 + 0.5f * (x + 0.5f), 0, -(2 - 0.5f * (y + 0.5f))}; }

}  // namespace

TEST_CASE("whitted: a point light with attenuation on a diffuse plane gives kd/pi*I*cos/(kc+kl*d+kq*d^2)") {
  int m;
  SceneDesc scene = lit_plane(&m, {0.8f, 0.5f, 0.25f});
  vec3 light_position = {0.3f, 1.5f, -0.2f};
  scene.lights.push_back(point_light(light_position, {10, 20, 30}, 1.0f, 0.5f, 0.25f));
  RenderResult r = render_scene(scene, one_sample_whitted());
  for (auto pixel : {std::pair{0, 0}, {3, 4}, {7, 7}, {5, 1}}) {
    int x = pixel.first, y = pixel.second;  // clang 14 cannot capture a structured binding in CAPTURE
    vec3 p = plane_point(x, y);
    vec3 to_light = light_position - p;
    float d = length(to_light);
    float cos_theta = to_light.y / d;
    color3 expected = color3{0.8f, 0.5f, 0.25f} * color3{10, 20, 30} * (cos_theta / (1.0f + 0.5f * d + 0.25f * d * d) / pi);
    color3 got = pixel_mean(r.film.at(x, y));
    CAPTURE(x);
    CAPTURE(y);
    for (int c = 0; c < 3; ++c) CHECK(got[c] == doctest::Approx(expected[c]).epsilon(1e-4));
  }
}

TEST_CASE("whitted: a spot light scales the point-light term by cos(angle to its axis)^exponent") {
  int m;
  SceneDesc scene = lit_plane(&m, {1, 1, 1});
  LightDesc spot = point_light({0, 2, 0}, {5, 5, 5}, 1, 0, 0);
  spot.kind = LightKind::spot;
  spot.direction = normalize(vec3{0.2f, -1, 0.1f});
  spot.spot_exponent = 4;
  scene.lights.push_back(spot);
  RenderResult r = render_scene(scene, one_sample_whitted());
  for (auto [x, y] : {std::pair{1, 1}, {4, 4}, {6, 2}}) {
    vec3 p = plane_point(x, y);
    vec3 to_light = spot.position - p;
    float d = length(to_light);
    float beam = std::pow(std::max(0.0f, dot(spot.direction, -to_light / d)), 4.0f);
    float expected = 5 * beam * (to_light.y / d) / pi;
    CHECK(pixel_mean(r.film.at(x, y)).x == doctest::Approx(expected).epsilon(1e-4));
  }
}

TEST_CASE("whitted: an opaque occluder leaves exactly the ambient term, kt = 0.5 halves the direct term") {
  for (float kt : {0.0f, 0.5f}) {
    int m;
    SceneDesc scene = lit_plane(&m, {0.5f, 0.5f, 0.5f});
    scene.materials[m].ka = {0.5f, 0.5f, 0.5f};
    LightDesc ambient;
    ambient.kind = LightKind::ambient;
    ambient.intensity = {0.1f, 0.1f, 0.1f};
    scene.lights.push_back(ambient);
    scene.lights.push_back(point_light({0, 4, 0}, {16, 16, 16}, 0, 0, 1));
    MaterialDesc blocker;
    blocker.kt = {kt, kt, kt};
    blocker.ior = 1;
    int b = add_material(scene, blocker);
    // A large occluder between the light and the whole plane (the camera sees it from above,
    // so look from below the occluder: put the camera under it facing down).
    add_quad(scene, {-10, 2, -10}, {-10, 2, 10}, {10, 2, 10}, {10, 2, -10}, b);
    scene.cameras[0] = ortho_camera({0, 1, 0}, {0, -1, 0}, {0, 0, -1}, 4);
    RenderResult r = render_scene(scene, one_sample_whitted());
    vec3 p = plane_point(2, 5);
    vec3 to_light = vec3{0, 4, 0} - p;
    float d = length(to_light);
    float direct = 0.5f * 16 * (to_light.y / d) / (d * d) / pi;
    float ambient_term = 0.5f * 0.1f;
    CAPTURE(kt);
    CHECK(pixel_mean(r.film.at(2, 5)).x == doctest::Approx(ambient_term + kt * direct).epsilon(1e-4));
  }
}

TEST_CASE("whitted: a triangle mesh lying in the plane y = 0 is lit, not shadowed by itself") {
  // Regression: the error bound of a point with y exactly 0 was 0 along the normal, so shadow
  // rays started on the surface and Embree hit it again at t = 0.
  SceneDesc scene;
  int m = add_diffuse(scene, {1, 1, 1});
  add_quad(scene, {-3, 0, 3}, {3, 0, 3}, {3, 0, -3}, {-3, 0, -3}, m);
  scene.lights.push_back(point_light({0, 2, 0}, {4, 4, 4}));
  scene.cameras.push_back(ortho_camera({0, 5, 0}, {0, -1, 0}, {0, 0, -1}, 4));
  RenderResult r = render_scene(scene, one_sample_whitted());
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      vec3 p = plane_point(x, y);
      vec3 to_light = vec3{0, 2, 0} - p;
      float d = length(to_light);
      CHECK(pixel_mean(r.film.at(x, y)).x == doctest::Approx(4 * (2 / d) / (d * d) / pi).epsilon(1e-4));
    }
}
