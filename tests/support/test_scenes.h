// Small scene texts shared by the command-line tests.
#pragma once

namespace radiant::test {

// An orthographic view straight down at a grey plane lit by a directional light: the cheapest
// scene that renders something, for tests about outputs rather than images.
inline constexpr const char* lit_plane_scene =
    "@camera\nposition 0 4 0\ndirection 0 -1 0\nup 0 0 -1\northographic 2\n"
    "@light directional\ndirection 0 -1 0\ncolor 1 1 1\n"
    "@plane\npoint 0 0 0\nnormal 0 1 0\nkd 0.5 0.5 0.5\n";

}  // namespace radiant::test
