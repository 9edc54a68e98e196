// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Section 3.1: splits of long edges.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_EDGE_SPLITS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_EDGE_SPLITS_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/edge_queue.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/local_operations.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// Harmonic mean of two scale-invariant qualities of Shewchuk's "What is a good linear finite
// element", both 1 for an equilateral triangle and 0 for a degenerate one: the radius ratio 2r/R
// (interpolation) and 4 sqrt(3) area / sum of squared edges (conditioning). The split criterion.
inline double split_quality(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c)
{
  const double la = (b - c).norm(), lb = (c - a).norm(), lc = (a - b).norm();
  const double twice_area = area_vector(a, b, c).norm();
  const double s = la + lb + lc;
  if(!(twice_area > 0) || !(s > 0))
    return 0;
  // r = area / half-perimeter, R = la lb lc / (4 area): 2r/R = 8 area^2 / (s la lb lc / ... )
  const double area = twice_area / 2;
  const double interpolation = 16 * area * area / (s * la * lb * lc);
  const double conditioning = 4 * std::sqrt(3.0) * area / (la * la + lb * lb + lc * lc);
  return 2 * interpolation * conditioning / (interpolation + conditioning);
}

// Splits of long edges (section 3.1): a split is kept when the worst split quality of the
// triangles improves; with a re-sampling sizing, every edge longer than its target allows is
// split, the longest first, unless the new triangles are much thinner than the old.
class Edge_splits : public Local_operations
{
public:
  // Below this smallest angle a split may not make a triangle worse than the one it cuts.
  static constexpr double min_split_angle = 0.5 * pi / 180;

  // Where a split puts its vertex: a sharp edge at the point of its reference polyline halfway
  // between its ends (`on_feature`), other edges at their midpoint brought onto the reference.
  struct Plan
  {
    double gain = 0;
    Vector_3d point;
    Location on_feature;
  };

  explicit Edge_splits(const Local_operations& operations) : Local_operations(operations) {}

  // The splits, best gain first; returns how many were made.
  std::size_t run()
  {
    const auto plan = [this](Edge e) { return plan_of(e); };
    const auto apply = [this](Edge e, const Plan& p) { return split(e, p); };
    if(m_sizing.resamples())
      return run_edge_queue(m_mesh, plan, apply, [this](Edge e) { return resampling_gain_bound(e); });
    return run_edge_queue(m_mesh, plan, apply);
  }

  // The gain plan_of(e) has with re-sampling when e may be split, from its length alone.
  double resampling_gain_bound(Edge e) const
  {
    const Halfedge h = face_side(e);
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
    const double length = (position(a) - position(b)).norm(), target = edge_length_target(a, b);
    return Sizing_field::is_too_long(length, target) ? Sizing_field::excess(length, target) : 0.;
  }

  Plan plan_of(Edge e) const
  {
    Plan plan;
    const char feature = m_state.feature_edge[std::size_t(e)];
    // Border edges are re-sampled only with the re-sampling sizing.
    if((m_mesh.is_border(e) && !m_sizing.resamples()) || feature == constrained_feature_edge ||
       (feature && !m_polylines))
      return Plan();
    const Halfedge h = face_side(e), o = m_mesh.opposite(h);
    const bool two_faces = !m_mesh.is_border(o);
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
    if(is_frozen(a) || is_frozen(b))
      return Plan();
    const Vertex c = m_mesh.target(m_mesh.next(h)), d = two_faces ? m_mesh.target(m_mesh.next(o)) : c;
    const Vector_3d pa = position(a), pb = position(b), pc = position(c), pd = position(d);
    const double length = (pa - pb).norm();
    if(!Sizing_field::is_too_long(length, edge_length_target(a, b)))
      return Plan();
    if(feature)
    {
      plan.on_feature = feature_midpoint(a, b);
      plan.point = m_polylines->point(plan.on_feature);
      // The polyline between a and b may be far from straight: the new vertex must still fall
      // well inside the edge's span.
      if(!((plan.point - pa).norm() > length / 4 && (plan.point - pb).norm() > length / 4))
        return Plan();
    }
    else
      plan.point = project((pa + pb) / 2, a);
    const Vector_3d& p = plan.point;
    if(m_sizing.resamples())
    {
      // Re-sampling: the longest edges first, relative to their target. The surface may bend
      // the midpoint far from the chord (next to a crease it lands on the crease, and splitting
      // would never shorten the edge), and the new triangles may not be much thinner than the
      // ones they cut. These tests first: those of acceptable() search the reference.
      if(!feature && !((p - (pa + pb) / 2).norm() <= length / 4))
        return Plan();
      double old_min = smallest_angle(pa, pb, pc), new_min = (std::min)(smallest_angle(pa, p, pc), smallest_angle(p, pb, pc));
      if(two_faces)
      {
        old_min = (std::min)(old_min, smallest_angle(pb, pa, pd));
        new_min = (std::min)({new_min, smallest_angle(pb, p, pd), smallest_angle(p, pa, pd)});
      }
      // Halving alone compounds: a row of slivers split again and again (a CAD cylinder's
      // side) reached triangles of 1e-4 degrees, some turned over.
      if(!(new_min >= 0.5 * old_min) || (new_min < old_min && new_min < min_split_angle))
        return Plan();
      plan.gain = Sizing_field::excess(length, edge_length_target(a, b));
    }
    const Vector_3d abc = area_vector(pa, pb, pc), bad = area_vector(pb, pa, pd);
    if(!acceptable(pa, p, pc, a, abc) || !acceptable(p, pb, pc, b, abc) ||
       (two_faces && (!acceptable(pb, p, pd, b, bad) || !acceptable(p, pa, pd, a, bad))))
      return Plan();
    if(!split_keeps_distance_bound(h, p))
      return Plan();
    if(m_sizing.resamples())
      return plan;
    const double old_q = (std::min)(split_quality(pa, pb, pc), split_quality(pb, pa, pd));
    const double new_q = (std::min)({split_quality(pa, p, pc), split_quality(p, pb, pc),
                                     split_quality(pb, p, pd), split_quality(p, pa, pd)});
    plan.gain = new_q - old_q;
    return plan;
  }

  // Splits the edge of h (h on a face) by a new vertex at p, on_feature on the edge's polyline
  // when it is a feature edge, and cuts the faces (one on a border); returns the new vertex.
  Vertex split_edge_at(Halfedge h, const Vector_3d& p, const Location& on_feature)
  {
    const Edge e = m_mesh.edge(h);
    const Vertex a = m_mesh.source(h);
    const char feature = m_state.feature_edge[std::size_t(e)];
    // The new halfedge points from a to the new vertex.
    const Halfedge hn = CGAL::Euler::split_edge(h, m_mesh);
    const Vertex v = m_mesh.target(hn);
    m_mesh.point(v) = Work_kernel::Point_3(p.x(), p.y(), p.z());
    CGAL::Euler::split_face(hn, m_mesh.next(m_mesh.next(hn)), m_mesh);
    const Halfedge on = m_mesh.opposite(hn);
    if(!m_mesh.is_border(on))
      CGAL::Euler::split_face(m_mesh.prev(on), m_mesh.next(on), m_mesh);
    m_state.fit(m_mesh);
    for(Halfedge g : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      m_state.feature_edge[std::size_t(m_mesh.edge(g))] = 0;
    if(feature)
    {
      // Both halves of a sharp edge are sharp; the new vertex slides on its polyline.
      m_state.feature_edge[std::size_t(e)] = feature;
      m_state.feature_edge[std::size_t(m_mesh.edge(hn))] = feature;
      m_state.edge_hint[std::size_t(m_mesh.edge(hn))] = m_state.edge_hint[std::size_t(e)];
      m_state.location[std::size_t(v)] = on_feature;
    }
    bind_new_vertex(v, a, feature ? Vertex_kind::feature_vertex : Vertex_kind::free_vertex);
    track_faces_from(v);
    return v;
  }

private:
  // Splits e as planned; returns the vertices whose edges changed.
  std::vector<Vertex> split(Edge e, const Plan& plan)
  {
    const Halfedge h = face_side(e);
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
    const Vertex v = split_edge_at(h, plan.point, plan.on_feature);
    std::vector<Vertex> touched{{a, b, v}};
    for(Vertex w : vertices_around_target(m_mesh.halfedge(v), m_mesh))
      touched.push_back(w);
    return touched;
  }
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_EDGE_SPLITS_H
