// glTF animations sampled at one time: the chosen animation's channels write node translation,
// rotation, scale and morph weights into the model before its nodes are converted, so that the
// SceneDesc is the file's plain state at that time (cameras and lights move with their nodes).
#pragma once

#include "gltf/gltf_context.h"

namespace radiant {

// The animation `which` names ("" = the first; a name, else an index), or -1 when the file has
// none and `which` is empty; throws LoadError when `which` matches nothing.
int find_animation(const GltfContext& context, const std::string& which);

// Samples every channel of animation `index` at `seconds` (before the first key: the first
// value; after the last: the last) with its STEP, LINEAR (slerp for rotations) or CUBICSPLINE
// interpolation, and writes the values into `model`'s nodes (the model `context` reads).
void apply_animation(tinygltf::Model& model, const GltfContext& context, int index, double seconds);

// How many evenly spaced time steps follow animation `index` from `from` to `to` seconds (from <
// to): one interval per stretch between its keys there, of the channel with the most, two for a
// rotation's or a cubic spline's curve; from 2 to max_motion_steps.
int motion_steps_between(const GltfContext& context, int index, double from, double to);

}  // namespace radiant
