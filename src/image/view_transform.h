// From scene-linear radiance to the values an 8- or 16-bit image stores (docs/cli.md, "Look"):
// an exposure in stops, then a view transform, each a documented curve.
//   standard  clamp to [0, 1], then the sRGB transfer function (IEC 61966-2-1)
//   linear    clamp to [0, 1], no transfer function: the values as they are, which is what the
//             classic Phong engine wrote (its images look washed out under `standard`)
//   filmic    Narkowicz's fit of the ACES filmic tone curve, x(2.51x + 0.03) / (x(2.43x + 0.59)
//             + 0.14) per channel, then sRGB: highlights roll off instead of clipping
//   agx       AgX (Sobotka), in Wrensch's minimal form: an inset matrix, log2 encoding over
//             [-12.47, 4.03] stops around 0.18, a polynomial fit of the default contrast
//             sigmoid, the outset matrix; its output is display-encoded already
//   neutral   Khronos PBR Neutral: base colours under diffuse white light show unchanged (less
//             a small offset near black), highlights are compressed and desaturated; then sRGB
//   aces      the ACES RRT+ODT fit three.js uses (ACESFilmicToneMapping: Hill's matrices and
//             curve, exposure pre-scale 1/0.6); then sRGB
// Float outputs (EXR) never pass through here: they keep scene-linear radiance.
#pragma once

#include <string>

#include "math/vec.h"
#include "scene/scene_desc.h"

namespace radiant {

struct DisplaySettings {
  float exposure = 0;  // stops: each one doubles the radiance before the view transform
  ViewTransform view = ViewTransform::standard;
  bool operator==(const DisplaySettings&) const = default;
};

// Linear to sRGB transfer function (IEC 61966-2-1), for values in [0, 1].
float linear_to_srgb(float linear);

// The display values in [0, 1] of a linear color.
color3 display_encode(color3 linear, const DisplaySettings& display);

// "standard", "linear", "filmic", "agx", "neutral", "aces"; parse throws std::invalid_argument
// naming the choices, which view_transform_choices lists ("standard, linear, ... or aces").
const char* view_transform_name(ViewTransform view);
ViewTransform parse_view_transform(const std::string& name);
std::string view_transform_choices();

}  // namespace radiant
