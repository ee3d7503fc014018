#include <doctest/doctest.h>

#include <sstream>

#include "scene_format/scene_format_loader.h"

using namespace radiant;

TEST_CASE("link probe") {
  std::istringstream in("@sphere\np 0 0 0\nr 1\n");
  SceneDesc scene = load_scene_format(in, "t.scene", ".", {});
  CHECK(scene.shapes.size() == 1);
}
