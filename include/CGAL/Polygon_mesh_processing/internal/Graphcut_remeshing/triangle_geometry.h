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

// Distance from p to the segment [a, b].
inline double distance_to_segment(const Vector_3d& p, const Vector_3d& a, const Vector_3d& b)
{
  const Vector_3d ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0 ? (std::min)(1.0, (std::max)(0.0, (p - a).dot(ab) / l2)) : 0.0;
  return (p - (a + t * ab)).norm();
}

// The three angles of triangle (a, b, c), at a, b and c, in radians.
inline std::array<double, 3> triangle_angles(const Vector_3d& a, const Vector_3d& b,
                                             const Vector_3d& c)
{
  return {{angle(a, b, c), angle(b, c, a), angle(c, a, b)}};
}

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_TRIANGLE_GEOMETRY_H
