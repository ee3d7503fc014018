// Turning a direction chosen in a BSDF's local frame into a BsdfSample, shared by the BSDF
// models. `Lobes` is a model's per-call state: it has `frame`, and `eval_local`/`pdf_local`
// (found by argument-dependent lookup) evaluate its non-delta lobes; a model whose two share
// work overloads `eval_with_pdf` as well.
#pragma once

#include <optional>

#include "materials/shading_frame.h"
#include "materials/surface.h"

namespace radiant {

// f(wo, wi) * |cos| and the pdf of wi, of a model that computes them apart.
template <class Lobes>
color3 eval_with_pdf(const Lobes& l, vec3 wi_local, float& pdf) {
  pdf = pdf_local(l, wi_local);
  return eval_local(l, wi_local);
}

// A sample of a delta lobe: its reflectance (or transmittance) over the lobe's selection probability.
template <class Lobes>
BsdfSample delta_sample(const Lobes& l, vec3 wi_local, color3 reflectance, float selection) {
  BsdfSample s;
  s.wi = to_world(l.frame, wi_local);
  s.weight = reflectance / selection;
  s.pdf = selection;
  s.delta = true;
  s.transmitted = wi_local.z < 0;
  return s;
}

// A direction chosen by one of the non-delta lobes, weighted by the whole mixture (one-sample MIS).
template <class Lobes>
std::optional<BsdfSample> mixture_sample(const Lobes& l, vec3 wi_local) {
  float pdf;
  color3 f = eval_with_pdf(l, wi_local, pdf);
  if (!(pdf > 0) || is_black(f)) return std::nullopt;
  BsdfSample s;
  s.wi = to_world(l.frame, wi_local);
  s.weight = f / pdf;
  s.pdf = pdf;
  s.transmitted = wi_local.z < 0;
  if (!is_finite(s.weight)) return std::nullopt;
  return s;
}

}  // namespace radiant
