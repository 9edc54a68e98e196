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
// pairs whose boxes, grown by a margin around where their vertices were, overlap, kept in a grid.
// The list holds as long as no vertex drifts farther than the margin; the triangles of a vertex
// that did, and those a connectivity change made, are put in the grid again and their pairs
// found anew, so that the list is made once and then kept up to date at the cost of the changes.
// The exact tests take the points the vertices will be written at (normalization.h's
// Output_points); the boxes stay in the unit box, where, rounded outwards to single precision,
// they hold the unit points of those too.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_INTERSECTIONS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_INTERSECTIONS_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/normalization.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/parallel.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_pair_tests.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <CGAL/Bbox_3.h>

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

using Small_box = std::array<float, 6>; // low x, y, z, high x, y, z

// The box of the triangle t's vertices at place(v), grown by `margin`, in single precision rounded
// outwards.
template <typename Place>
Small_box small_box(const std::array<Work_mesh::Vertex_index, 3>& t, const Place& place, double margin)
{
  std::array<double, 3> low, high;
  low.fill(std::numeric_limits<double>::infinity());
  high.fill(-std::numeric_limits<double>::infinity());
  for(Work_mesh::Vertex_index v : t)
  {
    const std::array<double, 3> p = place(v);
    for(int a = 0; a < 3; ++a)
    {
      low[a] = (std::min)(low[a], p[a]);
      high[a] = (std::max)(high[a], p[a]);
    }
  }
  const float inf = std::numeric_limits<float>::infinity();
  Small_box b;
  for(int a = 0; a < 3; ++a)
  {
    b[a] = std::nextafter(float(low[a] - margin), -inf);
    b[a + 3] = std::nextafter(float(high[a] + margin), inf);
  }
  return b;
}

inline bool overlap(const Small_box& a, const Small_box& b)
{
  return !(b[0] > a[3] || a[0] > b[3] || b[1] > a[4] || a[1] > b[4] || b[2] > a[5] || a[2] > b[5]);
}

template <typename Pair>
void sort_pairs(std::vector<Pair>& pairs)
{
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_sort(pairs.begin(), pairs.end());
#else
  std::sort(pairs.begin(), pairs.end());
#endif
}

class Triangle_intersections
{
  using Vertex = Work_mesh::Vertex_index;
  using Halfedge = Work_mesh::Halfedge_index;
  using Face = Work_mesh::Face_index;

public:
  using Face_pair = std::pair<Face, Face>; // first < second

  // `output`: where the vertices of m will be written; by default, where they are.
  explicit Triangle_intersections(const Work_mesh& m, Output_points output = Output_points())
    : m_mesh(m), m_output(std::move(output))
  {}

  // To be called when the mesh was replaced: the candidate list is made again.
  void invalidate() { m_valid = false; }

  // To be called when triangles were added, removed or put on other vertices: the candidate list
  // is updated for those triangles.
  void connectivity_changed() { m_reconnected = true; }

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
    // Entries keep a face index in 29 bits.
    CGAL_precondition(m_mesh.num_faces() < (std::size_t(1) << 29));
    if(m_valid)
      update_candidates();
    m_reconnected = false;
    if(!m_valid)
      make_candidates();

    const std::size_t nf = m_mesh.num_faces();
    std::vector<char> query(nf, 0);
    for_each_face(m_mesh, [&](Face f) {
      for(Vertex v : m_triangles[std::size_t(f)])
        query[std::size_t(f)] |= touched[std::size_t(v)];
    });

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
    // (each box made once, in single precision: a triangle has a few candidates).
    {
      std::vector<Small_box> boxes(nf);
      for_each_face(m_mesh, [&](Face f) { boxes[std::size_t(f)] = current_box(f); });
      collect_by_blocks(m_candidates.size(), out, [&](std::size_t i, std::vector<Face_pair>& found) {
        const Face_pair& p = m_candidates[i];
        if((query[std::size_t(p.first)] || query[std::size_t(p.second)]) &&
           overlap(boxes[std::size_t(p.first)], boxes[std::size_t(p.second)]) && intersect(p.first, p.second))
          found.push_back(p);
      });
    }
    // A pair with two common vertices comes from both fans.
    sort_pairs(out);
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

private:
  using Cell = std::array<long long, 3>;

  // A triangle listed in a grid cell, with the axes on which the cell is its box's first, in
  // 32 bits: a large mesh has tens of millions of entries.
  struct Entry
  {
    std::uint32_t bits; // face index * 8 + low-cell axes

    Entry(Face f, unsigned char low) : bits(std::uint32_t(std::size_t(f) << 3 | low)) {}
    Entry() : bits(0) {}
    Face face() const { return Face(static_cast<Face::size_type>(bits >> 3)); }
    unsigned char low() const { return static_cast<unsigned char>(bits & 7); }
  };

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

  // The candidate list: the pairs of triangles without a common vertex whose boxes, grown by the
  // margin, overlap. They come from a hashed uniform grid of the grown boxes: each triangle is
  // listed in every cell its box overlaps, and a pair is taken in the one cell that holds the low
  // corner of the intersection of the boxes. Linear in the number of triangles.
  void make_candidates()
  {
    const std::size_t nf = m_mesh.num_faces(), nv = m_mesh.num_vertices();
    m_triangles.assign(nf, no_triangle());
    m_anchor.assign(nv, std::array<double, 3>());
    for(Vertex v : m_mesh.vertices())
    {
      const auto& p = m_mesh.point(v);
      m_anchor[std::size_t(v)] = {{p.x(), p.y(), p.z()}};
    }
    std::vector<Face> faces;
    faces.reserve(m_mesh.number_of_faces());
    for(Face f : m_mesh.faces())
      faces.push_back(f);
    for_each_index(faces.size(), [&](std::size_t i) {
      m_triangles[std::size_t(faces[i])] = face_vertices(m_mesh, faces[i]);
    });
    m_candidates.clear();
    m_valid = true;
    m_entries = std::vector<Entry>();
    m_start.assign(2, 0);
    m_buckets = 1;
    if(faces.empty())
      return;
    double extent = 0;
    for(Face f : faces)
    {
      const CGAL::Bbox_3 b = box(f);
      extent += (std::max)({b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()});
    }
    extent /= double(faces.size());
    // A quarter of a triangle: the vertices of a relocation move less than that in most
    // iterations, and grown boxes still meet few triangles beyond their neighbours.
    m_margin = 0.25 * extent;
    // About the size of a grown box: a cell then holds a few triangles, a triangle a few cells.
    m_cell = extent + 2 * m_margin;
    if(!(m_cell > 0))
      m_cell = 1;
    m_face_box.assign(nf, Small_box());
    for_each_index(faces.size(), [&](std::size_t i) { m_face_box[std::size_t(faces[i])] = grown_box(faces[i]); });
    grid_entries(faces, true, m_entries, m_start);

    // The pairs of each bucket, each pair in the cell that holds the low corner of the
    // intersection of its boxes (both boxes overlap that cell, so both are listed there). The low
    // corner of the intersection is the largest of the low corners: in a cell both boxes meet, it
    // lies in that cell when on each axis one of the two boxes starts in it. Entries of another
    // cell of the same bucket can only give a pair found elsewhere too. The entries of a bucket
    // come by their low-cell axes: only the groups whose axes cover all three are paired. The
    // boxes of a bucket's entries are copied out first, so that its pairs read one small array.
    collect_by_blocks(m_buckets, m_candidates, [&](std::size_t k, std::vector<Face_pair>& found) {
      const std::size_t first = m_start[k], size = m_start[k + 1] - first;
      boost::container::small_vector<Small_box, 32> listed_box(size);
      for(std::size_t i = 0; i < size; ++i)
        listed_box[i] = m_face_box[std::size_t(m_entries[first + i].face())];
      std::array<std::size_t, 9> group; // the entries of low-cell axes m: [group[m], group[m + 1])
      for(std::size_t m = 0, i = 0; m < 8; ++m)
      {
        group[m] = i;
        while(i < size && m_entries[first + i].low() == m)
          ++i;
      }
      group[8] = size;
      for(int ga = 0; ga < 8; ++ga)
        for(int gb = ga; gb < 8; ++gb)
          if((ga | gb) == 7)
            for(std::size_t i = group[ga]; i < group[ga + 1]; ++i)
              for(std::size_t j = (ga == gb ? i + 1 : group[gb]); j < group[gb + 1]; ++j)
              {
                const Face fi = m_entries[first + i].face(), fj = m_entries[first + j].face();
                if(fi != fj && overlap(listed_box[i], listed_box[j]) && !share_vertex(fi, fj))
                  found.push_back(fi < fj ? Face_pair(fi, fj) : Face_pair(fj, fi));
              }
    });
    // Two cells may share a bucket, and a triangle be listed there twice: a pair can be found
    // more than once.
    sort_pairs(m_candidates);
    m_candidates.erase(std::unique(m_candidates.begin(), m_candidates.end()), m_candidates.end());
    m_candidates.shrink_to_fit();
  }

  // The candidates of the triangles that are new, gone, on other vertices or on a vertex that
  // drifted, found in the grid, which is updated for them; the other candidates stay. A drifted
  // vertex (or a new one) is anchored where it is, and the boxes of its triangles grown again.
  // When many triangles changed, the list is made again.
  void update_candidates()
  {
    const std::size_t nf = m_mesh.num_faces(), nv = m_mesh.num_vertices();
    if(nf < m_triangles.size() || nv < m_anchor.size())
    {
      m_valid = false;
      return;
    }
    std::vector<char> changed(nf, 0);
    std::vector<Face> changed_faces; // those still in the mesh
    const std::size_t number_changed = find_changed_triangles(changed, changed_faces);
    if(number_changed == 0)
      return;
    // Each changed triangle scans its cells; beyond an eighth of them a new grid costs less.
    if(8 * number_changed > nf || !update_grid(changed, changed_faces))
    {
      m_valid = false;
      return;
    }
    update_candidate_pairs(changed, changed_faces);
  }

  // By face, whether it was put on other vertices (when the connectivity changed) or one of its
  // vertices drifted past the margin (those vertices anchored again); the changed faces still in
  // the mesh; the number of changed faces.
  std::size_t find_changed_triangles(std::vector<char>& changed, std::vector<Face>& changed_faces)
  {
    const std::size_t nf = m_mesh.num_faces(), nv = m_mesh.num_vertices();
    grow_by_elements(m_triangles, nf, no_triangle());
    std::size_t number_changed = 0;
    if(m_reconnected)
    {
      for_each_index(nf, [&](std::size_t i) {
        const Face f(static_cast<Face::size_type>(i));
        const std::array<Vertex, 3> t = m_mesh.is_removed(f) ? no_triangle() : face_vertices(m_mesh, f);
        if(t != m_triangles[i])
        {
          changed[i] = 1;
          m_triangles[i] = t;
        }
      });
      for(std::size_t i = 0; i < nf; ++i)
        if(changed[i])
        {
          ++number_changed;
          if(!m_mesh.is_removed(Face(static_cast<Face::size_type>(i))))
            changed_faces.push_back(Face(static_cast<Face::size_type>(i)));
        }
    }
    // Any vertex, not only the touched ones: a caller may have put others back where they were.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    grow_by_elements(m_anchor, nv, {{nan, nan, nan}}); // new vertices have drifted
    std::vector<char> drift(nv, 0);
    for_each_vertex(m_mesh, [&](Vertex v) { drift[std::size_t(v)] = drifted(v); });
    for(Vertex v : m_mesh.vertices())
      if(drift[std::size_t(v)])
      {
        const auto& p = m_mesh.point(v);
        m_anchor[std::size_t(v)] = {{p.x(), p.y(), p.z()}};
        if(m_mesh.halfedge(v) != Work_mesh::null_halfedge())
          for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
            if(!m_mesh.is_border(h) && !changed[std::size_t(m_mesh.face(h))])
            {
              changed[std::size_t(m_mesh.face(h))] = 1;
              ++number_changed;
              changed_faces.push_back(m_mesh.face(h));
            }
      }
    return number_changed;
  }

  // The grid: the entries of changed triangles out, those of their new boxes in, each bucket still
  // by low-cell axes. False, and the grid left as it was, when the buckets would grow too full.
  bool update_grid(const std::vector<char>& changed, const std::vector<Face>& changed_faces)
  {
    grow_by_elements(m_face_box, m_mesh.num_faces());
    for(Face f : changed_faces)
      m_face_box[std::size_t(f)] = grown_box(f);
    std::vector<Entry> added;
    std::vector<std::size_t> added_start;
    grid_entries(changed_faces, false, added, added_start);
    if(m_entries.size() + added.size() > 16 * m_buckets)
      return false;
    std::vector<Entry> merged;
    merged.reserve(m_entries.size() + added.size());
    std::vector<std::size_t> start(m_buckets + 1);
    for(std::size_t b = 0; b < m_buckets; ++b)
    {
      start[b] = merged.size();
      std::size_t i = m_start[b], j = added_start[b];
      for(;;)
      {
        while(i < m_start[b + 1] && changed[std::size_t(m_entries[i].face())])
          ++i;
        const bool old_left = i < m_start[b + 1], added_left = j < added_start[b + 1];
        if(!old_left && !added_left)
          break;
        if(old_left && (!added_left || m_entries[i].low() <= added[j].low()))
          merged.push_back(m_entries[i++]);
        else
          merged.push_back(added[j++]);
      }
    }
    start[m_buckets] = merged.size();
    m_entries.swap(merged);
    m_start.swap(start);
    return true;
  }

  // The candidates: those of unchanged triangles kept, those of changed ones found in the cells of
  // their boxes by the rule of make_candidates(); a pair of two changed triangles from the one of
  // lower index.
  void update_candidate_pairs(const std::vector<char>& changed, const std::vector<Face>& changed_faces)
  {
    m_candidates.erase(std::remove_if(m_candidates.begin(), m_candidates.end(),
                                      [&](const Face_pair& p) {
                                        return changed[std::size_t(p.first)] || changed[std::size_t(p.second)];
                                      }),
                       m_candidates.end());
    std::vector<Face_pair> found;
    collect_by_blocks(changed_faces.size(), found, [&](std::size_t i, std::vector<Face_pair>& out) {
      const Face d = changed_faces[i];
      const Small_box& a = m_face_box[std::size_t(d)];
      for_each_cell(a, [&](const Cell& c, unsigned char low) {
        const std::size_t b = bucket(c);
        for(std::size_t k = m_start[b]; k < m_start[b + 1]; ++k)
        {
          const Face e = m_entries[k].face();
          if((low | m_entries[k].low()) != 7 || e == d || (changed[std::size_t(e)] && e < d))
            continue;
          if(overlap(a, m_face_box[std::size_t(e)]) && !share_vertex(d, e))
            out.push_back(d < e ? Face_pair(d, e) : Face_pair(e, d));
        }
      });
    });
    sort_pairs(found);
    found.erase(std::unique(found.begin(), found.end()), found.end());
    std::vector<Face_pair> all(m_candidates.size() + found.size());
    std::merge(m_candidates.begin(), m_candidates.end(), found.begin(), found.end(), all.begin());
    m_candidates.swap(all);
  }

  // The grid entries of `faces`, from their boxes in m_face_box: one per cell a box overlaps,
  // sorted by bucket and in a bucket by low-cell axes (two stable counting sorts); bucket b's
  // entries are [start[b], start[b + 1]). With `choose_buckets`, the number of buckets is first
  // set to the power of two at or above an eighth of the number of entries.
  void grid_entries(const std::vector<Face>& faces, bool choose_buckets, std::vector<Entry>& entries,
                    std::vector<std::size_t>& start)
  {
    const std::size_t n = faces.size();
    std::vector<std::size_t> offset(n + 1, 0);
    for_each_index(n, [&](std::size_t i) {
      std::size_t cells = 0;
      for_each_cell(m_face_box[std::size_t(faces[i])], [&](const Cell&, unsigned char) { ++cells; });
      offset[i + 1] = cells;
    });
    for(std::size_t i = 0; i < n; ++i)
      offset[i + 1] += offset[i];
    const std::size_t count = offset[n];
    if(choose_buckets)
    {
      // A cell holds some twenty entries: an eighth of them is still more buckets than cells.
      m_buckets = 1;
      while(8 * m_buckets < count)
        m_buckets *= 2;
    }
    struct Cell_entry
    {
      std::uint32_t bucket; // fewer buckets than entries, which are fewer than 2^31
      Entry entry;
    };
    std::vector<Cell_entry> unsorted(count);
    for_each_index(n, [&](std::size_t i) {
      std::size_t k = offset[i];
      for_each_cell(m_face_box[std::size_t(faces[i])], [&](const Cell& c, unsigned char low) {
        unsorted[k++] = Cell_entry{std::uint32_t(bucket(c)), Entry(faces[i], low)};
      });
    });
    offset = std::vector<std::size_t>();
    std::vector<Cell_entry> by_low(count);
    {
      std::array<std::size_t, 9> first{};
      for(const Cell_entry& e : unsorted)
        ++first[e.entry.low() + 1];
      for(int m = 0; m < 8; ++m)
        first[m + 1] += first[m];
      for(const Cell_entry& e : unsorted)
        by_low[first[e.entry.low()]++] = e;
    }
    unsorted = std::vector<Cell_entry>();
    start.assign(m_buckets + 1, 0);
    for(const Cell_entry& e : by_low)
      ++start[e.bucket + 1];
    for(std::size_t b = 0; b < m_buckets; ++b)
      start[b + 1] += start[b];
    entries.resize(count);
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for(const Cell_entry& e : by_low)
      entries[fill[e.bucket]++] = e.entry;
  }

  // The box of f's vertices at their anchors, grown by the margin: it holds f for as long as no
  // vertex drifts farther than the margin.
  Small_box grown_box(Face f) const
  {
    return small_box(m_triangles[std::size_t(f)], [&](Vertex v) { return m_anchor[std::size_t(v)]; }, m_margin);
  }

  // The box of f's vertices where they are.
  Small_box current_box(Face f) const
  {
    return small_box(m_triangles[std::size_t(f)], [&](Vertex v) {
      const auto& p = m_mesh.point(v);
      return std::array<double, 3>{{p.x(), p.y(), p.z()}};
    }, 0.);
  }

  bool share_vertex(Face f, Face g) const
  {
    const std::array<Vertex, 3>& a = m_triangles[std::size_t(f)];
    const std::array<Vertex, 3>& b = m_triangles[std::size_t(g)];
    for(Vertex u : a)
      if(u == b[0] || u == b[1] || u == b[2])
        return true;
    return false;
  }

  static std::array<Vertex, 3> no_triangle()
  {
    return {{Work_mesh::null_vertex(), Work_mesh::null_vertex(), Work_mesh::null_vertex()}};
  }

  Cell cell_of(double x, double y, double z) const
  {
    return {{(long long)std::floor(x / m_cell), (long long)std::floor(y / m_cell), (long long)std::floor(z / m_cell)}};
  }

  // function(c, low) for each cell c the box overlaps; bit a of `low` says whether c is the box's
  // first cell along axis a.
  template <typename Function>
  void for_each_cell(const Small_box& b, const Function& function) const
  {
    const Cell lo = cell_of(b[0], b[1], b[2]), hi = cell_of(b[3], b[4], b[5]);
    Cell c;
    for(c[0] = lo[0]; c[0] <= hi[0]; ++c[0])
      for(c[1] = lo[1]; c[1] <= hi[1]; ++c[1])
        for(c[2] = lo[2]; c[2] <= hi[2]; ++c[2])
          function(c, static_cast<unsigned char>((c[0] == lo[0]) | (c[1] == lo[1]) << 1 | (c[2] == lo[2]) << 2));
  }

  std::size_t bucket(const Cell& c) const
  {
    const std::uint64_t h = std::uint64_t(c[0]) * 73856093u ^ std::uint64_t(c[1]) * 19349663u ^
                            std::uint64_t(c[2]) * 83492791u;
    return std::size_t(h * 0x9E3779B97F4A7C15ull >> 20) & (m_buckets - 1);
  }

  // Where a vertex will be written: the exact tests' points.
  auto output_point() const
  {
    return [this](Vertex v) { return m_output(std::size_t(v), to_vector(m_mesh.point(v))); };
  }

  // The intersecting pairs among the triangles around v with a queried one. When the fan is
  // embedded there are none; otherwise each such pair is tested.
  void fan_pairs(Vertex v, const std::vector<char>& query, std::vector<Face_pair>& found) const
  {
    Vertex_fan fan;
    bool queried = false;
    for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      if(!m_mesh.is_border(h))
      {
        // The face is (source(h), v, target(next(h))).
        fan.push_back({m_mesh.face(h), {{m_mesh.target(m_mesh.next(h)), m_mesh.source(h)}}});
        queried = queried || query[std::size_t(m_mesh.face(h))];
      }
    if(!queried || fan.size() < 2 || is_embedded_fan(output_point(), v, fan))
      return;
    for(std::size_t i = 0; i < fan.size(); ++i)
      for(std::size_t j = i + 1; j < fan.size(); ++j)
      {
        const Face f = fan[i].first, g = fan[j].first;
        if((query[std::size_t(f)] || query[std::size_t(g)]) && intersect(f, g))
          found.push_back(f < g ? Face_pair(f, g) : Face_pair(g, f));
      }
  }

  // Whether triangles f and g share a point they do not share through the mesh.
  bool intersect(Face f, Face g) const
  {
    return triangles_intersect(output_point(), m_triangles[std::size_t(f)], m_triangles[std::size_t(g)]);
  }

  const Work_mesh& m_mesh;
  Output_points m_output;
  bool m_valid = false;                            // the grid and the candidate list exist
  bool m_reconnected = false;                      // triangles changed since they were updated
  double m_margin = 0;                             // how far boxes were grown
  double m_cell = 1;                               // the side of a grid cell
  std::size_t m_buckets = 1;                       // of the grid, a power of two
  std::vector<std::size_t> m_start;                // by bucket: its first entry
  std::vector<Entry> m_entries;                    // by bucket, in a bucket by low-cell axes
  std::vector<Small_box> m_face_box;               // by face: its grown box in the grid
  std::vector<std::array<Vertex, 3> > m_triangles; // by face: its vertices in the grid (or nulls)
  std::vector<std::array<double, 3> > m_anchor;    // by vertex: where its boxes were grown around
  std::vector<Face_pair> m_candidates;             // sorted
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_INTERSECTIONS_H
