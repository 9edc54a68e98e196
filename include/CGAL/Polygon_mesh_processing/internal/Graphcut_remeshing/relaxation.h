// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Section 3.2: tangential relaxation of the vertex positions.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_RELAXATION_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_RELAXATION_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/candidates.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/local_operations.h>

#include <boost/container/small_vector.hpp>

#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <utility>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// Section 3.2's relaxation: each free vertex moves towards the angle-based, else the Laplacian,
// target in its tangent plane, brought onto the reference, when no triangle around it folds or
// turns too far and the fit holds (keeps_fit()).
class Relaxation : public Local_operations
{
public:
  // local_energy(v, x, bound): the energy, or once it is known to reach `bound`, a value between
  // `bound` and the energy (the rest need not be evaluated).
  using Local_energy = std::function<double(Vertex, const Vector_3d&, double)>;

  // `local_energy(v, x)`, the terms of eq. (1) that depend on the position x of v (eq. 7), lets
  // the relaxation keep only the moves that do not raise it (none is checked without it).
  Relaxation(const Local_operations& operations, Local_energy local_energy)
    : Local_operations(operations), m_local_energy(std::move(local_energy))
  {}

  // One sweep over the free vertices; returns how many moved.
  std::size_t run()
  {
    std::size_t moved = 0;
    for(Vertex v : m_mesh.vertices())
    {
      if(!is_free(v) || is_frozen(v))
        continue;
      const Vector_3d x = position(v);
      Link link;
      boost::container::small_vector<Vector_3d, 12> ring;
      boost::container::small_vector<Vector_3d, 12> normals;
      for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      {
        const Vector_3d p = position(m_mesh.source(h)), q = position(m_mesh.target(m_mesh.next(h)));
        ring.push_back(p);
        link.emplace_back(q, p);
        normals.push_back(area_vector(x, q, p));
      }
      const Vector_3d normal = m_reference.frame(m_state.closest[std::size_t(v)]).normal;
      const bool within_tolerance_rule = m_sizing.resamples() && !next_to_feature(v);
      double energy_here = std::numeric_limits<double>::quiet_NaN(); // once a move is acceptable
      auto try_move = [&](const Vector_3d& target) {
        Face hint = m_state.vertex_hint[std::size_t(v)];
        const Vector_3d y = m_reference.closest_point(x + tangential(target - x, normal), hint);
        for(std::size_t k = 0; k < link.size(); ++k)
          if(!is_acceptable_triangle(y, link[k].first, link[k].second, normals[k], min_turn_cosine) ||
             !is_acceptable_triangle(y, link[k].first, link[k].second, m_reference.normal(hint)))
            return false;
        if(!keeps_fit(within_tolerance_rule, v, x, y, link, energy_here) || !move_keeps_distance_bound(v, y))
          return false;
        m_mesh.point(v) = Work_kernel::Point_3(y.x(), y.y(), y.z());
        return true;
      };
      // A vertex already where it should be stays: it is not counted as moved.
      if(take_smoothing_target(x, link, [&]() -> const auto& { return ring; }, try_move) && position(v) != x)
        ++moved;
    }
    return moved;
  }

  // Beyond the paper: whether the relaxation may move v from x to y. Plain smoothing undoes the
  // fit of the relocation where the surface is curved, so a move that raises the local energy is
  // not kept. When the surface is re-sampled, a move away from feature lines is kept as long as
  // its triangles stay within the sizing tolerance of the reference (at their centroids), as a
  // collapse's must: the energy rule would keep the thin triangles of a coarse tube.
  bool keeps_fit(bool within_tolerance_rule, Vertex v, const Vector_3d& x, const Vector_3d& y, const Link& link,
                 double& energy_here) const
  {
    if(within_tolerance_rule)
    {
      for(const auto& side : link)
        if(distance_to_reference((y + side.first + side.second) / 3, v) > m_sizing.tolerance)
          return false;
      return true;
    }
    if(!m_local_energy)
      return true;
    if(std::isnan(energy_here))
      energy_here = m_local_energy(v, x, std::numeric_limits<double>::infinity());
    return m_local_energy(v, y, std::nextafter(energy_here, std::numeric_limits<double>::infinity())) <= energy_here;
  }

  bool next_to_feature(Vertex v) const
  {
    for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      if(m_state.kind[std::size_t(m_mesh.source(h))] != Vertex_kind::free_vertex)
        return true;
    return false;
  }


private:
  Local_energy m_local_energy;
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_RELAXATION_H
