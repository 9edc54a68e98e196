// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Which triangles of the working mesh intersect: among all of them, or only those incident to a
// set of vertices (after a relocation only the triangles of the moved vertices can have started
// to intersect anything). A grid of boxes finds the candidate pairs; exact predicates decide.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_INTERSECTIONS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_INTERSECTIONS_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/parallel.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

class Triangle_intersections
{
  using Vertex = Work_mesh::Vertex_index;
  using Face = Work_mesh::Face_index;
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = Epick::Point_3;

public:
  using Face_pair = std::pair<Face, Face>; // first < second

  explicit Triangle_intersections(const Work_mesh& m) : m_mesh(m) {}

  // All intersecting pairs, sorted.
  std::vector<Face_pair> all_pairs()
  {
    return pairs_touching(std::vector<char>(m_mesh.num_vertices(), 1));
  }

  // The intersecting pairs with at least one triangle incident to a vertex v with touched[v],
  // sorted.
  //
  // Candidates come from a hashed uniform grid of the triangles' boxes: each triangle is listed in
  // every cell its box overlaps, and a pair of overlapping boxes is tested in the one cell holding
  // the low corner of their intersection. Building the grid and each query are linear in the
  // number of triangles, where a sweep over sorted boxes is not.
  std::vector<Face_pair> pairs_touching(const std::vector<char>& touched)
  {
    const std::size_t nf = m_mesh.num_faces();
    m_boxes.assign(nf, CGAL::Bbox_3());
    std::vector<char> query(nf, 0);
    double extent = 0;
    std::size_t count = 0;
    for(Face f : m_mesh.faces())
    {
      CGAL::Bbox_3& b = m_boxes[std::size_t(f)];
      for(Vertex v : face_vertices(m_mesh, f))
      {
        b += m_mesh.point(v).bbox();
        query[std::size_t(f)] |= touched[std::size_t(v)];
      }
      extent += (std::max)({b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()});
      ++count;
    }
    std::vector<Face_pair> out;
    if(count == 0)
      return out;
    // About the size of a triangle: a cell then holds a few triangles, a triangle a few cells.
    m_cell = 1.5 * extent / double(count);
    if(!(m_cell > 0))
      m_cell = 1;

    // Counting sort of (cell, triangle) entries by the hash of the cell.
    std::size_t entries = 0;
    for(Face f : m_mesh.faces())
      entries += number_of_cells(m_boxes[std::size_t(f)]);
    std::size_t buckets = 1;
    while(buckets < entries)
      buckets *= 2;
    m_start.assign(buckets + 1, 0);
    for(Face f : m_mesh.faces())
      for_each_cell(m_boxes[std::size_t(f)], [&](const Cell& c) { ++m_start[bucket(c, buckets) + 1]; });
    for(std::size_t i = 0; i < buckets; ++i)
      m_start[i + 1] += m_start[i];
    m_listed.resize(entries);
    std::vector<std::size_t> fill(m_start.begin(), m_start.end() - 1);
    for(Face f : m_mesh.faces())
      for_each_cell(m_boxes[std::size_t(f)], [&](const Cell& c) { m_listed[fill[bucket(c, buckets)]++] = f; });
    fill = std::vector<std::size_t>();

    // The queries by blocks of triangles, each block into its own list.
    const std::size_t block = 1024, number_of_blocks = (nf + block - 1) / block;
    std::vector<std::vector<Face_pair> > found(number_of_blocks);
    for_each_index(number_of_blocks, [&](std::size_t bi) {
      for(std::size_t fi = bi * block; fi < (std::min)(nf, (bi + 1) * block); ++fi)
      {
        const Face f(static_cast<Face::size_type>(fi));
        if(m_mesh.is_removed(f) || !query[fi])
          continue;
        const CGAL::Bbox_3& bf = m_boxes[fi];
        for_each_cell(bf, [&](const Cell& c) {
          const std::size_t k = bucket(c, buckets);
          for(std::size_t e = m_start[k]; e < m_start[k + 1]; ++e)
          {
            const Face g = m_listed[e];
            // A pair of two queried triangles once, from its smaller one.
            if(g == f || (query[std::size_t(g)] && g < f))
              continue;
            const CGAL::Bbox_3& bg = m_boxes[std::size_t(g)];
            if(!CGAL::do_overlap(bf, bg))
              continue;
            const Cell low = cell_of((std::max)(bf.xmin(), bg.xmin()), (std::max)(bf.ymin(), bg.ymin()),
                                     (std::max)(bf.zmin(), bg.zmin()));
            if(low != c)
              continue;
            if(intersect(f, g))
              found[bi].push_back(f < g ? Face_pair(f, g) : Face_pair(g, f));
          }
        });
      }
    });
    for(const std::vector<Face_pair>& pairs : found)
      out.insert(out.end(), pairs.begin(), pairs.end());
    // Two cells may share a bucket: a pair can be found twice.
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

private:
  using Cell = std::array<long long, 3>;

  Cell cell_of(double x, double y, double z) const
  {
    return {{(long long)std::floor(x / m_cell), (long long)std::floor(y / m_cell), (long long)std::floor(z / m_cell)}};
  }

  std::size_t number_of_cells(const CGAL::Bbox_3& b) const
  {
    const Cell lo = cell_of(b.xmin(), b.ymin(), b.zmin()), hi = cell_of(b.xmax(), b.ymax(), b.zmax());
    return std::size_t((hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1));
  }

  template <typename Function>
  void for_each_cell(const CGAL::Bbox_3& b, const Function& function) const
  {
    const Cell lo = cell_of(b.xmin(), b.ymin(), b.zmin()), hi = cell_of(b.xmax(), b.ymax(), b.zmax());
    Cell c;
    for(c[0] = lo[0]; c[0] <= hi[0]; ++c[0])
      for(c[1] = lo[1]; c[1] <= hi[1]; ++c[1])
        for(c[2] = lo[2]; c[2] <= hi[2]; ++c[2])
          function(c);
  }

  static std::size_t bucket(const Cell& c, std::size_t buckets)
  {
    const std::uint64_t h = std::uint64_t(c[0]) * 73856093u ^ std::uint64_t(c[1]) * 19349663u ^
                            std::uint64_t(c[2]) * 83492791u;
    return std::size_t(h * 0x9E3779B97F4A7C15ull >> 20) & (buckets - 1);
  }

  Point point(Vertex v) const
  {
    const auto& p = m_mesh.point(v);
    return Point(p.x(), p.y(), p.z());
  }

  // Whether triangles f and g share a point they do not share through the mesh: for neighbours,
  // a point other than their common vertex or edge.
  bool intersect(Face f, Face g) const
  {
    const std::array<Vertex, 3> a = face_vertices(m_mesh, f), b = face_vertices(m_mesh, g);
    // Put the shared vertices first, in the same order in both.
    std::array<Vertex, 3> fa = a, fb = b;
    int shared = 0;
    for(int i = 0; i < 3; ++i)
      for(int j = shared; j < 3; ++j)
        if(fa[i] == fb[j])
        {
          std::swap(fa[i], fa[shared]);
          std::swap(fb[j], fb[shared]);
          ++shared;
          break;
        }
    Epick k;
    if(shared == 3)
      return true; // two triangles on the same three vertices
    if(shared == 2)
    {
      // Across their common edge (p, q) they meet elsewhere only when folded onto each other.
      const Point p = point(fa[0]), q = point(fa[1]), r = point(fa[2]), s = point(fb[2]);
      return k.coplanar_3_object()(p, q, r, s) &&
             k.coplanar_orientation_3_object()(p, q, r, s) == CGAL::POSITIVE;
    }
    if(shared == 1)
    {
      // Their intersection is convex and holds the common vertex: it holds another point exactly
      // when the edge of one opposite that vertex meets the other.
      const Point v = point(fa[0]), a1 = point(fa[1]), a2 = point(fa[2]);
      const Point b1 = point(fb[1]), b2 = point(fb[2]);
      auto orientation = k.orientation_3_object();
      // Strictly on one side of the other's plane: nothing but the common vertex.
      const CGAL::Orientation o1 = orientation(v, a1, a2, b1), o2 = orientation(v, a1, a2, b2);
      if(o1 != CGAL::COPLANAR && o1 == o2)
        return false;
      const CGAL::Orientation o3 = orientation(v, b1, b2, a1), o4 = orientation(v, b1, b2, a2);
      if(o3 != CGAL::COPLANAR && o3 == o4)
        return false;
      return CGAL::do_intersect(Epick::Segment_3(a1, a2), Epick::Triangle_3(v, b1, b2)) ||
             CGAL::do_intersect(Epick::Segment_3(b1, b2), Epick::Triangle_3(v, a1, a2));
    }
    return CGAL::do_intersect(Epick::Triangle_3(point(a[0]), point(a[1]), point(a[2])),
                              Epick::Triangle_3(point(b[0]), point(b[1]), point(b[2])));
  }

  const Work_mesh& m_mesh;
  double m_cell = 1;                  // the side of a grid cell
  std::vector<CGAL::Bbox_3> m_boxes;  // by face
  std::vector<std::size_t> m_start;   // by bucket: where its triangles start in m_listed
  std::vector<Face> m_listed;         // by bucket, the triangles listed in its cells
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_INTERSECTIONS_H
