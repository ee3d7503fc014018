#include "gltf/gltf_animation.h"

#include <algorithm>
#include <cmath>

#include "gltf/gltf_accessors.h"
#include "message_text.h"

namespace radiant {

namespace {

enum class Interpolation { step, linear, cubic_spline };

// One channel's keys: times, and `width` floats per key value (three values a key for
// CUBICSPLINE: in-tangent, value, out-tangent).
struct Keys {
  std::vector<float> times, values;
  size_t width = 0;
  Interpolation interpolation = Interpolation::linear;
  // The `width` floats of value `element` (for CUBICSPLINE: 0 in-tangent, 1 value, 2 out-tangent) of key k.
  const float* at(size_t k, size_t element = 1) const {
    size_t per_key = interpolation == Interpolation::cubic_spline ? 3 : 1;
    size_t slot = per_key == 3 ? element : 0;
    return &values[(k * per_key + slot) * width];
  }
};

Interpolation interpolation_of(const GltfContext& context, const std::string& name, const std::string& where) {
  if (name.empty() || name == "LINEAR") return Interpolation::linear;
  if (name == "STEP") return Interpolation::step;
  if (name == "CUBICSPLINE") return Interpolation::cubic_spline;
  context.fail(where, "unknown interpolation '" + escaped(name) + "' (LINEAR, STEP or CUBICSPLINE)");
}

Keys read_keys(const GltfContext& context, const tinygltf::AnimationSampler& sampler, int value_type,
               const std::string& where) {
  Keys keys;
  keys.interpolation = interpolation_of(context, sampler.interpolation, where + ".interpolation");
  int components = 0;
  keys.times = read_accessor_floats(context, sampler.input, where + ".input", {TINYGLTF_TYPE_SCALAR}, components);
  if (keys.times.empty()) context.fail(where + ".input", "no keyframes");
  for (size_t k = 0; k < keys.times.size(); ++k) {
    if (!std::isfinite(keys.times[k])) context.fail(where + ".input", "non-finite time at key " + std::to_string(k));
    if (k > 0 && !(keys.times[k] > keys.times[k - 1]))
      context.fail(where + ".input", "times must increase (key " + std::to_string(k) + ")");
  }
  keys.values = read_accessor_floats(context, sampler.output, where + ".output", {value_type}, components);
  for (size_t i = 0; i < keys.values.size(); ++i)
    if (!std::isfinite(keys.values[i])) context.fail(where + ".output", "non-finite value in element " + std::to_string(i));
  size_t per_key = (keys.interpolation == Interpolation::cubic_spline ? 3 : 1) * keys.times.size();
  // Weights are SCALAR outputs, one per morph target per key.
  keys.width = keys.values.size() / per_key;
  if (keys.width == 0 || keys.values.size() != keys.width * per_key)
    context.fail(where + ".output", std::to_string(keys.values.size()) + " values for " + std::to_string(keys.times.size()) +
                                        " keys");
  if (value_type != TINYGLTF_TYPE_SCALAR && keys.width != size_t(components))
    context.fail(where + ".output", std::to_string(keys.values.size() / size_t(components)) + " elements for " +
                                        std::to_string(keys.times.size()) + " keys");
  return keys;
}

// Shortest-path spherical interpolation of unit quaternions (x, y, z, w).
void slerp(const float* a, const float* b, float u, float* out) {
  double d = double(a[0]) * b[0] + double(a[1]) * b[1] + double(a[2]) * b[2] + double(a[3]) * b[3];
  double sign = d < 0 ? -1 : 1;
  d = std::abs(d);
  double wa = 1 - u, wb = u;
  if (d < 0.9995) {  // nearly parallel quaternions: linear, then normalized below
    double angle = std::acos(d), s = std::sin(angle);
    wa = std::sin((1 - u) * angle) / s, wb = std::sin(u * angle) / s;
  }
  for (int c = 0; c < 4; ++c) out[c] = float(wa * a[c] + sign * wb * b[c]);
}

// The channel's value at `t` into `out` (keys.width floats).
void sample(const Keys& keys, bool rotation, double t, float* out) {
  size_t n = keys.times.size(), w = keys.width;
  auto copy = [&](const float* v) { std::copy(v, v + w, out); };
  if (t <= keys.times.front()) return copy(keys.at(0));
  if (t >= keys.times.back()) return copy(keys.at(n - 1));
  size_t k = size_t(std::upper_bound(keys.times.begin(), keys.times.end(), float(t)) - keys.times.begin()) - 1;
  if (k + 1 >= n) return copy(keys.at(n - 1));
  double dt = double(keys.times[k + 1]) - keys.times[k];
  float u = float((t - keys.times[k]) / dt);
  switch (keys.interpolation) {
    case Interpolation::step: return copy(keys.at(k));
    case Interpolation::linear:
      if (rotation) return slerp(keys.at(k), keys.at(k + 1), u, out);
      for (size_t c = 0; c < w; ++c) out[c] = keys.at(k)[c] * (1 - u) + keys.at(k + 1)[c] * u;
      return;
    case Interpolation::cubic_spline: {
      // glTF 2.0 appendix C: Hermite spline with tangents scaled by the key interval.
      double u2 = double(u) * u, u3 = u2 * u;
      double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
      for (size_t c = 0; c < w; ++c)
        out[c] = float(h00 * keys.at(k)[c] + h10 * dt * keys.at(k, 2)[c] + h01 * keys.at(k + 1)[c] +
                       h11 * dt * keys.at(k + 1, 0)[c]);
      return;
    }
  }
}

}  // namespace

int find_animation(const GltfContext& context, const std::string& which) {
  const auto& animations = context.model.animations;
  if (which.empty()) return animations.empty() ? -1 : 0;
  for (size_t i = 0; i < animations.size(); ++i)
    if (animations[i].name == which) return int(i);
  if (which.find_first_not_of("0123456789") == std::string::npos && which.size() < 10 &&
      size_t(std::stoul(which)) < animations.size())
    return int(std::stoul(which));
  std::string names;
  for (size_t i = 0; i < animations.size() && i < 8; ++i)
    names += (i ? ", " : "") + (animations[i].name.empty() ? std::to_string(i) : animations[i].name);
  throw LoadError(context.file + ": --animation '" + escaped(which) + "': no such animation (" +
                  std::to_string(animations.size()) + " animations" + (names.empty() ? "" : ": " + names) + ")");
}

void apply_animation(tinygltf::Model& model, const GltfContext& context, int index, double seconds) {
  const tinygltf::Animation& animation = model.animations.at(size_t(index));
  std::string where = element("animations", size_t(index));
  for (size_t c = 0; c < animation.channels.size(); ++c) {
    const tinygltf::AnimationChannel& channel = animation.channels[c];
    std::string at = where + "." + element("channels", c);
    // A channel without a node (KHR_animation_pointer) animates something radiant does not keep.
    if (channel.target_node < 0) continue;
    check_index(context, channel.target_node, model.nodes.size(), at + ".target.node", "node");
    check_index(context, channel.sampler, animation.samplers.size(), at + ".sampler", "sampler");
    const std::string& path = channel.target_path;
    int type = path == "translation" || path == "scale" ? TINYGLTF_TYPE_VEC3
               : path == "rotation"                      ? TINYGLTF_TYPE_VEC4
               : path == "weights"                       ? TINYGLTF_TYPE_SCALAR
                                                         : -1;
    if (type < 0) context.fail(at + ".target.path", "unknown path '" + escaped(path) + "'");
    Keys keys = read_keys(context, animation.samplers[size_t(channel.sampler)], type,
                          where + "." + element("samplers", size_t(channel.sampler)));
    std::vector<float> value(keys.width);
    sample(keys, path == "rotation", seconds, value.data());
    tinygltf::Node& node = model.nodes[size_t(channel.target_node)];
    if (path != "weights" && node.matrix.size() == 16)
      context.fail(element("nodes", size_t(channel.target_node)), "animated, but placed by a matrix (glTF asks for TRS)");
    std::vector<double> written(value.begin(), value.end());
    if (path == "translation") node.translation = written;
    else if (path == "rotation") node.rotation = written;
    else if (path == "scale") node.scale = written;
    else node.weights = written;
  }
}

int motion_steps_between(const GltfContext& context, int index, double from, double to) {
  const tinygltf::Animation& animation = context.model.animations.at(size_t(index));
  std::string where = element("animations", size_t(index));
  int intervals = 1;
  for (const tinygltf::AnimationChannel& channel : animation.channels) {
    if (channel.target_node < 0 || channel.sampler < 0 || size_t(channel.sampler) >= animation.samplers.size()) continue;
    int type = channel.target_path == "rotation" ? TINYGLTF_TYPE_VEC4
               : channel.target_path == "weights" ? TINYGLTF_TYPE_SCALAR
                                                  : TINYGLTF_TYPE_VEC3;
    Keys keys = read_keys(context, animation.samplers[size_t(channel.sampler)], type,
                          where + "." + element("samplers", size_t(channel.sampler)));
    if (keys.times.back() <= from || keys.times.front() >= to) continue;  // still all shutter long
    int inside = 0;
    for (float t : keys.times) inside += t > from && t < to;
    bool curved = channel.target_path == "rotation" || keys.interpolation == Interpolation::cubic_spline;
    intervals = std::max(intervals, (inside + 1) * (curved ? 2 : 1));
  }
  return std::min(intervals + 1, max_motion_steps);
}

}  // namespace radiant
