#include "scene/polygon_triangulation.h"

#include <cmath>
#include <numbers>

#include "math/dvec3.h"

namespace radiant {

namespace {

struct Point2 {
  double x, y;
};

// Twice the signed area of (a, b, c): positive when they turn counter-clockwise.
double orientation(Point2 a, Point2 b, Point2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

// Newell's normal of the corners taken about their centroid (robust when nearly planar).
dvec3 newell_normal(const std::vector<vec3>& corners) {
  dvec3 centroid = {0, 0, 0};
  for (vec3 c : corners) centroid = centroid + to_double(c) * (1.0 / double(corners.size()));
  dvec3 normal = {0, 0, 0};
  for (size_t i = 0; i < corners.size(); ++i)
    normal = normal + cross(to_double(corners[i]) - centroid, to_double(corners[(i + 1) % corners.size()]) - centroid);
  return normal;
}

// The axis along which `normal` is largest.
int largest_axis(dvec3 normal) {
  double x = std::abs(normal.x), y = std::abs(normal.y), z = std::abs(normal.z);
  return x > y ? (x > z ? 0 : 2) : (y > z ? 1 : 2);
}

// The corners in the plane across the normal's largest axis, turned so that the polygon runs
// counter-clockwise there.
std::vector<Point2> project(const std::vector<vec3>& corners, dvec3 normal) {
  int axis = largest_axis(normal);
  int u = (axis + 1) % 3, v = (axis + 2) % 3;  // u x v points along +axis
  double along = axis == 0 ? normal.x : axis == 1 ? normal.y : normal.z;
  if (along < 0) std::swap(u, v);
  std::vector<Point2> points;
  points.reserve(corners.size());
  for (vec3 c : corners) points.push_back({double(c[u]), double(c[v])});
  return points;
}

// Twice the area below which a turn counts as straight, relative to the squared polygon size.
constexpr double relative_area_tolerance = 1e-12;

// The larger side of the points' bounding rectangle: tolerances scale with it.
double polygon_size(const std::vector<Point2>& p) {
  double low_x = p[0].x, high_x = p[0].x, low_y = p[0].y, high_y = p[0].y;
  for (Point2 q : p) {
    low_x = std::min(low_x, q.x), high_x = std::max(high_x, q.x);
    low_y = std::min(low_y, q.y), high_y = std::max(high_y, q.y);
  }
  return std::max(high_x - low_x, high_y - low_y);
}

// Strictly convex and winding once: every corner turns left, by less than two turns in all
// (a pentagram turns left everywhere but winds twice).
bool is_convex(const std::vector<Point2>& p, double area_tolerance) {
  size_t n = p.size();
  double turning = 0;
  for (size_t i = 0; i < n; ++i) {
    Point2 a = p[(i + n - 1) % n], b = p[i], c = p[(i + 1) % n];
    double sine = orientation(a, b, c);
    if (sine <= area_tolerance) return false;
    double cosine = (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y);
    turning += std::atan2(sine, cosine);
  }
  return turning < 3 * std::numbers::pi;
}

// Whether two edges of the closed polygon cross properly (each passes strictly through the
// other). Edges that touch or overlap along a line do not count: a bridge edge walked there and
// back, or a repeated corner, is allowed. Quadratic, so checked up to a size (beyond it a
// polygon is taken as simple: no exporter writes such faces crossing).
bool edges_cross(const std::vector<Point2>& p) {
  constexpr size_t largest_checked = 4096;
  size_t n = p.size();
  if (n > largest_checked) return false;
  auto side = [](Point2 a, Point2 b, Point2 c) {
    double o = orientation(a, b, c);
    return o > 0 ? 1 : o < 0 ? -1 : 0;
  };
  for (size_t i = 0; i < n; ++i) {
    Point2 a = p[i], b = p[(i + 1) % n];
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // the closing edge meets the first
      Point2 c = p[j], d = p[(j + 1) % n];
      if (side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0) return true;
    }
  }
  return false;
}

// Ear clipping over a circular list of the corners still to cut.
struct EarClipper {
  const std::vector<Point2>& points;
  std::vector<uint32_t> previous, next;
  size_t remaining;
  double area_tolerance, distance_tolerance_squared;
  uint64_t work_left;  // point tests allowed before the rest is cut as a fan
  PolygonTriangles out;

  explicit EarClipper(const std::vector<Point2>& p) : points(p), remaining(p.size()) {
    size_t n = p.size();
    previous.resize(n), next.resize(n);
    for (size_t i = 0; i < n; ++i) previous[i] = uint32_t((i + n - 1) % n), next[i] = uint32_t((i + 1) % n);
    double size = polygon_size(p);
    area_tolerance = relative_area_tolerance * size * size;
    distance_tolerance_squared = 1e-18 * size * size;
    // Quadratic in the corners for simple shapes; a hostile face of 10^5 reflex corners would be
    // cubic, so the work is capped (about a tenth of a second).
    work_left = 50'000'000;
  }

  bool same_place(uint32_t a, uint32_t b) const {
    double dx = points[a].x - points[b].x, dy = points[a].y - points[b].y;
    return dx * dx + dy * dy <= distance_tolerance_squared;
  }

  // Inside or on the triangle (a, b, c), which turns counter-clockwise.
  bool touches_triangle(Point2 a, Point2 b, Point2 c, Point2 r) const {
    return orientation(a, b, r) >= -area_tolerance && orientation(b, c, r) >= -area_tolerance &&
           orientation(c, a, r) >= -area_tolerance;
  }

  // (p, i, q) is an ear when no other corner lies in it. Corners at the same place as one of its
  // own (the two ends of a bridge edge) are on its boundary and do not count.
  bool is_ear(uint32_t p, uint32_t i, uint32_t q) {
    for (uint32_t r = next[q]; r != p; r = next[r]) {
      if (work_left == 0) return false;
      --work_left;
      if (same_place(r, p) || same_place(r, i) || same_place(r, q)) continue;
      if (touches_triangle(points[p], points[i], points[q], points[r])) return false;
    }
    return true;
  }

  void remove(uint32_t i) {
    next[previous[i]] = next[i];
    previous[next[i]] = previous[i];
    --remaining;
  }

  void run() {
    uint32_t i = 0;
    size_t passed_over = 0;  // corners tried since the last cut
    while (remaining > 3) {
      uint32_t p = previous[i], q = next[i];
      double turn = orientation(points[p], points[i], points[q]);
      if (std::abs(turn) <= area_tolerance) {
        // A repeated corner, one on a straight edge or the tip of a zero-width spike: no area.
        remove(i);
        i = p, passed_over = 0;
      } else if (turn > 0 && is_ear(p, i, q)) {
        out.corners.insert(out.corners.end(), {p, i, q});
        remove(i);
        i = q, passed_over = 0;
      } else if (++passed_over > remaining || work_left == 0) {
        cut_fan(i);
        return;
      } else {
        i = q;
      }
    }
    uint32_t p = previous[i], q = next[i];
    if (std::abs(orientation(points[p], points[i], points[q])) > area_tolerance) out.corners.insert(out.corners.end(), {p, i, q});
  }

  // No ear left (the polygon crosses itself): the rest becomes a fan around `i`.
  void cut_fan(uint32_t i) {
    out.simple = false;
    for (uint32_t a = next[i]; next[a] != i; a = next[a]) out.corners.insert(out.corners.end(), {i, a, next[a]});
  }
};

}  // namespace

PolygonTriangles triangulate_polygon(const std::vector<vec3>& corners) {
  PolygonTriangles result;
  if (corners.size() < 3) return result;
  if (corners.size() == 3) {
    result.corners = {0, 1, 2};
    return result;
  }
  dvec3 normal = newell_normal(corners);
  if (!(dot(normal, normal) > 0)) return result;
  std::vector<Point2> points = project(corners, normal);
  // Convex polygons (what most exporters write) are fans from the first corner, as before.
  double size = polygon_size(points);
  if (is_convex(points, relative_area_tolerance * size * size)) {
    for (uint32_t k = 1; k + 1 < corners.size(); ++k) result.corners.insert(result.corners.end(), {0, k, k + 1});
    return result;
  }
  EarClipper clipper(points);
  clipper.run();
  // Ears are found in a polygon that crosses itself too (a pentagram's tips): look for crossings.
  if (edges_cross(points)) clipper.out.simple = false;
  return std::move(clipper.out);
}

}  // namespace radiant
