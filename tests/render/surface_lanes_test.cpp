// The surface lanes (integrators/surface_lanes.h), Lambert, glossy and Phong, against the one-path
// functions they stand in for, to the bit, on every instruction set this CPU runs. The
// render-level check, the batch against one path at a time, is in batched_paths_test.cpp.
#include <doctest/doctest.h>

#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <vector>

#include "accel/analytic_shapes.h"
#include "accel/scene_accel.h"
#include "integrators/surface_lanes.h"
#include "lights/area_light.h"
#include "lights/delta_light.h"
#include "lights/environment_light.h"
#include "lights/light_table.h"
#include "materials/bsdf.h"
#include "materials/bsdf_models.h"
#include "materials/metallic_roughness_lane.h"
#include "math/transform.h"
#include "sampling/warp.h"
#include "support/test_support.h"

using namespace radiant;

namespace {

bool same_bits(float a, float b) { return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b); }
bool same_bits(vec3 a, vec3 b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z); }

struct LaneCase {
  vec3 p0, p1, p2;
  vec2 barycentric;
  bool has_normals = false;
  vec3 n0, n1, n2;  // vertex normals, when it has them
  // Or the normal a normal or bump map made (on the authored side, as HitShading has it).
  bool has_given_normal = false;
  vec3 given_normal;
  vec3 direction;
  color3 albedo;
  LightDesc light;         // a point light, unless `area`
  bool area = false;       // an emitting triangle or sphere (by triangle.shape) instead
  const LightTable* environment = nullptr;  // or the environment of this table
  float u_environment = 0;                  // its choice of map or cosine sampling, with u_point
  AreaLight triangle;
  color3 emission;
  vec2 u_point;
  float select_pdf;
  vec3 cosine;
  color3 throughput;
  // A glossy lane's metallic-roughness material (its base colour instead of `albedo`), lobe
  // choice and the bounce's numbers, of which `cosine` is the diffuse warp.
  SurfaceMaterial material;
  float u_lobe = 0.5f;
  vec2 u;
  // The triangle's instance transform, where it has one.
  bool transformed = false;
  mat4 transform;
  // Or a sphere or a plane instead of the triangle, hit by a ray from `origin` at distance `t`,
  // with the intersector's unnormalised normal.
  bool is_shape = false;
  ShapeDesc shape;
  vec3 origin, raw_normal;
  float t = 0;
};


void set_lane(SurfaceLanes& l, int i, const LaneCase& c) {
  l.p0x[i] = c.p0.x, l.p0y[i] = c.p0.y, l.p0z[i] = c.p0.z;
  l.p1x[i] = c.p1.x, l.p1y[i] = c.p1.y, l.p1z[i] = c.p1.z;
  l.p2x[i] = c.p2.x, l.p2y[i] = c.p2.y, l.p2z[i] = c.p2.z;
  l.b1[i] = c.barycentric.x, l.b2[i] = c.barycentric.y;
  vec3 ng = c.is_shape ? c.raw_normal : cross(c.p1 - c.p0, c.p2 - c.p0);  // Embree's Ng
  l.ngx[i] = ng.x, l.ngy[i] = ng.y, l.ngz[i] = ng.z;
  l.shape[i] = !c.is_shape ? SurfaceLanes::triangle_hit
               : c.shape.kind == ShapeKind::sphere ? SurfaceLanes::sphere_hit : SurfaceLanes::plane_hit;
  if (c.is_shape) {
    l.hit_kinds |= SurfaceLanes::shape_hits;
    l.ray_ox[i] = c.origin.x, l.ray_oy[i] = c.origin.y, l.ray_oz[i] = c.origin.z, l.ray_t[i] = c.t;
    l.center_x[i] = c.shape.center.x, l.center_y[i] = c.shape.center.y, l.center_z[i] = c.shape.center.z;
    l.radius[i] = c.shape.radius;
    l.axis_x[i] = c.shape.axis.x, l.axis_y[i] = c.shape.axis.y, l.axis_z[i] = c.shape.axis.z;
  }
  l.normals[i] = c.has_given_normal ? SurfaceLanes::given_normal
                 : c.has_normals    ? SurfaceLanes::vertex_normals
                                    : SurfaceLanes::no_normals;
  vec3 n0 = c.has_given_normal ? c.given_normal : c.n0;
  l.n0x[i] = n0.x, l.n0y[i] = n0.y, l.n0z[i] = n0.z;
  l.n1x[i] = c.n1.x, l.n1y[i] = c.n1.y, l.n1z[i] = c.n1.z;
  l.n2x[i] = c.n2.x, l.n2y[i] = c.n2.y, l.n2z[i] = c.n2.z;
  l.dx[i] = c.direction.x, l.dy[i] = c.direction.y, l.dz[i] = c.direction.z;
  l.albedo_r[i] = c.albedo.x, l.albedo_g[i] = c.albedo.y, l.albedo_b[i] = c.albedo.z;
  bool sphere = c.area && c.triangle.shape == AreaLightShape::sphere;
  l.area[i] = c.area && !sphere;
  l.drawn[i] = c.environment != nullptr || sphere;
  l.sphere[i] = sphere ? &c.triangle : nullptr;
  if (c.environment || sphere) {
    l.any_drawn = true;
    if (sphere) {
      l.drawn_r[i] = c.emission.x, l.drawn_g[i] = c.emission.y, l.drawn_b[i] = c.emission.z;
    } else {
      l.lights = c.environment;
      l.u_environment[i] = c.u_environment;
    }
    l.u_point_x[i] = c.u_point.x, l.u_point_y[i] = c.u_point.y;
    l.light_x[i] = l.light_y[i] = l.light_z[i] = 0, l.intensity_r[i] = l.intensity_g[i] = l.intensity_b[i] = 0;
    l.kc[i] = 1, l.kl[i] = l.kq[i] = 0;
    l.shaped[i] = 0;
  } else if (c.area) {
    l.any_area = true;
    const AreaLight& t = c.triangle;
    l.light_x[i] = t.p0.x, l.light_y[i] = t.p0.y, l.light_z[i] = t.p0.z;
    l.light1_x[i] = t.p1.x, l.light1_y[i] = t.p1.y, l.light1_z[i] = t.p1.z;
    l.light2_x[i] = t.p2.x, l.light2_y[i] = t.p2.y, l.light2_z[i] = t.p2.z;
    l.light_nx[i] = t.normal.x, l.light_ny[i] = t.normal.y, l.light_nz[i] = t.normal.z;
    l.light_area[i] = t.area, l.two_sided[i] = t.two_sided;
    l.intensity_r[i] = c.emission.x, l.intensity_g[i] = c.emission.y, l.intensity_b[i] = c.emission.z;
    l.u_point_x[i] = c.u_point.x, l.u_point_y[i] = c.u_point.y;
    l.kc[i] = 1, l.kl[i] = l.kq[i] = 0;
    l.shaped[i] = 0;
  } else {
    set_lane_delta_light(l, i, c.light);
  }
  l.select_pdf[i] = c.select_pdf;
  l.cosine_x[i] = c.cosine.x, l.cosine_y[i] = c.cosine.y, l.cosine_z[i] = c.cosine.z;
  l.throughput_r[i] = c.throughput.x, l.throughput_g[i] = c.throughput.y, l.throughput_b[i] = c.throughput.z;
  l.transformed[i] = c.transformed;
  if (c.transformed) {
    l.hit_kinds |= SurfaceLanes::transformed_hits;
    mat4 inverse;
    REQUIRE(inverse_affine(c.transform, inverse));
    for (int r = 0; r < 3; ++r) {
      for (int col = 0; col < 4; ++col) l.to_world[r * 4 + col][i] = c.transform.m[r][col];
      for (int col = 0; col < 3; ++col) l.to_object[r * 3 + col][i] = inverse.m[r][col];
    }
    l.orientation[i] = determinant3(c.transform) < 0 ? -1.0f : 1.0f;
  }
  if (l.model == RenderContext::LaneModel::glossy) {
    BsdfMaterial material(c.material);
    const MetallicRoughnessParams* p = material.metallic_roughness();
    REQUIRE(p);
    REQUIRE(is_metallic_roughness_lane_case(*p));
    set_lane_glossy_material(l, i, *p);
    l.u_lobe[i] = c.u_lobe, l.u_x[i] = c.u.x, l.u_y[i] = c.u.y;
  } else if (l.model == RenderContext::LaneModel::phong) {
    BsdfMaterial material(c.material);
    REQUIRE(lane_model_of(c.material, material) == RenderContext::LaneModel::phong);
    const PhongWeights& w = *material.phong();
    l.albedo_r[i] = w.kd.x, l.albedo_g[i] = w.kd.y, l.albedo_b[i] = w.kd.z;
    l.ks_r[i] = w.ks.x, l.ks_g[i] = w.ks.y, l.ks_b[i] = w.ks.z;
    l.exponent[i] = w.exponent, l.p_diffuse[i] = w.p_diffuse, l.p_specular[i] = w.p_glossy;
    l.mirror_r[i] = w.kr.x, l.mirror_g[i] = w.kr.y, l.mirror_b[i] = w.kr.z, l.p_mirror[i] = w.p_mirror;
    l.u_lobe[i] = c.u_lobe, l.u_x[i] = c.u.x, l.u_y[i] = c.u.y;
  }
}

// The one-path code's BSDF at the hit, as path.cpp builds and asks it: the Lambert lobes, or
// the metallic-roughness material's Bsdf.
struct ReferenceBsdf {
  LambertLobes lambert;
  std::optional<Bsdf> glossy;
  color3 eval(vec3 wi) const { return glossy ? glossy->eval(wi) : eval_world(lambert, wi); }
  color3 eval(vec3 wi, float& pdf) const { return glossy ? glossy->eval(wi, pdf) : eval_world(lambert, wi, pdf); }
  std::optional<BsdfSample> sample(const LaneCase& c) const {
    return glossy ? glossy->sample(c.u_lobe, c.u, c.cosine) : sample_warped(lambert, c.cosine);
  }
};

// What the one-path code makes of the case: the hit as fill_triangle_hit writes it for an
// untransformed triangle, then the library's own shading, lobes, bounce, light
// sample and ray origins.
void check_lane(const SurfaceLanes& l, int i, const LaneCase& c, int& specular_bounces, int& mirror_bounces) {
  SurfaceHit hit;
  vec3 e1 = c.p1 - c.p0, e2 = c.p2 - c.p0;
  float b1 = c.barycentric.x, b2 = c.barycentric.y;
  vec3 object_point = c.p0 + (b1 * e1 + b2 * e2);
  vec3 error = rounding_gamma(5) * (abs(b1 * e1) + abs(b2 * e2)) + rounding_gamma(2) * abs(object_point);
  hit.position = object_point;
  hit.geometric_normal = normalize(cross(e1, e2));
  mat4 inverse;
  if (c.transformed) {  // fill_triangle_hit's instance
    REQUIRE(inverse_affine(c.transform, inverse));
    const mat4& m = c.transform;
    hit.position = transform_point(m, object_point);
    error = (1 + rounding_gamma(3)) * abs_transform_vector(m, error) +
            rounding_gamma(3) * (abs_transform_vector(m, abs(object_point)) + abs(vec3{m.m[0][3], m.m[1][3], m.m[2][3]}));
    hit.geometric_normal =
        normalize(transform_normal(inverse, cross(e1, e2))) * (determinant3(m) < 0 ? -1.0f : 1.0f);
  }
  float largest = max_component(error);
  hit.position_error = {largest, largest, largest};
  if (c.is_shape) {  // fill_shape_hit
    hit.geometric_normal = normalize(c.raw_normal);
    refine_shape_point(c.shape, c.origin + c.direction * c.t, hit.geometric_normal, hit.position, hit.position_error);
  }
  hit.front_face = dot(c.direction, hit.geometric_normal) < 0;
  hit.shading_normal = hit.geometric_normal;
  if (c.has_normals) {
    vec3 n = c.n0 * (1 - b1 - b2) + c.n1 * b1 + c.n2 * b2;
    n = normalize(c.transformed ? transform_normal(inverse, n) : n);
    if (is_finite(n) && length_squared(n) > 0.5f) hit.shading_normal = dot(n, hit.geometric_normal) < 0 ? -n : n;
  }
  if (c.has_given_normal) hit.shading_normal = c.given_normal;  // make_hit_shading's mapped normal
  REQUIRE(!l.fallback[i]);
  vec3 wo = -normalize(c.direction);
  vec3 normal = hit.front_face ? hit.shading_normal : -hit.shading_normal;
  CHECK(same_bits({l.px[i], l.py[i], l.pz[i]}, hit.position));
  CHECK(same_bits({l.nx[i], l.ny[i], l.nz[i]}, normal));
  ReferenceBsdf bsdf;
  if (l.model != RenderContext::LaneModel::lambert)
    bsdf.glossy.emplace(BsdfMaterial(c.material), normal, wo);
  else
    bsdf.lambert = make_lambert_lobes({c.albedo}, normal, wo);
  std::optional<BsdfSample> bounce = bsdf.sample(c);
  if (bounce && is_black(bounce->weight)) bounce.reset();  // the path tracer stops there too
  REQUIRE(bool(l.scatters[i]) == bounce.has_value());
  if (bounce) {
    CHECK(same_bits({l.wix[i], l.wiy[i], l.wiz[i]}, bounce->wi));
    CHECK(same_bits(l.pdf[i], bounce->pdf));
    CHECK(same_bits({l.weight_r[i], l.weight_g[i], l.weight_b[i]}, bounce->weight));
    CHECK(bool(l.delta[i]) == bounce->delta);
    mirror_bounces += bounce->delta;
    specular_bounces += l.model == RenderContext::LaneModel::glossy ? c.u_lobe < l.p_specular[i]
                        : l.model == RenderContext::LaneModel::phong  ? !(c.u_lobe < l.p_diffuse[i])
                                                                      : false;
    Ray next;
    spawn_ray(next, hit, bounce->wi);
    CHECK(same_bits({l.ox[i], l.oy[i], l.oz[i]}, next.origin));
  }
  // sample_one_light's contribution and shadow ray for either kind of light.
  bool lit = false;
  color3 contribution;
  vec3 direction;
  float distance = 0;
  if (c.environment) {
    vec3 wi;
    float light_pdf = sample_environment(*c.environment, normal, c.u_environment, c.u_point, wi);
    color3 emitted = light_pdf > 0 ? eval_environment(*c.environment, wi) : color3{};
    float bsdf_pdf;
    color3 f_cos = !is_black(emitted) ? bsdf.eval(wi, bsdf_pdf) : color3{};
    lit = !is_black(f_cos);
    if (lit) {
      float pdf = c.select_pdf * light_pdf;
      contribution = c.throughput * (f_cos * emitted * color3{1, 1, 1} * (power_heuristic(pdf, bsdf_pdf) / pdf));
      direction = wi, distance = std::numeric_limits<float>::infinity();
    }
  } else if (c.area) {
    AreaLightSample sample;
    lit = sample_area_light(c.triangle, hit.position, c.u_point, sample) &&
          area_light_emits(c.triangle, sample.normal, -sample.direction) && !is_black(c.emission);
    float bsdf_pdf;
    color3 f_cos = lit ? bsdf.eval(sample.direction, bsdf_pdf) : color3{};
    lit = lit && !is_black(f_cos);
    if (lit) {
      float pdf = c.select_pdf * sample.pdf;
      contribution = c.throughput * (f_cos * c.emission * color3{1, 1, 1} * (power_heuristic(pdf, bsdf_pdf) / pdf));
      direction = sample.direction, distance = sample.distance * (1 - 1e-4f);
    }
  } else {
    DeltaLightSample light;
    bool reaches = sample_delta_light(c.light, hit.position, light);
    color3 f_cos = reaches ? bsdf.eval(light.direction) : color3{};
    lit = reaches && !is_black(f_cos);
    if (lit) {
      contribution = c.throughput * (f_cos * light.irradiance * color3{1, 1, 1} / c.select_pdf);
      direction = light.direction, distance = light.distance;
    }
  }
  REQUIRE(bool(l.lit[i]) == lit);
  if (lit) {
    CHECK(same_bits({l.light_r[i], l.light_g[i], l.light_b[i]}, contribution));
    Ray shadow;  // set_shadow_ray's
    bool infinite = !std::isfinite(distance);
    if (infinite)
      spawn_ray(shadow, hit, direction);
    else
      spawn_ray_to(shadow, hit, hit.position + direction * distance);
    CHECK(same_bits({l.shadow_ox[i], l.shadow_oy[i], l.shadow_oz[i]}, shadow.origin));
    CHECK(same_bits({l.shadow_dx[i], l.shadow_dy[i], l.shadow_dz[i]}, shadow.direction));
    CHECK(bool(l.shadow_infinite[i]) == infinite);
  }
}

std::vector<LaneCase> lane_cases() {
  uint32_t state = 11;
  auto next = [&] { return float((state = state * 1664525u + 1013904223u) >> 8) * 0x1p-24f; };
  auto point = [&](float scale) { return vec3{next() - 0.5f, next() - 0.5f, next() - 0.5f} * scale; };
  std::vector<LaneCase> cases;
  for (int k = 0; k < 200; ++k) {
    LaneCase c;
    float scale = k % 4 == 0 ? 1e4f : 2;
    vec3 corner = point(scale) + (k % 5 == 0 ? vec3{1e5f, 0, 0} : vec3{});  // far from the origin too
    c.p0 = corner, c.p1 = corner + point(1), c.p2 = corner + point(1);
    float u = next(), v = next() * (1 - u);
    c.barycentric = {u, v};
    c.direction = point(3);
    c.albedo = {next(), next(), k % 7 == 0 ? 0.0f : next()};
    c.light = LightDesc{};
    c.light.kind = LightKind::point;
    c.light.position = corner + point(4);
    c.light.intensity = {5 * next(), 5 * next(), 5 * next()};
    c.light.kc = k % 3 == 0 ? 1.0f : 0.0f, c.light.kl = k % 3 == 1 ? 0.5f : 0.0f, c.light.kq = k % 3 == 2 ? 0.0f : 1.0f;
    // Beside plain point lights: glTF spots and classic spots (cos^exponent, from a wide beam to
    // a narrow one) aimed near the point, some with a range, point lights with a range that some
    // points are beyond, and directional lights from any side.
    if (k % 6 == 0) {
      c.light.kind = LightKind::spot, c.light.use_cone = k % 24 != 12;
      c.light.direction = normalize(corner - c.light.position + point(2));
      c.light.inner_cone = 0.2f * next(), c.light.outer_cone = c.light.inner_cone + (k % 12 == 0 ? 0.0f : 0.6f * next());
      c.light.spot_exponent = std::array{0.5f, 1.0f, 20.0f, 300.0f}[k / 24 % 4];
      c.light.range = k % 18 == 6 ? 3.0f : 0.0f;
    } else if (k % 6 == 2) {
      c.light.kind = LightKind::directional;
      c.light.direction = normalize(point(2));
    } else if (k % 12 == 5) {
      c.light.range = 1 + 3 * next();
    }
    c.select_pdf = 0.25f + next();
    c.cosine = sample_cosine_hemisphere({next(), next()});
    c.throughput = {next(), next(), next()};
    if (k % 3 == 1) {  // an emitting triangle, one- or two-sided, facing the point or not
      c.area = true;
      c.triangle.p0 = corner + point(4), c.triangle.p1 = c.triangle.p0 + point(1), c.triangle.p2 = c.triangle.p0 + point(1);
      vec3 n = cross(c.triangle.p1 - c.triangle.p0, c.triangle.p2 - c.triangle.p0);
      c.triangle.area = 0.5f * length(n);
      c.triangle.normal = normalize(n);
      c.triangle.two_sided = k % 4 == 1;
      c.emission = {4 * next(), 4 * next(), k % 11 == 1 ? 0.0f : 4 * next()};
      c.u_point = {next(), next()};
      if (k % 9 == 7) {  // an emitting sphere instead: small and seen from outside, or around the point
        c.triangle.shape = AreaLightShape::sphere;
        c.triangle.center = c.triangle.p0;
        c.triangle.radius = k % 18 == 7 ? 0.3f : 10.0f;
        c.triangle.area = 4 * pi * c.triangle.radius * c.triangle.radius;
      }
    }
    if (k % 2 == 1) {  // vertex normals, some of them turned against the triangle's
      c.has_normals = true;
      c.n0 = normalize(point(2)), c.n1 = normalize(point(2)), c.n2 = normalize(point(2));
    }
    cases.push_back(c);
  }
  // A triangle in a coordinate plane, hit at a vertex on the origin (exact zeros: the offset's
  // floor and the one-ulp step from zero), lit from below and from behind the ray.
  LaneCase plane = cases[0];  // a point light
  plane.p0 = {0, 0, 0}, plane.p1 = {1, 0, 0}, plane.p2 = {0, 0, 1}, plane.barycentric = {0, 0};
  plane.direction = {0.2f, -1, 0.1f};
  cases.push_back(plane);
  plane.light.position = {0.3f, -2, 0.3f};
  cases.push_back(plane);
  plane.direction = {0.2f, 1, 0.1f};
  cases.push_back(plane);
  // A grazing ray, a bounce below the cosine floor, and the light at the hit itself.
  LaneCase grazing = cases[2];
  grazing.direction = grazing.p1 - grazing.p0;
  cases.push_back(grazing);
  LaneCase low = cases[3];
  low.cosine = {1, 0, 1e-8f};
  cases.push_back(low);
  LaneCase at_light = plane;
  at_light.light.position = {0, 0, 0};
  cases.push_back(at_light);
  // Vertex normals that nearly cancel where the triangle is hit: what is left is normalised.
  LaneCase cancelling = cases[5];
  cancelling.has_normals = true;
  cancelling.n0 = {0, 1, 0}, cancelling.n1 = {0, -1, 0}, cancelling.n2 = {0.01f, 1, 0}, cancelling.barycentric = {0.49f, 0.02f};
  cases.push_back(cancelling);
  return cases;
}

// The same hits on metallic-roughness materials of the glossy lanes' case: metals, coated
// Lambert and mixes of them, rough to nearly smooth, with tinted and weak coatings, an ior
// whose F0 is 0, and black base colours (the coating's lobe alone).
std::vector<LaneCase> glossy_cases() {
  uint32_t state = 7;
  auto next = [&] { return float((state = state * 1664525u + 1013904223u) >> 8) * 0x1p-24f; };
  std::vector<LaneCase> cases = lane_cases();
  for (size_t k = 0; k < cases.size(); ++k) {
    LaneCase& c = cases[k];
    SurfaceMaterial& m = c.material;
    m.model = MaterialModel::metallic_roughness;
    m.base_color = k % 9 == 4 ? color3{} : c.albedo;
    m.metallic = k % 4 == 0 ? 1.0f : k % 4 == 1 ? next() : 0.0f;
    m.roughness = k % 6 == 5 ? 0.04f : 0.1f + 0.9f * next();
    m.specular = k % 5 == 2 ? 0.2f : 1.0f;
    m.specular_color = k % 3 == 0 ? color3{next(), next(), 1} : color3{1, 1, 1};
    m.ior = k % 7 == 3 ? 1.0f : k % 7 == 5 ? 2.4f : 1.5f;
    c.u_lobe = next();
    c.u = {next(), next()};
    c.cosine = sample_cosine_hemisphere(c.u);  // the batch warps the same numbers
  }
  return cases;
}

// The same hits on Phong materials with a glossy lobe (the .scene format's kd, ks and
// shininess): broad and sharp lobes, a glossy lobe alone, and weights that sum past one (scaled);
// a mirror (kr) beside them in a third, and beside the diffuse lobe alone in a few.
std::vector<LaneCase> phong_cases() {
  uint32_t state = 13;
  auto next = [&] { return float((state = state * 1664525u + 1013904223u) >> 8) * 0x1p-24f; };
  std::vector<LaneCase> cases = lane_cases();
  for (size_t k = 0; k < cases.size(); ++k) {
    LaneCase& c = cases[k];
    SurfaceMaterial& m = c.material;
    m.model = MaterialModel::phong;
    m.kd = k % 9 == 4 ? color3{} : k % 7 == 3 ? color3{0.9f, 0.8f, 0.95f} : c.albedo;
    m.ks = k % 7 == 3 ? color3{0.8f, 0.6f, 0.7f} : color3{0.05f + 0.5f * next(), 0.05f + 0.5f * next(), 0.3f};
    m.shininess = k % 5 == 0 ? 1.0f : k % 5 == 1 ? 500.0f : 10 + 200 * next();
    if (k % 3 == 2) m.kr = k % 4 == 2 ? color3{0.5f, 0.45f, 0.4f} : color3{0.3f * next(), 0.2f, 0.0f};
    if (k % 12 == 2 && !is_black(m.kd)) m.ks = {};
    c.u_lobe = next();
    c.u = {next(), next()};
    c.cosine = sample_cosine_hemisphere(c.u);  // the batch warps the same numbers
  }
  return cases;
}

// Spheres and planes in place of the triangles: hit points on them, far from the origin too, and
// rays that reach them from either side, as the analytic intersector leaves them (its distance
// rounded, so that the refinement moves the point).
std::vector<LaneCase> shapes(std::vector<LaneCase> cases) {
  uint32_t state = 5;
  auto next = [&] { return float((state = state * 1664525u + 1013904223u) >> 8) * 0x1p-24f; };
  for (size_t k = 0; k < cases.size(); ++k) {
    if (k % 5 == 4) continue;  // some triangles beside them
    LaneCase& c = cases[k];
    c.is_shape = true;
    c.has_normals = false;
    vec3 center = c.p0;
    vec3 normal = normalize(vec3{next() - 0.5f, next() - 0.5f, next() - 0.5f});
    vec3 point;
    if (k % 2 == 0) {
      c.shape.kind = ShapeKind::sphere;
      c.shape.center = center, c.shape.radius = 0.1f + 3 * next();
      point = center + normal * c.shape.radius;
      c.raw_normal = (point - center) * 7.0f;
    } else {
      c.shape.kind = ShapeKind::plane;
      c.shape.center = center, c.shape.axis = normal;
      vec3 t, b;
      orthonormal_basis(normal, t, b);
      point = center + t * (4 * next() - 2) + b * (4 * next() - 2);
      c.raw_normal = normal;
    }
    c.t = 0.5f + 5 * next();
    c.origin = point - c.direction * c.t;
  }
  return cases;
}

// The same hits on triangles placed by instances: rotated, stretched, mirrored, and moved far.
std::vector<LaneCase> transformed(std::vector<LaneCase> cases) {
  for (size_t k = 0; k < cases.size(); ++k) {
    if (k % 4 == 3) continue;  // some lanes untransformed, beside the others
    LaneCase& c = cases[k];
    c.transformed = true;
    vec3 scale = k % 5 == 0 ? vec3{-1, 2, 0.5f} : vec3{1.5f, 1.5f, 1.5f};
    vec3 offset = k % 3 == 0 ? vec3{3e4f, -2, 7} : vec3{0.25f, 1, -0.5f};
    c.transform = translation(offset) * rotation_axis(normalize(vec3{1, 2, float(k % 7)}), 10.0f + float(k)) * scaling(scale);
    // The world-space ray and lights as the untransformed case had them, moved along.
    vec3 moved = transform_point(c.transform, c.p0) - c.p0;
    c.light.position = c.light.position + moved;
    for (vec3* p : {&c.triangle.p0, &c.triangle.p1, &c.triangle.p2, &c.triangle.center}) *p = *p + moved;
  }
  return cases;
}

// The same hits with normals that normal maps bent, given to the lanes: some tilted a little from
// the geometric normal, some far, some behind the surface (a map can turn the normal away from
// the ray; the lobes then flip it, as the one-path BSDF does).
std::vector<LaneCase> given_normals(std::vector<LaneCase> cases) {
  uint32_t state = 3;
  auto next = [&] { return float((state = state * 1664525u + 1013904223u) >> 8) * 0x1p-24f; };
  for (size_t k = 0; k < cases.size(); ++k) {
    if (k % 4 == 1) continue;  // some lanes with their own normals beside them
    LaneCase& c = cases[k];
    vec3 tilt = {next() - 0.5f, next() - 0.5f, next() - 0.5f};
    vec3 geometric = normalize(c.is_shape ? c.raw_normal : cross(c.p1 - c.p0, c.p2 - c.p0));
    if (c.transformed) geometric = normalize(transform_vector(c.transform, geometric));  // near it: any normal does
    c.has_given_normal = true;
    c.given_normal = normalize(k % 3 == 0 ? tilt : geometric + tilt * 0.6f);
  }
  return cases;
}

// The same hits lit by the environment of `lights` in two lanes of three.
std::vector<LaneCase> environment_lit(std::vector<LaneCase> cases, const LightTable& lights) {
  uint32_t state = 9;
  auto next = [&] { return float((state = state * 1664525u + 1013904223u) >> 8) * 0x1p-24f; };
  for (size_t k = 0; k < cases.size(); ++k) {
    if (k % 3 == 2) continue;
    LaneCase& c = cases[k];
    c.area = false;
    c.environment = &lights;
    c.u_environment = next(), c.u_point = {next(), next()};
  }
  return cases;
}

}  // namespace

TEST_CASE("Lambert lanes: each lane is the one-path vertex to the bit, on every instruction set") {
  // Point lights, emitting triangles and spheres mixed, as in a batch; and point lights alone,
  // which the kernel shades without its triangle and drawn lights' loops.
  std::vector<LaneCase> mixed = lane_cases(), points, placed = transformed(mixed), shaped = shapes(mixed);
  std::vector<LaneCase> mapped = given_normals(placed), mapped_shapes = given_normals(shaped);
  for (const LaneCase& c : mixed)
    if (!c.area) points.push_back(c);
  for (const std::vector<LaneCase>* cases : {&mixed, &points, &placed, &shaped, &mapped, &mapped_shapes}) {
    REQUIRE(int(cases->size()) <= SurfaceLanes::capacity);
    for (LaneIsa isa : {LaneIsa::best, LaneIsa::baseline, LaneIsa::avx2}) {
      if (!lane_isa_available(isa)) continue;
      CAPTURE(cases->size());
      CAPTURE(int(isa));
      auto lanes = std::make_unique<SurfaceLanes>();
      for (size_t i = 0; i < cases->size(); ++i) set_lane(*lanes, int(i), (*cases)[i]);
      lanes->count = int(cases->size());
      shade_surface_lanes(*lanes, isa);
      int lit = 0, scatters = 0, lit_by_triangles = 0, shaped = 0, lit_by_shaped = 0, spheres = 0, lit_by_spheres = 0;
      for (size_t i = 0; i < cases->size(); ++i) {
        CAPTURE(i);
        int unused = 0;
        check_lane(*lanes, int(i), (*cases)[i], unused, unused);
        lit += lanes->lit[i], scatters += lanes->scatters[i];
        lit_by_triangles += lanes->lit[i] && (*cases)[i].area;
        bool sphere = (*cases)[i].area && (*cases)[i].triangle.shape == AreaLightShape::sphere;
        spheres += sphere, lit_by_spheres += sphere && lanes->lit[i];
        bool shaped_light = !(*cases)[i].area && lanes->shaped[i];
        shaped += shaped_light, lit_by_shaped += shaped_light && lanes->lit[i];
      }
      // Spots, ranges and directional lights light some lanes and not others.
      CHECK(lit_by_shaped > 10);
      CHECK(shaped - lit_by_shaped > 10);
      // Both outcomes of both tests occur, for both kinds of light.
      CHECK(lit > 20);
      CHECK(lit < int(cases->size()) - 20);
      CHECK(scatters > 20);
      CHECK(scatters < int(cases->size()));
      CHECK(lit_by_triangles > (cases != &points ? 10 : -1));
      CHECK(lit - lit_by_triangles > 10);
      // Spheres, seen from outside and from within, light some lanes and not others.
      CHECK(lit_by_spheres > (cases != &points ? 3 : -1));
      CHECK(spheres - lit_by_spheres > (cases != &points ? 3 : -1));
    }
  }
}

TEST_CASE("Lambert lanes: a normal whose squared length leaves float's range falls back to one path") {
  // The geometric normal's or the interpolated vertex normal's: normalize() rescales there.
  auto lanes = std::make_unique<SurfaceLanes>();
  LaneCase huge = lane_cases()[1];
  huge.p0 = {-1e20f, 0, -1e20f}, huge.p1 = {-1e20f, 0, 1e20f}, huge.p2 = {1e20f, 0, 1e20f};  // Ng overflows
  set_lane(*lanes, 0, huge);
  LaneCase tiny = huge;
  tiny.p0 = {0, 0, 0}, tiny.p1 = {0, 0, 1e-20f}, tiny.p2 = {1e-20f, 0, 0};  // Ng's squared length underflows
  set_lane(*lanes, 1, tiny);
  LaneCase zero_normals = lane_cases()[0];  // normalize() rescales the zero vector
  zero_normals.has_normals = true;
  set_lane(*lanes, 2, zero_normals);
  LaneCase infinite_normal = zero_normals;  // and infinities
  infinite_normal.n0 = {0, 1, 0}, infinite_normal.n1 = {0, 1, 0};
  infinite_normal.n2 = {std::numeric_limits<float>::infinity(), 0, 0};
  set_lane(*lanes, 3, infinite_normal);
  set_lane(*lanes, 4, lane_cases()[0]);
  lanes->count = 5;
  shade_surface_lanes(*lanes);
  CHECK(lanes->fallback[0]);
  CHECK(lanes->fallback[1]);
  CHECK(lanes->fallback[2]);
  CHECK(lanes->fallback[3]);
  CHECK(!lanes->fallback[4]);
}

TEST_CASE("Glossy and Phong lanes: each lane is the one-path vertex to the bit, on every instruction set") {
  for (RenderContext::LaneModel model : {RenderContext::LaneModel::glossy, RenderContext::LaneModel::phong}) {
    CAPTURE(int(model));
    std::vector<LaneCase> mixed = model == RenderContext::LaneModel::glossy ? glossy_cases() : phong_cases();
    std::vector<LaneCase> points, placed = transformed(mixed), shaped = shapes(mixed);
    std::vector<LaneCase> mapped = given_normals(placed), mapped_shapes = given_normals(shaped);
    for (const LaneCase& c : mixed)
      if (!c.area) points.push_back(c);
    for (const std::vector<LaneCase>* cases : {&mixed, &points, &placed, &shaped, &mapped, &mapped_shapes}) {
      REQUIRE(int(cases->size()) <= SurfaceLanes::capacity);
      for (LaneIsa isa : {LaneIsa::best, LaneIsa::baseline, LaneIsa::avx2}) {
        if (!lane_isa_available(isa)) continue;
        CAPTURE(cases->size());
        CAPTURE(int(isa));
        auto lanes = std::make_unique<SurfaceLanes>();
        lanes->model = model;
        for (size_t i = 0; i < cases->size(); ++i) set_lane(*lanes, int(i), (*cases)[i]);
        lanes->count = int(cases->size());
        shade_surface_lanes(*lanes, isa);
        int lit = 0, scatters = 0, lit_by_triangles = 0, specular_bounces = 0, mirror_bounces = 0, shaped = 0,
            lit_by_shaped = 0, classic_spots = 0, lit_by_classic_spots = 0;
        for (size_t i = 0; i < cases->size(); ++i) {
          CAPTURE(i);
          check_lane(*lanes, int(i), (*cases)[i], specular_bounces, mirror_bounces);
          lit += lanes->lit[i], scatters += lanes->scatters[i];
          lit_by_triangles += lanes->lit[i] && (*cases)[i].area;
          bool shaped_light = !(*cases)[i].area && lanes->shaped[i];
          shaped += shaped_light, lit_by_shaped += shaped_light && lanes->lit[i];
          bool classic_spot = shaped_light && lanes->classic_spot[i];
          classic_spots += classic_spot, lit_by_classic_spots += classic_spot && lanes->lit[i];
        }
        CHECK(lit_by_classic_spots > 3);
        CHECK(classic_spots - lit_by_classic_spots > 0);
        if (model == RenderContext::LaneModel::phong) CHECK(mirror_bounces > 5);
        CHECK(lit_by_shaped > 10);
        CHECK(shaped - lit_by_shaped > 10);
        // Both outcomes of both tests occur, for both kinds of light and both lobes.
        CHECK(lit > 20);
        CHECK(lit < int(cases->size()) - 20);
        CHECK(scatters > 20);
        CHECK(scatters < int(cases->size()));
        CHECK(specular_bounces > 10);
        CHECK(scatters - specular_bounces > 10);
        CHECK(lit_by_triangles > (cases != &points ? 10 : -1));
        CHECK(lit - lit_by_triangles > 10);
      }
    }
  }
}

TEST_CASE("Surface lanes: the environment's light sample is the one-path vertex's to the bit") {
  // A uniform sky (cosine sampling about the normal) and a map (its distribution as well, chosen
  // by u_environment), with a dark band whose texels a map sample can land on.
  test::ScratchDir dir("lanes-environment");
  std::vector<float> sky;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x)
      for (int c = 0; c < 3; ++c) sky.push_back(y == 5 ? 0.0f : 0.2f + 0.1f * float((x * 7 + y * 3 + c) % 11));
  test::write_test_image(dir.file("sky.exr"), 16, 8, {"R", "G", "B"}, sky);
  SceneDesc empty;
  LightTable uniform = make_light_table(empty, {0.4f, 0.5f, 0.7f}, "", true, nullptr, LightSampler::power);
  LightTable mapped = make_light_table(empty, {}, dir.file("sky.exr").string(), true, nullptr, LightSampler::power);
  for (const LightTable* table : {&uniform, &mapped}) {
    for (RenderContext::LaneModel model :
         {RenderContext::LaneModel::lambert, RenderContext::LaneModel::glossy, RenderContext::LaneModel::phong}) {
      std::vector<LaneCase> cases = environment_lit(model == RenderContext::LaneModel::glossy ? glossy_cases()
                                                    : model == RenderContext::LaneModel::phong ? phong_cases()
                                                                                                : lane_cases(),
                                                    *table);
      for (LaneIsa isa : {LaneIsa::best, LaneIsa::baseline, LaneIsa::avx2}) {
        if (!lane_isa_available(isa)) continue;
        CAPTURE(table == &mapped);
        CAPTURE(int(model));
        CAPTURE(int(isa));
        auto lanes = std::make_unique<SurfaceLanes>();
        lanes->model = model;
        for (size_t i = 0; i < cases.size(); ++i) set_lane(*lanes, int(i), cases[i]);
        lanes->count = int(cases.size());
        shade_surface_lanes(*lanes, isa);
        int environment = 0, lit_by_environment = 0, unused = 0;
        for (size_t i = 0; i < cases.size(); ++i) {
          CAPTURE(i);
          check_lane(*lanes, int(i), cases[i], unused, unused);
          environment += cases[i].environment != nullptr;
          lit_by_environment += cases[i].environment && lanes->lit[i];
        }
        CHECK(lit_by_environment > 20);
        CHECK(environment - lit_by_environment > 5);
      }
    }
  }
}
