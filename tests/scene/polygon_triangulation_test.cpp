// Ear clipping of planar polygons: triangles that cover exactly the polygon, winding kept.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "scene/polygon_triangulation.h"

using namespace radiant;

namespace {

// Signed area of triangle (a, b, c) seen along +z (positive when counter-clockwise).
double signed_area_z(vec3 a, vec3 b, vec3 c) {
  return 0.5 * ((double(b.x) - a.x) * (double(c.y) - a.y) - (double(b.y) - a.y) * (double(c.x) - a.x));
}

// The polygon's corners in the z = 0 plane.
std::vector<vec3> in_plane(const std::vector<vec2>& points) {
  std::vector<vec3> corners;
  for (vec2 p : points) corners.push_back({p.x, p.y, 0});
  return corners;
}

// Sum of the triangles' signed areas; every triangle must turn counter-clockwise like the polygon.
double covered_area(const std::vector<vec3>& corners, const PolygonTriangles& triangles) {
  double total = 0;
  for (size_t t = 0; t + 2 < triangles.corners.size(); t += 3) {
    double area = signed_area_z(corners[triangles.corners[t]], corners[triangles.corners[t + 1]],
                                corners[triangles.corners[t + 2]]);
    CHECK(area > 0);
    total += area;
  }
  return total;
}

// Whether point (x, y) lies inside one of the triangles (strictly).
bool covers(const std::vector<vec3>& corners, const PolygonTriangles& triangles, float x, float y) {
  for (size_t t = 0; t < triangles.corners.size(); t += 3) {
    vec3 a = corners[triangles.corners[t]], b = corners[triangles.corners[t + 1]], c = corners[triangles.corners[t + 2]];
    vec3 p = {x, y, 0};
    if (signed_area_z(a, b, p) > 0 && signed_area_z(b, c, p) > 0 && signed_area_z(c, a, p) > 0) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("triangulation: a convex polygon is a fan from its first corner") {
  std::vector<vec3> pentagon = in_plane({{0, 0}, {2, 0}, {3, 1}, {1, 3}, {-1, 1}});
  PolygonTriangles t = triangulate_polygon(pentagon);
  CHECK(t.simple);
  CHECK(t.corners == std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4});
}

TEST_CASE("triangulation: a concave L covers exactly its area, not the notch a fan would fill") {
  // An L of area 3: the fan from corner 0 would cover the notch [1,2]x[1,2] too.
  std::vector<vec3> l_shape = in_plane({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  PolygonTriangles t = triangulate_polygon(l_shape);
  CHECK(t.simple);
  CHECK(t.corners.size() == 12);
  CHECK(covered_area(l_shape, t) == doctest::Approx(3).epsilon(1e-12));
  CHECK_FALSE(covers(l_shape, t, 1.5f, 1.5f));
  CHECK(covers(l_shape, t, 0.5f, 1.5f));
}

TEST_CASE("triangulation: an annulus joined by a bridge edge keeps its hole (assimp's concave_polygon.obj)") {
  // Outer square counter-clockwise, the bridge to the inner square, the inner square clockwise,
  // and the bridge back: area 16 - 4.
  std::vector<vec3> annulus =
      in_plane({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}, {1, 1}, {1, 3}, {3, 3}, {3, 1}, {1, 1}});
  PolygonTriangles t = triangulate_polygon(annulus);
  CHECK(t.simple);
  CHECK(covered_area(annulus, t) == doctest::Approx(12).epsilon(1e-12));
  CHECK_FALSE(covers(annulus, t, 2, 2));
  CHECK_FALSE(covers(annulus, t, 1.2f, 2.8f));
  CHECK(covers(annulus, t, 0.3f, 2.1f));
  CHECK(covers(annulus, t, 3.7f, 3.4f));
}

TEST_CASE("triangulation: repeated corners and corners on a straight edge add no triangles") {
  std::vector<vec3> square = in_plane({{0, 0}, {1, 0}, {1, 0}, {2, 0}, {2, 2}, {1, 2}, {0, 2}, {0, 2}});
  PolygonTriangles t = triangulate_polygon(square);
  CHECK(t.simple);
  CHECK(covered_area(square, t) == doctest::Approx(4).epsilon(1e-12));  // and no triangle without area
  CHECK(covers(square, t, 0.5f, 0.1f));
  CHECK(covers(square, t, 1.9f, 1.9f));
}

TEST_CASE("triangulation: a polygon that crosses itself or has no area is reported") {
  std::vector<vec3> star;
  for (int k = 0; k < 5; ++k) {
    float angle = float(k) * 4 * 3.14159265f / 5;
    star.push_back({std::cos(angle), std::sin(angle), 0});
  }
  CHECK_FALSE(triangulate_polygon(star).simple);
  std::vector<vec3> bow_tie = in_plane({{0, 0}, {3, 3}, {3, 0}, {0, 1}});  // uneven: it has an area
  CHECK_FALSE(triangulate_polygon(bow_tie).simple);
  CHECK(triangulate_polygon(in_plane({{0, 0}, {1, 1}, {2, 2}, {3, 3}})).corners.empty());
}

TEST_CASE("triangulation: a concave polygon in a tilted plane keeps its winding around the plane's normal") {
  // The L in the plane x = 5, walked counter-clockwise seen from +x, and clockwise.
  std::vector<vec3> l_shape;
  for (vec2 p : std::vector<vec2>{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}) l_shape.push_back({5, p.x, p.y});
  for (float side : {1.0f, -1.0f}) {
    std::vector<vec3> corners = l_shape;
    if (side < 0) std::reverse(corners.begin(), corners.end());
    PolygonTriangles t = triangulate_polygon(corners);
    REQUIRE(t.corners.size() == 12);
    double area = 0;
    for (size_t k = 0; k < t.corners.size(); k += 3) {
      vec3 a = corners[t.corners[k]], b = corners[t.corners[k + 1]], c = corners[t.corners[k + 2]];
      float along_x = cross(b - a, c - a).x * side;
      CHECK(along_x > 0);
      area += 0.5 * along_x;
    }
    CHECK(area == doctest::Approx(3).epsilon(1e-6));
  }
}
