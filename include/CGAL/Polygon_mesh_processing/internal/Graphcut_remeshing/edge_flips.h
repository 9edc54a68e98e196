// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Section 3.1: edge flips.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_EDGE_FLIPS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_EDGE_FLIPS_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/edge_queue.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/local_operations.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// Section 3.1's edge flips: the smallest of the six angles of the two triangles must grow and the
// valence deviation must not rise; beyond the paper, a flip that makes the valence more regular is
// also kept when its triangles stay well shaped.
class Edge_flips : public Local_operations
{
public:
  // A valence-improving flip whose six angles stay above this is kept (see flip_gain).
  static constexpr double flip_angle_floor = 25 * pi / 180;
  // The least growth of an angle that counts as an improvement (0.01 degree).
  static constexpr double min_angle_margin = 0.01 * pi / 180;

  explicit Edge_flips(const Local_operations& operations) : Local_operations(operations) {}

  // The flips, best gain first; returns how many were made.
  std::size_t run()
  {
    return run_edge_queue(m_mesh, [this](Edge e) { return Plan{flip_gain(e)}; },
                          [this](Edge e, const Plan&) { return flip(e); });
  }

  // The gain in smallest angle of flipping e, or a non-positive value when e may not be flipped.
  // The angles first: the reference is searched only for a flip that would pay.
  double flip_gain(Edge e) const
  {
    if(!flippable(e))
      return 0;
    const Halfedge h = m_mesh.halfedge(e), o = m_mesh.opposite(h);
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
    const Vertex c = m_mesh.target(m_mesh.next(h)), d = m_mesh.target(m_mesh.next(o));
    const int change = deviation_change(a, -1) + deviation_change(b, -1) + deviation_change(c, +1) +
                       deviation_change(d, +1);
    if(change > 0)
      return 0;
    const Vector_3d pa = position(a), pb = position(b), pc = position(c), pd = position(d);
    const double new_min = (std::min)(smallest_angle(pa, pd, pc), smallest_angle(pd, pb, pc));
    const double old_min = (std::min)(smallest_angle(pa, pb, pc), smallest_angle(pb, pa, pd));
    double gain = new_min - old_min;
    // Section 3.1's smooth flip where the valence stays as regular: the six angles' minimum must
    // grow, by a margin so that rounding cannot make two flips undo each other. (The paper only
    // tries flips that make the valence more regular; around the corners of an organic mesh
    // those are rare and its triangles would stay thin.)
    if(change == 0)
      gain -= min_angle_margin;
    // Beyond the paper: a flip that makes the valence more regular is also kept when its
    // triangles stay well shaped; the relocation then improves them (the min-angle rule alone
    // leaves most irregular vertices).
    else if(new_min >= flip_angle_floor)
      gain = (std::max)(gain, 0.0) + 1e-3 * (new_min - flip_angle_floor + 1e-9);
    if(!(gain > 0))
      return gain;
    return flip_keeps_to_reference(e) ? gain : 0;
  }

  // The smallest angle of the two triangles that flipping the flippable edge e makes, or -1 when
  // flip_keeps_to_reference(e) is false.
  double flipped_smallest_angle(Edge e) const
  {
    if(!flip_keeps_to_reference(e))
      return -1;
    const Halfedge h = m_mesh.halfedge(e), o = m_mesh.opposite(h);
    const Vector_3d pa = position(m_mesh.source(h)), pb = position(m_mesh.target(h));
    const Vector_3d pc = position(m_mesh.target(m_mesh.next(h))), pd = position(m_mesh.target(m_mesh.next(o)));
    return (std::min)(smallest_angle(pa, pd, pc), smallest_angle(pd, pb, pc));
  }

  // Whether both triangles that flipping the flippable edge e makes are acceptable and the new
  // edge leaves the reference no more than e did.
  bool flip_keeps_to_reference(Edge e) const
  {
    const Halfedge h = m_mesh.halfedge(e), o = m_mesh.opposite(h);
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
    const Vertex c = m_mesh.target(m_mesh.next(h)), d = m_mesh.target(m_mesh.next(o));
    const Vector_3d pa = position(a), pb = position(b), pc = position(c), pd = position(d);
    // (a, b, c) and (b, a, d) become (a, d, c) and (d, b, c).
    const Vector_3d quad = area_vector(pa, pb, pc) + area_vector(pb, pa, pd);
    if(!acceptable(pa, pd, pc, a, quad) || !acceptable(pd, pb, pc, b, quad))
      return false;
    const double before = distance_to_reference((pa + pb) / 2, a);
    const double after = distance_to_reference((pc + pd) / 2, c);
    if(after > (std::max)(before, m_sizing.tolerance))
      return false;
    return keeps_distance_bound(std::array<Face, 2>{{m_mesh.face(h), m_mesh.face(o)}},
                                {Triangle_3d{{pa, pd, pc}}, Triangle_3d{{pd, pb, pc}}});
  }

  // Whether e may be flipped: off the features and the border, its vertices not frozen, its
  // ends keeping three edges (two on a border, one triangle, with `border_ends_of_one_triangle`),
  // the new edge not there already.
  bool flippable(Edge e, bool border_ends_of_one_triangle = false) const
  {
    if(m_state.feature_edge[std::size_t(e)] || m_mesh.is_border(e))
      return false;
    const Halfedge h = m_mesh.halfedge(e), o = m_mesh.opposite(h);
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
    const Vertex c = m_mesh.target(m_mesh.next(h)), d = m_mesh.target(m_mesh.next(o));
    for(Vertex u : {a, b, c, d})
      if(is_frozen(u))
        return false;
    for(Vertex u : {a, b})
      if(m_mesh.degree(u) < (border_ends_of_one_triangle && m_mesh.is_border(u) ? 3u : 4u))
        return false;
    return c != d && m_mesh.halfedge(c, d) == Work_mesh::null_halfedge();
  }

  // Flips e; returns the vertices of its two triangles.
  std::vector<Vertex> flip(Edge e)
  {
    const Halfedge h = m_mesh.halfedge(e);
    std::vector<Vertex> touched{{m_mesh.source(h), m_mesh.target(h), m_mesh.target(m_mesh.next(h)),
                                 m_mesh.target(m_mesh.next(m_mesh.opposite(h)))}};
    CGAL::Euler::flip_edge(h, m_mesh);
    for(Face f : {m_mesh.face(h), m_mesh.face(m_mesh.opposite(h))})
      m_state.face_hint[std::size_t(f)] = m_state.vertex_hint[std::size_t(m_mesh.target(h))];
    return touched;
  }

private:
  struct Plan
  {
    double gain;
  };
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_EDGE_FLIPS_H
