// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesh the method works on: a Surface_mesh over doubles, in the unit box, whatever the user's
// mesh type and kernel; the reference surface is one too.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_WORK_MESH_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_WORK_MESH_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/parallel.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

using Work_kernel = CGAL::Simple_cartesian<double>;
using Work_mesh = CGAL::Surface_mesh<Work_kernel::Point_3>;

// The three vertices of a triangle, in the order of its halfedges.
template <typename Mesh>
std::array<typename Mesh::Vertex_index, 3> face_vertices(const Mesh& m, typename Mesh::Face_index f)
{
  const auto h = m.halfedge(f);
  return {{m.source(h), m.target(h), m.target(m.next(h))}};
}

// Twice the area vector of the face of h, from the source of h round the face.
template <typename Mesh>
Vector_3d face_area_vector(const Mesh& m, typename Mesh::Halfedge_index h)
{
  return area_vector(to_vector(m.point(m.source(h))), to_vector(m.point(m.target(h))),
                     to_vector(m.point(m.target(m.next(h)))));
}

// Grows an array indexed by the mesh's elements to n entries, the new ones `value`. When it has to
// move it takes room for a sixteenth more, not twice as many as std::vector would: on a large mesh
// such an array is megabytes, and a connectivity pass adds a few percent of elements, one at a time.
template <typename T>
void grow_by_elements(std::vector<T>& a, std::size_t n, const T& value = T())
{
  if(a.capacity() < n)
    a.reserve(n + n / 16);
  a.resize(n, value);
}

// Whether the two triangles of the edge of h are folded onto each other (is_folded_pair()); never
// on a border.
template <typename Mesh>
bool is_folded_edge(const Mesh& m, typename Mesh::Halfedge_index h)
{
  const auto o = m.opposite(h);
  return !m.is_border(h) && !m.is_border(o) && is_folded_pair(face_area_vector(m, h), face_area_vector(m, o));
}

// function(x) for every element x of m of the index type Index (n slots, the removed ones left
// out), as independent items: in parallel where TBB is.
template <typename Index, typename Mesh, typename Function>
void for_each_live(const Mesh& m, std::size_t n, const Function& function)
{
  for_each_index(n, [&](std::size_t i) {
    const Index x(static_cast<typename Index::size_type>(i));
    if(!m.is_removed(x))
      function(x);
  });
}

template <typename Mesh, typename Function>
void for_each_vertex(const Mesh& m, const Function& function)
{
  for_each_live<typename Mesh::Vertex_index>(m, m.num_vertices(), function);
}

template <typename Mesh, typename Function>
void for_each_edge(const Mesh& m, const Function& function)
{
  for_each_live<typename Mesh::Edge_index>(m, m.num_edges(), function);
}

template <typename Mesh, typename Function>
void for_each_face(const Mesh& m, const Function& function)
{
  for_each_live<typename Mesh::Face_index>(m, m.num_faces(), function);
}

// By vertex of `after`: whether it is new, moved, or on a triangle that is new or on other
// vertices since the mesh was `before` (the same mesh, before local changes, indices kept).
inline std::vector<char> changed_vertices(const Work_mesh& before, const Work_mesh& after)
{
  std::vector<char> changed(after.num_vertices(), 0);
  for(Work_mesh::Vertex_index v : after.vertices())
    changed[std::size_t(v)] = std::size_t(v) >= before.num_vertices() || before.is_removed(v) ||
                              before.point(v) != after.point(v);
  for(Work_mesh::Face_index f : after.faces())
    if(std::size_t(f) >= before.num_faces() || before.is_removed(f) || face_vertices(before, f) != face_vertices(after, f))
      for(Work_mesh::Vertex_index v : face_vertices(after, f))
        changed[std::size_t(v)] = 1;
  return changed;
}

// b grown by r on every side.
inline CGAL::Bbox_3 grown_by(const CGAL::Bbox_3& b, double r)
{
  return CGAL::Bbox_3(b.xmin() - r, b.ymin() - r, b.zmin() - r, b.xmax() + r, b.ymax() + r, b.zmax() + r);
}

// The box of the triangles f and g of `mesh` grown by r on every side.
inline CGAL::Bbox_3 box_around(const Work_mesh& mesh, Work_mesh::Face_index f, Work_mesh::Face_index g, double r)
{
  CGAL::Bbox_3 b;
  for(Work_mesh::Face_index h : {f, g})
    for(Work_mesh::Vertex_index u : face_vertices(mesh, h))
      b += mesh.point(u).bbox();
  return grown_by(b, r);
}

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_WORK_MESH_H
