#include "image/view_transform.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "scene/enum_names.h"

namespace radiant {

float linear_to_srgb(float v) {
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

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

// Khronos PBR Neutral (KhronosGroup/ToneMapping, PBR_Neutral): below its start of compression a
// colour passes unchanged but for a small offset that keeps black black; above, its peak channel
// is compressed towards 1 and the colour desaturated as much as the peak was lowered.
constexpr float neutral_f90 = 0.04f;                          // the offset: F0 of an ior-1.5 dielectric
constexpr float neutral_start = 0.8f - neutral_f90;           // K_s, where compression starts
constexpr float neutral_desaturation = 0.15f;                 // K_d
color3 pbr_neutral(color3 c) {
  c = max(c, {0, 0, 0});
  float x = min_component(c);
  float offset = x <= 2 * neutral_f90 ? x - x * x / (4 * neutral_f90) : neutral_f90;
  c = c - color3{offset, offset, offset};
  float peak = max_component(c);
  if (peak <= neutral_start) return c;
  float d = 1 - neutral_start;
  float new_peak = 1 - d * d / (peak + d - neutral_start);
  float g = 1 / (neutral_desaturation * (peak - new_peak) + 1);
  return c * (new_peak / peak * g) + color3{new_peak, new_peak, new_peak} * (1 - g);
}

// ACES as three.js's ACESFilmicToneMapping: Stephen Hill's fit of the RRT and ODT between his
// input matrix (sRGB to AP1 with the RRT's saturation) and output matrix (back to sRGB), after
// three.js's exposure pre-scale of 1/0.6. Rows here; three.js's GLSL gives them by columns.
constexpr float aces_input[3][3] = {{0.59719f, 0.35458f, 0.04823f},
                                    {0.07600f, 0.90834f, 0.01566f},
                                    {0.02840f, 0.13383f, 0.83777f}};
constexpr float aces_output[3][3] = {{1.60475f, -0.53108f, -0.07367f},
                                     {-0.10208f, 1.10813f, -0.00605f},
                                     {-0.00327f, -0.07276f, 1.07602f}};
constexpr float aces_exposure = 1 / 0.6f;
float rrt_odt_fit(float v) {
  return (v * (v + 0.0245786f) - 0.000090537f) / (v * (0.983729f * v + 0.4329510f) + 0.238081f);
}
color3 aces(color3 linear) {
  color3 c = multiply(aces_input, max(linear, {0, 0, 0}) * aces_exposure);
  c = multiply(aces_output, {rrt_odt_fit(c.x), rrt_odt_fit(c.y), rrt_odt_fit(c.z)});
  return {clamp01(c.x), clamp01(c.y), clamp01(c.z)};
}

color3 srgb_encode(color3 display_linear) {
  return {linear_to_srgb(clamp01(display_linear.x)), linear_to_srgb(clamp01(display_linear.y)),
          linear_to_srgb(clamp01(display_linear.z))};
}

}  // namespace

color3 display_encode(color3 linear, const DisplaySettings& display) {
  color3 c = display.exposure == 0 ? linear : linear * std::exp2(display.exposure);
  switch (display.view) {
    case ViewTransform::standard: return srgb_encode(c);
    case ViewTransform::linear: return {clamp01(c.x), clamp01(c.y), clamp01(c.z)};
    case ViewTransform::filmic: return srgb_encode({aces_fitted(c.x), aces_fitted(c.y), aces_fitted(c.z)});
    case ViewTransform::agx: return agx(c);
    case ViewTransform::neutral: return srgb_encode(pbr_neutral(c));
    case ViewTransform::aces: return srgb_encode(aces(c));
  }
  return c;
}

const char* view_transform_name(ViewTransform view) { return name_of(view_transform_names, view); }

ViewTransform parse_view_transform(const std::string& name) {
  if (std::optional<ViewTransform> view = value_named(view_transform_names, name)) return *view;
  throw std::invalid_argument("unknown view '" + name + "' (" + view_transform_choices() + ")");
}

std::string view_transform_choices() { return names_text(view_transform_names); }

}  // namespace radiant
