// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Elementary triangle geometry in double precision, shared by the quality report, the energy and
// the connectivity operators: the one place that computes an angle.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_TRIANGLE_GEOMETRY_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_TRIANGLE_GEOMETRY_H

#include <CGAL/number_utils.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

using Vector_3d = Eigen::Vector3d;

constexpr double pi = 3.14159265358979323846;

inline double to_degrees(double radians) { return radians * (180.0 / pi); }

// A point of any CGAL kernel as a double vector.
template <typename Point_3>
Vector_3d to_vector(const Point_3& p)
{
  return Vector_3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

// Angle between two vectors, in radians. atan2 of the cross and dot products stays accurate near
// 0 and pi, where acos of a normalised dot product does not.
inline double angle_between(const Vector_3d& u, const Vector_3d& v)
{
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

// Angle at `apex` between the rays to `p` and `q`, in radians.
inline double angle(const Vector_3d& apex, const Vector_3d& p, const Vector_3d& q)
{
  return angle_between(p - apex, q - apex);
}

// Twice the area vector of triangle (a, b, c): its direction is the triangle's normal.
inline Vector_3d area_vector(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c)
{
  return (b - a).cross(c - a);
}

// Two triangles of area vectors a and b that share an edge are folded onto each other when they
// turn by more than 120 degrees (sharp edges are 35 degrees and more: no smooth part turns this
// much over one edge).
inline bool is_folded_pair(const Vector_3d& a, const Vector_3d& b)
{
  return a.dot(b) < -0.5 * a.norm() * b.norm();
}

// The component of v in the plane of unit normal n.
inline Vector_3d tangential(const Vector_3d& v, const Vector_3d& n)
{
  return v - v.dot(n) * n;
}

// The three angles of triangle (a, b, c), at a, b and c, in radians.
inline std::array<double, 3> triangle_angles(const Vector_3d& a, const Vector_3d& b,
                                             const Vector_3d& c)
{
  return {{angle(a, b, c), angle(b, c, a), angle(c, a, b)}};
}

// The point of segment [a, b] closest to p, with t its parameter from a.
inline Vector_3d closest_point_on_segment(const Vector_3d& p, const Vector_3d& a, const Vector_3d& b,
                                          double& t)
{
  const Vector_3d ab = b - a;
  const double l2 = ab.squaredNorm();
  t = l2 > 0 ? (std::min)(1.0, (std::max)(0.0, (p - a).dot(ab) / l2)) : 0.0;
  return a + t * ab;
}

// Distance from p to the segment [a, b].
inline double distance_to_segment(const Vector_3d& p, const Vector_3d& a, const Vector_3d& b)
{
  double t;
  return (p - closest_point_on_segment(p, a, b, t)).norm();
}

// A needle or a cap: a triangle whose area is at the rounding level of its edges. It has no
// reliable interior region: barycentric weights there would be noise.
inline bool is_needle_or_cap(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c)
{
  const Vector_3d ab = b - a, ac = c - a;
  const double longest2 = (std::max)({ab.squaredNorm(), ac.squaredNorm(), (c - b).squaredNorm()});
  return ab.cross(ac).norm() <= 1e-12 * longest2;
}

// The point of triangle (a, b, c) closest to p, with its barycentric coordinates (Voronoi regions
// of the vertices, then of the edges, then the interior); `needle` is is_needle_or_cap(a, b, c),
// which callers with fixed triangles compute once.
inline Vector_3d closest_point_on_triangle(const Vector_3d& p, const Vector_3d& a, const Vector_3d& b,
                                           const Vector_3d& c, std::array<double, 3>& barycentric,
                                           bool needle)
{
  const Vector_3d ab = b - a, ac = c - a, ap = p - a;
  // The closest point of a needle or a cap is on its longest sides.
  if(needle)
  {
    const std::array<const Vector_3d*, 3> corner = {{&a, &b, &c}};
    double best = std::numeric_limits<double>::infinity();
    Vector_3d closest = a;
    for(int i = 0; i < 3; ++i)
    {
      const int j = (i + 1) % 3;
      double t;
      const Vector_3d q = closest_point_on_segment(p, *corner[i], *corner[j], t);
      const double d = (p - q).squaredNorm();
      if(d < best)
      {
        best = d;
        closest = q;
        barycentric = {{0, 0, 0}};
        barycentric[i] = 1 - t;
        barycentric[j] = t;
      }
    }
    return closest;
  }
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if(d1 <= 0 && d2 <= 0) { barycentric = {{1, 0, 0}}; return a; }
  const Vector_3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if(d3 >= 0 && d4 <= d3) { barycentric = {{0, 1, 0}}; return b; }
  const double vc = d1 * d4 - d3 * d2;
  if(vc <= 0 && d1 >= 0 && d3 <= 0)
  {
    const double t = d1 / (d1 - d3);
    barycentric = {{1 - t, t, 0}};
    return a + t * ab;
  }
  const Vector_3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if(d6 >= 0 && d5 <= d6) { barycentric = {{0, 0, 1}}; return c; }
  const double vb = d5 * d2 - d1 * d6;
  if(vb <= 0 && d2 >= 0 && d6 <= 0)
  {
    const double t = d2 / (d2 - d6);
    barycentric = {{1 - t, 0, t}};
    return a + t * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if(va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
  {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    barycentric = {{0, 1 - t, t}};
    return b + t * (c - b);
  }
  const double denominator = va + vb + vc;
  if(!(denominator > 0)) { barycentric = {{1, 0, 0}}; return a; } // degenerate triangle
  const double v = vb / denominator, w = vc / denominator;
  barycentric = {{1 - v - w, v, w}};
  return a + v * ab + w * ac;
}

inline Vector_3d closest_point_on_triangle(const Vector_3d& p, const Vector_3d& a, const Vector_3d& b,
                                           const Vector_3d& c, std::array<double, 3>& barycentric)
{
  return closest_point_on_triangle(p, a, b, c, barycentric, is_needle_or_cap(a, b, c));
}

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_TRIANGLE_GEOMETRY_H
