// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a run promises about the working mesh, checked after every run in debug builds: a valid
// halfedge structure of triangles, none degenerate, the topology of the input (Euler
// characteristic, connected components, border cycles), fixed vertices where they were, no more
// folds off the sharp edges than the input had. The driver, which knows where the input's own
// intersections are, adds that no two triangles intersect away from them: a triangle folded over
// onto its neighbours would.
//
// (Not "no triangle faces against the nearest reference triangle": where the reference is thinner
// than a triangle, as on CGAL's anchor, the nearest triangle can be on the other sheet.)

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_GUARANTEES_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_GUARANTEES_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/helpers.h>

#include <cstddef>
#include <numeric>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

struct Topology_summary
{
  long long euler_characteristic = 0;
  std::size_t components = 0;
  std::size_t border_cycles = 0;

  bool operator==(const Topology_summary& o) const
  {
    return euler_characteristic == o.euler_characteristic && components == o.components &&
           border_cycles == o.border_cycles;
  }
  bool operator!=(const Topology_summary& o) const { return !(*this == o); }
};

inline Topology_summary topology_summary(const Work_mesh& m)
{
  Topology_summary s;
  s.euler_characteristic = (long long)m.number_of_vertices() - (long long)m.number_of_edges() +
                           (long long)m.number_of_faces();
  // Components of the faces across their edges (union-find over face indices); a vertex joins
  // only faces that share an edge with each other too, since the mesh is manifold.
  std::vector<std::size_t> parent(m.num_faces());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto root = [&](std::size_t i) {
    while(parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  };
  for(auto e : m.edges())
  {
    const auto h = m.halfedge(e), o = m.opposite(h);
    if(!m.is_border(h) && !m.is_border(o))
      parent[root(std::size_t(m.face(h)))] = root(std::size_t(m.face(o)));
  }
  for(auto f : m.faces())
    if(root(std::size_t(f)) == std::size_t(f))
      ++s.components;
  std::vector<char> seen(m.num_halfedges(), 0);
  for(auto h : m.halfedges())
    if(m.is_border(h) && !seen[std::size_t(h)])
    {
      ++s.border_cycles;
      for(auto g : halfedges_around_face(h, m))
        seen[std::size_t(g)] = 1;
    }
  return s;
}

// The edges of m whose two triangles are folded onto each other, leaving out those `skip` flags
// when given.
inline std::size_t folded_edges(const Work_mesh& m, const std::vector<char>* skip = nullptr)
{
  std::size_t folds = 0;
  for(auto e : m.edges())
    if(!(skip && (*skip)[std::size_t(e)]) && is_folded_edge(m, m.halfedge(e)))
      ++folds;
  return folds;
}

// The first guarantee `mesh` breaks, in words, or an empty string. `topology` is the input's,
// `fixed` the vertices that may not move and `fixed_point` their input positions,
// `input_folds` the input's folded_edges(), `feature_edge` flags mesh's sharp and border edges.
inline std::string broken_guarantee(const Work_mesh& mesh, const Topology_summary& topology,
                                    const std::vector<Work_mesh::Vertex_index>& fixed,
                                    const std::vector<Vector_3d>& fixed_point, std::size_t input_folds,
                                    const std::vector<char>& feature_edge)
{
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  if(!CGAL::is_valid_polygon_mesh(mesh) || !CGAL::is_triangle_mesh(mesh))
    return "the halfedge structure is not a valid triangle mesh";
  const Topology_summary now = topology_summary(mesh);
  if(now.euler_characteristic != topology.euler_characteristic)
    return "the Euler characteristic changed";
  if(now.components != topology.components)
    return "the number of connected components changed";
  if(now.border_cycles != topology.border_cycles)
    return "the number of border cycles changed";
  for(std::size_t i = 0; i < fixed.size(); ++i)
    if(to_vector(mesh.point(fixed[i])) != fixed_point[i])
      return "a fixed vertex moved";
  for(auto f : mesh.faces())
  {
    const std::array<Work_mesh::Vertex_index, 3> t = face_vertices(mesh, f);
    std::array<Epick::Point_3, 3> p;
    for(int i = 0; i < 3; ++i)
      p[i] = Epick::Point_3(mesh.point(t[i]).x(), mesh.point(t[i]).y(), mesh.point(t[i]).z());
    if(CGAL::collinear(p[0], p[1], p[2]))
      return "a triangle is degenerate";
  }
  // A fold along a sharp edge can be the shape (a thin fin); off them only where the input had one.
  if(folded_edges(mesh, &feature_edge) > input_folds)
    return "a triangle is folded over onto a neighbour";
  return std::string();
}

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_GUARANTEES_H
