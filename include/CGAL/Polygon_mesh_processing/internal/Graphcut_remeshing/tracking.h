// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Section 2.1's tracking: for each vertex of the working mesh, its closest reference vertex y_s0
// (whose frame gives eq. (4) and the tangent plane of the candidates), found by local search, and
// the nearest reference triangles of vertices, centroids and feature-edge midpoints, from which
// the closest-point descents of the data terms start.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_TRACKING_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_TRACKING_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/features.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/reference_surface.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// The state of the working mesh shared by the relocation and the connectivity stage: vertex
// kinds and the reference elements each vertex and face is tracked to, all indexed by the
// working mesh's indices.
struct Tracking_state
{
  std::vector<char> feature_edge;            // by edge: 0, sharp_or_border_feature_edge or constrained_feature_edge
  std::vector<Vertex_kind> kind;             // by vertex
  std::vector<Work_mesh::Vertex_index> closest; // by vertex: y_s0
  std::vector<Work_mesh::Face_index> vertex_hint; // by vertex: nearest reference triangle
  std::vector<Work_mesh::Face_index> face_hint;   // by face: nearest reference triangle of its centroid
  std::vector<Feature_polylines<Work_mesh>::Location> location; // by vertex: place on its polyline
  std::vector<Work_mesh::Face_index> edge_hint; // by edge: nearest reference triangle of its midpoint

  // Grows the arrays to m's capacity (removed elements included), after an operation added
  // elements: a new vertex is free, a new edge no feature.
  void fit(const Work_mesh& m)
  {
    const std::size_t nv = m.num_vertices(), ne = m.num_edges(), nf = m.num_faces();
    if(kind.size() < nv)
    {
      grow_by_elements(kind, nv, Vertex_kind::free_vertex);
      grow_by_elements(closest, nv);
      grow_by_elements(vertex_hint, nv);
      grow_by_elements(location, nv);
    }
    if(feature_edge.size() < ne)
    {
      grow_by_elements(feature_edge, ne, char(0));
      grow_by_elements(edge_hint, ne);
    }
    if(face_hint.size() < nf)
      grow_by_elements(face_hint, nf);
  }
};

// Where a vertex at the end of a feature edge is on its reference polyline. A fixed vertex (a
// corner or a user's vertex) never moved, so it is the reference vertex of the same index.
inline Feature_polylines<Work_mesh>::Location line_location(const Tracking_state& state,
                                                            const Feature_polylines<Work_mesh>& polylines,
                                                            Work_mesh::Vertex_index v)
{
  return state.kind[std::size_t(v)] == Vertex_kind::feature_vertex ? state.location[std::size_t(v)]
                                                                   : polylines.at_vertex(v);
}

// Keeps a Tracking_state up to date as the vertices move. Both searches end where they start
// when they start where they last ended: only the vertices moved since the last update, and the
// elements with one, are searched.
class Reference_tracking
{
  using Vertex = Work_mesh::Vertex_index;
  using Halfedge = Work_mesh::Halfedge_index;
  using Edge = Work_mesh::Edge_index;
  using Face = Work_mesh::Face_index;
  using Location = Feature_polylines<Work_mesh>::Location;

public:
  Reference_tracking(const Work_mesh& mesh, const Reference_surface<Work_mesh>& reference,
                     const Feature_polylines<Work_mesh>& polylines, Tracking_state& state)
    : m_mesh(mesh), m_reference(reference), m_polylines(polylines), m_state(state)
  {}

  // The state of a working mesh that is the reference, index for index, with these features.
  void start(std::vector<char> feature_edge, std::vector<Vertex_kind> kind)
  {
    const std::size_t n = m_mesh.num_vertices();
    m_state.feature_edge = std::move(feature_edge);
    m_state.kind = std::move(kind);
    m_state.closest.resize(n);
    m_state.location.resize(n);
    m_state.vertex_hint.resize(n);
    m_state.face_hint.resize(m_mesh.num_faces());
    for(Face f : m_mesh.faces())
      m_state.face_hint[std::size_t(f)] = f;
    m_state.edge_hint.resize(m_mesh.num_edges());
    for(Edge e : m_mesh.edges())
    {
      const Halfedge h = m_mesh.halfedge(e);
      m_state.edge_hint[std::size_t(e)] = m_mesh.face(m_mesh.is_border(h) ? m_mesh.opposite(h) : h);
    }
    for(Vertex v : m_mesh.vertices())
    {
      m_state.closest[std::size_t(v)] = v;
      m_state.vertex_hint[std::size_t(v)] = m_reference.incident_face(v);
      if(m_state.kind[std::size_t(v)] == Vertex_kind::feature_vertex)
        m_state.location[std::size_t(v)] = m_polylines.at_vertex(v);
    }
    mark_all();
  }

  // Every vertex to be searched again (after the connectivity changed).
  void mark_all() { m_untracked.assign(m_mesh.num_vertices(), 1); }

  void mark_moved(Vertex v) { m_untracked[std::size_t(v)] = 1; }

  // The searches for the vertices marked since the last update and the elements with one; the
  // elements of `feature_edges` are the feature edges of the working mesh. Caching where a
  // descent ends does not change any term at the current positions.
  void update(const std::vector<Edge>& feature_edges)
  {
    auto untracked = [&](Vertex v) { return m_untracked[std::size_t(v)] != 0; };
    for_each_vertex(m_mesh, [&](Vertex v) {
      if(untracked(v))
        track_vertex(v);
    });
    for_each_face(m_mesh, [&](Face f) {
      const std::array<Vertex, 3> t = face_vertices(m_mesh, f);
      if(untracked(t[0]) || untracked(t[1]) || untracked(t[2]))
        m_reference.closest_point((position(t[0]) + position(t[1]) + position(t[2])) / 3,
                                  m_state.face_hint[std::size_t(f)]);
    });
    for(Edge e : feature_edges)
    {
      const Halfedge h = m_mesh.halfedge(e);
      if(untracked(m_mesh.source(h)) || untracked(m_mesh.target(h)))
        m_reference.closest_point((position(m_mesh.source(h)) + position(m_mesh.target(h))) / 2,
                                  m_state.edge_hint[std::size_t(e)]);
    }
    std::fill(m_untracked.begin(), m_untracked.end(), 0);
  }

private:
  Vector_3d position(Vertex v) const { return to_vector(m_mesh.point(v)); }

  void track_vertex(Vertex v)
  {
    const Vertex_kind kind = m_state.kind[std::size_t(v)];
    if(kind == Vertex_kind::feature_vertex)
    {
      // On its polyline: the reference elements come with its place there.
      const Location& l = m_state.location[std::size_t(v)];
      const Work_mesh& reference = m_reference.mesh();
      const Halfedge h = reference.is_border(l.h) ? reference.opposite(l.h) : l.h;
      m_state.closest[std::size_t(v)] = m_polylines.nearest_vertex(l);
      m_state.vertex_hint[std::size_t(v)] = reference.face(h);
    }
    if(kind != Vertex_kind::free_vertex)
      return;
    const Vector_3d x = position(v);
    m_state.closest[std::size_t(v)] = m_reference.closest_vertex(x, m_state.closest[std::size_t(v)]);
    m_reference.closest_point(x, m_state.vertex_hint[std::size_t(v)]);
  }

  const Work_mesh& m_mesh;
  const Reference_surface<Work_mesh>& m_reference;
  const Feature_polylines<Work_mesh>& m_polylines;
  Tracking_state& m_state;
  std::vector<char> m_untracked; // by vertex: moved since the last update
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_TRACKING_H
