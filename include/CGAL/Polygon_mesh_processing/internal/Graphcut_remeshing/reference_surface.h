// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The reference surface (section 2): an unchanged copy of the input with, per vertex, the frame of
// eq. (4) from jet fitting, and the closest-reference-vertex tracking by local search.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_REFERENCE_SURFACE_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_REFERENCE_SURFACE_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/parallel.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// The frame of a reference point: the surface normal and the principal directions, with the
// principal curvatures k1 (along d1, the larger in absolute value) and k2 (along d2).
struct Local_frame
{
  Vector_3d origin = Vector_3d::Zero();
  Vector_3d normal = Vector_3d::UnitZ();
  Vector_3d d1 = Vector_3d::UnitX();
  Vector_3d d2 = Vector_3d::UnitY();
  double k1 = 0;
  double k2 = 0;

  // The smallest principal radius 1 / max |k|, infinite where the surface is flat.
  double min_radius() const
  {
    const double k = (std::max)(std::abs(k1), std::abs(k2));
    return k > 0 ? 1.0 / k : std::numeric_limits<double>::infinity();
  }
};

// eq. (4) in the frame at the reference point: d / (d + |rho_i|) = d |k_i| / (d |k_i| + 1), so a
// flat direction (k = 0, rho infinite) contributes nothing.
inline double squared_distance_approximation(const Vector_3d& x, const Local_frame& f, double epsilon)
{
  const Vector_3d v = x - f.origin;
  const double x1 = v.dot(f.d1), x2 = v.dot(f.d2), x3 = v.dot(f.normal);
  const double d = (std::min)(epsilon, std::abs(x3));
  const double w1 = d * std::abs(f.k1), w2 = d * std::abs(f.k2);
  return w1 / (w1 + 1) * x1 * x1 + w2 / (w2 + 1) * x2 * x2 + x3 * x3;
}

template <typename Mesh>
class Reference_surface
{
public:
  using Vertex = typename Mesh::Vertex_index;
  using Face = typename Mesh::Face_index;

  // Triangles whose normals make less than `smooth_angle` (degrees; the lower sharp-edge bound
  // theta_false of eq. (8)) count as one smooth sheet for closest-point tracking.
  Reference_surface(const Mesh& m, double smooth_angle) : m_mesh(m), m_smooth_cosine(std::cos(smooth_angle * (pi / 180)))
  {
    collect_faces();
    compute_frames();
    // A degenerate triangle takes the normal of its first vertex.
    for(Face_record& r : m_faces)
      if(r.normal == Vector_3d::Zero())
        r.normal = frame(r.vertices[0]).normal;
    for(Face_record& r : m_faces)
    {
      r.offset = r.normal.dot(point(r.vertices[0]));
      for(int i = 0; i < 3; ++i)
        if(r.across[i] != Mesh::null_face())
          for(Vertex u : m_faces[std::size_t(r.across[i])].vertices)
            if(u != r.vertices[(i + 1) % 3] && u != r.vertices[(i + 2) % 3])
            {
              const double rise = r.normal.dot(point(u)) - r.offset;
              r.rise[i] = static_cast<signed char>((rise > 0) - (rise < 0));
            }
    }
  }

  const Mesh& mesh() const { return m_mesh; }
  const Local_frame& frame(Vertex v) const { return m_frames[std::size_t(v)]; }
  Vector_3d point(Vertex v) const { return to_vector(m_mesh.point(v)); }

  // Local search of section 2.1: from `start`, move to a neighbour closer to x while there is one.
  Vertex closest_vertex(const Vector_3d& x, Vertex start) const
  {
    Vertex current = start;
    double best = (point(current) - x).squaredNorm();
    for(bool improved = true; improved;)
    {
      improved = false;
      const auto h0 = m_mesh.halfedge(current);
      if(h0 == Mesh::null_halfedge())
        break;
      for(auto h : halfedges_around_target(h0, m_mesh))
      {
        const Vertex w = m_mesh.source(h);
        const double d = (point(w) - x).squaredNorm();
        if(d < best)
        {
          best = d;
          current = w;
          improved = true;
        }
      }
    }
    return current;
  }

  // The frame of eq. (4) at the point of the reference triangles closest to x, found by descent
  // from the triangle `hint` (updated to the triangle of that point): across an edge when the
  // closest point of the current triangle is on that edge, around a vertex when it is that vertex.
  // There the normal is the triangle's, and the principal directions and curvatures are
  // interpolated from the triangle's vertices. When the closest point is inside a triangle,
  // x - origin is along the normal and eq. (4) is the exact squared distance to the reference.
  Local_frame frame_at_closest_point(const Vector_3d& x, Face& hint) const
  {
    std::array<double, 3> w;
    const Vector_3d c = closest_point(x, hint, w);
    return frame_at(hint, c, w);
  }

  // F of eq. (4) at x, in the frame at the closest point of the reference triangles (searched
  // from `hint`, updated). When that point is inside a triangle, x - origin is along the normal
  // and F is the squared distance: no frame is needed.
  double approximate_squared_distance(const Vector_3d& x, Face& hint, double epsilon) const
  {
    std::array<double, 3> w;
    const Vector_3d c = closest_point(x, hint, w);
    if(w[0] > 0 && w[1] > 0 && w[2] > 0)
      return (x - c).squaredNorm();
    return squared_distance_approximation(x, frame_at(hint, c, w), epsilon);
  }

  // The point of the reference triangles closest to x, searched from `hint` (updated).
  Vector_3d closest_point(const Vector_3d& x, Face& hint) const
  {
    std::array<double, 3> w;
    return closest_point(x, hint, w);
  }

  // The unit normal of reference triangle f, the normal of the frames on it.
  const Vector_3d& normal(Face f) const { return m_faces[std::size_t(f)].normal; }

  // The descent of frame_at_closest_point: the closest point, its triangle (in `hint`) and its
  // barycentric coordinates there.
  Vector_3d closest_point(const Vector_3d& x, Face& hint, std::array<double, 3>& w) const
  {
    Vector_3d c = project(x, hint, w);
    double best = (x - c).squaredNorm();
    for(std::size_t guard = 0; guard < m_mesh.number_of_faces(); ++guard)
    {
      const Face_record& r = m_faces[std::size_t(hint)];
      Face next_face = hint;
      const int zeros = (w[0] == 0) + (w[1] == 0) + (w[2] == 0);
      if(zeros == 1)
      {
        // On the edge opposite the vertex of weight 0: look across it.
        const int i = w[0] == 0 ? 0 : (w[1] == 0 ? 1 : 2);
        if(r.across[i] != Mesh::null_face())
          next_face = r.across[i];
      }
      else if(zeros == 2)
      {
        // At a vertex: the closest of the triangles around it.
        const Vertex u = r.vertices[w[0] == 1 ? 0 : (w[1] == 1 ? 1 : 2)];
        double around = best;
        for(auto h : halfedges_around_target(m_mesh.halfedge(u), m_mesh))
          if(!m_mesh.is_border(h))
          {
            std::array<double, 3> wg;
            const double d = (x - project(x, m_mesh.face(h), wg)).squaredNorm();
            if(d < around)
            {
              around = d;
              next_face = m_mesh.face(h);
            }
          }
      }
      std::array<double, 3> wg;
      Vector_3d cg;
      double d = best;
      if(next_face != hint)
      {
        cg = project(x, next_face, wg);
        d = (x - cg).squaredNorm();
      }
      if(!(d < best))
      {
        next_face = closer_smooth_neighbour(x, hint, w, d, wg, cg);
        if(next_face == hint || !(d < best))
          break;
      }
      best = d;
      hint = next_face;
      w = wg;
      c = cg;
    }
    return c;
  }

  // Where the reference is smooth and concave a triangle sharing an edge with f can be closer to x
  // than f's closest point (of weights w, at squared distance d) although that point is not on the
  // edge: the closest of the three, with its point (cg, weights wg) and its squared distance in
  // d, or f when none is closer. Not across a sharp edge: there the other sheet may be closer (a
  // thin part, a concave crease) and tracking must stay on the side it came from.
  Face closer_smooth_neighbour(const Vector_3d& x, Face f, const std::array<double, 3>& w, double& d,
                               std::array<double, 3>& wg, Vector_3d& cg) const
  {
    const Face_record& r = m_faces[std::size_t(f)];
    Face next_face = f;
    // With the closest point inside f, a neighbour can only be closer across a dihedral that is
    // concave on the side of x: elsewhere its points are no closer than the common edge, which is
    // no closer than f's plane.
    const bool inside = w[0] > 0 && w[1] > 0 && w[2] > 0;
    const double height = r.normal.dot(x) - r.offset;
    for(int i : {2, 0, 1}) // the order of the face's halfedges
    {
      if(!((r.smooth_across >> i) & 1) || (inside && !(height * r.rise[i] > 0)))
        continue;
      const Face o = r.across[i];
      // The distance to a triangle is at least the distance to its plane.
      const Face_record& ro = m_faces[std::size_t(o)];
      const double to_plane = ro.normal.dot(x) - ro.offset;
      if(to_plane * to_plane > d * (1 + 1e-9))
        continue;
      std::array<double, 3> wo;
      const Vector_3d co = project(x, o, wo);
      const double dn = (x - co).squaredNorm();
      if(dn < d)
      {
        d = dn;
        next_face = o;
        wg = wo;
        cg = co;
      }
    }
    return next_face;
  }

  // The frame at point c of triangle f, of barycentric coordinates w.
  Local_frame frame_at(Face f, const Vector_3d& c, const std::array<double, 3>& w) const
  {
    const Face_record& r = m_faces[std::size_t(f)];
    Local_frame result;
    result.origin = c;
    result.normal = normal(f);
    const Local_frame& f0 = frame(r.vertices[0]);
    Vector_3d d1 = Vector_3d::Zero();
    for(int i = 0; i < 3; ++i)
    {
      const Local_frame& fi = frame(r.vertices[i]);
      // Principal directions are defined up to sign: align them before averaging.
      d1 += w[i] * (fi.d1.dot(f0.d1) < 0 ? Vector_3d(-fi.d1) : fi.d1);
      result.k1 += w[i] * fi.k1;
      result.k2 += w[i] * fi.k2;
    }
    d1 = tangential(d1, result.normal);
    result.d1 = d1.norm() > 1e-12 ? Vector_3d(d1.normalized()) : Vector_3d(result.normal.unitOrthogonal());
    result.d2 = result.normal.cross(result.d1);
    return result;
  }

  // A triangle incident to v (the null face for an isolated vertex).
  Face incident_face(Vertex v) const
  {
    const auto h0 = m_mesh.halfedge(v);
    if(h0 != Mesh::null_halfedge())
      for(auto h : halfedges_around_target(h0, m_mesh))
        if(!m_mesh.is_border(h))
          return m_mesh.face(h);
    return Mesh::null_face();
  }

  std::array<Vertex, 3> face_vertices(Face f) const { return m_faces[std::size_t(f)].vertices; }

  // Area-weighted vertex normal (unit, or zero for an isolated vertex).
  Vector_3d area_weighted_normal(Vertex v) const
  {
    Vector_3d n = Vector_3d::Zero();
    const auto h0 = m_mesh.halfedge(v);
    if(h0 == Mesh::null_halfedge())
      return n;
    for(auto h : halfedges_around_target(h0, m_mesh))
      if(!m_mesh.is_border(h))
        n += area_vector(point(m_mesh.target(h)), point(m_mesh.target(m_mesh.next(h))),
                         point(m_mesh.source(h)));
    return n.norm() > 0 ? Vector_3d(n.normalized()) : n;
  }

private:
  // What the descent reads of a triangle, in flat arrays: the reference never changes, and the
  // descent runs for every term of every energy evaluation.
  struct Face_record
  {
    std::array<Vertex, 3> vertices;  // in the order of the face's halfedges
    std::array<Face, 3> across;      // the triangle across the edge opposite vertices[i], or null
    unsigned char smooth_across = 0; // bit i: across[i] is within the smooth angle of this triangle
    bool needle = false;             // is_needle_or_cap
    std::array<signed char, 3> rise{}; // sign of the height of across[i]'s third vertex over the plane
    Vector_3d normal = Vector_3d::UnitZ();
    double offset = 0;                // the plane is normal . x = offset
    // e0.e0, e0.e1, e1.e1 for the edges e0, e1 from vertices[0], then 1 / the Gram determinant.
    std::array<double, 4> gram{};
  };

  Vector_3d project(const Vector_3d& x, Face f, std::array<double, 3>& weights) const
  {
    const Face_record& r = m_faces[std::size_t(f)];
    const Vector_3d& a = point(r.vertices[0]);
    if(!r.needle)
    {
      // Most queries are near the surface and project inside the triangle: barycentric
      // coordinates of the projection onto the plane from the triangle's Gram matrix.
      const Vector_3d e0 = point(r.vertices[1]) - a, e1 = point(r.vertices[2]) - a, ax = x - a;
      const double d0 = e0.dot(ax), d1 = e1.dot(ax);
      const double v = (r.gram[2] * d0 - r.gram[1] * d1) * r.gram[3];
      const double w = (r.gram[0] * d1 - r.gram[1] * d0) * r.gram[3];
      if(v > 0 && w > 0 && v + w < 1)
      {
        weights = {{1 - v - w, v, w}};
        return a + v * e0 + w * e1;
      }
    }
    return closest_point_on_triangle(x, a, point(r.vertices[1]), point(r.vertices[2]), weights, r.needle);
  }

  void collect_faces()
  {
    m_faces.assign(m_mesh.num_faces(), Face_record());
    for(Face f : m_mesh.faces())
    {
      Face_record& r = m_faces[std::size_t(f)];
      r.vertices = Graphcut_remeshing::face_vertices(m_mesh, f);
      r.needle = is_needle_or_cap(point(r.vertices[0]), point(r.vertices[1]), point(r.vertices[2]));
      const Vector_3d e0 = point(r.vertices[1]) - point(r.vertices[0]), e1 = point(r.vertices[2]) - point(r.vertices[0]);
      r.gram = {{e0.dot(e0), e0.dot(e1), e1.dot(e1), 0}};
      const double determinant = r.gram[0] * r.gram[2] - r.gram[1] * r.gram[1];
      if(!r.needle && determinant > 0)
        r.gram[3] = 1 / determinant;
      else
        r.needle = true; // no reliable interior either
      const auto h = m_mesh.halfedge(f);
      // The edge opposite vertices[i]: next(h) for 0, prev(h) for 1, h for 2.
      const std::array<typename Mesh::Halfedge_index, 3> side{{m_mesh.next(h), m_mesh.prev(h), h}};
      for(int i = 0; i < 3; ++i)
      {
        const auto o = m_mesh.opposite(side[i]);
        r.across[i] = m_mesh.is_border(o) ? Mesh::null_face() : m_mesh.face(o);
      }
    }
    for(Face f : m_mesh.faces())
    {
      Face_record& r = m_faces[std::size_t(f)];
      const Vector_3d n = face_area_vector(m_mesh, m_mesh.halfedge(f));
      for(int i = 0; i < 3; ++i)
        if(r.across[i] != Mesh::null_face())
        {
          const Vector_3d no = face_area_vector(m_mesh, m_mesh.halfedge(r.across[i]));
          if(n.dot(no) > m_smooth_cosine * n.norm() * no.norm())
            r.smooth_across |= static_cast<unsigned char>(1 << i);
        }
      r.normal = n.norm() > 0 ? Vector_3d(n.normalized()) : Vector_3d::Zero();
    }
  }

  // Principal curvatures, directions and normal from a degree-2 jet fitted to the 2-ring (a wider
  // ring where the 2-ring has fewer than the six points a quadric needs), oriented like the
  // area-weighted normal. Where no quadric can be fitted the frame is flat. Each vertex on its
  // own: the rings are small, membership is a search in the ring.
  void compute_frames()
  {
    m_frames.assign(m_mesh.num_vertices(), Local_frame());
    for_each_vertex(m_mesh, [&](Vertex v) { compute_frame(v, m_frames[std::size_t(v)]); });
  }

  void compute_frame(Vertex v, Local_frame& f) const
  {
    using K = CGAL::Simple_cartesian<double>;
    using Fitting = CGAL::Monge_via_jet_fitting<K>;
    std::vector<Vertex> ring, frontier, next_frontier;
    std::vector<K::Point_3> points;
    f.origin = point(v);
    const Vector_3d n = area_weighted_normal(v);
    if(n.norm() > 0)
    {
      f.normal = n;
      f.d1 = n.unitOrthogonal();
      f.d2 = n.cross(f.d1);
    }
    if(m_mesh.halfedge(v) == Mesh::null_halfedge())
      return;

    ring.assign(1, v);
    frontier.assign(1, v);
    for(int depth = 0; depth < 4 && !frontier.empty() && (depth < 2 || ring.size() < 6); ++depth)
    {
      next_frontier.clear();
      for(Vertex u : frontier)
        for(auto h : halfedges_around_target(m_mesh.halfedge(u), m_mesh))
        {
          const Vertex w = m_mesh.source(h);
          if(std::find(ring.begin(), ring.end(), w) == ring.end())
          {
            ring.push_back(w);
            next_frontier.push_back(w);
          }
        }
      frontier.swap(next_frontier);
    }
    if(ring.size() < 6 || !(n.norm() > 0))
      return;

    for(Vertex u : ring)
      points.push_back(m_mesh.point(u));
    Fitting fitting;
    typename Fitting::Monge_form form = fitting(points.begin(), points.end(), 2, 2);
    form.comply_wrt_given_normal(K::Vector_3(n.x(), n.y(), n.z()));
    const K::Vector_3 d1 = form.maximal_principal_direction(), d2 = form.minimal_principal_direction();
    const K::Vector_3 normal = form.normal_direction();
    const double k1 = form.principal_curvatures(0), k2 = form.principal_curvatures(1);
    if(!std::isfinite(k1) || !std::isfinite(k2))
      return;
    f.normal = Vector_3d(normal.x(), normal.y(), normal.z()).normalized();
    f.d1 = Vector_3d(d1.x(), d1.y(), d1.z()).normalized();
    f.d2 = Vector_3d(d2.x(), d2.y(), d2.z()).normalized();
    // Keep d1 along the curvature of larger magnitude.
    if(std::abs(k2) > std::abs(k1))
    {
      std::swap(f.d1, f.d2);
      f.k1 = k2;
      f.k2 = k1;
    }
    else
    {
      f.k1 = k1;
      f.k2 = k2;
    }
  }

  const Mesh& m_mesh;
  std::vector<Face_record> m_faces;    // by face
  std::vector<Local_frame> m_frames;
  double m_smooth_cosine;
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_REFERENCE_SURFACE_H
