#include "image/view_transform.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "image/image_writer.h"

namespace radiant {

namespace {

float clamp01(float v) { return std::clamp(v, 0.0f, 1.0f); }  // NaN never reaches here: the film drops it

float aces_fitted(float x) {
  x = std::max(x, 0.0f);
  return clamp01(x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f));
}

// Rows of the AgX inset and outset matrices (Wrensch's GLSL gives them by columns).
constexpr float agx_inset[3][3] = {{0.842479062253094f, 0.0784335999999992f, 0.0792237451477643f},
                                   {0.0423282422610123f, 0.878468636469772f, 0.0791661274605434f},
                                   {0.0423756549057051f, 0.0784336f, 0.879142973793104f}};
constexpr float agx_outset[3][3] = {{1.19687900512017f, -0.0980208811401368f, -0.0990297440797205f},
                                    {-0.0528968517574562f, 1.15190312990417f, -0.0989611768448433f},
                                    {-0.0529716355144438f, -0.0980434501171241f, 1.15107367264116f}};
constexpr float agx_min_ev = -12.47393f, agx_max_ev = 4.026069f;

color3 multiply(const float (&m)[3][3], color3 c) {
  return {m[0][0] * c.x + m[0][1] * c.y + m[0][2] * c.z, m[1][0] * c.x + m[1][1] * c.y + m[1][2] * c.z,
          m[2][0] * c.x + m[2][1] * c.y + m[2][2] * c.z};
}

// The default-contrast sigmoid, fitted by a polynomial (mean squared error 3.7e-6).
float agx_contrast(float x) {
  float x2 = x * x, x4 = x2 * x2;
  return 15.5f * x4 * x2 - 40.14f * x4 * x + 31.96f * x4 - 6.868f * x2 * x + 0.4298f * x2 + 0.1191f * x - 0.00232f;
}

color3 agx(color3 linear) {
  color3 c = multiply(agx_inset, linear);
  for (int i = 0; i < 3; ++i) {
    float stops = std::clamp(std::log2(std::max(c[i], 1e-10f)), agx_min_ev, agx_max_ev);
    c[i] = agx_contrast((stops - agx_min_ev) / (agx_max_ev - agx_min_ev));
  }
  c = multiply(agx_outset, c);
  return {clamp01(c.x), clamp01(c.y), clamp01(c.z)};
}

}  // namespace

color3 display_encode(color3 linear, const DisplaySettings& display) {
  color3 c = display.exposure == 0 ? linear : linear * std::exp2(display.exposure);
  switch (display.view) {
    case ViewTransform::standard:
      return {linear_to_srgb(clamp01(c.x)), linear_to_srgb(clamp01(c.y)), linear_to_srgb(clamp01(c.z))};
    case ViewTransform::linear: return {clamp01(c.x), clamp01(c.y), clamp01(c.z)};
    case ViewTransform::filmic:
      return {linear_to_srgb(aces_fitted(c.x)), linear_to_srgb(aces_fitted(c.y)), linear_to_srgb(aces_fitted(c.z))};
    case ViewTransform::agx: return agx(c);
  }
  return c;
}

const char* view_transform_name(ViewTransform view) {
  switch (view) {
    case ViewTransform::standard: return "standard";
    case ViewTransform::linear: return "linear";
    case ViewTransform::filmic: return "filmic";
    case ViewTransform::agx: return "agx";
  }
  return "?";
}

ViewTransform parse_view_transform(const std::string& name) {
  for (ViewTransform v : {ViewTransform::standard, ViewTransform::linear, ViewTransform::filmic, ViewTransform::agx})
    if (name == view_transform_name(v)) return v;
  throw std::invalid_argument("unknown view '" + name + "' (standard, linear, filmic or agx)");
}

}  // namespace radiant
