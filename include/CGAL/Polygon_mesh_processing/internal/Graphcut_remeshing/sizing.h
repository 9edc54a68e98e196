// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sizing field of the connectivity stage (section 3.1: e_min and e_max follow the local
// curvature): a target edge length at each point of the reference surface.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_SIZING_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_SIZING_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/reference_surface.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// The target edge length at a point of the reference: the mean edge length of the input, shorter
// where the surface is curved so that a chord of that length stays within `tolerance` of it
// (l = sqrt(6 tolerance rho - 3 tolerance^2)), never below half the mean.
struct Sizing
{
  double mean_length = 0;
  double tolerance = 1e-3;

  double length(const Local_frame& f) const
  {
    const double rho = f.min_radius();
    if(!std::isfinite(rho))
      return mean_length;
    const double l2 = 6 * tolerance * rho - 3 * tolerance * tolerance;
    const double curved = l2 > 0 ? std::sqrt(l2) : 0;
    return (std::max)(0.5 * mean_length, (std::min)(mean_length, curved));
  }
};

// The mean length of the edges of m (0 without edges).
inline double mean_edge_length(const Work_mesh& m)
{
  double total = 0;
  for(Work_mesh::Edge_index e : m.edges())
    total += (to_vector(m.point(m.source(m.halfedge(e)))) - to_vector(m.point(m.target(m.halfedge(e))))).norm();
  return m.number_of_edges() > 0 ? total / double(m.number_of_edges()) : 0;
}

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_SIZING_H
