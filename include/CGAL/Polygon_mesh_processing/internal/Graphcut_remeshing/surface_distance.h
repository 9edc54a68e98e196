// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Metro-style one-sided distance from a densely sampled surface to another triangle mesh, and
// from the sharp edges of one mesh to those of another.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_SURFACE_DISTANCE_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_SURFACE_DISTANCE_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/version.h>

#if CGAL_VERSION_NR >= 1060000000
#include <CGAL/AABB_segment_primitive_3.h>
#include <CGAL/AABB_traits_3.h>
#else
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// Samples of a triangle mesh surface: every vertex, then `number_of_face_samples` points spread
// over the faces in proportion to their areas (each face gets its share, rounded with a carried
// remainder so the total is exact) at uniformly random places inside the face.
struct Surface_samples
{
  std::vector<Vector_3d> vertex_samples;
  std::vector<Vector_3d> face_samples; // equal-area samples: their mean squared distance is RMS
};

template <typename TriangleMesh, typename VertexPointMap>
Surface_samples sample_surface(const TriangleMesh& tm, VertexPointMap vpm,
                               std::size_t number_of_face_samples, CGAL::Random& rng)
{
  Surface_samples samples;
  samples.vertex_samples.reserve(num_vertices(tm));
  for(auto v : vertices(tm))
    samples.vertex_samples.push_back(to_vector(get(vpm, v)));

  std::vector<std::array<Vector_3d, 3> > triangles;
  std::vector<double> areas;
  triangles.reserve(num_faces(tm));
  areas.reserve(num_faces(tm));
  double total_area = 0;
  for(auto f : faces(tm))
  {
    const auto h = halfedge(f, tm);
    const std::array<Vector_3d, 3> t{{to_vector(get(vpm, source(h, tm))),
                                      to_vector(get(vpm, target(h, tm))),
                                      to_vector(get(vpm, target(next(h, tm), tm)))}};
    const double a = 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).norm();
    triangles.push_back(t);
    areas.push_back(a);
    total_area += a;
  }
  if(!(total_area > 0) || number_of_face_samples == 0)
    return samples;

  samples.face_samples.reserve(number_of_face_samples);
  const double per_area = double(number_of_face_samples) / total_area;
  double wanted = 0;
  for(std::size_t i = 0; i < triangles.size(); ++i)
  {
    wanted += areas[i] * per_area;
    const std::size_t n = std::min(number_of_face_samples,
                                   static_cast<std::size_t>(std::floor(wanted + 0.5)));
    const auto& t = triangles[i];
    while(samples.face_samples.size() < n)
    {
      double r1 = rng.get_double(), r2 = rng.get_double();
      if(r1 + r2 > 1) { r1 = 1 - r1; r2 = 1 - r2; } // fold back into the triangle
      samples.face_samples.push_back(t[0] + r1 * (t[1] - t[0]) + r2 * (t[2] - t[0]));
    }
  }
  return samples;
}

// Maximum over all samples and root mean square over the face samples of the distance from the
// samples to the triangles of `tm`.
struct One_sided_distance
{
  double max = 0;
  double rms = 0;
};

template <typename TriangleMesh, typename VertexPointMap, typename GeomTraits>
One_sided_distance distance_to_mesh(const Surface_samples& samples, const TriangleMesh& tm,
                                    VertexPointMap vpm, const GeomTraits&)
{
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, VertexPointMap>;
#if CGAL_VERSION_NR >= 1060000000
  using Traits = CGAL::AABB_traits_3<GeomTraits, Primitive>;
#else
  using Traits = CGAL::AABB_traits<GeomTraits, Primitive>;
#endif
  using Point_3 = typename GeomTraits::Point_3;

  CGAL::AABB_tree<Traits> tree(faces(tm).first, faces(tm).second, tm, vpm);
  tree.accelerate_distance_queries();

  auto squared_distance = [&tree](const Vector_3d& p) {
    return CGAL::to_double(tree.squared_distance(Point_3(p.x(), p.y(), p.z())));
  };

  One_sided_distance d;
  double max_squared = 0;
  for(const Vector_3d& p : samples.vertex_samples)
    max_squared = (std::max)(max_squared, squared_distance(p));
  double sum_squared = 0;
  for(const Vector_3d& p : samples.face_samples)
  {
    const double s = squared_distance(p);
    sum_squared += s;
    max_squared = (std::max)(max_squared, s);
  }
  d.max = std::sqrt(max_squared);
  if(!samples.face_samples.empty())
    d.rms = std::sqrt(sum_squared / double(samples.face_samples.size()));
  return d;
}

// The length of the diagonal of the bounding box of `tm`'s vertices (0 without vertices).
template <typename TriangleMesh, typename VertexPointMap>
double bounding_box_diagonal(const TriangleMesh& tm, VertexPointMap vpm)
{
  if(vertices(tm).begin() == vertices(tm).end())
    return 0;
  Vector_3d low = Vector_3d::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for(auto v : vertices(tm))
  {
    const Vector_3d p = to_vector(get(vpm, v));
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return (high - low).norm();
}

// The edges of `tm` whose dihedral angle is at least `min_degrees` (border edges have none), as
// segments.
template <typename TriangleMesh, typename VertexPointMap>
std::vector<std::array<Vector_3d, 2> > sharp_edge_segments(const TriangleMesh& tm, VertexPointMap vpm,
                                                           double min_degrees)
{
  auto normal = [&](auto h) {
    const Vector_3d a = to_vector(get(vpm, source(h, tm))), b = to_vector(get(vpm, target(h, tm))),
                    c = to_vector(get(vpm, target(next(h, tm), tm)));
    return Vector_3d((b - a).cross(c - a));
  };
  std::vector<std::array<Vector_3d, 2> > segments;
  for(auto e : edges(tm))
  {
    const auto h = halfedge(e, tm);
    if(is_border_edge(h, tm))
      continue;
    if(to_degrees(angle_between(normal(h), normal(opposite(h, tm)))) >= min_degrees)
      segments.push_back({{to_vector(get(vpm, source(h, tm))), to_vector(get(vpm, target(h, tm)))}});
  }
  return segments;
}

// The largest distance from a point of the segments `from` to the union of the segments `to`,
// with points every `step` along each segment of `from` (the distance is 1-Lipschitz along a
// segment, so the true maximum is at most step / 2 above). Infinite when `to` is empty and `from`
// is not.
template <typename GeomTraits>
double max_distance_to_segments(const std::vector<std::array<Vector_3d, 2> >& from,
                                const std::vector<std::array<Vector_3d, 2> >& to, double step)
{
  using Point_3 = typename GeomTraits::Point_3;
  using Segment_3 = typename GeomTraits::Segment_3;
  using Iterator = typename std::vector<Segment_3>::const_iterator;
#if CGAL_VERSION_NR >= 1060000000
  using Primitive = CGAL::AABB_segment_primitive_3<GeomTraits, Iterator>;
  using Traits = CGAL::AABB_traits_3<GeomTraits, Primitive>;
#else
  using Primitive = CGAL::AABB_segment_primitive<GeomTraits, Iterator>;
  using Traits = CGAL::AABB_traits<GeomTraits, Primitive>;
#endif
  if(from.empty())
    return 0;
  if(to.empty())
    return std::numeric_limits<double>::infinity();
  auto point = [](const Vector_3d& p) { return Point_3(p.x(), p.y(), p.z()); };
  std::vector<Segment_3> targets;
  targets.reserve(to.size());
  for(const auto& s : to)
    targets.push_back(Segment_3(point(s[0]), point(s[1])));
  CGAL::AABB_tree<Traits> tree(targets.begin(), targets.end());
  tree.accelerate_distance_queries();

  double max_squared = 0;
  for(const auto& s : from)
  {
    const std::size_t pieces = (std::max)(std::size_t(1), std::size_t(std::ceil((s[1] - s[0]).norm() / step)));
    for(std::size_t i = 0; i <= pieces; ++i)
    {
      const double t = double(i) / double(pieces);
      const Vector_3d p = (1 - t) * s[0] + t * s[1];
      max_squared = (std::max)(max_squared, CGAL::to_double(tree.squared_distance(point(p))));
    }
  }
  return std::sqrt(max_squared);
}

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_SURFACE_DISTANCE_H
