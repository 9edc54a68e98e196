// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Beyond the paper: the coverings of what stands out between the mesh and the reference.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_COVERINGS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_COVERINGS_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/edge_splits.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/local_operations.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/version.h>
#if CGAL_VERSION_NR >= 1060000000
#include <CGAL/AABB_traits_3.h>
#else
#include <CGAL/AABB_traits.h>
#endif

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// Beyond the paper, when the user asked for a length coarser than the input's: vertices where the
// mesh has cut off a tip or a rim of the reference, and where an edge cuts across a hollow.
class Coverings : public Local_operations
{
public:
  // With a coarse length asked for, the reference vertices this share of the farthest one's
  // distance from the mesh, or farther, get a vertex (cover_reference()).
  static constexpr double cover_share_of_worst = 0.8;
  // ... and as far as cover_outlier_ratio times the distance that this share of the reference
  // vertices keep within.
  static constexpr double cover_typical_rank = 0.9;
  static constexpr double cover_outlier_ratio = 2;
  // How far from the mesh towards such a vertex the new vertex goes: all the way, else, where its
  // triangles would fold, part of the way.
  static constexpr std::array<double, 3> cover_shares{{1.0, 0.75, 0.5}};

  explicit Coverings(const Local_operations& operations) : Local_operations(operations) {}

  // Beyond the paper: the data terms measure how far the mesh is from the reference, not how far
  // the reference is from the mesh, and the relocation may slide the vertex of a thin tip or rim
  // down its side: the triangles then cut the tip off while every vertex and centroid stays near
  // the surface. When the user asked for a length coarser than the input's, the reference vertices
  // that stand out, within cover_share_of_worst of the farthest from the mesh and far beyond most,
  // each get a vertex, at themselves, the farthest first and one per neighbourhood. Returns the
  // number of vertices added.
  std::size_t cover_reference()
  {
    using Primitive = CGAL::AABB_face_graph_triangle_primitive<Work_mesh>;
#if CGAL_VERSION_NR >= 1060000000
    using Tree = CGAL::AABB_tree<CGAL::AABB_traits_3<Work_kernel, Primitive> >;
#else
    using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Work_kernel, Primitive> >;
#endif
    Tree tree(faces(m_mesh).first, faces(m_mesh).second, m_mesh);
    tree.build();
    tree.accelerate_distance_queries();
    const Work_mesh& reference = m_reference.mesh();
    std::vector<double> distance(reference.num_vertices(), 0);
    std::vector<Face> nearest(reference.num_vertices());
    std::vector<Vector_3d> closest(reference.num_vertices());
    for_each_vertex(reference, [&](Vertex r) {
      const Vector_3d x = m_reference.point(r);
      const auto hit = tree.closest_point_and_primitive(Work_kernel::Point_3(x.x(), x.y(), x.z()));
      closest[std::size_t(r)] = to_vector(hit.first);
      distance[std::size_t(r)] = (closest[std::size_t(r)] - x).norm();
      nearest[std::size_t(r)] = hit.second;
    });
    std::vector<char> changed_near(m_mesh.num_faces(), 0);
    std::size_t added = 0;
    for(std::size_t i : standing_out(distance))
    {
      const Face f = nearest[i];
      if(changed_near[std::size_t(f)])
        continue;
      const Vertex v = cover_toward(f, closest[i], m_reference.point(Vertex(Work_mesh::size_type(i))));
      if(v == Vertex())
        continue;
      ++added;
      mark_neighbourhood(v, changed_near);
    }
    return added;
  }

  // Beyond the paper, the other way round: an edge of the mesh may cut across a crease or a
  // hollow of the reference that the coarse target hides, while its ends, and the centroids the
  // data terms see, stay on the surface. Once the relocation is over (Graphcut_remesher::run()),
  // the edges whose midpoints stand out from the reference as cover_reference()'s vertices do
  // get a vertex on the reference below the midpoint, or part of the way there, one per
  // neighbourhood. Feature edges keep to their lines and borders are not moved off. Returns the
  // number of vertices added.
  std::size_t cover_chords()
  {
    std::vector<Edge> edges;
    std::vector<double> distance;
    std::vector<Vector_3d> below;
    for(Edge e : m_mesh.edges())
    {
      if(m_state.feature_edge[std::size_t(e)] || m_mesh.is_border(e))
        continue;
      const Halfedge h = m_mesh.halfedge(e);
      const Vector_3d middle = (position(m_mesh.source(h)) + position(m_mesh.target(h))) / 2;
      edges.push_back(e);
      below.push_back(project(middle, m_mesh.source(h)));
      distance.push_back((below.back() - middle).norm());
    }
    std::vector<char> changed_near(m_mesh.num_faces(), 0);
    std::size_t added = 0;
    for(std::size_t i : standing_out(distance))
    {
      const Halfedge h = m_mesh.halfedge(edges[i]);
      const Face f = m_mesh.face(h);
      if(changed_near[std::size_t(f)] || changed_near[std::size_t(m_mesh.face(m_mesh.opposite(h)))])
        continue;
      const Vector_3d middle = (position(m_mesh.source(h)) + position(m_mesh.target(h))) / 2;
      const Vertex v = cover_toward(f, middle, below[i]);
      if(v == Vertex())
        continue;
      ++added;
      mark_neighbourhood(v, changed_near);
    }
    return added;
  }

  // The indices of the distances that stand out, the largest first: within cover_share_of_worst
  // of the largest and far beyond most (on a sphere or a tube every chord leaves the surface
  // alike, and vertices there would only make the mesh denser than the length asked for).
  static std::vector<std::size_t> standing_out(const std::vector<double>& distance)
  {
    std::vector<std::size_t> far;
    if(distance.empty())
      return far;
    const double worst = *std::max_element(distance.begin(), distance.end());
    std::vector<double> sorted = distance;
    const std::size_t typical_rank = std::size_t(cover_typical_rank * double(sorted.size() - 1));
    std::nth_element(sorted.begin(), sorted.begin() + typical_rank, sorted.end());
    const double bound = (std::max)(cover_share_of_worst * worst, cover_outlier_ratio * sorted[typical_rank]);
    for(std::size_t i = 0; i < distance.size(); ++i)
      if(distance[i] > 0 && distance[i] >= bound)
        far.push_back(i);
    std::stable_sort(far.begin(), far.end(), [&](std::size_t i, std::size_t j) { return distance[i] > distance[j]; });
    return far;
  }

  // A vertex for the triangle f at `to`, or, where its triangles would fold over, part of the way
  // there from `from` (cover_shares); none (a null vertex) when no way keeps acceptable triangles.
  Vertex cover_toward(Face f, const Vector_3d& from, const Vector_3d& to)
  {
    for(double share : cover_shares)
    {
      const Vertex v = cover(f, from + share * (to - from));
      if(v != Vertex())
        return v;
    }
    return Vertex();
  }

  // Marks the triangles around v's neighbours, where a covering has changed the mesh.
  void mark_neighbourhood(Vertex v, std::vector<char>& changed_near) const
  {
    changed_near.resize(m_mesh.num_faces(), 0);
    for(Vertex w : vertices_around_target(m_mesh.halfedge(v), m_mesh))
      for(Halfedge g : halfedges_around_target(m_mesh.halfedge(w), m_mesh))
        if(!m_mesh.is_border(g))
          changed_near[std::size_t(m_mesh.face(g))] = 1;
  }

  // A vertex at x for the triangle f: on the side of f whose split keeps the best triangles, or
  // inside f; none (a null vertex) when no way keeps acceptable triangles.
  Vertex cover(Face f, const Vector_3d& x)
  {
    const Halfedge h0 = m_mesh.halfedge(f);
    for(Halfedge h : halfedges_around_face(h0, m_mesh))
      if(is_frozen(m_mesh.target(h)))
        return Vertex();
    double best = 0;
    Halfedge best_h;
    for(Halfedge h : halfedges_around_face(h0, m_mesh))
    {
      if(m_state.feature_edge[std::size_t(m_mesh.edge(h))])
        continue;
      const Halfedge o = m_mesh.opposite(h);
      const Vertex a = m_mesh.source(h), b = m_mesh.target(h), c = m_mesh.target(m_mesh.next(h));
      const Vector_3d pa = position(a), pb = position(b), pc = position(c);
      const Vector_3d abc = area_vector(pa, pb, pc);
      if(!acceptable(pa, x, pc, a, abc) || !acceptable(x, pb, pc, b, abc))
        continue;
      boost::container::small_vector<Halfedge, 4> link{m_mesh.next(h), m_mesh.prev(h)};
      if(!m_mesh.is_border(o))
        link.insert(link.end(), {m_mesh.next(o), m_mesh.prev(o)});
      if(!fan_unfolded(link, x))
        continue;
      double smallest = (std::min)(smallest_angle(pa, x, pc), smallest_angle(x, pb, pc));
      if(!m_mesh.is_border(o))
      {
        const Vector_3d pd = position(m_mesh.target(m_mesh.next(o)));
        const Vector_3d bad = area_vector(pb, pa, pd);
        if(is_frozen(m_mesh.target(m_mesh.next(o))) || !acceptable(pb, x, pd, b, bad) || !acceptable(x, pa, pd, a, bad))
          continue;
        smallest = (std::min)({smallest, smallest_angle(pb, x, pd), smallest_angle(x, pa, pd)});
      }
      if(smallest > best && split_keeps_distance_bound(h, x))
      {
        best = smallest;
        best_h = h;
      }
    }
    // Inside f: three triangles.
    {
      const std::array<Vertex, 3> t = face_vertices(m_mesh, f);
      const Vector_3d p0 = position(t[0]), p1 = position(t[1]), p2 = position(t[2]);
      const Vector_3d n = area_vector(p0, p1, p2);
      if(acceptable(p0, p1, x, t[0], n) && acceptable(p1, p2, x, t[1], n) && acceptable(p2, p0, x, t[2], n) &&
         fan_unfolded(std::array<Halfedge, 3>{{h0, m_mesh.next(h0), m_mesh.prev(h0)}}, x))
      {
        const double smallest = (std::min)({smallest_angle(p0, p1, x), smallest_angle(p1, p2, x), smallest_angle(p2, p0, x)});
        if(smallest > best && keeps_distance_bound(std::array<Face, 1>{{f}}, {Triangle_3d{{p0, p1, x}}, Triangle_3d{{p1, p2, x}},
                                                                               Triangle_3d{{p2, p0, x}}}))
        {
          const Vertex from = t[0];
          const Halfedge hv = CGAL::Euler::add_center_vertex(h0, m_mesh);
          const Vertex v = m_mesh.target(hv);
          m_mesh.point(v) = Work_kernel::Point_3(x.x(), x.y(), x.z());
          m_state.fit(m_mesh);
          for(Halfedge g : halfedges_around_target(hv, m_mesh))
            m_state.feature_edge[std::size_t(m_mesh.edge(g))] = 0;
          bind_new_vertex(v, from);
          track_faces_from(v);
          return v;
        }
      }
    }
    if(best_h == Halfedge())
      return Vertex();
    return Edge_splits(*this).split_edge_at(best_h, x, Location());
  }
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_COVERINGS_H
