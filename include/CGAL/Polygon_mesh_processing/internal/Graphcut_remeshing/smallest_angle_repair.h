// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Beyond the paper: once the relocation is over, the triangles with a small angle are worked on,
// worst first, by local operations that raise the smallest angle around them.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_SMALLEST_ANGLE_REPAIR_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_SMALLEST_ANGLE_REPAIR_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/edge_collapses.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/edge_flips.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/edge_queue.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/local_operations.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// The triangles with an angle below `poor_angle`, worst first: a flip of one of their edges (which
// may leave a border vertex with one triangle) or a collapse of one (as the re-sampling collapses
// do, along its line for a feature edge, and also a free end into a vertex on a line or a corner,
// which the re-sampling at the input's density does not make), whichever leaves the larger
// smallest angle; then a move of their free vertices towards the centroid of
// their neighbours or towards the apex that would make their worst triangle equilateral, in the
// tangent plane and onto the reference, and a slide of their vertices on feature lines towards
// the middle of their line neighbours. An operation is taken only when
// it raises the smallest angle of the triangles it changes, so the worst triangle never gets
// worse, and with the checks of its kind: acceptable triangles, no fold, within the sizing
// tolerance of the reference. New self-intersections are the pass's to check
// (Graphcut_remesher::safe_pass()).
class Smallest_angle_repair : public Local_operations
{
public:
  static constexpr double poor_angle = 30 * pi / 180;

  Smallest_angle_repair(const Local_operations& operations, bool flip, bool collapse, bool move)
    : Local_operations(operations), m_flip(flip), m_collapse(collapse), m_move(move)
  {}

  struct Counts
  {
    std::size_t flips = 0;
    std::size_t collapses = 0;
    std::size_t moves = 0;
  };

  Counts run()
  {
    Counts counts;
    run_edge_queue(m_mesh, [this](Edge e) { return plan(e); },
                   [this, &counts](Edge e, const Plan& p) {
                     ++(p.flip ? counts.flips : counts.collapses);
                     return p.flip ? Edge_flips(*this).flip(e) : Edge_collapses(*this).collapse_and_touch(e, p.collapse);
                   });
    if(m_move)
      counts.moves = move_vertices();
    return counts;
  }

private:
  // The least growth of the smallest angle that counts (as for the flips).
  static constexpr double margin = Edge_flips::min_angle_margin;

  struct Plan
  {
    double gain = 0; // pi less the smallest angle of e's triangles: the worst first
    bool flip = false;
    Collapse collapse;
  };

  // The operation on e, a side of a triangle with a small angle, that leaves the larger smallest
  // angle, if it raises the smallest angle of the triangles it changes.
  Plan plan(Edge e) const
  {
    const double on_e = smallest_angle_on(e);
    if(!(on_e < poor_angle))
      return Plan();
    Plan p;
    double best = -1;
    if(m_flip && Edge_flips(*this).flippable(e, true))
    {
      const double flipped = Edge_flips(*this).flipped_smallest_angle(e);
      if(flipped > on_e + margin)
      {
        best = flipped;
        p.flip = true;
      }
    }
    Collapse c;
    double collapsed = -1;
    const Halfedge h = m_mesh.halfedge(e);
    const double least_angle = (std::max)(best, smallest_angle_around(m_mesh.source(h), m_mesh.target(h)) + margin);
    if(m_collapse && Edge_collapses(*this).best_collapse(e, c, collapsed, least_angle, true) && collapsed > least_angle)
    {
      best = collapsed;
      p.flip = false;
      p.collapse = c;
    }
    if(best < 0)
      return Plan();
    p.gain = pi - on_e;
    return p;
  }

  // The smallest angle of the triangles on e.
  double smallest_angle_on(Edge e) const
  {
    double smallest = pi;
    for(Halfedge g : {m_mesh.halfedge(e), m_mesh.opposite(m_mesh.halfedge(e))})
      if(!m_mesh.is_border(g))
        smallest = (std::min)(smallest, smallest_angle(position(m_mesh.source(g)), position(m_mesh.target(g)),
                                                       position(m_mesh.target(m_mesh.next(g)))));
    return smallest;
  }

  // The free vertices and the vertices sliding on a feature line with a small angle around them,
  // worst first, each moved once when that pays.
  std::size_t move_vertices()
  {
    std::vector<std::pair<double, Vertex> > worst;
    for(Vertex v : m_mesh.vertices())
      if(is_free(v) || m_state.kind[std::size_t(v)] == Vertex_kind::feature_vertex)
      {
        const double s = smallest_angle_around(v, v);
        if(s < poor_angle)
          worst.emplace_back(s, v);
      }
    std::sort(worst.begin(), worst.end());
    std::size_t moved = 0;
    for(const auto& w : worst)
      moved += (is_free(w.second) ? move_vertex(w.second) : slide_vertex(w.second)) ? 1 : 0;
    return moved;
  }

  // v, sliding on a feature line between its neighbours a and b along it, to the point of the line
  // halfway between them or half the way there (the relocation can slide a vertex up to a corner,
  // where a collapse would make a line edge too long): the one that raises the smallest angle
  // around v most, if one does, with both line edges within the tolerance of the line.
  bool slide_vertex(Vertex v)
  {
    if(!m_polylines)
      return false;
    Vertex ends[2];
    std::size_t degree = 0;
    boost::container::small_vector<Halfedge, 16> link; // on each triangle, the side facing v
    for(Halfedge g : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
    {
      const char feature = m_state.feature_edge[std::size_t(m_mesh.edge(g))];
      if(feature == constrained_feature_edge || (feature && degree == 2))
        return false;
      if(feature)
        ends[degree++] = m_mesh.source(g);
      if(!m_mesh.is_border(g))
        link.push_back(m_mesh.prev(g));
    }
    if(degree != 2)
      return false;
    const Vector_3d x = position(v);
    const Location middle = feature_midpoint(ends[0], ends[1]);
    const Location halfway = m_polylines->move(feature_location(v), (m_polylines->point(middle) - x) / 2);
    double best = smallest_angle_around(v, v) + margin;
    const std::size_t poor = poor_triangles(link, x);
    std::optional<Location> best_location;
    for(const Location& l : {middle, halfway})
    {
      const Vector_3d y = m_polylines->point(l);
      bool on_line = true;
      for(Vertex end : ends)
      {
        const double chord = (y - position(end)).norm(), target = edge_length_target(v, end);
        on_line = on_line && !Sizing_field::is_too_long(chord, target) &&
                  m_polylines->chord_deviation(l, feature_location(end), 2 * chord) <= m_sizing.tolerance_for(chord, target);
      }
      const double smallest = on_line ? smallest_angle_after_move(link, x, y, v, poor) : -1;
      if(smallest > best && fan_unfolded(link, y, {v}) && move_keeps_distance_bound(v, y))
      {
        best = smallest;
        best_location = l;
      }
    }
    if(!best_location)
      return false;
    const Vector_3d y = m_polylines->point(*best_location);
    m_mesh.point(v) = Work_kernel::Point_3(y.x(), y.y(), y.z());
    m_state.location[std::size_t(v)] = *best_location;
    bind_new_vertex(v, v, Vertex_kind::feature_vertex);
    track_faces_from(v);
    return true;
  }

  // How many triangles of `link` (their sides facing v) are below poor_angle with v at x.
  std::size_t poor_triangles(const boost::container::small_vector<Halfedge, 16>& link, const Vector_3d& x) const
  {
    std::size_t poor = 0;
    for(Halfedge g : link)
      poor += smallest_angle(position(m_mesh.source(g)), position(m_mesh.target(g)), x) < poor_angle ? 1 : 0;
    return poor;
  }

  // The smallest angle of the triangles of `link` (their sides facing v) once v moves from x to y,
  // or -1 when one of them turns (against its own normal, and against `normal` when one is given),
  // leaves the reference by more than the tolerance, or when more of them than `poor` fall below
  // poor_angle.
  double smallest_angle_after_move(const boost::container::small_vector<Halfedge, 16>& link, const Vector_3d& x,
                                   const Vector_3d& y, Vertex v, std::size_t poor,
                                   const std::optional<Vector_3d>& normal = std::nullopt) const
  {
    double smallest = pi;
    std::size_t poor_after = 0;
    for(Halfedge g : link)
    {
      const Vector_3d p = position(m_mesh.source(g)), q = position(m_mesh.target(g));
      if(!is_acceptable_triangle(p, q, y, area_vector(p, q, x), min_turn_cosine) ||
         (normal && !is_acceptable_triangle(p, q, y, *normal)) ||
         distance_to_reference((p + q + y) / 3, v) > m_sizing.tolerance)
        return -1;
      const double s = smallest_angle(p, q, y);
      smallest = (std::min)(smallest, s);
      poor_after += s < poor_angle ? 1 : 0;
    }
    return poor_after <= poor ? smallest : -1;
  }

  // v towards the centroid of its neighbours or the apex of the equilateral triangle on the far side
  // of its worst triangle, all the way or half of it, in its tangent plane and then onto the
  // reference: the one that raises the smallest angle around v most, if one does.
  bool move_vertex(Vertex v)
  {
    const Vector_3d x = position(v);
    boost::container::small_vector<Halfedge, 16> link; // on each triangle, the side facing v
    Vector_3d centroid(0, 0, 0);
    for(Halfedge g : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
    {
      if(m_mesh.is_border(g))
        return false;
      link.push_back(m_mesh.prev(g));
      centroid += position(m_mesh.source(g));
    }
    centroid /= double(link.size());
    // The apex of the equilateral triangle on the side facing v of v's worst triangle.
    Halfedge worst = link.front();
    for(Halfedge g : link)
      if(smallest_angle(position(m_mesh.source(g)), position(m_mesh.target(g)), x) <
         smallest_angle(position(m_mesh.source(worst)), position(m_mesh.target(worst)), x))
        worst = g;
    const Vector_3d a = position(m_mesh.source(worst)), b = position(m_mesh.target(worst));
    const Vector_3d side = b - a, up = area_vector(a, b, x);
    const Vector_3d apex = (a + b) / 2 + (std::sqrt(3.0) / 2) * side.norm() * up.cross(side).normalized();
    const Vector_3d normal = m_reference.frame(m_state.closest[std::size_t(v)]).normal;
    double best = smallest_angle_around(v, v) + margin;
    const std::size_t poor = poor_triangles(link, x); // a move may not make more
    Vector_3d best_y = x;
    for(const Vector_3d& target : {centroid, Vector_3d((x + centroid) / 2), apex, Vector_3d((x + apex) / 2)})
    {
      Face hint = m_state.vertex_hint[std::size_t(v)];
      const Vector_3d y = m_reference.closest_point(x + tangential(target - x, normal), hint);
      const double smallest = smallest_angle_after_move(link, x, y, v, poor, m_reference.normal(hint));
      if(smallest > best && fan_unfolded(link, y, {v}) && move_keeps_distance_bound(v, y))
      {
        best = smallest;
        best_y = y;
      }
    }
    if(best_y == x)
      return false;
    m_mesh.point(v) = Work_kernel::Point_3(best_y.x(), best_y.y(), best_y.z());
    bind_new_vertex(v, v);
    track_faces_from(v);
    return true;
  }

  bool m_flip, m_collapse, m_move;
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_SMALLEST_ANGLE_REPAIR_H
