// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The energy of eq. (1): a shape term per triangle (eq. 2) and a data term per vertex, the
// second-order approximation of the squared distance to the reference surface (eq. 4); its terms
// at the current positions, kept up to date, and the local evidence of eq. (7) over a star.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_ENERGY_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_ENERGY_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/features.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/reference_surface.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/tracking.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

struct Energy_weights
{
  double lambda_shape = 1;
  double lambda_data = 1e7;
  double epsilon = 0.01; // bound on the Taylor expansion point of eq. (4)
  // Beyond the paper: the weight, relative to lambda_data, of the data term at triangle centroids.
  double face_data_weight = 0.05;
  // Beyond the paper: the weight, relative to lambda_data, of the data term at feature-edge
  // midpoints. A chord of a curved feature line deviates where CAD models keep most of their
  // distance to the remesh; models without features are left alone.
  double feature_data_weight = 4;
  // Beyond the paper: the distance of a centroid from the reference that its data term does not
  // count; only the part beyond it is paid for. Zero unless set by resampling_weights().
  double face_data_free_distance = 0;
};

// Beyond the paper: when the connectivity stage re-samples the surface, distances count relative
// to the sizing tolerance once it exceeds this (unit box). The tolerance is how far the chords of
// the target lengths leave the surface: 1e-4 of the unit box on fandisk, but 2e-3 to 6e-3 on
// coarse curved inputs (knot, head, helmet), where the unit-box weight would hold the vertices
// where the input's were and keep their triangles worse than isotropic_remeshing's.
constexpr double full_data_weight_tolerance = 9e-4;

// Beyond the paper: at the input's density the sizing field chooses lengths whose chords leave the
// surface by up to its tolerance, so a centroid that far below the reference is what the field asked
// for. The centroid term counts only the distance beyond this fraction of the tolerance: counting
// all of it held the vertices where the chords are shallowest rather than where the triangles are
// best (on sphere966 and geosphere, below isotropic_remeshing's mean minimum angle). At a length the
// user asked for, the term counts all of it: there the lengths do not come from the tolerance.
constexpr double face_data_free_fraction = 0.5;

// The weights with which a re-sampled surface of sizing tolerance `tolerance` is fitted: the data
// terms scaled by min(1, (full_data_weight_tolerance / tolerance)^2), so that a vertex at the
// tolerance from the surface costs no more than one at 9e-4 does on a finer input; and, at the
// input's density, the centroid term's free distance.
inline Energy_weights resampling_weights(Energy_weights weights, double tolerance, bool at_input_density)
{
  const double ratio = full_data_weight_tolerance / tolerance;
  if(ratio < 1)
    weights.lambda_data *= ratio * ratio;
  if(at_input_density)
    weights.face_data_free_distance = face_data_free_fraction * tolerance;
  return weights;
}

// eq. (2): circumradius over shortest edge; 1/sqrt(3) for an equilateral triangle, infinite for a
// degenerate one. R = abc / (4 area), so R / min = (product of the two longer edges) / (4 area).
inline double shape_energy(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c)
{
  const double la = (b - c).norm(), lb = (c - a).norm(), lc = (a - b).norm();
  const double twice_area = area_vector(a, b, c).norm();
  const double shortest = (std::min)({la, lb, lc});
  if(!(twice_area > 0) || !(shortest > 0))
    return std::numeric_limits<double>::infinity();
  return la * lb * lc / (2 * twice_area * shortest);
}

// A triangle that a move may not create: degenerate, or turned over against its current normal
// (turned by more than the angle whose cosine is `min_cosine`, a right angle by default).
inline bool is_acceptable_triangle(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c,
                                   const Vector_3d& current_area_vector, double min_cosine = 0)
{
  const Vector_3d n = area_vector(a, b, c);
  const double longest2 = (std::max)({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  // A relative area of 1e-12 is a shape energy above 1e11: nothing an optimiser should produce.
  if(!(n.norm() > 1e-12 * longest2))
    return false;
  return n.dot(current_area_vector) > min_cosine * n.norm() * current_area_vector.norm();
}

// What the local evidence of a vertex v reads of the mesh, gathered once for all the positions of
// v it is evaluated at: the triangles around v with their corners (v's to be replaced by the
// position), and for a vertex on a feature its feature edges with their other ends.
struct Star
{
  struct Triangle
  {
    Work_mesh::Halfedge_index h;      // to v
    std::array<Vector_3d, 3> corners; // in the order of the face's vertices
    int slot;                         // which corner is v
  };
  Work_mesh::Vertex_index v;
  boost::container::small_vector<Triangle, 12> triangles;
  boost::container::small_vector<std::pair<std::size_t, Vector_3d>, 4> feature_edges; // slot, other end
};

// The terms of eq. (1) of the working mesh at its current positions, by element, and the energy
// of other positions: the triangle terms (shape, and beyond the paper a data term at the
// centroid), the data terms of the free vertices and, beyond the paper, the data terms at the
// midpoints of the feature edges.
class Mesh_energy
{
  using Vertex = Work_mesh::Vertex_index;
  using Halfedge = Work_mesh::Halfedge_index;
  using Edge = Work_mesh::Edge_index;
  using Face = Work_mesh::Face_index;

public:
  static constexpr std::size_t no_slot = std::size_t(-1);

  Mesh_energy(const Work_mesh& mesh, const Reference_surface<Work_mesh>& reference, const Tracking_state& state,
              const Energy_weights& weights)
    : m_mesh(mesh), m_reference(reference), m_state(state), m_weights(weights)
  {}

  // eq. (1), from the terms at the current positions.
  double energy() const
  {
    double u = 0;
    for(Face f : m_mesh.faces())
      u += m_face_term[std::size_t(f)];
    for(Vertex v : m_mesh.vertices())
      u += m_vertex_term[std::size_t(v)];
    for(double t : m_edge_term)
      u += t;
    return u;
  }

  // The terms at the current positions, to be put back should a relocation be undone.
  struct Saved_terms
  {
    std::vector<double> face, vertex, edge;
  };
  Saved_terms saved_terms() const { return {m_face_term, m_vertex_term, m_edge_term}; }
  void restore_terms(Saved_terms&& saved)
  {
    m_face_term = std::move(saved.face);
    m_vertex_term = std::move(saved.vertex);
    m_edge_term = std::move(saved.edge);
  }

  double face_term(Face f) const { return m_face_term[std::size_t(f)]; }
  double vertex_term(Vertex v) const { return m_vertex_term[std::size_t(v)]; }
  double edge_term(std::size_t slot) const { return m_edge_term[slot]; }

  // The feature edges of the working mesh, by slot (splits of sharp edges add some).
  const std::vector<Edge>& feature_edges() const { return m_feature_edges; }

  // By halfedge h: the terms of face(h) with target(h) at its candidate, written by the candidates.
  std::vector<double>& proposal_face_term() { return m_proposal_face_term; }
  double proposal_face_term(Halfedge h) const { return m_proposal_face_term[std::size_t(h)]; }

  // The feature edges and their slots, again from the state (after the connectivity changed).
  void collect_feature_edges()
  {
    m_feature_edges.clear();
    m_feature_edge_slot.assign(m_mesh.num_edges(), no_slot);
    for(Edge e : m_mesh.edges())
      if(m_state.feature_edge[std::size_t(e)])
      {
        m_feature_edge_slot[std::size_t(e)] = m_feature_edges.size();
        m_feature_edges.push_back(e);
      }
  }

  // The terms of eq. (1) at the current positions, all of them (after the mesh changed). The
  // tracking hints only ever move to where the closest-point descent from the previous hint ends,
  // so the terms stay exact when they change.
  void compute_terms()
  {
    m_face_term.assign(m_mesh.num_faces(), 0);
    m_vertex_term.assign(m_mesh.num_vertices(), 0);
    m_edge_term.assign(m_feature_edges.size(), 0);
    for_each_face(m_mesh, [&](Face f) { m_face_term[std::size_t(f)] = current_triangle_energy(f); });
    for_each_vertex(m_mesh, [&](Vertex v) { m_vertex_term[std::size_t(v)] = data_energy(v, position(v)); });
    for(std::size_t i = 0; i < m_feature_edges.size(); ++i)
      m_edge_term[i] = current_feature_edge_energy(i);
  }

  // After a relocation, the terms that depend on a vertex with moved[v]. A moved vertex's data
  // term (`data`, by vertex) and the terms of the triangles where it alone moved were evaluated
  // at its candidate already, with the same hints; the others are evaluated again.
  void update_terms_after_relocation(const std::vector<char>& moved, const std::vector<double>& data)
  {
    for_each_face(m_mesh, [&](Face f) {
      const std::array<Vertex, 3> t = face_vertices(m_mesh, f);
      const int count = moved[std::size_t(t[0])] + moved[std::size_t(t[1])] + moved[std::size_t(t[2])];
      if(count == 1)
        m_face_term[std::size_t(f)] =
          m_proposal_face_term[std::size_t(halfedges_to_vertices(f)[moved[std::size_t(t[0])] ? 0 : (moved[std::size_t(t[1])] ? 1 : 2)])];
      else if(count > 1)
        m_face_term[std::size_t(f)] = current_triangle_energy(f);
    });
    for_each_vertex(m_mesh, [&](Vertex v) {
      if(moved[std::size_t(v)])
        m_vertex_term[std::size_t(v)] = data[std::size_t(v)];
    });
    for(std::size_t i = 0; i < m_feature_edges.size(); ++i)
    {
      const Halfedge h = m_mesh.halfedge(m_feature_edges[i]);
      if(moved[std::size_t(m_mesh.source(h))] || moved[std::size_t(m_mesh.target(h))])
        m_edge_term[i] = current_feature_edge_energy(i);
    }
  }

  // The halfedges of f to its vertices, in the order of face_vertices(f).
  std::array<Halfedge, 3> halfedges_to_vertices(Face f) const
  {
    const Halfedge h = m_mesh.halfedge(f);
    return {{m_mesh.prev(h), h, m_mesh.next(h)}};
  }

  // lambda_data F(x) for a free vertex; vertices on features lie on the reference polylines by
  // construction and fixed vertices do not move, so they have no data term.
  // The search starts from `hint`, by default the vertex's triangle.
  double data_energy(Vertex v, const Vector_3d& x, Face hint = Work_mesh::null_face()) const
  {
    if(m_state.kind[std::size_t(v)] != Vertex_kind::free_vertex)
      return 0;
    return m_weights.lambda_data *
           squared_distance(x, hint != Work_mesh::null_face() ? hint : m_state.vertex_hint[std::size_t(v)]);
  }

  // The terms of eq. (1) that belong to triangle f at positions (a, b, c): its shape, and beyond
  // the paper a data term at its centroid, so that a triangle cutting a chord through a curved
  // part of the reference pays for it even when its vertices lie on the reference.
  double triangle_energy(Face f, const Vector_3d& a, const Vector_3d& b, const Vector_3d& c) const
  {
    return triangle_shape_term(a, b, c) + triangle_data_term(f, a, b, c);
  }

  // Beyond the paper: the data term at the midpoint of the feature edge of slot i at (a, b).
  // Feature vertices lie on the reference polylines, but an edge between two of them is a chord
  // that leaves a curved feature line; this term makes it pay for that.
  double feature_edge_energy(std::size_t i, const Vector_3d& a, const Vector_3d& b) const
  {
    return m_weights.feature_data_weight * m_weights.lambda_data *
           squared_distance((a + b) / 2, m_state.edge_hint[std::size_t(m_feature_edges[i])]);
  }

  // eq. (7) at the current position of v, from the terms kept: local_evidence(v, position(v)).
  double current_local_evidence(Vertex v) const
  {
    double u = m_vertex_term[std::size_t(v)];
    for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      if(!m_mesh.is_border(h))
        u += m_face_term[std::size_t(m_mesh.face(h))];
    if(is_on_feature(v))
      for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      {
        const std::size_t i = m_feature_edge_slot[std::size_t(m_mesh.edge(h))];
        if(i != no_slot)
          u += m_edge_term[i];
      }
    return u;
  }

  Star star(Vertex v) const
  {
    Star s;
    s.v = v;
    for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
    {
      if(!m_mesh.is_border(h))
      {
        const std::array<Vertex, 3> t = face_vertices(m_mesh, m_mesh.face(h));
        Star::Triangle triangle{h, {}, 0};
        for(int i = 0; i < 3; ++i)
        {
          triangle.corners[i] = position(t[i]);
          if(t[i] == v)
            triangle.slot = i;
        }
        s.triangles.push_back(triangle);
      }
      if(is_on_feature(v))
      {
        const std::size_t i = m_feature_edge_slot[std::size_t(m_mesh.edge(h))];
        if(i != no_slot)
          s.feature_edges.emplace_back(i, position(m_mesh.source(h)));
      }
    }
    return s;
  }

  // eq. (7): the energy terms that depend on the position x of vertex v. The terms are not
  // negative: once their sum reaches `bound` the rest is not evaluated (a candidate that reaches
  // the current local evidence is refused whatever the rest adds). The shape terms come first:
  // they need no search on the reference.
  //
  // With `record`, the terms of each triangle are also written there, at the index of the
  // triangle's halfedge to v. `hint` is where the search for the data term of v starts.
  double local_evidence(const Star& s, const Vector_3d& x, double bound = std::numeric_limits<double>::infinity(),
                        std::vector<double>* record = nullptr, Face hint = Work_mesh::null_face()) const
  {
    boost::container::small_vector<double, 12> shape;
    double u = 0;
    for(const Star::Triangle& t : s.triangles)
    {
      std::array<Vector_3d, 3> p = t.corners;
      p[t.slot] = x;
      shape.push_back(triangle_shape_term(p[0], p[1], p[2]));
      u += shape.back();
      if(!(u < bound))
        return u;
    }
    u += data_energy(s.v, x, hint);
    for(std::size_t k = 0; k < s.triangles.size(); ++k)
    {
      if(!(u < bound))
        return u;
      std::array<Vector_3d, 3> p = s.triangles[k].corners;
      p[s.triangles[k].slot] = x;
      const double data = triangle_data_term(m_mesh.face(s.triangles[k].h), p[0], p[1], p[2]);
      if(record)
        (*record)[std::size_t(s.triangles[k].h)] = shape[k] + data;
      u += data;
    }
    for(const auto& e : s.feature_edges)
      u += feature_edge_energy(e.first, x, e.second);
    return u;
  }

  double local_evidence(Vertex v, const Vector_3d& x, double bound = std::numeric_limits<double>::infinity()) const
  {
    return local_evidence(star(v), x, bound);
  }

private:
  Vector_3d position(Vertex v) const { return to_vector(m_mesh.point(v)); }

  bool is_on_feature(Vertex v) const { return m_state.kind[std::size_t(v)] == Vertex_kind::feature_vertex; }

  // F of eq. (4) in the frame at the point of the reference triangles closest to x, searched from
  // the triangle `hint`.
  double squared_distance(const Vector_3d& x, Face hint) const
  {
    return m_reference.approximate_squared_distance(x, hint, m_weights.epsilon);
  }

  double triangle_shape_term(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c) const
  {
    return m_weights.lambda_shape * shape_energy(a, b, c);
  }

  double triangle_data_term(Face f, const Vector_3d& a, const Vector_3d& b, const Vector_3d& c) const
  {
    const double d2 = squared_distance((a + b + c) / 3, m_state.face_hint[std::size_t(f)]);
    return m_weights.face_data_weight * m_weights.lambda_data * beyond_free_distance(d2);
  }

  // The square of the part of a distance sqrt(d2) beyond face_data_free_distance.
  double beyond_free_distance(double d2) const
  {
    const double free = m_weights.face_data_free_distance;
    if(!(free > 0))
      return d2;
    const double beyond = std::sqrt((std::max)(d2, 0.0)) - free;
    return beyond > 0 ? beyond * beyond : 0;
  }

  double current_triangle_energy(Face f) const
  {
    const std::array<Vertex, 3> t = face_vertices(m_mesh, f);
    return triangle_energy(f, position(t[0]), position(t[1]), position(t[2]));
  }

  double current_feature_edge_energy(std::size_t i) const
  {
    const Halfedge h = m_mesh.halfedge(m_feature_edges[i]);
    return feature_edge_energy(i, position(m_mesh.source(h)), position(m_mesh.target(h)));
  }

  const Work_mesh& m_mesh;
  const Reference_surface<Work_mesh>& m_reference;
  const Tracking_state& m_state;
  Energy_weights m_weights;
  std::vector<Edge> m_feature_edges;
  std::vector<std::size_t> m_feature_edge_slot; // by edge index: position in m_feature_edges
  std::vector<double> m_face_term;   // by face: its terms of eq. (1) at the current positions
  std::vector<double> m_vertex_term; // by vertex: its data term at its current position
  std::vector<double> m_edge_term;   // by feature-edge slot: its term at the current positions
  std::vector<double> m_proposal_face_term; // by halfedge h: face(h)'s terms with target(h) at its candidate
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_ENERGY_H
