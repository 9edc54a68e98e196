// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Section 3.1: vertex splits.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_VERTEX_SPLITS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_VERTEX_SPLITS_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/local_operations.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdlib>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// Section 3.1's vertex splits: a vertex of high valence becomes two, where the split lowers the
// global valence deviation and keeps the worst triangle around it.
class Vertex_splits : public Local_operations
{
public:
  // The valence up to which a vertex split tries every way to cut the ring in two.
  static constexpr std::size_t max_exhaustive_split = 12;

  // The best split of v: its ring (in the order of its incident triangles) is cut at wings i and j;
  // one new vertex takes the ring from i to j, the other from j to i, and both see the wings.
  struct Vertex_split
  {
    int change = 0;
    std::size_t i = 0, j = 0;
    Vector_3d first, second;
  };

  explicit Vertex_splits(const Local_operations& operations) : Local_operations(operations) {}

  // The splits, one pass over the vertices; returns how many were made.
  std::size_t run()
  {
    std::size_t done = 0;
    std::vector<Vertex> todo(m_mesh.vertices().begin(), m_mesh.vertices().end());
    for(Vertex v : todo)
    {
      if(m_mesh.is_removed(v) || !is_free(v) || m_mesh.degree(v) < 7)
        continue;
      const std::vector<Vertex> ring = ring_of(v);
      if(const std::optional<Vertex_split> s = best_split(v, ring))
      {
        split(v, ring, *s);
        ++done;
      }
    }
    return done;
  }

  // The vertices around v, counterclockwise: v's faces are (v, ring[k], ring[k+1]).
  std::vector<Vertex> ring_of(Vertex v) const
  {
    std::vector<Vertex> ring;
    for(Halfedge g : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      ring.push_back(m_mesh.source(g));
    std::reverse(ring.begin(), ring.end());
    return ring;
  }

  // The best split of v, whose ring is `ring` (ring_of(v)), if one lowers the valence deviation
  // and keeps acceptable triangles.
  std::optional<Vertex_split> best_split(Vertex v, const std::vector<Vertex>& ring) const
  {
    const std::size_t n = ring.size();
    for(Vertex r : ring)
    {
      // The fan of v is removed and rebuilt: each ring vertex must keep a triangle of its own.
      const std::size_t faces_of_r = m_mesh.degree(r) - (m_mesh.is_border(r) ? 1 : 0);
      if(is_frozen(r) || faces_of_r < 3)
        return std::nullopt;
    }
    const Vector_3d x = position(v);
    Vector_3d fan = Vector_3d::Zero();
    for(std::size_t k = 0; k < n; ++k)
      fan += area_vector(x, position(ring[k]), position(ring[(k + 1) % n]));
    bool found = false;
    double best_angle = 0;
    Vertex_split best;
    // Every split of a high valence into two sides of valence 6 or more changes the deviation
    // alike, so none could be pruned and a fan of n triangles would cost n^4; above
    // max_exhaustive_split only the near-halves are tried, which also leave the lowest valences.
    const std::size_t first_span = n <= max_exhaustive_split ? 3 : n / 2 - 1;
    const std::size_t last_span = n <= max_exhaustive_split ? n - 3 : (n + 1) / 2 + 1;
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t span = first_span; span <= last_span; ++span)
      {
        const std::size_t j = (i + span) % n;
        const int change = std::abs(int(span) + 2 - 6) + std::abs(int(n - span) + 2 - 6) -
                           std::abs(int(n) - 6) + deviation_change(ring[i], +1) +
                           deviation_change(ring[j], +1);
        if(change >= 0 || (found && change > best.change))
          continue;
        // Each new vertex on the way to the centroid of its side of the ring, as far along as
        // gives the best triangles.
        std::array<Vector_3d, 2> side{{Vector_3d::Zero(), Vector_3d::Zero()}};
        for(std::size_t k = 0; k <= span; ++k)
          side[0] += position(ring[(i + k) % n]);
        for(std::size_t k = 0; k <= n - span; ++k)
          side[1] += position(ring[(j + k) % n]);
        side[0] /= double(span + 1);
        side[1] /= double(n - span + 1);
        for(double along : {0.4, 0.55, 0.7})
        {
          const Vector_3d p = project(x + along * (side[0] - x), v);
          const Vector_3d q = project(x + along * (side[1] - x), v);
          const double smallest = split_smallest_angle(v, ring, i, span, p, q, fan);
          if(!(smallest >= 0))
            continue;
          if(!found || change < best.change || (change == best.change && smallest > best_angle))
          {
            found = true;
            best_angle = smallest;
            best.change = change;
            best.i = i;
            best.j = j;
            best.first = p;
            best.second = q;
          }
        }
      }
    // A split must not make the worst triangle around v worse than it was, unless that one stays
    // above 30 degrees.
    if(found)
    {
      double old_min = pi;
      for(std::size_t k = 0; k < n; ++k)
        old_min = (std::min)(old_min, smallest_angle(x, position(ring[k]), position(ring[(k + 1) % n])));
      found = best_angle >= (std::min)(old_min, 30 * pi / 180) && keeps_distance_bound_after(v, ring, best);
    }
    return found ? std::optional<Vertex_split>(best) : std::nullopt;
  }

private:
  // Whether splitting v as s keeps the distance bound (Local_operations::keeps_distance_bound()).
  bool keeps_distance_bound_after(Vertex v, const std::vector<Vertex>& ring, const Vertex_split& s) const
  {
    const std::size_t n = ring.size(), span = (s.j + n - s.i) % n;
    boost::container::small_vector<Face, 16> fan;
    for(Halfedge g : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      if(!m_mesh.is_border(g))
        fan.push_back(m_mesh.face(g));
    std::vector<Triangle_3d> created;
    for(std::size_t k = 0; k < span; ++k)
      created.push_back(Triangle_3d{{s.first, position(ring[(s.i + k) % n]), position(ring[(s.i + k + 1) % n])}});
    for(std::size_t k = 0; k < n - span; ++k)
      created.push_back(Triangle_3d{{s.second, position(ring[(s.j + k) % n]), position(ring[(s.j + k + 1) % n])}});
    created.push_back(Triangle_3d{{s.first, position(ring[s.j]), s.second}});
    created.push_back(Triangle_3d{{s.second, position(ring[s.i]), s.first}});
    return keeps_distance_bound(fan, created);
  }

  // The smallest angle of the triangles that split v into p, fanned to ring[i] .. ring[i + span],
  // and q, fanned to the rest of the ring, or -1 when one of them is not acceptable (`fan` is the
  // area vector of v's fan).
  double split_smallest_angle(Vertex v, const std::vector<Vertex>& ring, std::size_t i, std::size_t span,
                              const Vector_3d& p, const Vector_3d& q, const Vector_3d& fan) const
  {
    const std::size_t n = ring.size(), j = (i + span) % n;
    double smallest = pi;
    bool ok = true;
    auto check = [&](const Vector_3d& u, const Vector_3d& w, const Vector_3d& z) {
      ok = ok && acceptable(u, w, z, v, fan);
      if(ok)
        smallest = (std::min)(smallest, smallest_angle(u, w, z));
    };
    for(std::size_t k = 0; k < span; ++k)
      check(p, position(ring[(i + k) % n]), position(ring[(i + k + 1) % n]));
    for(std::size_t k = 0; k < n - span; ++k)
      check(q, position(ring[(j + k) % n]), position(ring[(j + k + 1) % n]));
    check(p, position(ring[j]), q);
    check(q, position(ring[i]), p);
    return ok ? smallest : -1;
  }

  // Replaces v by the two vertices of s; `ring` is v's (ring_of(v)).
  void split(Vertex v, const std::vector<Vertex>& ring, const Vertex_split& s)
  {
    const std::size_t n = ring.size();
    const Vertex_kind kind = m_state.kind[std::size_t(v)];
    const Face hint = m_state.vertex_hint[std::size_t(v)];
    const Vertex closest = m_state.closest[std::size_t(v)];
    // The ring's edges outlive the fan unless they are on the border: then removing the fan
    // removes them, and the slots they come back in must get their flags again.
    std::vector<std::pair<char, Face> > ring_edge(n);
    for(std::size_t k = 0; k < n; ++k)
    {
      const Edge r = m_mesh.edge(m_mesh.halfedge(ring[k], ring[(k + 1) % n]));
      ring_edge[k] = {m_state.feature_edge[std::size_t(r)], m_state.edge_hint[std::size_t(r)]};
    }
    // Remove the fan around v and triangulate the hole with the two new vertices.
    std::vector<Face> fan;
    for(Halfedge g : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      fan.push_back(m_mesh.face(g));
    for(Face f : fan)
      CGAL::Euler::remove_face(m_mesh.halfedge(f), m_mesh);
    const Vertex p = m_mesh.add_vertex(Work_kernel::Point_3(s.first.x(), s.first.y(), s.first.z()));
    const Vertex q = m_mesh.add_vertex(Work_kernel::Point_3(s.second.x(), s.second.y(), s.second.z()));
    m_state.fit(m_mesh);
    for(Vertex w : {p, q})
    {
      m_state.kind[std::size_t(w)] = kind;
      m_state.closest[std::size_t(w)] = closest;
      m_state.vertex_hint[std::size_t(w)] = hint;
    }
    const std::size_t span = (s.j + n - s.i) % n;
    auto add = [&](Vertex u, Vertex w, Vertex z) {
      const Face f = m_mesh.add_face(u, w, z);
      CGAL_assertion(f != Work_mesh::null_face());
      m_state.fit(m_mesh);
      m_state.face_hint[std::size_t(f)] = hint;
    };
    for(std::size_t k = 0; k < span; ++k)
      add(p, ring[(s.i + k) % n], ring[(s.i + k + 1) % n]);
    for(std::size_t k = 0; k < n - span; ++k)
      add(q, ring[(s.j + k) % n], ring[(s.j + k + 1) % n]);
    add(p, ring[s.j], q);
    add(q, ring[s.i], p);
    for(std::size_t k = 0; k < n; ++k)
    {
      const Edge r = m_mesh.edge(m_mesh.halfedge(ring[k], ring[(k + 1) % n]));
      std::tie(m_state.feature_edge[std::size_t(r)], m_state.edge_hint[std::size_t(r)]) = ring_edge[k];
    }
    for(Halfedge g : halfedges_around_target(m_mesh.halfedge(p), m_mesh))
      m_state.feature_edge[std::size_t(m_mesh.edge(g))] = 0;
    for(Halfedge g : halfedges_around_target(m_mesh.halfedge(q), m_mesh))
      m_state.feature_edge[std::size_t(m_mesh.edge(g))] = 0;
    bind_new_vertex(p, p);
    bind_new_vertex(q, q);
  }
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_VERTEX_SPLITS_H
