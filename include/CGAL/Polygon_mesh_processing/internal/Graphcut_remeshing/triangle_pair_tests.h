// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The exact tests of the intersections' search (intersections.h): whether two triangles of the mesh
// meet beyond what they share, and whether a vertex fan is embedded, which spares the tests of its
// pairs. Both read the vertices' points through `points(v)` (a Vector_3d): the mesh's own, or
// those it will be written at (normalization.h's Output_points).

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_TRIANGLE_PAIR_TESTS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_TRIANGLE_PAIR_TESTS_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

using Exact_predicates_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// The triangles around a vertex, each with its other two vertices in the order of the face.
using Vertex_fan =
  boost::container::small_vector<std::pair<Work_mesh::Face_index, std::array<Work_mesh::Vertex_index, 2> >, 16>;

// Whether the triangles of `fan` meet only in the edges and at the vertex v they share. Seen
// along the coordinate axis nearest their mean normal (the projection then only drops a
// coordinate, and exact predicates stay exact), the triangles must be positively oriented
// sectors at v going at most once around it: the ray to a first rim vertex (an end of an open
// fan) lies in no sector but the ones it bounds. Then two sectors share only v or a bounding
// ray, each triangle projects one to one, and two triangles share only v or their common edge.
template <typename Points>
bool is_embedded_fan(const Points& points, Work_mesh::Vertex_index v, const Vertex_fan& fan)
{
  const Vector_3d p = points(v);
  Vector_3d n = Vector_3d::Zero();
  for(const auto& t : fan)
    n += area_vector(p, points(t.second[0]), points(t.second[1]));
  const int axis = std::abs(n[0]) >= std::abs(n[1]) ? (std::abs(n[0]) >= std::abs(n[2]) ? 0 : 2)
                                                     : (std::abs(n[1]) >= std::abs(n[2]) ? 1 : 2);
  const CGAL::Orientation positive = n[axis] > 0 ? CGAL::POSITIVE : CGAL::NEGATIVE;
  const CGAL::Orientation negative = n[axis] > 0 ? CGAL::NEGATIVE : CGAL::POSITIVE;
  using Point_2 = std::array<double, 2>;
  auto project = [axis](const Vector_3d& q) {
    return axis == 0 ? Point_2{{q.y(), q.z()}} : (axis == 1 ? Point_2{{q.z(), q.x()}} : Point_2{{q.x(), q.y()}});
  };
  const Point_2 o = project(p);
  boost::container::small_vector<std::array<Point_2, 2>, 16> rim;
  // All orientations are of (o, a, b) with a and b on the rim: one error bound of CGAL's static
  // filter for orientation_2, from the largest coordinate differences to o, serves them all.
  double max_x = 0, max_y = 0;
  for(const auto& t : fan)
  {
    rim.push_back({{project(points(t.second[0])), project(points(t.second[1]))}});
    for(const Point_2& q : rim.back())
    {
      max_x = (std::max)(max_x, std::abs(q[0] - o[0]));
      max_y = (std::max)(max_y, std::abs(q[1] - o[1]));
    }
  }
  const bool filtered = max_x > 1e-146 && max_y > 1e-146 && max_x < 1e153 && max_y < 1e153;
  const double bound = 8.8872057372592798e-16 * max_x * max_y;
  auto orientation = [&](const Point_2& a, const Point_2& b) {
    if(filtered)
    {
      const double det = (a[0] - o[0]) * (b[1] - o[1]) - (b[0] - o[0]) * (a[1] - o[1]);
      if(det > bound)
        return CGAL::POSITIVE;
      if(det < -bound)
        return CGAL::NEGATIVE;
    }
    return CGAL::orientation(Exact_predicates_kernel::Point_2(o[0], o[1]), Exact_predicates_kernel::Point_2(a[0], a[1]), Exact_predicates_kernel::Point_2(b[0], b[1]));
  };
  for(const auto& r : rim)
    if(orientation(r[0], r[1]) != positive)
      return false;
  auto sectors_at = [&](Work_mesh::Vertex_index u) {
    std::size_t k = 0;
    for(const auto& t : fan)
      k += (t.second[0] == u) + (t.second[1] == u);
    return k;
  };
  std::size_t start = 0; // the rim vertex rim[start][0]
  for(std::size_t k = 0; k < fan.size(); ++k)
    if(sectors_at(fan[k].second[0]) == 1)
    {
      start = k;
      break;
    }
  const Work_mesh::Vertex_index start_vertex = fan[start].second[0];
  if(sectors_at(start_vertex) > 2)
    return false;
  const Point_2 s = rim[start][0];
  for(std::size_t k = 0; k < fan.size(); ++k)
    if(fan[k].second[0] != start_vertex && fan[k].second[1] != start_vertex &&
       orientation(rim[k][0], s) != negative && orientation(s, rim[k][1]) != negative)
      return false;
  return true;
}

// Whether the triangles a and b (their vertices) share a point they do not share through the mesh:
// for neighbours, a point other than their common vertex or edge.
template <typename Points>
bool triangles_intersect(const Points& points, const std::array<Work_mesh::Vertex_index, 3>& a,
                         const std::array<Work_mesh::Vertex_index, 3>& b)
{
  using Epick = Exact_predicates_kernel;
  const auto point = [&points](Work_mesh::Vertex_index v) {
    const Vector_3d p = points(v);
    return Epick::Point_3(p.x(), p.y(), p.z());
  };
  // Put the shared vertices first, in the same order in both.
  std::array<Work_mesh::Vertex_index, 3> fa = a, fb = b;
  int shared = 0;
  for(int i = 0; i < 3; ++i)
    for(int j = shared; j < 3; ++j)
      if(fa[i] == fb[j])
      {
        std::swap(fa[i], fa[shared]);
        std::swap(fb[j], fb[shared]);
        ++shared;
        break;
      }
  Epick k;
  if(shared == 3)
    return true; // two triangles on the same three vertices
  if(shared == 2)
  {
    // Across their common edge (p, q) they meet elsewhere only when folded onto each other.
    const Epick::Point_3 p = point(fa[0]), q = point(fa[1]), r = point(fa[2]), s = point(fb[2]);
    return k.coplanar_3_object()(p, q, r, s) &&
           k.coplanar_orientation_3_object()(p, q, r, s) == CGAL::POSITIVE;
  }
  if(shared == 1)
  {
    // Their intersection is convex and holds the common vertex: it holds another point exactly
    // when the edge of one opposite that vertex meets the other.
    const Epick::Point_3 v = point(fa[0]), a1 = point(fa[1]), a2 = point(fa[2]);
    const Epick::Point_3 b1 = point(fb[1]), b2 = point(fb[2]);
    auto orientation = k.orientation_3_object();
    // Strictly on one side of the other's plane: nothing but the common vertex.
    const CGAL::Orientation o1 = orientation(v, a1, a2, b1), o2 = orientation(v, a1, a2, b2);
    if(o1 != CGAL::COPLANAR && o1 == o2)
      return false;
    const CGAL::Orientation o3 = orientation(v, b1, b2, a1), o4 = orientation(v, b1, b2, a2);
    if(o3 != CGAL::COPLANAR && o3 == o4)
      return false;
    return CGAL::do_intersect(Epick::Segment_3(a1, a2), Epick::Triangle_3(v, b1, b2)) ||
           CGAL::do_intersect(Epick::Segment_3(b1, b2), Epick::Triangle_3(v, a1, a2));
  }
  return CGAL::do_intersect(Epick::Triangle_3(point(a[0]), point(a[1]), point(a[2])),
                            Epick::Triangle_3(point(b[0]), point(b[1]), point(b[2])));
}

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_TRIANGLE_PAIR_TESTS_H
