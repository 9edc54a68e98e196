// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Which triangles of the working mesh intersect: among all of them, or only those incident to a
// set of vertices (after a relocation only the triangles of the moved vertices can have started
// to intersect anything). Exact predicates decide.
//
// Triangles that share a vertex are checked one vertex fan at a time: a fan that, seen along a
// coordinate axis, is a ring of positively oriented sectors going once around its vertex cannot
// meet itself. Triangles that share no vertex are checked in pairs from a candidate list: the
// pairs whose boxes, grown by a margin, overlap. The list stays valid until a vertex drifts
// farther than the margin from where it was when the list was made, so the relocations of
// several iterations share one list.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_INTERSECTIONS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_INTERSECTIONS_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/parallel.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <boost/container/small_vector.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_sort.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

class Triangle_intersections
{
  using Vertex = Work_mesh::Vertex_index;
  using Halfedge = Work_mesh::Halfedge_index;
  using Face = Work_mesh::Face_index;
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = Epick::Point_3;

public:
  using Face_pair = std::pair<Face, Face>; // first < second

  explicit Triangle_intersections(const Work_mesh& m) : m_mesh(m) {}

  // To be called when the connectivity of the mesh changed: the candidate list is made again.
  void invalidate() { m_valid = false; }

  // All intersecting pairs, sorted.
  std::vector<Face_pair> all_pairs()
  {
    m_valid = false;
    return pairs_touching(std::vector<char>(m_mesh.num_vertices(), 1));
  }

  // The intersecting pairs with at least one triangle incident to a vertex v with touched[v],
  // sorted: all those that may have started to intersect when only the touched vertices moved
  // since the mesh was last known to be without new intersections.
  std::vector<Face_pair> pairs_touching(const std::vector<char>& touched)
  {
    // Any vertex, not only the touched ones: a caller may have put others back where they were.
    if(m_valid)
      for(Vertex v : m_mesh.vertices())
        if(drifted(v))
        {
          m_valid = false;
          break;
        }
    if(!m_valid)
      make_candidates();

    const std::size_t nf = m_mesh.num_faces();
    std::vector<char> query(nf, 0);
    for(Face f : m_mesh.faces())
      for(Vertex v : m_triangles[std::size_t(f)])
        query[std::size_t(f)] |= touched[std::size_t(v)];

    std::vector<Face_pair> out;
    // Triangles that share a vertex: the fans of the vertices of the queried triangles.
    const std::size_t nv = m_mesh.num_vertices();
    std::vector<char> fan(nv, 0);
    for(Face f : m_mesh.faces())
      if(query[std::size_t(f)])
        for(Vertex v : m_triangles[std::size_t(f)])
          fan[std::size_t(v)] = 1;
    collect_by_blocks(nv, out, [&](std::size_t i, std::vector<Face_pair>& found) {
      const Vertex v(static_cast<Vertex::size_type>(i));
      if(fan[i] && !m_mesh.is_removed(v))
        fan_pairs(v, query, found);
    });
    // Triangles that share no vertex: the candidates with a queried triangle, whose boxes overlap
    // (each box made once: a triangle has a few candidates).
    m_boxes.resize(nf);
    for_each_index(nf, [&](std::size_t i) {
      const Face f(static_cast<Face::size_type>(i));
      if(!m_mesh.is_removed(f))
        m_boxes[i] = box(f);
    });
    collect_by_blocks(m_candidates.size(), out, [&](std::size_t i, std::vector<Face_pair>& found) {
      const Face_pair& p = m_candidates[i];
      if((query[std::size_t(p.first)] || query[std::size_t(p.second)]) &&
         CGAL::do_overlap(m_boxes[std::size_t(p.first)], m_boxes[std::size_t(p.second)]) &&
         intersect(p.first, p.second))
        found.push_back(p);
    });
    // A pair with two common vertices comes from both fans.
    sort_pairs(out);
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

private:
  using Cell = std::array<long long, 3>;

  Point point(Vertex v) const
  {
    const auto& p = m_mesh.point(v);
    return Point(p.x(), p.y(), p.z());
  }

  CGAL::Bbox_3 box(Face f) const
  {
    CGAL::Bbox_3 b;
    for(Vertex v : m_triangles[std::size_t(f)])
      b += m_mesh.point(v).bbox();
    return b;
  }

  bool drifted(Vertex v) const
  {
    const auto& p = m_mesh.point(v);
    const std::array<double, 3>& a = m_anchor[std::size_t(v)];
    return !(std::abs(p.x() - a[0]) <= m_margin && std::abs(p.y() - a[1]) <= m_margin &&
             std::abs(p.z() - a[2]) <= m_margin);
  }

  // function(i, list) for i in [0, n), by blocks in parallel, each block into its own list; then
  // the lists appended to `out` in the order of the blocks.
  template <typename Function>
  static void collect_by_blocks(std::size_t n, std::vector<Face_pair>& out, const Function& function)
  {
    const std::size_t block = 4096, number_of_blocks = (n + block - 1) / block;
    std::vector<std::vector<Face_pair> > found(number_of_blocks);
    for_each_index(number_of_blocks, [&](std::size_t bi) {
      for(std::size_t i = bi * block; i < (std::min)(n, (bi + 1) * block); ++i)
        function(i, found[bi]);
    });
    for(const std::vector<Face_pair>& pairs : found)
      out.insert(out.end(), pairs.begin(), pairs.end());
  }

  // The candidate list: the pairs of triangles without a common vertex whose boxes, grown by the
  // margin, overlap. They come from a hashed uniform grid of the grown boxes: each triangle is
  // listed in every cell its box overlaps, and a pair is taken in the one cell that holds the low
  // corner of the intersection of the boxes. Linear in the number of triangles.
  void make_candidates()
  {
    const std::size_t nf = m_mesh.num_faces(), nv = m_mesh.num_vertices();
    m_triangles.assign(nf, std::array<Vertex, 3>());
    m_anchor.assign(nv, std::array<double, 3>());
    for(Vertex v : m_mesh.vertices())
    {
      const auto& p = m_mesh.point(v);
      m_anchor[std::size_t(v)] = {{p.x(), p.y(), p.z()}};
    }
    std::vector<CGAL::Bbox_3> boxes(nf);
    for_each_face([&](Face f) {
      m_triangles[std::size_t(f)] = face_vertices(m_mesh, f);
      boxes[std::size_t(f)] = box(f);
    });
    double extent = 0;
    std::size_t count = 0;
    for(Face f : m_mesh.faces())
    {
      const CGAL::Bbox_3& b = boxes[std::size_t(f)];
      extent += (std::max)({b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()});
      ++count;
    }
    m_candidates.clear();
    m_valid = true;
    if(count == 0)
      return;
    extent /= double(count);
    // A quarter of a triangle: the vertices of a relocation move less than that in most
    // iterations, and grown boxes still meet few triangles beyond their neighbours.
    m_margin = 0.25 * extent;
    // About the size of a grown box: a cell then holds a few triangles, a triangle a few cells.
    m_cell = extent + 2 * m_margin;
    if(!(m_cell > 0))
      m_cell = 1;
    // Grown, then in single precision (rounded outwards) for a compact grid; the cells are those
    // of the single-precision boxes. Each entry carries its box, so that a bucket is read in one
    // sweep of memory, and the axes on which its cell is the cell of the box's low corner.
    struct Entry
    {
      Face face;
      unsigned char low;
      std::array<float, 6> box;
    };
    std::vector<std::array<float, 6> > small_boxes(nf);
    std::vector<std::size_t> offset(nf + 1, 0);
    for_each_face([&](Face f) {
      CGAL::Bbox_3& b = boxes[std::size_t(f)];
      std::array<float, 6>& s = small_boxes[std::size_t(f)];
      const float inf = std::numeric_limits<float>::infinity();
      s = {{std::nextafter(float(b.xmin() - m_margin), -inf), std::nextafter(float(b.ymin() - m_margin), -inf),
            std::nextafter(float(b.zmin() - m_margin), -inf), std::nextafter(float(b.xmax() + m_margin), inf),
            std::nextafter(float(b.ymax() + m_margin), inf), std::nextafter(float(b.zmax() + m_margin), inf)}};
      b = CGAL::Bbox_3(s[0], s[1], s[2], s[3], s[4], s[5]);
      std::size_t cells = 0;
      for_each_cell(b, [&](const Cell&, unsigned char) { ++cells; });
      offset[std::size_t(f) + 1] = cells;
    });
    for(std::size_t i = 0; i < nf; ++i)
      offset[i + 1] += offset[i];
    const std::size_t entries = offset[nf];
    std::size_t buckets = 1;
    while(buckets < entries)
      buckets *= 2;
    // The cells of each triangle, in order, at its offset; then a counting sort by bucket.
    struct Cell_entry
    {
      std::uint32_t bucket; // fewer buckets than twice the entries, which are fewer than 2^31
      Face face;
      unsigned char low;
    };
    std::vector<Cell_entry> unsorted(entries);
    for_each_face([&](Face f) {
      std::size_t k = offset[std::size_t(f)];
      for_each_cell(boxes[std::size_t(f)], [&](const Cell& c, unsigned char low) {
        unsorted[k++] = Cell_entry{std::uint32_t(bucket(c, buckets)), f, low};
      });
    });
    offset = std::vector<std::size_t>();
    boxes = std::vector<CGAL::Bbox_3>();
    // By low-cell axes first, so that each bucket lists its entries by them (a radix sort).
    {
      std::array<std::size_t, 9> by_low{};
      for(const Cell_entry& e : unsorted)
        ++by_low[e.low + 1];
      for(int m = 0; m < 8; ++m)
        by_low[m + 1] += by_low[m];
      std::vector<Cell_entry> sorted(entries);
      for(const Cell_entry& e : unsorted)
        sorted[by_low[e.low]++] = e;
      unsorted.swap(sorted);
    }
    std::vector<std::size_t> start(buckets + 1, 0);
    for(const Cell_entry& e : unsorted)
      ++start[e.bucket + 1];
    for(std::size_t i = 0; i < buckets; ++i)
      start[i + 1] += start[i];
    std::vector<Entry> listed(entries);
    {
      std::vector<std::size_t> fill(start.begin(), start.end() - 1);
      for(const Cell_entry& e : unsorted)
        listed[fill[e.bucket]++] = Entry{e.face, e.low, small_boxes[std::size_t(e.face)]};
    }
    unsorted = std::vector<Cell_entry>();
    small_boxes = std::vector<std::array<float, 6> >();

    // The pairs of each bucket, each pair in the cell that holds the low corner of the
    // intersection of its boxes (both boxes overlap that cell, so both are listed there). The low
    // corner of the intersection is the largest of the low corners: in a cell both boxes meet, it
    // lies in that cell when on each axis one of the two boxes starts in it. Entries of another
    // cell of the same bucket can only give a pair found elsewhere too. The entries of a bucket
    // come by their low-cell axes: only the groups whose axes cover all three are paired.
    auto consider = [&](const Entry& ei, const Entry& ej, std::vector<Face_pair>& found) {
      const std::array<float, 6>& a = ei.box;
      const std::array<float, 6>& b = ej.box;
      if(ei.face == ej.face || b[0] > a[3] || a[0] > b[3] || b[1] > a[4] || a[1] > b[4] || b[2] > a[5] || a[2] > b[5])
        return;
      const std::array<Vertex, 3>& ti = m_triangles[std::size_t(ei.face)];
      const std::array<Vertex, 3>& tj = m_triangles[std::size_t(ej.face)];
      bool common = false;
      for(Vertex u : ti)
        common = common || u == tj[0] || u == tj[1] || u == tj[2];
      if(!common)
        found.push_back(ei.face < ej.face ? Face_pair(ei.face, ej.face) : Face_pair(ej.face, ei.face));
    };
    collect_by_blocks(buckets, m_candidates, [&](std::size_t k, std::vector<Face_pair>& found) {
      std::array<std::size_t, 9> group; // the entries of low-cell axes m: [group[m], group[m + 1])
      for(std::size_t m = 0, i = start[k]; m < 8; ++m)
      {
        group[m] = i;
        while(i < start[k + 1] && listed[i].low == m)
          ++i;
      }
      group[8] = start[k + 1];
      for(int ga = 0; ga < 8; ++ga)
        for(int gb = ga; gb < 8; ++gb)
          if((ga | gb) == 7)
            for(std::size_t i = group[ga]; i < group[ga + 1]; ++i)
              for(std::size_t j = (ga == gb ? i + 1 : group[gb]); j < group[gb + 1]; ++j)
                consider(listed[i], listed[j], found);
    });
    // Two cells may share a bucket, and a triangle be listed there twice: a pair can be found
    // more than once.
    sort_pairs(m_candidates);
    m_candidates.erase(std::unique(m_candidates.begin(), m_candidates.end()), m_candidates.end());
    m_candidates.shrink_to_fit();
  }

  // function(f) for each face, in parallel.
  template <typename Function>
  void for_each_face(const Function& function) const
  {
    for_each_index(m_mesh.num_faces(), [&](std::size_t i) {
      const Face f(static_cast<Face::size_type>(i));
      if(!m_mesh.is_removed(f))
        function(f);
    });
  }

  static void sort_pairs(std::vector<Face_pair>& pairs)
  {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::parallel_sort(pairs.begin(), pairs.end());
#else
    std::sort(pairs.begin(), pairs.end());
#endif
  }

  Cell cell_of(double x, double y, double z) const
  {
    return {{(long long)std::floor(x / m_cell), (long long)std::floor(y / m_cell), (long long)std::floor(z / m_cell)}};
  }

  // function(c, low) for each cell c the box overlaps; bit a of `low` says whether c is the box's
  // first cell along axis a.
  template <typename Function>
  void for_each_cell(const CGAL::Bbox_3& b, const Function& function) const
  {
    const Cell lo = cell_of(b.xmin(), b.ymin(), b.zmin()), hi = cell_of(b.xmax(), b.ymax(), b.zmax());
    Cell c;
    for(c[0] = lo[0]; c[0] <= hi[0]; ++c[0])
      for(c[1] = lo[1]; c[1] <= hi[1]; ++c[1])
        for(c[2] = lo[2]; c[2] <= hi[2]; ++c[2])
          function(c, static_cast<unsigned char>((c[0] == lo[0]) | (c[1] == lo[1]) << 1 | (c[2] == lo[2]) << 2));
  }

  static std::size_t bucket(const Cell& c, std::size_t buckets)
  {
    const std::uint64_t h = std::uint64_t(c[0]) * 73856093u ^ std::uint64_t(c[1]) * 19349663u ^
                            std::uint64_t(c[2]) * 83492791u;
    return std::size_t(h * 0x9E3779B97F4A7C15ull >> 20) & (buckets - 1);
  }

  // The triangles around v, each with its other two vertices in the order of the face.
  using Fan = boost::container::small_vector<std::pair<Face, std::array<Vertex, 2> >, 16>;

  // The intersecting pairs among the triangles around v with a queried one. When the fan is
  // embedded there are none; otherwise each such pair is tested.
  void fan_pairs(Vertex v, const std::vector<char>& query, std::vector<Face_pair>& found) const
  {
    Fan fan;
    bool queried = false;
    for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      if(!m_mesh.is_border(h))
      {
        // The face is (source(h), v, target(next(h))).
        fan.push_back({m_mesh.face(h), {{m_mesh.target(m_mesh.next(h)), m_mesh.source(h)}}});
        queried = queried || query[std::size_t(m_mesh.face(h))];
      }
    if(!queried || fan.size() < 2 || is_embedded_fan(v, fan))
      return;
    for(std::size_t i = 0; i < fan.size(); ++i)
      for(std::size_t j = i + 1; j < fan.size(); ++j)
      {
        const Face f = fan[i].first, g = fan[j].first;
        if((query[std::size_t(f)] || query[std::size_t(g)]) && intersect(f, g))
          found.push_back(f < g ? Face_pair(f, g) : Face_pair(g, f));
      }
  }

  // Whether the triangles of `fan` meet only in the edges and at the vertex v they share. Seen
  // along the coordinate axis nearest their mean normal (the projection then only drops a
  // coordinate, and exact predicates stay exact), the triangles must be positively oriented
  // sectors at v going at most once around it: the ray to a first rim vertex (an end of an open
  // fan) lies in no sector but the ones it bounds. Then two sectors share only v or a bounding
  // ray, each triangle projects one to one, and two triangles share only v or their common edge.
  bool is_embedded_fan(Vertex v, const Fan& fan) const
  {
    const Vector_3d p = to_vector(m_mesh.point(v));
    Vector_3d n = Vector_3d::Zero();
    for(const auto& t : fan)
      n += area_vector(p, to_vector(m_mesh.point(t.second[0])), to_vector(m_mesh.point(t.second[1])));
    const int axis = std::abs(n[0]) >= std::abs(n[1]) ? (std::abs(n[0]) >= std::abs(n[2]) ? 0 : 2)
                                                       : (std::abs(n[1]) >= std::abs(n[2]) ? 1 : 2);
    const CGAL::Orientation positive = n[axis] > 0 ? CGAL::POSITIVE : CGAL::NEGATIVE;
    const CGAL::Orientation negative = n[axis] > 0 ? CGAL::NEGATIVE : CGAL::POSITIVE;
    auto project = [&](Vertex u) {
      const auto& q = m_mesh.point(u);
      return axis == 0 ? Epick::Point_2(q.y(), q.z())
                       : (axis == 1 ? Epick::Point_2(q.z(), q.x()) : Epick::Point_2(q.x(), q.y()));
    };
    const Epick::Point_2 o = project(v);
    for(const auto& t : fan)
      if(CGAL::orientation(o, project(t.second[0]), project(t.second[1])) != positive)
        return false;
    auto sectors_at = [&](Vertex u) {
      std::size_t k = 0;
      for(const auto& t : fan)
        k += (t.second[0] == u) + (t.second[1] == u);
      return k;
    };
    Vertex start = fan[0].second[0];
    for(const auto& t : fan)
      if(sectors_at(t.second[0]) == 1)
      {
        start = t.second[0];
        break;
      }
    if(sectors_at(start) > 2)
      return false;
    const Epick::Point_2 s = project(start);
    for(const auto& t : fan)
      if(t.second[0] != start && t.second[1] != start &&
         CGAL::orientation(o, project(t.second[0]), s) != negative &&
         CGAL::orientation(o, s, project(t.second[1])) != negative)
        return false;
    return true;
  }

  // Whether triangles f and g share a point they do not share through the mesh: for neighbours,
  // a point other than their common vertex or edge.
  bool intersect(Face f, Face g) const
  {
    const std::array<Vertex, 3>& a = m_triangles[std::size_t(f)];
    const std::array<Vertex, 3>& b = m_triangles[std::size_t(g)];
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
  bool m_valid = false;
  double m_margin = 0;                           // how far boxes were grown
  double m_cell = 1;                             // the side of a grid cell
  std::vector<std::array<Vertex, 3> > m_triangles; // by face, when the list was made
  std::vector<std::array<double, 3> > m_anchor;    // by vertex, where it was then
  std::vector<Face_pair> m_candidates;           // sorted
  std::vector<CGAL::Bbox_3> m_boxes;              // by face, at the last check
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_INTERSECTIONS_H
