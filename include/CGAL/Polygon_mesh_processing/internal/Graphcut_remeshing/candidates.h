// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Candidate positions (section 2.3): per vertex, the first of angle-based smoothing, Laplacian
// smoothing and a guided random move that lies in the freedom sphere of eq. (5) and lowers the
// local evidence of eq. (7); the smoothing targets, the sphere and the cooling schedule.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_CANDIDATES_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_CANDIDATES_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/energy.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/features.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/reference_surface.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/tracking.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <CGAL/Random.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// The link of a vertex as the segments opposite to it in its incident triangles (on the stack for
// the valences a mesh has: one is made per vertex and candidate round).
using Link = boost::container::small_vector<std::pair<Vector_3d, Vector_3d>, 12>;

// Smallest distance from x to its one-ring boundary (the ||x_s, x_Ns|| of eq. 5).
inline double ring_radius(const Vector_3d& x, const Link& link)
{
  double r = std::numeric_limits<double>::infinity();
  for(const auto& s : link)
    r = (std::min)(r, distance_to_segment(x, s.first, s.second));
  return r;
}

// Angle-based smoothing (Zhou & Shimada): for each link segment (a, b), turn x about each end so
// that the edge to x bisects the angle the two ring neighbours make there; average the results.
// `link` lists the segments of a closed ring (each ring vertex is an end of two segments).
inline Vector_3d angle_based_target(const Vector_3d& x, const Link& link)
{
  Vector_3d sum = Vector_3d::Zero();
  int count = 0;
  // Around a ring vertex p with ring neighbours q (before) and r (after): p is the end of two
  // segments, (q, p) and (p, r); in a manifold ring only one segment starts at p. Around a vertex
  // the segments come in order, one way or the other: the two beside (q, p) are looked at first.
  const std::size_t k = link.size();
  for(std::size_t i = 0; i < k; ++i)
  {
    const auto& in = link[i];
    auto starts_at_p = [&](std::size_t j) { return link[j].first == in.second; };
    std::size_t j = starts_at_p((i + k - 1) % k) ? (i + k - 1) % k : (starts_at_p((i + 1) % k) ? (i + 1) % k : 0);
    while(j < k && !starts_at_p(j))
      ++j;
    if(j < k)
    {
      const auto& out = link[j];
      const Vector_3d& p = in.second;
      const Vector_3d u = in.first - p, w = out.second - p;
      const double lu = u.norm(), lw = w.norm(), lx = (x - p).norm();
      if(!(lu > 0) || !(lw > 0) || !(lx > 0))
        continue;
      const Vector_3d bisector = u / lu + w / lw;
      if(!(bisector.norm() > 1e-12))
        continue;
      sum += p + lx * bisector.normalized();
      ++count;
    }
  }
  return count > 0 ? Vector_3d(sum / count) : x;
}

// Laplacian smoothing: the centroid of the ring vertices.
template <typename PointRange>
Vector_3d laplacian_target(const Vector_3d& x, const PointRange& ring)
{
  Vector_3d sum = Vector_3d::Zero();
  int count = 0;
  for(const Vector_3d& p : ring)
  {
    sum += p;
    ++count;
  }
  return count > 0 ? Vector_3d(sum / count) : x;
}

// The smoothing of section 3.2, which the candidates of section 2.3 also propose: the angle-based
// target when take(target) takes it, else the Laplacian one (`ring()`, the ring's points, asked
// for only then). Returns whether one was taken.
template <typename Ring, typename Take>
bool take_smoothing_target(const Vector_3d& x, const Link& link, const Ring& ring, const Take& take)
{
  return take(angle_based_target(x, link)) || take(laplacian_target(x, ring()));
}

// eq. (5): sigma = 0.5 / (1 + exp(-T)) * ring radius * min(1, rho).
inline double freedom_radius(double temperature, double ring_radius, double min_curvature_radius)
{
  return 0.5 / (1 + std::exp(-temperature)) * ring_radius * (std::min)(1.0, min_curvature_radius);
}

// T(i) = T(1) K^(i-1), i from 1.
inline double temperature(double initial_temperature, double cooling_factor, std::size_t iteration)
{
  return initial_temperature * std::pow(cooling_factor, double(iteration) - 1.0);
}

// One candidate per vertex: what the relocation offers the graph cut.
class Candidate_generator
{
  using Vertex = Work_mesh::Vertex_index;
  using Halfedge = Work_mesh::Halfedge_index;
  using Face = Work_mesh::Face_index;
  using Location = Feature_polylines<Work_mesh>::Location;

public:
  Candidate_generator(const Work_mesh& mesh, const Reference_surface<Work_mesh>& reference,
                      const Feature_polylines<Work_mesh>& polylines, const Tracking_state& state,
                      const Mesh_energy& energy, double smoothing_step)
    : m_mesh(mesh), m_reference(reference), m_polylines(polylines), m_state(state), m_energy(energy),
      m_smoothing_step(smoothing_step)
  {}

  // Section 2.3: the first candidate, in the order of the paper, that lies in the freedom sphere
  // and lowers the local evidence. False when there is none. The terms of the triangles around v
  // with v at the candidate go to `face_term`, by the triangles' halfedges to v; a free vertex's
  // candidate lies on the reference triangle `out_face`.
  bool propose(Vertex v, double temperature, bool greedy, CGAL::Random& rng, Vector_3d& out,
               Location& out_location, Face& out_face, std::vector<double>& face_term) const
  {
    if(kind_of(v) == Vertex_kind::fixed_vertex)
      return false;
    const Vector_3d x = position(v);
    const Star around = m_energy.star(v);
    // The link from the star: around a triangle's halfedge to v come target(next(h)), then source(h).
    Link link;
    for(const Star::Triangle& t : around.triangles)
      link.emplace_back(t.corners[(t.slot + 1) % 3], t.corners[(t.slot + 2) % 3]);
    const double before = m_energy.current_local_evidence(v);
    if(kind_of(v) == Vertex_kind::feature_vertex)
      return propose_on_feature(around, x, link, before, temperature, greedy, rng, out, out_location, face_term);

    const Local_frame& frame = m_reference.frame(m_state.closest[std::size_t(v)]);
    const double sigma = freedom_radius(temperature, ring_radius(x, link), frame.min_radius());
    if(!(sigma > 0))
      return false;
    Face face = Work_mesh::null_face(); // where the last candidate was brought onto the reference
    auto accept = [&](const Vector_3d& c) {
      if(!((c - x).norm() <= sigma) || !(m_energy.local_evidence(around, c, before, &face_term, face) < before))
        return false;
      out = c;
      out_face = face;
      return true;
    };
    // Beyond the paper: a tangent-plane move leaves a curved surface by about k d^2 / 2; bringing
    // the candidate back onto the reference triangles keeps the data term near zero, so the shape
    // term alone decides, as the paper intends its tangent moves to.
    auto on_surface = [&](const Vector_3d& c) {
      face = m_state.vertex_hint[std::size_t(v)];
      return m_reference.closest_point(c, face);
    };
    if(!greedy)
    {
      if(take_smoothing_target(x, link, [&] { return ring(v); }, [&](const Vector_3d& target) {
           return accept(on_surface(x + m_smoothing_step * tangential(target - x, frame.normal)));
         }))
        return true;
      // Guided random: a random direction of the tangent plane, a random length in the sphere.
      for(int attempt = 0; attempt < 3; ++attempt)
      {
        const double angle = rng.get_double(0, 2 * pi);
        const double length = sigma * rng.get_double(0.1, 1.0);
        if(accept(on_surface(x + length * (std::cos(angle) * frame.d1 + std::sin(angle) * frame.d2))))
          return true;
      }
      return false;
    }
    // Greedy phase: along the negative gradient of the local evidence (forward differences from
    // its value here, kept), brought back onto the reference like the other candidates.
    const double step = 1e-3 * sigma;
    Vector_3d gradient;
    for(int a = 0; a < 3; ++a)
      gradient[a] = (m_energy.local_evidence(around, x + Vector_3d::Unit(a) * step) - before) / step;
    if(!(gradient.norm() > 0) || !std::isfinite(gradient.norm()))
      return false;
    const Vector_3d descent = -gradient.normalized();
    for(int attempt = 0; attempt < 3; ++attempt)
      if(accept(on_surface(x + sigma * rng.get_double(0.05, 1.0) * descent)))
        return true;
    return false;
  }

private:
  Vertex_kind kind_of(Vertex v) const { return m_state.kind[std::size_t(v)]; }
  Vector_3d position(Vertex v) const { return to_vector(m_mesh.point(v)); }

  // The neighbours of v, border ones too.
  boost::container::small_vector<Vector_3d, 12> ring(Vertex v) const
  {
    boost::container::small_vector<Vector_3d, 12> r;
    for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      r.push_back(position(m_mesh.source(h)));
    return r;
  }

  // Vertices on a feature slide along their reference polyline: the 1D Laplacian towards the
  // middle of their two feature neighbours, or a random (greedy: downhill) slide.
  bool propose_on_feature(const Star& around, const Vector_3d& x, const Link& link, double before, double temperature,
                          bool greedy, CGAL::Random& rng, Vector_3d& out, Location& out_location,
                          std::vector<double>& face_term) const
  {
    const Location here = m_state.location[std::size_t(around.v)];
    // The polyline is followed exactly, so its curvature does not limit the sphere.
    const double sigma = freedom_radius(temperature, ring_radius(x, link), 1.0);
    if(!(sigma > 0))
      return false;
    auto accept = [&](const Vector_3d& displacement) {
      const Location l = m_polylines.move(here, displacement);
      const Vector_3d c = m_polylines.point(l);
      if(!((c - x).norm() <= sigma) || (c - x).norm() == 0 || !keeps_lines(around.v, l, c) ||
         !(m_energy.local_evidence(around, c, before, &face_term) < before))
        return false;
      out = c;
      out_location = l;
      return true;
    };
    const Vector_3d tangent = m_polylines.tangent(here);
    if(!greedy)
    {
      const std::pair<int, Vector_3d> neighbours = feature_neighbours(around.v);
      if(neighbours.first == 2 && accept(m_smoothing_step * (neighbours.second / 2 - x)))
        return true;
      for(int attempt = 0; attempt < 3; ++attempt)
      {
        const double sign = rng.get_bool() ? 1. : -1.;
        if(accept(sign * sigma * rng.get_double(0.1, 1.0) * tangent))
          return true;
      }
      return false;
    }
    const double step = 1e-3 * sigma;
    const double forward = m_energy.local_evidence(around, m_polylines.point(m_polylines.move(here, step * tangent)));
    const double backward = m_energy.local_evidence(around, m_polylines.point(m_polylines.move(here, -step * tangent)));
    if(!(forward != backward))
      return false;
    const Vector_3d descent = forward < backward ? tangent : Vector_3d(-tangent);
    for(int attempt = 0; attempt < 3; ++attempt)
      if(accept(sigma * rng.get_double(0.05, 1.0) * descent))
        return true;
    return false;
  }

  // Whether v's feature edges stay within the polylines' line tolerance of their polyline with v
  // at `l` (the point `c`), as its neighbours are now, where that is a border or a strong crease:
  // weaker lines slide freely, as the paper's.
  bool keeps_lines(Vertex v, const Location& l, const Vector_3d& c) const
  {
    if(!std::isfinite(m_polylines.line_tolerance()) || !m_polylines.holds_turns(l))
      return true;
    for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      if(m_state.feature_edge[std::size_t(m_mesh.edge(h))])
      {
        const Vertex n = m_mesh.source(h);
        const Location at_n = line_location(m_state, m_polylines, n);
        if(!(m_polylines.chord_deviation(l, at_n, 2 * (c - position(n)).norm()) <= m_polylines.line_tolerance()))
          return false;
      }
    return true;
  }

  // The number of feature neighbours of v and the sum of their positions.
  std::pair<int, Vector_3d> feature_neighbours(Vertex v) const
  {
    Vector_3d sum = Vector_3d::Zero();
    int count = 0;
    for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      if(m_state.feature_edge[std::size_t(m_mesh.edge(h))])
      {
        sum += position(m_mesh.source(h));
        ++count;
      }
    return {count, sum};
  }

  const Work_mesh& m_mesh;
  const Reference_surface<Work_mesh>& m_reference;
  const Feature_polylines<Work_mesh>& m_polylines;
  const Tracking_state& m_state;
  const Mesh_energy& m_energy;
  double m_smoothing_step; // gamma of section 2.3
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_CANDIDATES_H
