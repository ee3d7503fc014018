// Small scene texts shared by the command-line tests.
#pragma once

namespace radiant::test {

// An orthographic view straight down at a grey plane lit by a directional light: the cheapest
// scene that renders something, for tests about outputs rather than images.
inline constexpr const char* lit_plane_scene =
    "@camera\nposition 0 4 0\ndirection 0 -1 0\nup 0 0 -1\northographic 2\n"
    "@light directional\ndirection 0 -1 0\ncolor 1 1 1\n"
    "@plane\npoint 0 0 0\nnormal 0 1 0\nkd 0.5 0.5 0.5\n";

// Inside a closed white sphere every path bounces --max-depth times: at depth 1000 one sample
// of every pixel of 32x32 takes about half a second on one thread, so tests that need a render
// to be under way (signals, progress) can count on it.
inline constexpr const char* closed_sphere_scene =
    "@camera\nposition 0 0 0\ndirection 0 0 -1\nup 0 1 0\n"
    "@light point\ncolor 255 255 255\nposition 0 0 0\n"
    "@sphere\ncenter 0 0 0\nradius 10\nkd 1\n";

// A white unit sphere at the origin lit by a point light, seen by the default camera: for tests
// of command-line flags that need some geometry in view.
inline constexpr const char* lit_sphere_scene = "@sphere\ncenter 0 0 0\nradius 1\nkd 1\n@light point\nposition 0 3 3\n";

}  // namespace radiant::test
