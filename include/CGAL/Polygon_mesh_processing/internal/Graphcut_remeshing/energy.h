// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The energy of eq. (1): a shape term per triangle (eq. 2) and a data term per vertex, the
// second-order approximation of the squared distance to the reference surface (eq. 4).

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_ENERGY_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_ENERGY_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// The frame of a reference point: the surface normal and the principal directions, with the
// principal curvatures k1 (along d1, the larger in absolute value) and k2 (along d2).
struct Local_frame
{
  Vector_3d origin = Vector_3d::Zero();
  Vector_3d normal = Vector_3d::UnitZ();
  Vector_3d d1 = Vector_3d::UnitX();
  Vector_3d d2 = Vector_3d::UnitY();
  double k1 = 0;
  double k2 = 0;

  // The smallest principal radius 1 / max |k|, infinite where the surface is flat.
  double min_radius() const
  {
    const double k = (std::max)(std::abs(k1), std::abs(k2));
    return k > 0 ? 1.0 / k : std::numeric_limits<double>::infinity();
  }
};

struct Energy_weights
{
  double lambda_shape = 1;
  double lambda_data = 1e7;
  double epsilon = 0.01; // bound on the Taylor expansion point of eq. (4)
  // Beyond the paper: the weight, relative to lambda_data, of the data term at triangle centroids.
  double face_data_weight = 0.05;
  // Beyond the paper: the weight, relative to lambda_data, of the data term at feature-edge
  // midpoints. A chord of a curved feature line deviates where CAD models keep most of their
  // distance to the remesh; weighing it more lowers fandisk's RMS distance by about 5 % and leaves
  // models without features alone.
  double feature_data_weight = 4;
};

// eq. (2): circumradius over shortest edge; 1/sqrt(3) for an equilateral triangle, infinite for a
// degenerate one. R = abc / (4 area), so R / min = (product of the two longer edges) / (4 area).
inline double shape_energy(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c)
{
  const double la = (b - c).norm(), lb = (c - a).norm(), lc = (a - b).norm();
  const double twice_area = area_vector(a, b, c).norm();
  const double shortest = (std::min)({la, lb, lc});
  if(!(twice_area > 0) || !(shortest > 0))
    return std::numeric_limits<double>::infinity();
  return la * lb * lc / (2 * twice_area * shortest);
}

// eq. (4) in the frame at the reference point: d / (d + |rho_i|) = d |k_i| / (d |k_i| + 1), so a
// flat direction (k = 0, rho infinite) contributes nothing.
inline double squared_distance_approximation(const Vector_3d& x, const Local_frame& f, double epsilon)
{
  const Vector_3d v = x - f.origin;
  const double x1 = v.dot(f.d1), x2 = v.dot(f.d2), x3 = v.dot(f.normal);
  const double d = (std::min)(epsilon, std::abs(x3));
  const double w1 = d * std::abs(f.k1), w2 = d * std::abs(f.k2);
  return w1 / (w1 + 1) * x1 * x1 + w2 / (w2 + 1) * x2 * x2 + x3 * x3;
}

// A triangle that a move may not create: degenerate, or turned over against its current normal
// (turned by more than the angle whose cosine is `min_cosine`, a right angle by default).
inline bool is_acceptable_triangle(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c,
                                   const Vector_3d& current_area_vector, double min_cosine = 0)
{
  const Vector_3d n = area_vector(a, b, c);
  const double longest2 = (std::max)({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  // A relative area of 1e-12 is a shape energy above 1e11: nothing an optimiser should produce.
  if(!(n.norm() > 1e-12 * longest2))
    return false;
  return n.dot(current_area_vector) > min_cosine * n.norm() * current_area_vector.norm();
}

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_ENERGY_H
