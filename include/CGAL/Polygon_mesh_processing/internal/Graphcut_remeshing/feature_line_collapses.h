// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Re-sampling: collapses along feature lines.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_FEATURE_LINE_COLLAPSES_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_FEATURE_LINE_COLLAPSES_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/local_operations.h>

#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// A collapse of an edge: `removed` goes, `kept` keeps its index and moves to `point`.
struct Collapse
{
  Work_mesh::Vertex_index removed, kept;
  Vector_3d point;
  bool to_line_midpoint = false; // the kept vertex slides to `on_line`, the point of its line
  Feature_polylines<Work_mesh>::Location on_line{};
};

// The re-sampling collapses of feature edges (edge_collapses.h asks for them): a feature line is
// shortened by one vertex where it runs on, within the tolerance of its reference polyline.
class Feature_line_collapses : public Local_operations
{
public:
  explicit Feature_line_collapses(const Local_operations& operations) : Local_operations(operations) {}

  // A feature edge shortens its line by removing an end that slides on it, where the line runs
  // on: the end has no other feature edge than the next one along, the line turns there by less
  // than the corner angle, and the shortened line keeps within the tolerance of the reference
  // polyline between its ends.
  std::optional<Collapse> removing_an_end(Edge e) const
  {
    const double min_cosine = std::cos(m_sizing.corner_angle * pi / 180);
    const Halfedge h = m_mesh.halfedge(e);
    double best = min_cosine;
    std::optional<Collapse> found;
    for(const auto& ends : {std::make_pair(m_mesh.source(h), m_mesh.target(h)),
                            std::make_pair(m_mesh.target(h), m_mesh.source(h))})
    {
      const Vertex r = ends.first, k = ends.second;
      Vertex x;
      if(m_state.kind[std::size_t(r)] != Vertex_kind::feature_vertex || feature_degree(r, e, x) != 2 || x == k)
        continue;
      // A user's constrained edge keeps its ends.
      if(m_state.feature_edge[std::size_t(m_mesh.edge(m_mesh.halfedge(r, x)))] == constrained_feature_edge)
        continue;
      const Vector_3d pr = position(r), pk = position(k), px = position(x);
      const double turn = (pr - pk).normalized().dot((px - pr).normalized());
      if(!(turn > best) || Sizing_field::is_too_long((pk - px).norm(), edge_length_target(k, x)))
        continue;
      if(!(m_polylines->chord_deviation(feature_location(k), feature_location(x), 2 * (pk - px).norm()) <=
           m_sizing.tolerance_for((pk - px).norm(), edge_length_target(k, x))))
        continue;
      best = turn;
      found = Collapse{r, k, pk};
    }
    return found;
  }

  // A feature edge whose two ends both slide on the line also shortens it by one vertex when the
  // kept end moves to the point of the line halfway between them: the two edges beside it then
  // share its length. Removing an end alone merges two edges, which cannot shorten a line whose
  // edges are all about 2/3 of their target (their sum is beyond 4/3 of it). Both ends must be
  // turns below the corner angle, and both new chords are at most 4/3 of their target and keep
  // within the tolerance of the line. Only when the user asked for a density, as the collapses
  // into lines.
  std::optional<Collapse> to_the_midpoint(Edge e) const
  {
    const double min_cosine = std::cos(m_sizing.corner_angle * pi / 180);
    const Halfedge h = m_mesh.halfedge(e);
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
    Vertex xa = a, xb = b;
    for(Vertex v : {a, b})
      if(m_state.kind[std::size_t(v)] != Vertex_kind::feature_vertex)
        return std::nullopt;
    if(feature_degree(a, e, xa) != 2 || feature_degree(b, e, xb) != 2 || xa == b || xb == a || xa == xb)
      return std::nullopt;
    const Vector_3d pa = position(a), pb = position(b), pxa = position(xa), pxb = position(xb);
    if(!((pa - pxa).normalized().dot((pb - pa).normalized()) > min_cosine) ||
       !((pb - pa).normalized().dot((pxb - pb).normalized()) > min_cosine))
      return std::nullopt;
    // As for a split of a sharp edge: the polyline between a and b may be far from straight, and
    // the point must still fall well inside the segment's span.
    const Location middle = feature_midpoint(a, b);
    const Vector_3d pm = m_polylines->point(middle);
    const double length = (pa - pb).norm();
    if(!((pm - pa).norm() > length / 4 && (pm - pb).norm() > length / 4))
      return std::nullopt;
    for(const auto& end : {std::make_pair(a, xa), std::make_pair(b, xb)})
    {
      // A user's constrained edge keeps its ends.
      if(m_state.feature_edge[std::size_t(m_mesh.edge(m_mesh.halfedge(end.first, end.second)))] ==
         constrained_feature_edge)
        return std::nullopt;
      const double chord = (pm - position(end.second)).norm(), target = edge_length_target(end.first, end.second);
      if(Sizing_field::is_too_long(chord, target) ||
         !(m_polylines->chord_deviation(middle, feature_location(end.second), 2 * chord) <= m_sizing.tolerance_for(chord, target)))
        return std::nullopt;
    }
    return Collapse{a, b, pm, true, middle};
  }

private:
  // How many feature edges v has, and the far end of one that is not e.
  std::size_t feature_degree(Vertex v, Edge e, Vertex& other) const
  {
    std::size_t n = 0;
    for(Halfedge g : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      if(m_state.feature_edge[std::size_t(m_mesh.edge(g))])
      {
        ++n;
        if(m_mesh.edge(g) != e)
          other = m_mesh.source(g);
      }
    return n;
  }
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_FEATURE_LINE_COLLAPSES_H
