// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesh the method works on: a Surface_mesh over doubles, in the unit box, whatever the user's
// mesh type and kernel; the reference surface is one too.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_WORK_MESH_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_WORK_MESH_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <array>

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

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_WORK_MESH_H
