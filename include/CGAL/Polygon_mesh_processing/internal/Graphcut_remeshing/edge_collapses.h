// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Section 3.1 and re-sampling: collapses of short edges.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_EDGE_COLLAPSES_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_EDGE_COLLAPSES_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/edge_queue.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/feature_line_collapses.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/local_operations.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <optional>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// Collapses of short edges. The paper's (section 3.1) only in flat regions, when the smallest
// angle grows; with a re-sampling sizing, every edge shorter than its target allows, also where the
// surface is curved and along feature lines (feature_line_collapses.h), as long as the new
// triangles stay near the reference.
class Edge_collapses : public Local_operations
{
public:
  // Collapses only of edges whose dihedral angle is below this, in degrees (section 3.1).
  static constexpr double flat_dihedral = 10;

  struct Plan
  {
    double gain = 0;
    Collapse collapse;
  };

  explicit Edge_collapses(const Local_operations& operations) : Local_operations(operations) {}

  // The collapses, best gain first; returns how many were made.
  std::size_t run()
  {
    if(m_sizing.resamples())
      return run_edge_queue(m_mesh, [this](Edge e) { return resampling_plan(e); },
                            [this](Edge e, const Plan& plan) { return collapse_and_touch(e, plan.collapse); },
                            [this](Edge e) { return resampling_gain_bound(e); });
    return run_edge_queue(m_mesh, [this](Edge e) { return flat_plan(e); },
                          [this](Edge e, const Plan& plan) { return flat_collapse(e, plan.collapse.point); });
  }

  // Section 3.1: a short edge in a flat region is collapsed when the smallest angle around it grows
  // and the valence gets more regular.
  Plan flat_plan(Edge e) const
  {
    Plan plan;
    const Halfedge h = m_mesh.halfedge(e), o = m_mesh.opposite(h);
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
    if(!is_free(a) || !is_free(b) || m_mesh.is_border(e))
      return Plan();
    const Vertex c = m_mesh.target(m_mesh.next(h)), d = m_mesh.target(m_mesh.next(o));
    const Vector_3d pa = position(a), pb = position(b);
    if(!Sizing_field::is_too_short((pa - pb).norm(), edge_length_target(a, b)))
      return Plan();
    if(m_mesh.degree(c) < 4 || m_mesh.degree(d) < 4)
      return Plan();
    const int merged = int(m_mesh.degree(a) + m_mesh.degree(b)) - 4;
    const int change = std::abs(merged - 6) - std::abs(int(m_mesh.degree(a)) - 6) -
                       std::abs(int(m_mesh.degree(b)) - 6) + deviation_change(c, -1) +
                       deviation_change(d, -1);
    if(change >= 0 || merged < 4)
      return Plan();
    if(!(dihedral_angle(m_mesh, e) < flat_dihedral))
      return Plan();
    if(!CGAL::Euler::does_satisfy_link_condition(e, m_mesh))
      return Plan();
    // The triangles that stay, around a and b, before and after; the merged vertex goes to a, b
    // or the midpoint brought onto the reference, whichever gives the largest smallest angle.
    const double old_min = smallest_angle_around(a, b);
    plan.gain = -1;
    for(const Vector_3d& x : {pa, pb, project((pa + pb) / 2, a)})
    {
      double new_min = pi;
      bool ok = true;
      for(Vertex u : {a, b})
        for(Halfedge g : halfedges_around_target(m_mesh.halfedge(u), m_mesh))
        {
          const Vertex p = m_mesh.source(g), q = m_mesh.target(m_mesh.next(g));
          if(p == a || p == b || q == a || q == b)
            continue; // one of the two triangles that disappear
          if(!acceptable(x, position(q), position(p), u, area_vector(position(u), position(q), position(p))))
          {
            ok = false;
            break;
          }
          new_min = (std::min)(new_min, smallest_angle(x, position(q), position(p)));
        }
      if(ok && new_min - old_min > plan.gain && collapse_keeps_distance_bound(a, b, x))
      {
        plan.gain = new_min - old_min;
        plan.collapse = Collapse{a, b, x};
      }
    }
    return plan;
  }

  // Re-sampling: an edge shorter than its target allows is collapsed, the shortest for its target
  // first, as best_collapse() says, when the new triangles are at most twice as thin as the old.
  Plan resampling_plan(Edge e) const
  {
    const double gain = resampling_gain_bound(e);
    if(!(gain > 0))
      return Plan();
    const Halfedge h = m_mesh.halfedge(e);
    double smallest = -1;
    Plan plan;
    if(!best_collapse(e, plan.collapse, smallest, 0.5 * smallest_angle_around(m_mesh.source(h), m_mesh.target(h)),
                      m_sizing.into_lines))
      return Plan();
    plan.gain = gain;
    return plan;
  }

  // The gain resampling_plan(e) has when e may be collapsed, from its length alone.
  double resampling_gain_bound(Edge e) const
  {
    const Halfedge h = m_mesh.halfedge(e);
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
    const double length = (position(a) - position(b)).norm(), target = edge_length_target(a, b);
    return Sizing_field::is_too_short(length, target) ? Sizing_field::shortfall(length, target) : 0.;
  }

  // The way to collapse e that keeps the best triangles, and the smallest angle of its triangles;
  // false when e may not be collapsed (a constrained or frozen edge, a vertex that would lose too
  // many edges, two feature edges merging, a link condition broken, no acceptable way with no
  // angle below `least_angle`). With `free_into_lines`, a free edge with one end on a feature line or
  // fixed may collapse into that end.
  bool best_collapse(Edge e, Collapse& best, double& smallest, double least_angle, bool free_into_lines) const
  {
    const char feature = m_state.feature_edge[std::size_t(e)];
    const Halfedge h = m_mesh.halfedge(e);
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
    if(feature == constrained_feature_edge || is_frozen(a) || is_frozen(b))
      return false;
    const Vector_3d pa = position(a), pb = position(b);
    // A free edge with one end on a feature line or fixed: the free end goes to the other, which
    // stays where it is. A coarse target needs these collapses (without them the lines'
    // neighbours hold their vertices); at the input's density the re-sampling's would only thin
    // the triangles next to the lines (the manual, "A Density and a Region").
    const bool into_feature = free_into_lines && !feature && is_free(a) != is_free(b);
    // The ways to collapse e: where the kept vertex goes.
    boost::container::small_vector<Collapse, 3> trials;
    if(into_feature)
      trials.push_back(is_free(a) ? Collapse{a, b, pb} : Collapse{b, a, pa});
    else if(feature)
    {
      const Feature_line_collapses line(*this);
      std::optional<Collapse> f;
      if(m_polylines && (f = line.removing_an_end(e)))
        trials.push_back(*f);
      if(m_sizing.into_lines && m_polylines && (f = line.to_the_midpoint(e)))
        trials.push_back(*f);
    }
    else if(!(is_free(a) && is_free(b)))
      return false;
    if(feature && trials.empty())
      return false;
    // The triangles on e go; their far vertices keep three edges (two on a border, where one
    // triangle is enough, when the user asked for a density: a strip two triangles wide is made
    // of such vertices), and no two feature edges merge (the free end of a collapse into a line
    // has none). When the user asked for a density, a feature edge's triangle may have one
    // feature edge beside it, which the merged edge carries on: a line leaving a corner next to a
    // short segment (without it such segments stay, shorter than half their target), or the next
    // segment of the line at an ear.
    for(Halfedge g : {h, m_mesh.opposite(h)})
      if(!m_mesh.is_border(g))
      {
        const int wings = (m_state.feature_edge[std::size_t(m_mesh.edge(m_mesh.next(g)))] ? 1 : 0) +
                          (m_state.feature_edge[std::size_t(m_mesh.edge(m_mesh.prev(g)))] ? 1 : 0);
        const Vertex far = m_mesh.target(m_mesh.next(g));
        if(m_mesh.degree(far) < (m_sizing.into_lines && m_mesh.is_border(far) ? 3u : 4u) ||
           (!into_feature && wings > (m_sizing.into_lines && feature ? 1 : 0)))
          return false;
      }
    if(!CGAL::Euler::does_satisfy_link_condition(e, m_mesh))
      return false;
    if(trials.empty())
      // A free edge becomes its end or its midpoint on the reference.
      for(const Vector_3d& p : {pb, pa, project((pa + pb) / 2, a)})
        trials.push_back(Collapse{a, b, p});
    smallest = -1;
    for(const Collapse& trial : trials)
    {
      const double s = collapsed_smallest_angle(trial, least_angle);
      if(s > smallest)
      {
        smallest = s;
        best = trial;
      }
    }
    return smallest >= 0;
  }


  // Collapses e as c says: c.kept keeps its index (a corner or a user's vertex is found by it).
  Vertex collapse(Edge e, const Collapse& c)
  {
    if(m_mesh.target(m_mesh.halfedge(e)) != c.kept)
    {
      // collapse_edge keeps the target of e's halfedge: the two vertices trade their
      // connectivity first (not their points nor their state), which makes c.kept that target.
      Vertex kept = c.kept, removed = c.removed;
      CGAL::internal::swap_vertices(kept, removed, m_mesh);
    }
    // The two edges of a triangle on e merge into one. Euler::collapse_edge keeps the kept
    // vertex's on the side of e's halfedge and the removed vertex's on the other side, so a
    // feature edge beside e (the kept vertex's, where a free end collapses into a line, or the
    // removed vertex's, where a feature edge collapses beside another line) may lose its index:
    // the merged edge takes its flag and hint.
    struct Wing
    {
      Vertex far;
      Edge feature;
    };
    boost::container::small_vector<Wing, 2> wings;
    for(Halfedge g : {m_mesh.halfedge(e), m_mesh.opposite(m_mesh.halfedge(e))})
      if(!m_mesh.is_border(g))
        for(Halfedge w : {m_mesh.next(g), m_mesh.prev(g)})
          if(m_state.feature_edge[std::size_t(m_mesh.edge(w))])
            wings.push_back(Wing{m_mesh.target(m_mesh.next(g)), m_mesh.edge(w)});
    const Vertex v = CGAL::Euler::collapse_edge(e, m_mesh);
    CGAL_assertion(v == c.kept);
    for(const Wing& wing : wings)
    {
      const Halfedge merged = m_mesh.halfedge(wing.far, v);
      CGAL_assertion(merged != Work_mesh::null_halfedge());
      m_state.feature_edge[std::size_t(m_mesh.edge(merged))] = m_state.feature_edge[std::size_t(wing.feature)];
      m_state.edge_hint[std::size_t(m_mesh.edge(merged))] = m_state.edge_hint[std::size_t(wing.feature)];
    }
    m_mesh.point(v) = Work_kernel::Point_3(c.point.x(), c.point.y(), c.point.z());
    if(c.to_line_midpoint)
    {
      m_state.location[std::size_t(v)] = c.on_line;
      bind_new_vertex(v, v, Vertex_kind::feature_vertex);
    }
    else if(is_free(v))
      bind_new_vertex(v, v);
    track_faces_from(v);
    return v;
  }

  // Collapses e as c says; returns the kept vertex and its neighbours.
  std::vector<Vertex> collapse_and_touch(Edge e, const Collapse& c)
  {
    const Vertex v = collapse(e, c);
    std::vector<Vertex> touched{v};
    for(Vertex w : vertices_around_target(m_mesh.halfedge(v), m_mesh))
      touched.push_back(w);
    return touched;
  }

private:
  std::vector<Vertex> flat_collapse(Edge e, const Vector_3d& p)
  {
    const Vertex v = CGAL::Euler::collapse_edge(e, m_mesh);
    m_mesh.point(v) = Work_kernel::Point_3(p.x(), p.y(), p.z());
    bind_new_vertex(v, v);
    std::vector<Vertex> touched{v};
    for(Halfedge g : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
    {
      touched.push_back(m_mesh.source(g));
      m_state.face_hint[std::size_t(m_mesh.face(g))] = m_state.vertex_hint[std::size_t(v)];
    }
    return touched;
  }

  // The smallest angle of the triangles around c.removed and c.kept that stay, with both at
  // c.point, or -1 when one of them has an angle below `least_angle` (no use to the caller), is not
  // acceptable, leaves the reference by more than the tolerance or has an edge longer than 4/3 of
  // its target (a split would undo the collapse). When the user asked for a length (whose
  // tolerance grows with the triangles, see m_sizing.tolerance_for()), the removed vertex, and the
  // kept one where it was when it moves, must also stay within the tolerance of one of the new
  // triangles: their centroids alone may keep near the surface while a tip or a rim between them
  // is cut off. The tests on the triangles alone come first, those that search the reference last.
  double collapsed_smallest_angle(const Collapse& c, double least_angle) const
  {
    struct New_triangle
    {
      Vertex around;
      Vector_3d p, q;
      double allowed;
    };
    boost::container::small_vector<New_triangle, 16> fan;
    boost::container::small_vector<Halfedge, 16> link;
    double smallest = pi;
    for(Vertex u : {c.removed, c.kept})
      for(Halfedge g : halfedges_around_target(m_mesh.halfedge(u), m_mesh))
      {
        if(m_mesh.is_border(g))
          continue;
        const Vertex p = m_mesh.source(g), q = m_mesh.target(m_mesh.next(g));
        if(p == c.removed || p == c.kept || q == c.removed || q == c.kept)
          continue; // one of the triangles that disappear
        link.push_back(m_mesh.prev(g));
        const Vector_3d pp = position(p), pq = position(q);
        const double target = edge_length_target(c.kept, p);
        const double longest = (std::max)({(c.point - pp).norm(), (c.point - pq).norm(), (pp - pq).norm()});
        const double angle = smallest_angle(c.point, pq, pp);
        if(angle < least_angle || Sizing_field::is_too_long((c.point - pp).norm(), target) ||
           !is_acceptable_triangle(c.point, pq, pp, area_vector(position(u), pq, pp), min_turn_cosine))
          return -1;
        smallest = (std::min)(smallest, angle);
        fan.push_back(New_triangle{u, pp, pq, m_sizing.tolerance_for(longest, target)});
      }
    if(!fan_unfolded(link, c.point, {c.removed, c.kept}))
      return -1;
    const Vector_3d gone = position(c.removed), was = position(c.kept);
    bool gone_covered = !m_sizing.target_asked_for, was_covered = !m_sizing.target_asked_for || was == c.point;
    for(const New_triangle& t : fan)
    {
      // Turned over or not, by the reference around the triangle's own vertex; its distance, from
      // the kept vertex's (the same search when that is the vertex).
      double centroid_distance;
      if(!faces_reference(c.point, t.q, t.p, t.around, centroid_distance))
        return -1;
      if(t.around != c.kept)
        centroid_distance = distance_to_reference((c.point + t.q + t.p) / 3, c.kept);
      if(centroid_distance > t.allowed)
        return -1;
      std::array<double, 3> barycentric;
      gone_covered = gone_covered || (gone - closest_point_on_triangle(gone, c.point, t.q, t.p, barycentric)).norm() <= t.allowed;
      was_covered = was_covered || (was - closest_point_on_triangle(was, c.point, t.q, t.p, barycentric)).norm() <= t.allowed;
    }
    if(!gone_covered || !was_covered || !collapse_keeps_distance_bound(c.removed, c.kept, c.point))
      return -1;
    return smallest;
  }
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_EDGE_COLLAPSES_H
