// Scene pieces the stability cases share: a triangle-mesh box placed by an instance transform.
#pragma once

#include "support/scene_builders.h"

namespace radiant::test {

// The unit cube [0,1]^3 as 12 triangles wound so that every normal points outward.
inline MeshDesc unit_cube_mesh(int material) {
  MeshDesc mesh;
  mesh.material = material;
  for (int i = 0; i < 8; ++i) mesh.positions.push_back({float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1)});
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      int b = (axis + 1) % 3, c = (axis + 2) % 3;
      uint32_t corner[4];
      const int around[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (int k = 0; k < 4; ++k)
        corner[k] = uint32_t((side << axis) | (around[k][0] << b) | (around[k][1] << c));
      vec3 outward;
      outward[axis] = side ? 1.0f : -1.0f;
      vec3 p0 = mesh.positions[corner[0]], p1 = mesh.positions[corner[1]], p2 = mesh.positions[corner[2]];
      bool flip = dot(cross(p1 - p0, p2 - p0), outward) < 0;
      if (flip) mesh.indices.insert(mesh.indices.end(), {corner[0], corner[2], corner[1], corner[0], corner[3], corner[2]});
      else mesh.indices.insert(mesh.indices.end(), {corner[0], corner[1], corner[2], corner[0], corner[2], corner[3]});
    }
  }
  return mesh;
}

// Adds the box [lower, lower + size] as the unit cube under translation(lower) * scaling(size).
inline void add_box(SceneDesc& scene, vec3 lower, vec3 size, int material) {
  scene.meshes.push_back(unit_cube_mesh(material));
  InstanceDesc instance;
  instance.mesh = int(scene.meshes.size()) - 1;
  instance.transform = translation(lower) * scaling(size);
  scene.instances.push_back(instance);
}

}  // namespace radiant::test
