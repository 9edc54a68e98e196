// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The user's mesh as the method's working mesh and back: the working copy in the unit box (a
// Surface_mesh over doubles, whatever the user's mesh type and kernel), its features, and the
// result written back into the user's mesh with the input's exact coordinates where a vertex
// did not move.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_WORKING_COPY_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_WORKING_COPY_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/features.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/normalization.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/tracking.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// `VertexPointMap` and `VertexIndexMap` are the user's maps of `TriangleMesh`; `Construct_point`
// makes the user's points from three doubles.
template <typename TriangleMesh, typename VertexPointMap, typename VertexIndexMap, typename Construct_point>
class Working_copy
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using edge_descriptor = typename boost::graph_traits<TriangleMesh>::edge_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using Work_vertex = Work_mesh::Vertex_index;

public:
  Working_copy(TriangleMesh& tmesh, VertexPointMap vpm, VertexIndexMap vertex_index, Construct_point construct_point)
    : m_tmesh(tmesh), m_vpm(vpm), m_vertex_index(vertex_index), m_construct_point(construct_point)
  {}

  // The working copy of the faces `region` (`in_region(f)` tells whether f is one of them),
  // scaled into the unit box. Its vertices follow a Hilbert curve and its faces their first
  // vertex: neighbours on the surface are then near in memory, which keeps the cost per vertex of
  // an iteration flat on large meshes. `vcm` tells the user's fixed vertices. Where the region
  // meets the rest of the mesh, the seam, its vertices are fixed and its edges constrained, so
  // that the rest stays as it is.
  template <typename VertexConstrainedMap, typename InRegion>
  void make(Work_mesh& work, const VertexConstrainedMap& vcm, std::vector<face_descriptor> region,
            const InRegion& in_region)
  {
    m_region = std::move(region);
    m_in_region = in_region;
    // (num_faces() would also count the faces a Surface_mesh keeps as removed.)
    m_whole = m_region.size() == std::size_t(std::distance(faces(m_tmesh).begin(), faces(m_tmesh).end()));
    std::vector<char> used(num_vertices(m_tmesh), 0), outside(num_vertices(m_tmesh), 0);
    for(face_descriptor f : faces(m_tmesh))
      for(vertex_descriptor v : vertices_around_face(halfedge(f, m_tmesh), m_tmesh))
        (in_region(f) ? used : outside)[get(m_vertex_index, v)] = 1;
    for(vertex_descriptor v : vertices(m_tmesh))
      if(used[get(m_vertex_index, v)])
      {
        m_input_vertices.push_back(v);
        m_input_points.push_back(to_vector(get(m_vpm, v)));
      }
    m_normalization = Unit_box_normalization(m_input_points);
    CGAL_precondition(work.number_of_vertices() == 0); // working vertex i is the i-th added
    work.reserve(static_cast<Work_mesh::size_type>(m_input_vertices.size()),
                 static_cast<Work_mesh::size_type>(3 * m_region.size() / 2 + m_input_vertices.size()),
                 static_cast<Work_mesh::size_type>(m_region.size()));
    m_work_vertex.resize(num_vertices(m_tmesh));
    add_vertices(work, vcm, outside);
    add_faces(work);
    for(face_descriptor f : m_region)
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, m_tmesh), m_tmesh))
      {
        const face_descriptor g = face(opposite(h, m_tmesh), m_tmesh);
        if(g != boost::graph_traits<TriangleMesh>::null_face() && !in_region(g))
          m_seam_edges.emplace_back(to_work(source(h, m_tmesh)), to_work(target(h, m_tmesh)));
      }
  }

  // A length of the mesh's units in the unit box.
  double to_unit_length(double length) const { return length * m_normalization.scale(); }

  // Where the vertices of the working copy will be written (while this copy lives).
  Output_points output_points() const { return Output_points(m_normalization, m_input_points); }

  // By edge of the working copy: the sharp edges of eq. (8) (hysteresis bounds in degrees),
  // border edges, and the user's constrained edges (`ecm`), those as
  // constrained_feature_edge; the kinds of the vertices with them, where a border that
  // turns by more than the upper bound is a corner, and so is a strong crease that turns by more
  // than `crease_turn_angle` (see classify_vertices()); with `follow_creases`, fading creases run on
  // (see detect_sharp_edges()); sharp lines shorter than `shortest_sharp_line` are dropped (see
  // drop_short_sharp_lines()), and so are the border's corners closer than it to a stronger one
  // (see merge_close_border_corners()).
  // The edges between two faces of different patches of `face_patch` are sharp edges too; with
  // `relax_constraints` false, the vertices of the user's constrained edges are fixed.
  template <typename EdgeConstrainedMap, typename FacePatchMap>
  std::pair<std::vector<char>, std::vector<Vertex_kind> > features(const Work_mesh& work, const EdgeConstrainedMap& ecm,
                                                                   const FacePatchMap& face_patch,
                                                                   const std::pair<double, double>& sharp_bounds,
                                                                   double crease_turn_angle, bool follow_creases,
                                                                   bool relax_constraints, double shortest_sharp_line = 0)
  {
    std::vector<char> feature_edge = detect_sharp_edges(work, sharp_bounds.first, sharp_bounds.second, follow_creases);
    if(shortest_sharp_line > 0)
      drop_short_sharp_lines(work, shortest_sharp_line, feature_edge);
    for(auto e : work.edges())
      if(work.is_border(e))
        feature_edge[std::size_t(e)] = sharp_or_border_feature_edge;
    for(face_descriptor f : m_region)
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, m_tmesh), m_tmesh))
      {
        const face_descriptor g = face(opposite(h, m_tmesh), m_tmesh);
        if(g != boost::graph_traits<TriangleMesh>::null_face() && m_in_region(g) && get(face_patch, f) != get(face_patch, g))
          feature_edge[std::size_t(work.edge(work.halfedge(to_work(source(h, m_tmesh)), to_work(target(h, m_tmesh)))))] =
            sharp_or_border_feature_edge;
      }
    for(const auto& seam : m_seam_edges)
      feature_edge[std::size_t(work.edge(work.halfedge(seam.first, seam.second)))] = constrained_feature_edge;
    for(face_descriptor f : m_region)
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, m_tmesh), m_tmesh))
        if(get(ecm, edge(h, m_tmesh)))
        {
          const auto wh = work.halfedge(to_work(source(h, m_tmesh)), to_work(target(h, m_tmesh)));
          feature_edge[std::size_t(work.edge(wh))] = constrained_feature_edge;
          m_user_edges.emplace_back(work.source(wh), work.target(wh));
          if(!relax_constraints)
            m_constrained_vertex[std::size_t(work.source(wh))] = m_constrained_vertex[std::size_t(work.target(wh))] = 1;
        }
    std::vector<Vertex_kind> kind =
      classify_vertices(work, feature_edge, m_constrained_vertex, sharp_bounds.second, crease_turn_angle);
    if(shortest_sharp_line > 0)
      merge_close_border_corners(work, feature_edge, m_constrained_vertex, shortest_sharp_line, kind);
    return {std::move(feature_edge), std::move(kind)};
  }

  // Same connectivity: back to the input's scale, vertex by vertex (output_points()). Vertices
  // that never moved keep their exact input coordinates.
  void copy_positions_back(const Work_mesh& work)
  {
    const Output_points output = output_points();
    for(std::size_t i = 0; i < m_input_vertices.size(); ++i)
    {
      const std::size_t w = std::size_t(to_work(m_input_vertices[i]));
      const Vector_3d unit = to_vector(work.point(Work_vertex(static_cast<Work_vertex::size_type>(w))));
      if(output.at_input_point(w, unit))
        continue;
      const Vector_3d p = output(w, unit);
      put(m_vpm, m_input_vertices[i], m_construct_point(p.x(), p.y(), p.z()));
    }
  }

  // New connectivity: the region's faces of `tmesh` are replaced by the working mesh's (changed
  // to the input's scale: output_points()), with the constrained maps updated. Feature and fixed
  // vertices are never removed, so a working vertex of an input index still at its input position
  // is that input vertex, and keeps its exact coordinates.
  // `face_patch` takes, for each new face, the patch of the input face below it: the one from
  // which the working copy made the reference face `below[f]` (by working face; empty: no patches).
  template <typename EdgeConstrainedMap, typename VertexConstrainedMap, typename FacePatchMap>
  void copy_mesh_back(Work_mesh& work, EdgeConstrainedMap& ecm, VertexConstrainedMap& vcm, FacePatchMap& face_patch,
                      const std::vector<Work_mesh::Face_index>& below)
  {
    using Patch = typename boost::property_traits<FacePatchMap>::value_type;
    std::vector<Patch> patch; // by working face; a removed one has no reference face below it
    patch.reserve(below.size());
    for(Work_mesh::Face_index r : below)
      patch.push_back(r == Work_mesh::null_face() ? Patch() : get(face_patch, m_input_face[std::size_t(r)]));
    const Output_points output = output_points();
    std::vector<Point> exact(work.num_vertices());
    std::vector<char> is_exact(work.num_vertices(), 0);
    for(std::size_t i = 0; i < m_input_vertices.size(); ++i)
    {
      const Work_vertex w = to_work(m_input_vertices[i]);
      if(!work.is_removed(w) && output.at_input_point(std::size_t(w), to_vector(work.point(w))))
      {
        exact[std::size_t(w)] = get(m_vpm, m_input_vertices[i]);
        is_exact[std::size_t(w)] = 1;
      }
    }
    for(Work_vertex w : work.vertices())
    {
      const Vector_3d p = output(std::size_t(w), to_vector(work.point(w)));
      work.point(w) = Work_kernel::Point_3(p.x(), p.y(), p.z());
    }
    const std::function<void(Work_mesh::Face_index, face_descriptor)> put_patch =
      [&](Work_mesh::Face_index w, face_descriptor f) {
        if(!patch.empty())
          put(face_patch, f, patch[std::size_t(w)]);
      };
    if(m_whole)
      copy_whole_back(work, exact, is_exact, ecm, vcm, put_patch);
    else
      replace_region(work, exact, is_exact, ecm, vcm, put_patch);
  }

private:
  // The whole mesh: `tmesh` is emptied element by element (so that the property maps of its owner
  // stay alive) and receives the working mesh.
  template <typename EdgeConstrainedMap, typename VertexConstrainedMap>
  void copy_whole_back(const Work_mesh& work, const std::vector<Point>& exact, const std::vector<char>& is_exact,
                       EdgeConstrainedMap& ecm, VertexConstrainedMap& vcm,
                       const std::function<void(Work_mesh::Face_index, face_descriptor)>& put_patch)
  {
    for(face_descriptor f : m_region)
      CGAL::Euler::remove_face(halfedge(f, m_tmesh), m_tmesh);
    std::vector<std::pair<Work_vertex, vertex_descriptor> > v2v;
    std::vector<std::pair<Work_mesh::Halfedge_index, halfedge_descriptor> > h2h;
    std::vector<std::pair<Work_mesh::Face_index, face_descriptor> > f2f;
    CGAL::copy_face_graph(work, m_tmesh,
                          parameters::vertex_to_vertex_output_iterator(std::back_inserter(v2v))
                            .halfedge_to_halfedge_output_iterator(std::back_inserter(h2h))
                            .face_to_face_output_iterator(std::back_inserter(f2f)),
                          parameters::vertex_point_map(m_vpm));
    for(const auto& p : f2f)
      put_patch(p.first, p.second);
    std::vector<vertex_descriptor> user(work.num_vertices());
    for(const auto& p : v2v)
    {
      if(is_exact[std::size_t(p.first)])
        put(m_vpm, p.second, exact[std::size_t(p.first)]);
      const std::size_t i = std::size_t(p.first);
      put(vcm, p.second, i < m_constrained_vertex.size() && m_constrained_vertex[i] && !work.is_removed(p.first));
      user[i] = p.second;
    }
    for(const auto& p : h2h)
      put(ecm, edge(p.second, m_tmesh), false);
    put_user_edges(work, user, ecm);
  }

  // The user's constrained edges, by their ends: they are never flipped, split or collapsed, but a
  // vertex split may remove and make again an edge of its ring, under another index.
  template <typename EdgeConstrainedMap>
  void put_user_edges(const Work_mesh& work, const std::vector<vertex_descriptor>& user, EdgeConstrainedMap& ecm) const
  {
    for(const auto& ends : m_user_edges)
      if(!work.is_removed(ends.first) && !work.is_removed(ends.second) &&
         work.halfedge(ends.first, ends.second) != Work_mesh::null_halfedge())
      {
        const auto found = halfedge(user[std::size_t(ends.first)], user[std::size_t(ends.second)], m_tmesh);
        if(found.second)
          put(ecm, edge(found.first, m_tmesh), true);
      }
  }

  // Part of the mesh: the region's faces are removed (and with them the vertices and edges no
  // other face has) and the working mesh's added in their place, sewn to the rest at the seam's
  // vertices, which are the input's own; the rest of the mesh is not touched.
  template <typename EdgeConstrainedMap, typename VertexConstrainedMap>
  void replace_region(const Work_mesh& work, const std::vector<Point>& exact, const std::vector<char>& is_exact,
                      EdgeConstrainedMap& ecm, VertexConstrainedMap& vcm,
                      const std::function<void(Work_mesh::Face_index, face_descriptor)>& put_patch)
  {
    // The seam's vertices, found before the other vertices of the range are removed.
    std::vector<vertex_descriptor> user(work.num_vertices());
    for(vertex_descriptor v : m_input_vertices)
      if(m_on_seam[std::size_t(to_work(v))])
        user[std::size_t(to_work(v))] = v;
    std::vector<char> seam(work.num_edges(), 0);
    for(const auto& s : m_seam_edges)
      seam[std::size_t(work.edge(work.halfedge(s.first, s.second)))] = 1;
    check_seam(work, user, seam);
    for(face_descriptor f : m_region)
      CGAL::Euler::remove_face(halfedge(f, m_tmesh), m_tmesh);
    for(Work_vertex w : work.vertices())
    {
      const std::size_t i = std::size_t(w);
      if(i < m_on_seam.size() && m_on_seam[i])
        continue;
      const vertex_descriptor v = add_vertex(m_tmesh);
      const Vector_3d p = to_vector(work.point(w));
      put(m_vpm, v, is_exact[i] ? exact[i] : m_construct_point(p.x(), p.y(), p.z()));
      put(vcm, v, i < m_constrained_vertex.size() && m_constrained_vertex[i] != 0);
      user[i] = v;
    }
    for(Work_mesh::Face_index f : faces_from_seam(work))
    {
      const Work_mesh::Halfedge_index h = work.halfedge(f);
      const std::array<vertex_descriptor, 3> t{{user[std::size_t(work.source(h))], user[std::size_t(work.target(h))],
                                                user[std::size_t(work.target(work.next(h)))]}};
      const face_descriptor added = CGAL::Euler::add_face(t, m_tmesh);
      CGAL_assertion(added != boost::graph_traits<TriangleMesh>::null_face());
      put_patch(f, added);
    }
    // The seam's edges are the user's own, with their flags.
    for(Work_mesh::Edge_index e : work.edges())
      if(!seam[std::size_t(e)])
      {
        const Work_mesh::Halfedge_index h = work.halfedge(e);
        const auto found = halfedge(user[std::size_t(work.source(h))], user[std::size_t(work.target(h))], m_tmesh);
        CGAL_assertion(found.second);
        put(ecm, edge(found.first, m_tmesh), false);
      }
    put_user_edges(work, user, ecm);
  }

  // Before `tmesh` changes: the working mesh must not join two seam vertices by an edge that the
  // rest of the mesh already has (the working mesh does not see it), else it could not be sewn.
  void check_seam(const Work_mesh& work, const std::vector<vertex_descriptor>& user, const std::vector<char>& seam) const
  {
    for(Work_mesh::Edge_index e : work.edges())
    {
      const Work_mesh::Halfedge_index h = work.halfedge(e);
      const std::size_t a = std::size_t(work.source(h)), b = std::size_t(work.target(h));
      if(seam[std::size_t(e)] || a >= m_on_seam.size() || b >= m_on_seam.size() || !m_on_seam[a] || !m_on_seam[b])
        continue;
      const auto found = halfedge(user[a], user[b], m_tmesh);
      if(!found.second)
        continue;
      for(halfedge_descriptor g : {found.first, opposite(found.first, m_tmesh)})
        if(face(g, m_tmesh) != boost::graph_traits<TriangleMesh>::null_face() && !m_in_region(face(g, m_tmesh)))
          throw std::runtime_error("graphcut_isotropic_remeshing: the remeshed faces would meet the rest of the mesh "
                                   "along one of its edges; the mesh is left unchanged");
    }
  }

  // The working mesh's faces, each component breadth first from its faces on the seam: every face
  // but a component's first is then added next to one already there.
  std::vector<Work_mesh::Face_index> faces_from_seam(const Work_mesh& work) const
  {
    std::vector<Work_mesh::Face_index> starts, order;
    for(const auto& s : m_seam_edges)
      starts.push_back(work.face(work.halfedge(s.first, s.second)));
    starts.insert(starts.end(), work.faces().begin(), work.faces().end());
    std::vector<char> seen(work.num_faces(), 0);
    for(Work_mesh::Face_index start : starts)
    {
      if(seen[std::size_t(start)])
        continue;
      seen[std::size_t(start)] = 1;
      std::size_t k = order.size();
      order.push_back(start);
      for(; k < order.size(); ++k)
        for(Work_mesh::Halfedge_index h : halfedges_around_face(work.halfedge(order[k]), work))
        {
          const Work_mesh::Face_index g = work.face(work.opposite(h));
          if(g != Work_mesh::null_face() && !seen[std::size_t(g)])
          {
            seen[std::size_t(g)] = 1;
            order.push_back(g);
          }
        }
    }
    return order;
  }

  Work_vertex to_work(vertex_descriptor v) const { return m_work_vertex[get(m_vertex_index, v)]; }

  template <typename VertexConstrainedMap>
  void add_vertices(Work_mesh& work, const VertexConstrainedMap& vcm, const std::vector<char>& outside)
  {
    std::vector<Work_kernel::Point_3> unit_points;
    unit_points.reserve(m_input_points.size());
    for(const Vector_3d& q : m_input_points)
    {
      const Vector_3d p = m_normalization.to_unit(q);
      unit_points.emplace_back(p.x(), p.y(), p.z());
    }
    std::vector<std::size_t> order(m_input_vertices.size());
    for(std::size_t i = 0; i < order.size(); ++i)
      order[i] = i;
    CGAL::hilbert_sort(order.begin(), order.end(),
                       CGAL::Spatial_sort_traits_adapter_3<Work_kernel, decltype(CGAL::make_property_map(unit_points))>(
                         CGAL::make_property_map(unit_points)));
    m_constrained_vertex.reserve(order.size());
    for(std::size_t i : order)
    {
      m_work_vertex[get(m_vertex_index, m_input_vertices[i])] = work.add_vertex(unit_points[i]);
      const bool on_seam = outside[get(m_vertex_index, m_input_vertices[i])] != 0;
      m_on_seam.push_back(on_seam ? 1 : 0);
      m_constrained_vertex.push_back(on_seam || get(vcm, m_input_vertices[i]) ? 1 : 0);
    }
    // The input's vertices and points by working vertex, as output_points() reads them.
    std::vector<vertex_descriptor> vertices;
    std::vector<Vector_3d> points;
    vertices.reserve(order.size());
    points.reserve(order.size());
    for(std::size_t i : order)
    {
      vertices.push_back(m_input_vertices[i]);
      points.push_back(m_input_points[i]);
    }
    m_input_vertices.swap(vertices);
    m_input_points.swap(points);
  }

  void add_faces(Work_mesh& work)
  {
    std::vector<std::pair<std::size_t, std::size_t> > order; // (first working vertex, region face)
    order.reserve(m_region.size());
    for(std::size_t i = 0; i < m_region.size(); ++i)
    {
      const auto h = halfedge(m_region[i], m_tmesh);
      order.emplace_back(std::size_t((std::min)(
                           {to_work(source(h, m_tmesh)), to_work(target(h, m_tmesh)), to_work(target(next(h, m_tmesh), m_tmesh))})),
                         i);
    }
    std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    m_input_face.reserve(order.size());
    for(const auto& o : order)
    {
      const auto h = halfedge(m_region[o.second], m_tmesh);
      work.add_face(to_work(source(h, m_tmesh)), to_work(target(h, m_tmesh)), to_work(target(next(h, m_tmesh), m_tmesh)));
      m_input_face.push_back(m_region[o.second]);
    }
  }

  TriangleMesh& m_tmesh;
  VertexPointMap m_vpm;
  VertexIndexMap m_vertex_index;
  Construct_point m_construct_point;
  std::vector<face_descriptor> m_region;      // the faces remeshed
  std::vector<face_descriptor> m_input_face;  // by working face as made: the region's face it copies
  bool m_whole = true;                        // the region is the whole mesh
  std::vector<std::pair<Work_vertex, Work_vertex> > m_seam_edges;
  std::vector<char> m_on_seam;                // by working vertex: shared with faces outside the region
  std::vector<vertex_descriptor> m_input_vertices; // the region's, by working vertex
  std::vector<Vector_3d> m_input_points;      // as the input has them, by working vertex
  Unit_box_normalization m_normalization;
  std::vector<Work_vertex> m_work_vertex;     // by the input's vertex index
  std::vector<char> m_constrained_vertex;     // by working vertex: the user's fixed vertices and the seam's
  std::vector<std::pair<Work_vertex, Work_vertex> > m_user_edges; // the user's constrained edges, by their ends
  std::function<bool(face_descriptor)> m_in_region;
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_WORKING_COPY_H
