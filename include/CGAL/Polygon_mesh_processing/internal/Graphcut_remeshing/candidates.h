// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Candidate positions (section 2.3): the smoothing targets, the freedom sphere of eq. (5) and the
// cooling schedule.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_CANDIDATES_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_CANDIDATES_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// The link of a vertex as the segments opposite to it in its incident triangles (on the stack for
// the valences a mesh has: one is made per vertex and candidate round).
using Link = boost::container::small_vector<std::pair<Vector_3d, Vector_3d>, 12>;

// Smallest distance from x to its one-ring boundary (the ||x_s, x_Ns|| of eq. 5).
inline double ring_radius(const Vector_3d& x, const Link& link)
{
  double r = std::numeric_limits<double>::infinity();
  for(const auto& s : link)
    r = (std::min)(r, distance_to_segment(x, s.first, s.second));
  return r;
}

// Angle-based smoothing (Zhou & Shimada): for each link segment (a, b), turn x about each end so
// that the edge to x bisects the angle the two ring neighbours make there; average the results.
// `link` lists the segments of a closed ring (each ring vertex is an end of two segments).
inline Vector_3d angle_based_target(const Vector_3d& x, const Link& link)
{
  Vector_3d sum = Vector_3d::Zero();
  int count = 0;
  // Around a ring vertex p with ring neighbours q (before) and r (after): p is the end of two
  // segments, (q, p) and (p, r); in a manifold ring only one segment starts at p. Around a vertex
  // the segments come in order, one way or the other: the two beside (q, p) are looked at first.
  const std::size_t k = link.size();
  for(std::size_t i = 0; i < k; ++i)
  {
    const auto& in = link[i];
    auto starts_at_p = [&](std::size_t j) { return link[j].first == in.second; };
    std::size_t j = starts_at_p((i + k - 1) % k) ? (i + k - 1) % k : (starts_at_p((i + 1) % k) ? (i + 1) % k : 0);
    while(j < k && !starts_at_p(j))
      ++j;
    if(j < k)
    {
      const auto& out = link[j];
      const Vector_3d& p = in.second;
      const Vector_3d u = in.first - p, w = out.second - p;
      const double lu = u.norm(), lw = w.norm(), lx = (x - p).norm();
      if(!(lu > 0) || !(lw > 0) || !(lx > 0))
        continue;
      const Vector_3d bisector = u / lu + w / lw;
      if(!(bisector.norm() > 1e-12))
        continue;
      sum += p + lx * bisector.normalized();
      ++count;
    }
  }
  return count > 0 ? Vector_3d(sum / count) : x;
}

// Laplacian smoothing: the centroid of the ring vertices.
template <typename PointRange>
Vector_3d laplacian_target(const Vector_3d& x, const PointRange& ring)
{
  Vector_3d sum = Vector_3d::Zero();
  int count = 0;
  for(const Vector_3d& p : ring)
  {
    sum += p;
    ++count;
  }
  return count > 0 ? Vector_3d(sum / count) : x;
}

// eq. (5): sigma = 0.5 / (1 + exp(-T)) * ring radius * min(1, rho).
inline double freedom_radius(double temperature, double ring_radius, double min_curvature_radius)
{
  return 0.5 / (1 + std::exp(-temperature)) * ring_radius * (std::min)(1.0, min_curvature_radius);
}

// T(i) = T(1) K^(i-1), i from 1.
inline double temperature(double initial_temperature, double cooling_factor, std::size_t iteration)
{
  return initial_temperature * std::pow(cooling_factor, double(iteration) - 1.0);
}

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_CANDIDATES_H
