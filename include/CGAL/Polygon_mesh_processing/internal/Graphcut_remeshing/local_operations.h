// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the connectivity operations of section 3 share: the working mesh with its tracking state,
// the reference, the sizing field and the feature polylines; the acceptability of a new triangle
// and the fold check of a new fan, the distance bound's check of an operation, the projection onto
// the reference, and the binding of a new vertex to the reference.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_LOCAL_OPERATIONS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_LOCAL_OPERATIONS_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/distance_bound.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/energy.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/features.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/guarantees.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/reference_surface.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/sizing.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/tracking.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <initializer_list>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// The smallest angle of the triangle (a, b, c): the one opposite its shortest side (the law of
// sines), one arc tangent instead of three.
inline double smallest_angle(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c)
{
  const double ab = (b - a).squaredNorm(), bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm();
  if(bc <= ab && bc <= ca)
    return angle(a, b, c);
  return ca <= ab ? angle(b, c, a) : angle(c, a, b);
}

// The base of the operations (edge_flips.h, edge_splits.h, edge_collapses.h, vertex_splits.h,
// relaxation.h, coverings.h): references to what they change and read, and the small predicates
// they share. Copying it copies the references.
class Local_operations
{
protected:
  using Vertex = Work_mesh::Vertex_index;
  using Halfedge = Work_mesh::Halfedge_index;
  using Edge = Work_mesh::Edge_index;
  using Face = Work_mesh::Face_index;
  using Location = Feature_polylines<Work_mesh>::Location;

public:
  // Beyond the paper: no operation and no relaxation step turns a triangle by more than 60
  // degrees (this cosine) from the surface it replaces. Where the sampling is fine enough for the
  // shape none needs to; more folds a thin triangle along a crease or a stretched part, where the
  // reference's normal alone can be either side's.
  static constexpr double min_turn_cosine = 0.5;

  // `polylines`, the reference's feature polylines, lets long sharp edges be split and feature
  // lines be re-sampled (none are without it). No operation touches a vertex v with frozen[v]
  // (by vertex index; a vertex beyond its end is not frozen): frozen vertices are never removed,
  // so that the index of a removed vertex that a new one takes was not frozen either. With
  // `bound`, every operation keeps the distance bound (distance_bound.h).
  Local_operations(Work_mesh& mesh, const Reference_surface<Work_mesh>& reference, Tracking_state& state,
                   const Sizing_field& sizing, const Feature_polylines<Work_mesh>* polylines = nullptr,
                   const std::vector<char>& frozen = nothing_frozen(), const Distance_bound* bound = nullptr)
    : m_mesh(mesh), m_reference(reference), m_state(state), m_sizing(sizing), m_polylines(polylines),
      m_frozen(frozen), m_bound(bound)
  {
    m_state.fit(m_mesh);
  }

  Vector_3d position(Vertex v) const { return to_vector(m_mesh.point(v)); }

  bool is_free(Vertex v) const
  {
    return m_state.kind[std::size_t(v)] == Vertex_kind::free_vertex && !is_frozen(v);
  }
  bool is_frozen(Vertex v) const { return std::size_t(v) < m_frozen.size() && m_frozen[std::size_t(v)] != 0; }

  static const std::vector<char>& nothing_frozen()
  {
    static const std::vector<char> none;
    return none;
  }

  // The halfedge of e on a face (e's own halfedge unless that one is on the border).
  Halfedge face_side(Edge e) const
  {
    const Halfedge h = m_mesh.halfedge(e);
    return m_mesh.is_border(h) ? m_mesh.opposite(h) : h;
  }

  // How |valence - 6| (4 on a border) changes when v's valence changes by `delta`.
  int deviation_change(Vertex v, int delta) const
  {
    const int target = m_mesh.is_border(v) ? 4 : 6;
    const int d = int(m_mesh.degree(v));
    return std::abs(d + delta - target) - std::abs(d - target);
  }

  // A triangle an operation may create in place of triangles of area vector `replaced`: not
  // degenerate, not turned by more than 60 degrees from them, not turned over against the
  // reference (its normal where the triangle's centroid is closest to it, searched from `near`'s
  // triangle).
  bool acceptable(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c, Vertex near,
                  const Vector_3d& replaced) const
  {
    return is_acceptable_triangle(a, b, c, replaced, min_turn_cosine) && faces_reference(a, b, c, near);
  }

  // The last test of acceptable(): the triangle is not turned over against the reference.
  bool faces_reference(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c, Vertex near) const
  {
    double centroid_distance;
    return faces_reference(a, b, c, near, centroid_distance);
  }

  // The same, with the distance from the triangle's centroid to the reference, from the same search.
  bool faces_reference(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c, Vertex near,
                       double& centroid_distance) const
  {
    Face hint = m_state.vertex_hint[std::size_t(near)];
    const Vector_3d centroid = (a + b + c) / 3;
    centroid_distance = (centroid - m_reference.closest_point(centroid, hint)).norm();
    if(is_acceptable_triangle(a, b, c, m_reference.normal(hint)))
      return true;
    // At a coarse length the triangle spans several reference vertices: the triangles around the
    // one `near` is tracked to say little about the side its centroid is on.
    if(m_sizing.covers_reference)
      return false;
    const Face first = hint;
    centroid_distance = search_around(centroid, m_state.closest[std::size_t(near)], centroid_distance, hint);
    // Found from the other side of a sharp edge: next to it the triangle must face the reference
    // clearly, as a new triangle must face the ones it replaces; a sliver seen edge-on there has a
    // normal the rounding decides.
    return hint != first && is_acceptable_triangle(a, b, c, m_reference.normal(hint), min_turn_cosine);
  }

  // The descent from a triangle of the reference stops where no step brings it closer. Next to a
  // sharp edge that triangle may be on the other side of it: at the bottom of a hole, the centroid
  // of a triangle on the hole's wall, searched from a triangle of the bottom, stops inside it, as
  // far from the wall as the centroid is high, and the wall's triangle seems turned over. So where
  // that matters the search is made again from the triangles around the reference vertex y near
  // x, and a point found there is kept when it is less than half as far as the one found before
  // (at `distance`, in `hint`): between two triangles about as close, a seam where a triangle is
  // seen edge-on, the first search decides, as without this one. Returns the distance kept.
  double search_around(const Vector_3d& x, Vertex y, double distance, Face& hint) const
  {
    const Work_mesh& reference = m_reference.mesh();
    const double first = distance;
    for(Halfedge g : halfedges_around_target(reference.halfedge(y), reference))
    {
      if(reference.is_border(g))
        continue;
      Face other = reference.face(g);
      const double d = (x - m_reference.closest_point(x, other)).norm();
      if(d < distance && d < first / 2)
      {
        distance = d;
        hint = other;
      }
    }
    return distance;
  }

  Vector_3d project(const Vector_3d& x, Vertex near) const
  {
    Face hint = m_state.vertex_hint[std::size_t(near)];
    return m_reference.closest_point(x, hint);
  }

  Location feature_location(Vertex v) const { return line_location(m_state, *m_polylines, v); }

  // The point of the reference polyline halfway, along it, from a to b, the ends of a sharp edge.
  Location feature_midpoint(Vertex a, Vertex b) const
  {
    return m_polylines->move(feature_location(a), (position(b) - position(a)) / 2);
  }

  double distance_to_reference(const Vector_3d& x, Vertex near) const
  {
    return (x - project(x, near)).norm();
  }

  // The target length of the edge from a to b, by the reference vertices they are tracked to.
  double edge_length_target(Vertex a, Vertex b) const
  {
    return m_sizing.edge_target(m_state.closest[std::size_t(a)], m_state.closest[std::size_t(b)], m_reference);
  }

  // A new or moved vertex is tracked from its neighbour's reference elements, then by the same
  // local searches as every vertex.
  void bind_new_vertex(Vertex v, Vertex from, Vertex_kind kind = Vertex_kind::free_vertex)
  {
    m_state.kind[std::size_t(v)] = kind;
    m_state.closest[std::size_t(v)] = m_state.closest[std::size_t(from)];
    m_state.vertex_hint[std::size_t(v)] = m_state.vertex_hint[std::size_t(from)];
    const Vector_3d x = position(v);
    m_state.closest[std::size_t(v)] = m_reference.closest_vertex(x, m_state.closest[std::size_t(v)]);
    m_reference.closest_point(x, m_state.vertex_hint[std::size_t(v)]);
  }

  // Whether the triangles (source(g), target(g), x) that an operation makes, one for each halfedge
  // g of `link` (g on the triangle it replaces), fold (guarantees.h) neither onto each other,
  // across their edges at x, nor onto the triangles across the g: a vertex placed or moved off the
  // mesh (on a tip, on a coarse tube) may turn a new triangle over its neighbour. The vertex at x
  // replaces those of `replaced`; an edge that was folded already or is a feature edge may stay
  // folded, as the guarantee allows.
  template <typename Link>
  bool fan_unfolded(const Link& link, const Vector_3d& x, std::initializer_list<Vertex> replaced = {}) const
  {
    const auto exempt = [&](Halfedge h) {
      return m_state.feature_edge[std::size_t(m_mesh.edge(h))] || is_folded_edge(m_mesh, h);
    };
    const auto exempt_at_x = [&](Vertex w) {
      for(Vertex u : replaced)
      {
        const Halfedge h = m_mesh.halfedge(u, w);
        if(h != Work_mesh::null_halfedge() && exempt(h))
          return true;
      }
      return false;
    };
    boost::container::small_vector<Vector_3d, 16> fan;
    for(Halfedge g : link)
    {
      fan.push_back(area_vector(position(m_mesh.source(g)), position(m_mesh.target(g)), x));
      const Halfedge across = m_mesh.opposite(g);
      if(!m_mesh.is_border(across) && is_folded_pair(fan.back(), face_area_vector(m_mesh, across)) && !exempt(g))
        return false;
    }
    for(std::size_t k = 0; k < link.size(); ++k)
      for(std::size_t j = 0; j < link.size(); ++j)
        if(m_mesh.target(link[k]) == m_mesh.source(link[j]) && is_folded_pair(fan[k], fan[j]) &&
           !exempt_at_x(m_mesh.target(link[k])))
          return false;
    return true;
  }

  // The distance bound, when one is set (distance_bound.h): whether an operation keeps it. These
  // tests come last in each operation: they are the dearest.
  template <typename Faces>
  bool keeps_distance_bound(const Faces& removed, const std::vector<Triangle_3d>& created) const
  {
    return !m_bound || m_bound->allows_replacing(m_mesh, removed, created);
  }
  bool move_keeps_distance_bound(Vertex v, const Vector_3d& x) const
  {
    return !m_bound || m_bound->allows_move(m_mesh, v, x);
  }
  bool split_keeps_distance_bound(Halfedge h, const Vector_3d& p) const
  {
    return !m_bound || m_bound->allows_split(m_mesh, h, p);
  }
  bool collapse_keeps_distance_bound(Vertex removed, Vertex kept, const Vector_3d& x) const
  {
    return !m_bound || m_bound->allows_collapse(m_mesh, removed, kept, x);
  }

  // The triangles around the new or moved vertex v are tracked from v's reference triangle.
  void track_faces_from(Vertex v)
  {
    for(Halfedge g : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      if(!m_mesh.is_border(g))
        m_state.face_hint[std::size_t(m_mesh.face(g))] = m_state.vertex_hint[std::size_t(v)];
  }

  // The smallest angle of the triangles around a and b.
  double smallest_angle_around(Vertex a, Vertex b) const
  {
    double smallest = pi;
    for(Vertex u : {a, b})
      for(Halfedge g : halfedges_around_target(m_mesh.halfedge(u), m_mesh))
        if(!m_mesh.is_border(g))
          smallest = (std::min)(smallest, smallest_angle(position(u), position(m_mesh.target(m_mesh.next(g))),
                                                         position(m_mesh.source(g))));
    return smallest;
  }

protected:
  Work_mesh& m_mesh;
  const Reference_surface<Work_mesh>& m_reference;
  Tracking_state& m_state;
  const Sizing_field& m_sizing;
  const Feature_polylines<Work_mesh>* m_polylines;
  const std::vector<char>& m_frozen;
  const Distance_bound* m_bound;
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_LOCAL_OPERATIONS_H
