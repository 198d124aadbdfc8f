// The one translation unit of modeling that includes CGAL's polygon, triangulation and mesh
// headers (about 20 s and 1.1 GB to compile): keep other CGAL work here or in one more file.
// The solids themselves are assembled and checked in OpenMesh (solid_mesh.cpp).
#include "extrude_cgal.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Triangulation_face_base_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cmath>

namespace inlay::detail {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point2 = K::Point_2;
using Segment2 = K::Segment_2;
using Polygon2 = CGAL::Polygon_2<K>;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<uint32_t, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

Point2 toCgal(const Vec2& p) { return Point2(p.x(), p.y()); }

// The first pair of edges that cross or overlap (for the message); -1, -1 if none is found.
std::pair<int, int> firstCrossing(const std::vector<Vec2>& p) {
  const size_t n = p.size();
  for (size_t i = 0; i < n; ++i) {
    const Segment2 a(toCgal(p[i]), toCgal(p[(i + 1) % n]));
    for (size_t j = i + 1; j < n; ++j) {
      const Segment2 b(toCgal(p[j]), toCgal(p[(j + 1) % n]));
      const bool next = j == i + 1, wrap = i == 0 && j == n - 1;
      if (next || wrap) {
        // Neighbours share one endpoint; anything more (an overlap) is a fold back.
        const auto x = CGAL::intersection(a, b);
        if (x && boost::get<Segment2>(&*x)) return {int(i), int(j)};
        continue;
      }
      if (CGAL::do_intersect(a, b)) return {int(i), int(j)};
    }
  }
  return {-1, -1};
}

}  // namespace

Expected<std::vector<Vec2>> counterClockwiseSimplePolygon(const std::vector<Vec2>& points,
                                                          const std::string& key) {
  for (size_t i = 0; i < points.size(); ++i)
    if (!points[i].allFinite())
      return Error{"", key + "[" + std::to_string(i) + "]", "is not a finite number"};
  std::vector<Vec2> p;
  for (const Vec2& q : points)
    if (p.empty() || (q - p.back()).norm() > 1e-9) p.push_back(q);
  while (p.size() > 1 && (p.front() - p.back()).norm() <= 1e-9) p.pop_back();  // closed by hand
  if (p.size() < 3)
    return Error{
        "", key,
        "an outline needs at least 3 distinct points, this one has " + std::to_string(p.size())};
  Polygon2 poly;
  for (const Vec2& q : p) poly.push_back(toCgal(q));
  // Collinear up to round-off: no point farther from the line through the two extreme points
  // than 1e-7 of their distance (an exact test lets float slivers through).
  size_t far = 0;
  for (size_t i = 1; i < p.size(); ++i)
    if ((p[i] - p[0]).squaredNorm() > (p[far] - p[0]).squaredNorm()) far = i;
  const Vec2 axis = p[far] - p[0];
  double maxOff = 0;
  for (const Vec2& q : p) {
    const Vec2 w = q - p[0];
    maxOff = std::max(maxOff, std::abs(axis.x() * w.y() - axis.y() * w.x()) / axis.norm());
  }
  if (!(maxOff > 1e-7 * axis.norm()))
    return Error{"", key, "all points lie on one line: the outline encloses no area"};
  // The free function with a kernel of our own: Polygon_2::is_simple() passes its member kernel (an
  // empty object), which GCC 12 takes for uninitialized (-Wmaybe-uninitialized) after inlining.
  if (!CGAL::is_simple_2(poly.vertices_begin(), poly.vertices_end(), K())) {
    const auto [a, b] = firstCrossing(p);
    return Error{"", key,
                 a >= 0 ? "the outline crosses itself (edge " + std::to_string(a) + " meets edge " +
                              std::to_string(b) + "): draw it without crossings"
                        : std::string("the outline crosses itself: draw it without crossings")};
  }
  if (poly.orientation() == CGAL::CLOCKWISE) std::reverse(p.begin(), p.end());
  return p;
}

std::vector<std::array<uint32_t, 3>> triangulatePolygon(const std::vector<Vec2>& polygon) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> vh(polygon.size());
  for (size_t i = 0; i < polygon.size(); ++i) {
    vh[i] = cdt.insert(toCgal(polygon[i]));
    vh[i]->info() = uint32_t(i);
  }
  for (size_t i = 0; i < polygon.size(); ++i) cdt.insert_constraint(vh[i], vh[(i + 1) % polygon.size()]);
  Polygon2 poly;
  for (const Vec2& q : polygon) poly.push_back(toCgal(q));
  std::vector<std::array<uint32_t, 3>> tris;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const Point2 c = CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    if (poly.bounded_side(c) != CGAL::ON_BOUNDED_SIDE) continue;
    // A simple polygon gets no Steiner points: every vertex is one of ours.
    tris.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  }
  return tris;
}

bool insideOrOnPolygon(const std::vector<Vec2>& polygon, const Vec2& p) {
  std::vector<Point2> pts;
  pts.reserve(polygon.size());
  for (const Vec2& q : polygon) pts.push_back(toCgal(q));
  return CGAL::bounded_side_2(pts.begin(), pts.end(), toCgal(p), K()) != CGAL::ON_UNBOUNDED_SIDE;
}

}  // namespace inlay::detail
