// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Section 3: smooth local changes of the connectivity (edge flips, splits, collapses, then vertex
// splits), each kept only when it improves its own criterion, and the relaxation of the vertex
// positions. Sharp, border and constrained edges are never flipped or collapsed and no collapse
// or relaxation touches a vertex on one; a long sharp edge may be split at a point of its
// reference polyline. With a re-sampling sizing (`resampling`), edges are split and collapsed to
// their target lengths first, also where the surface is curved and along feature lines; with a
// length asked for coarser than the input, the reference vertices farthest from the mesh then get
// vertices.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_CONNECTIVITY_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_CONNECTIVITY_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/candidates.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/energy.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/features.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/parallel.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/reference_surface.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/sizing.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/tracking.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/version.h>
#if CGAL_VERSION_NR >= 1060000000
#include <CGAL/AABB_traits_3.h>
#else
#include <CGAL/AABB_traits.h>
#endif

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <functional>
#include <initializer_list>
#include <limits>
#include <queue>
#include <tuple>
#include <utility>
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

inline double smallest_angle(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c)
{
  const std::array<double, 3> angles = triangle_angles(a, b, c);
  return (std::min)({angles[0], angles[1], angles[2]});
}

struct Connectivity_counts
{
  std::size_t flips = 0;
  std::size_t splits = 0;
  std::size_t collapses = 0;
  std::size_t vertex_splits = 0;
  std::size_t relaxed = 0;
};

// Which operations a pass makes (CGAL's do_split, which also covers the vertex splits that add
// a vertex, do_collapse and do_flip) and how many relaxation sweeps end it.
struct Connectivity_operations
{
  bool split = true;
  bool collapse = true;
  bool flip = true;
  std::size_t relaxation_steps = 1;
};

class Connectivity_optimizer
{
  using Vertex = Work_mesh::Vertex_index;
  using Halfedge = Work_mesh::Halfedge_index;
  using Edge = Work_mesh::Edge_index;
  using Face = Work_mesh::Face_index;
  using Location = Feature_polylines<Work_mesh>::Location;

public:
  // Collapses only of edges whose dihedral angle is below this, in degrees (section 3.1).
  static constexpr double flat_dihedral = 10;
  // A valence-improving flip whose six angles stay above this is kept (see flip_gain).
  static constexpr double flip_angle_floor = 25 * pi / 180;
  // The least growth of an angle that counts as an improvement (0.01 degree).
  static constexpr double min_angle_margin = 0.01 * pi / 180;
  // Beyond the paper: no operation and no relaxation step turns a triangle by more than 60
  // degrees (this cosine) from the surface it replaces. Where the sampling is fine enough for the
  // shape none needs to; more folds a thin triangle along a crease or a stretched part, where the
  // reference's normal alone can be either side's.
  static constexpr double min_turn_cosine = 0.5;
  // With a coarse length asked for, the reference vertices this share of the farthest one's
  // distance from the mesh, or farther, get a vertex (cover_reference()).
  static constexpr double cover_share_of_worst = 0.8;
  // ... and as far as cover_outlier_ratio times the distance that this share of the reference
  // vertices keep within.
  static constexpr double cover_typical_rank = 0.9;
  static constexpr double cover_outlier_ratio = 2;
  // How far from the mesh towards such a vertex the new vertex goes: all the way, else, where its
  // triangles would fold, part of the way.
  static constexpr std::array<double, 3> cover_shares{{1.0, 0.75, 0.5}};
  // The valence up to which a vertex split tries every way to cut the ring in two.
  static constexpr std::size_t max_exhaustive_split = 12;

  // local_energy(v, x, bound): the energy, or once it is known to reach `bound`, a value between
  // `bound` and the energy (the rest need not be evaluated).
  using Local_energy = std::function<double(Vertex, const Vector_3d&, double)>;

  // `polylines`, the reference's feature polylines, lets long sharp edges be split (none are
  // without it); `local_energy(v, x)`, the terms of eq. (1) that depend on the position x of v
  // (eq. 7), lets the relaxation keep only the moves that do not raise it.
  Connectivity_optimizer(Work_mesh& mesh, const Reference_surface<Work_mesh>& reference,
                         Tracking_state& state, const Sizing& sizing,
                         const Feature_polylines<Work_mesh>* polylines = nullptr,
                         Local_energy local_energy = Local_energy(),
                         Connectivity_operations operations = Connectivity_operations())
    : m_mesh(mesh), m_reference(reference), m_state(state), m_sizing(sizing), m_polylines(polylines),
      m_local_energy(std::move(local_energy)), m_operations(operations)
  {
    fit_arrays();
  }

  // One pass of section 3: flips, splits, collapses, vertex splits, then relaxation. When the
  // sizing re-samples the surface, the splits and collapses bring every edge within 4/5 and 4/3 of
  // its target first, as CGAL's incremental remesher does, the reference's farthest vertices get
  // vertices when the length asked for is coarser than the input's, and the flips follow.
  Connectivity_counts run()
  {
    Connectivity_counts counts;
    const Connectivity_operations& op = m_operations;
    if(m_sizing.resamples())
    {
      counts.splits = op.split ? split_edges() : 0;
      counts.collapses = op.collapse ? collapse_edges() : 0;
      if(m_sizing.covers_reference && op.split)
        counts.splits += cover_reference();
      counts.flips = op.flip ? flip_edges() : 0;
    }
    else
    {
      counts.flips = op.flip ? flip_edges() : 0;
      counts.splits = op.split ? split_edges() : 0;
      counts.collapses = op.collapse ? collapse_edges() : 0;
    }
    counts.vertex_splits = op.split ? split_vertices() : 0;
    for(std::size_t k = 0; k < op.relaxation_steps; ++k)
      counts.relaxed += relax();
    return counts;
  }

  // The coverings alone, once the relocation is over (Graphcut_remesher::run()): where the
  // reference still stands out from the mesh (cover_reference()) and the mesh from the reference
  // (cover_chords()).
  Connectivity_counts cover_what_stands_out()
  {
    Connectivity_counts counts;
    if(!m_operations.split)
      return counts;
    counts.splits = cover_reference();
    counts.splits += cover_chords();
    return counts;
  }

  // --- edge flips: the smallest of the six angles must grow, the valence deviation not rise ---

  // The gain in smallest angle of flipping e, or a non-positive value when e may not be flipped.
  double flip_gain(Edge e) const
  {
    if(!flippable(e))
      return 0;
    const Halfedge h = m_mesh.halfedge(e), o = m_mesh.opposite(h);
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
    const Vertex c = m_mesh.target(m_mesh.next(h)), d = m_mesh.target(m_mesh.next(o));
    if(c == d || m_mesh.halfedge(c, d) != Work_mesh::null_halfedge())
      return 0;
    if(m_mesh.degree(a) < 4 || m_mesh.degree(b) < 4)
      return 0;
    const int change = deviation_change(a, -1) + deviation_change(b, -1) + deviation_change(c, +1) +
                       deviation_change(d, +1);
    if(change > 0)
      return 0;
    const Vector_3d pa = position(a), pb = position(b), pc = position(c), pd = position(d);
    // (a, b, c) and (b, a, d) become (a, d, c) and (d, b, c).
    const Vector_3d quad = area_vector(pa, pb, pc) + area_vector(pb, pa, pd);
    if(!acceptable(pa, pd, pc, a, quad) || !acceptable(pd, pb, pc, b, quad))
      return 0;
    // The new edge must not leave the reference more than the old one did.
    const double before = distance_to_reference((pa + pb) / 2, a);
    const double after = distance_to_reference((pc + pd) / 2, c);
    if(after > (std::max)(before, m_sizing.tolerance))
      return 0;
    const double old_min = (std::min)(smallest_angle(pa, pb, pc), smallest_angle(pb, pa, pd));
    const double new_min = (std::min)(smallest_angle(pa, pd, pc), smallest_angle(pd, pb, pc));
    // Section 3.1's smooth flip where the valence stays as regular: the six angles' minimum must
    // grow, by a margin so that rounding cannot make two flips undo each other. (The paper only
    // tries flips that make the valence more regular; around the corners of an organic mesh
    // those are rare and its triangles would stay thin.)
    if(change == 0)
      return new_min - old_min - min_angle_margin;
    // Beyond the paper: a flip that makes the valence more regular is also kept when its
    // triangles stay well shaped; the relocation then improves them (the min-angle rule alone
    // leaves most irregular vertices).
    if(new_min >= flip_angle_floor)
      return (std::max)(new_min - old_min, 0.0) + 1e-3 * (new_min - flip_angle_floor + 1e-9);
    return new_min - old_min;
  }

  std::size_t flip_edges()
  {
    std::size_t done = 0;
    run_queue([&](Edge e) { return flip_gain(e); }, [&](Edge e) { return flip_gain(e); },
              [&](Edge e) {
                const Halfedge h = m_mesh.halfedge(e);
                std::vector<Vertex> touched{{m_mesh.source(h), m_mesh.target(h),
                                             m_mesh.target(m_mesh.next(h)),
                                             m_mesh.target(m_mesh.next(m_mesh.opposite(h)))}};
                CGAL::Euler::flip_edge(h, m_mesh);
                for(Face f : {m_mesh.face(h), m_mesh.face(m_mesh.opposite(h))})
                  m_state.face_hint[std::size_t(f)] = m_state.vertex_hint[std::size_t(m_mesh.target(h))];
                ++done;
                return touched;
              });
    return done;
  }

  // --- edge splits of long edges: the worst split quality must improve ---

  // A sharp edge is split at the point of its reference polyline halfway between its ends, which
  // `on_feature` receives; other edges at their midpoint brought onto the reference.
  double split_gain(Edge e, Vector_3d& new_point, Location& on_feature) const
  {
    const char feature = m_state.feature_edge[std::size_t(e)];
    // Border edges are re-sampled only with the re-sampling sizing.
    if((m_mesh.is_border(e) && !m_sizing.resamples()) || feature == Tracking_state::constrained_edge ||
       (feature && !m_polylines))
      return 0;
    const Halfedge h = face_side(e), o = m_mesh.opposite(h);
    const bool two_faces = !m_mesh.is_border(o);
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
    if(is_frozen(a) || is_frozen(b))
      return 0;
    const Vertex c = m_mesh.target(m_mesh.next(h)), d = two_faces ? m_mesh.target(m_mesh.next(o)) : c;
    const Vector_3d pa = position(a), pb = position(b), pc = position(c), pd = position(d);
    const double length = (pa - pb).norm();
    if(!(length > 4.0 / 3.0 * edge_length_target(a, b)))
      return 0;
    if(feature)
    {
      on_feature = feature_midpoint(a, b);
      new_point = m_polylines->point(on_feature);
      // The polyline between a and b may be far from straight: the new vertex must still fall
      // well inside the edge's span.
      if(!((new_point - pa).norm() > length / 4 && (new_point - pb).norm() > length / 4))
        return 0;
    }
    else
      new_point = project((pa + pb) / 2, a);
    const Vector_3d& p = new_point;
    const Vector_3d abc = area_vector(pa, pb, pc), bad = area_vector(pb, pa, pd);
    if(!acceptable(pa, p, pc, a, abc) || !acceptable(p, pb, pc, b, abc) ||
       (two_faces && (!acceptable(pb, p, pd, b, bad) || !acceptable(p, pa, pd, a, bad))))
      return 0;
    if(m_sizing.resamples())
    {
      // Re-sampling: the longest edges first, relative to their target. The surface may bend
      // the midpoint far from the chord (next to a crease it lands on the crease, and splitting
      // would never shorten the edge), and the new triangles may not be much thinner than the
      // ones they cut.
      if(!feature && !((p - (pa + pb) / 2).norm() <= length / 4))
        return 0;
      double old_min = smallest_angle(pa, pb, pc), new_min = (std::min)(smallest_angle(pa, p, pc), smallest_angle(p, pb, pc));
      if(two_faces)
      {
        old_min = (std::min)(old_min, smallest_angle(pb, pa, pd));
        new_min = (std::min)({new_min, smallest_angle(pb, p, pd), smallest_angle(p, pa, pd)});
      }
      if(!(new_min >= 0.5 * old_min))
        return 0;
      return length / edge_length_target(a, b) - 4.0 / 3.0;
    }
    const double old_q = (std::min)(split_quality(pa, pb, pc), split_quality(pb, pa, pd));
    const double new_q = (std::min)({split_quality(pa, p, pc), split_quality(p, pb, pc),
                                     split_quality(pb, p, pd), split_quality(p, pa, pd)});
    return new_q - old_q;
  }

  std::size_t split_edges()
  {
    std::size_t done = 0;
    Vector_3d p;
    Location on_feature;
    run_queue([&](Edge e) { return split_gain(e, p, on_feature); },
              [&](Edge e) {
                Vector_3d q;
                Location l;
                return split_gain(e, q, l);
              },
              [&](Edge e) {
                const Halfedge h = face_side(e);
                const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
                const Vertex v = split_edge_at(h, p, on_feature);
                ++done;
                std::vector<Vertex> touched{{a, b, v}};
                for(Vertex w : vertices_around_target(m_mesh.halfedge(v), m_mesh))
                  touched.push_back(w);
                return touched;
              });
    return done;
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
    fit_arrays();
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
    for(Halfedge g : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      if(!m_mesh.is_border(g))
        m_state.face_hint[std::size_t(m_mesh.face(g))] = m_state.vertex_hint[std::size_t(v)];
    return v;
  }

  // --- covering: vertices where the mesh has cut off a tip or a rim of the reference ---

  // Beyond the paper: the data terms measure how far the mesh is from the reference, not how far
  // the reference is from the mesh, and the relocation may slide the vertex of a thin tip or rim
  // down its side: the triangles then cut the tip off while every vertex and centroid stays near
  // the surface. When the user asked for a length coarser than the input's, the reference vertices
  // that stand out, within cover_share_of_worst of the farthest from the mesh and far beyond most,
  // each get a vertex, at themselves, the farthest first and one per neighbourhood. Returns the
  // number of vertices added.
  std::size_t cover_reference()
  {
    using Primitive = CGAL::AABB_face_graph_triangle_primitive<Work_mesh>;
#if CGAL_VERSION_NR >= 1060000000
    using Tree = CGAL::AABB_tree<CGAL::AABB_traits_3<Work_kernel, Primitive> >;
#else
    using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Work_kernel, Primitive> >;
#endif
    Tree tree(faces(m_mesh).first, faces(m_mesh).second, m_mesh);
    tree.build();
    tree.accelerate_distance_queries();
    const Work_mesh& reference = m_reference.mesh();
    std::vector<double> distance(reference.num_vertices(), 0);
    std::vector<Face> nearest(reference.num_vertices());
    std::vector<Vector_3d> closest(reference.num_vertices());
    for_each_vertex(reference, [&](Vertex r) {
      const Vector_3d x = m_reference.point(r);
      const auto hit = tree.closest_point_and_primitive(Work_kernel::Point_3(x.x(), x.y(), x.z()));
      closest[std::size_t(r)] = to_vector(hit.first);
      distance[std::size_t(r)] = (closest[std::size_t(r)] - x).norm();
      nearest[std::size_t(r)] = hit.second;
    });
    std::vector<char> changed_near(m_mesh.num_faces(), 0);
    std::size_t added = 0;
    for(std::size_t i : standing_out(distance))
    {
      const Face f = nearest[i];
      if(changed_near[std::size_t(f)])
        continue;
      const Vertex v = cover_toward(f, closest[i], m_reference.point(Vertex(Work_mesh::size_type(i))));
      if(v == Vertex())
        continue;
      ++added;
      mark_neighbourhood(v, changed_near);
    }
    return added;
  }

  // Beyond the paper, the other way round: an edge of the mesh may cut across a crease or a
  // hollow of the reference that the coarse target hides, while its ends, and the centroids the
  // data terms see, stay on the surface. Once the relocation is over (Graphcut_remesher::run()),
  // the edges whose midpoints stand out from the reference as cover_reference()'s vertices do
  // get a vertex on the reference below the midpoint, or part of the way there, one per
  // neighbourhood. Feature edges keep to their lines and borders are not moved off. Returns the
  // number of vertices added.
  std::size_t cover_chords()
  {
    std::vector<Edge> edges;
    std::vector<double> distance;
    std::vector<Vector_3d> below;
    for(Edge e : m_mesh.edges())
    {
      if(m_state.feature_edge[std::size_t(e)] || m_mesh.is_border(e))
        continue;
      const Halfedge h = m_mesh.halfedge(e);
      const Vector_3d middle = (position(m_mesh.source(h)) + position(m_mesh.target(h))) / 2;
      edges.push_back(e);
      below.push_back(project(middle, m_mesh.source(h)));
      distance.push_back((below.back() - middle).norm());
    }
    std::vector<char> changed_near(m_mesh.num_faces(), 0);
    std::size_t added = 0;
    for(std::size_t i : standing_out(distance))
    {
      const Halfedge h = m_mesh.halfedge(edges[i]);
      const Face f = m_mesh.face(h);
      if(changed_near[std::size_t(f)] || changed_near[std::size_t(m_mesh.face(m_mesh.opposite(h)))])
        continue;
      const Vector_3d middle = (position(m_mesh.source(h)) + position(m_mesh.target(h))) / 2;
      const Vertex v = cover_toward(f, middle, below[i]);
      if(v == Vertex())
        continue;
      ++added;
      mark_neighbourhood(v, changed_near);
    }
    return added;
  }

  // The indices of the distances that stand out, the largest first: within cover_share_of_worst
  // of the largest and far beyond most (on a sphere or a tube every chord leaves the surface
  // alike, and vertices there would only make the mesh denser than the length asked for).
  static std::vector<std::size_t> standing_out(const std::vector<double>& distance)
  {
    std::vector<std::size_t> far;
    if(distance.empty())
      return far;
    const double worst = *std::max_element(distance.begin(), distance.end());
    std::vector<double> sorted = distance;
    const std::size_t typical_rank = std::size_t(cover_typical_rank * double(sorted.size() - 1));
    std::nth_element(sorted.begin(), sorted.begin() + typical_rank, sorted.end());
    const double bound = (std::max)(cover_share_of_worst * worst, cover_outlier_ratio * sorted[typical_rank]);
    for(std::size_t i = 0; i < distance.size(); ++i)
      if(distance[i] > 0 && distance[i] >= bound)
        far.push_back(i);
    std::stable_sort(far.begin(), far.end(), [&](std::size_t i, std::size_t j) { return distance[i] > distance[j]; });
    return far;
  }

  // A vertex for the triangle f at `to`, or, where its triangles would fold over, part of the way
  // there from `from` (cover_shares); none (a null vertex) when no way keeps acceptable triangles.
  Vertex cover_toward(Face f, const Vector_3d& from, const Vector_3d& to)
  {
    for(double share : cover_shares)
    {
      const Vertex v = cover(f, from + share * (to - from));
      if(v != Vertex())
        return v;
    }
    return Vertex();
  }

  // Marks the triangles around v's neighbours, where a covering has changed the mesh.
  void mark_neighbourhood(Vertex v, std::vector<char>& changed_near) const
  {
    changed_near.resize(m_mesh.num_faces(), 0);
    for(Vertex w : vertices_around_target(m_mesh.halfedge(v), m_mesh))
      for(Halfedge g : halfedges_around_target(m_mesh.halfedge(w), m_mesh))
        if(!m_mesh.is_border(g))
          changed_near[std::size_t(m_mesh.face(g))] = 1;
  }

  // A vertex at x for the triangle f: on the side of f whose split keeps the best triangles, or
  // inside f; none (a null vertex) when no way keeps acceptable triangles.
  Vertex cover(Face f, const Vector_3d& x)
  {
    const Halfedge h0 = m_mesh.halfedge(f);
    for(Halfedge h : halfedges_around_face(h0, m_mesh))
      if(is_frozen(m_mesh.target(h)))
        return Vertex();
    double best = 0;
    Halfedge best_h;
    for(Halfedge h : halfedges_around_face(h0, m_mesh))
    {
      if(m_state.feature_edge[std::size_t(m_mesh.edge(h))])
        continue;
      const Halfedge o = m_mesh.opposite(h);
      const Vertex a = m_mesh.source(h), b = m_mesh.target(h), c = m_mesh.target(m_mesh.next(h));
      const Vector_3d pa = position(a), pb = position(b), pc = position(c);
      const Vector_3d abc = area_vector(pa, pb, pc);
      if(!acceptable(pa, x, pc, a, abc) || !acceptable(x, pb, pc, b, abc))
        continue;
      boost::container::small_vector<Halfedge, 4> link{m_mesh.next(h), m_mesh.prev(h)};
      if(!m_mesh.is_border(o))
        link.insert(link.end(), {m_mesh.next(o), m_mesh.prev(o)});
      if(!fan_unfolded(link, x))
        continue;
      double smallest = (std::min)(smallest_angle(pa, x, pc), smallest_angle(x, pb, pc));
      if(!m_mesh.is_border(o))
      {
        const Vector_3d pd = position(m_mesh.target(m_mesh.next(o)));
        const Vector_3d bad = area_vector(pb, pa, pd);
        if(is_frozen(m_mesh.target(m_mesh.next(o))) || !acceptable(pb, x, pd, b, bad) || !acceptable(x, pa, pd, a, bad))
          continue;
        smallest = (std::min)({smallest, smallest_angle(pb, x, pd), smallest_angle(x, pa, pd)});
      }
      if(smallest > best)
      {
        best = smallest;
        best_h = h;
      }
    }
    // Inside f: three triangles.
    {
      const std::array<Vertex, 3> t = face_vertices(m_mesh, f);
      const Vector_3d p0 = position(t[0]), p1 = position(t[1]), p2 = position(t[2]);
      const Vector_3d n = area_vector(p0, p1, p2);
      if(acceptable(p0, p1, x, t[0], n) && acceptable(p1, p2, x, t[1], n) && acceptable(p2, p0, x, t[2], n) &&
         fan_unfolded(std::array<Halfedge, 3>{{h0, m_mesh.next(h0), m_mesh.prev(h0)}}, x))
      {
        const double smallest = (std::min)({smallest_angle(p0, p1, x), smallest_angle(p1, p2, x), smallest_angle(p2, p0, x)});
        if(smallest > best)
        {
          const Vertex from = t[0];
          const Halfedge hv = CGAL::Euler::add_center_vertex(h0, m_mesh);
          const Vertex v = m_mesh.target(hv);
          m_mesh.point(v) = Work_kernel::Point_3(x.x(), x.y(), x.z());
          fit_arrays();
          for(Halfedge g : halfedges_around_target(hv, m_mesh))
            m_state.feature_edge[std::size_t(m_mesh.edge(g))] = 0;
          bind_new_vertex(v, from);
          for(Halfedge g : halfedges_around_target(hv, m_mesh))
            if(!m_mesh.is_border(g))
              m_state.face_hint[std::size_t(m_mesh.face(g))] = m_state.vertex_hint[std::size_t(v)];
          return v;
        }
      }
    }
    if(best_h == Halfedge())
      return Vertex();
    return split_edge_at(best_h, x, Location());
  }

  // Whether the triangles (source(g), target(g), x) that an operation makes, one for each halfedge
  // g of `link` (g on the triangle it replaces), fold (guarantees.h) neither onto each other,
  // across their edges at x, nor onto the triangles across the g: a vertex placed or moved off the
  // mesh (on a tip, on a coarse tube) may turn a new triangle over its neighbour. The vertex at x
  // replaces those of `replaced`; an edge that was folded already or is a feature edge may stay
  // folded, as the guarantee allows.
  template <typename Link>
  bool fan_unfolded(const Link& link, const Vector_3d& x, std::initializer_list<Vertex> replaced = {}) const
  {
    const auto exempt = [&](Halfedge h) {
      return m_state.feature_edge[std::size_t(m_mesh.edge(h))] || is_folded_edge(m_mesh, h);
    };
    const auto exempt_at_x = [&](Vertex w) {
      for(Vertex u : replaced)
      {
        const Halfedge h = m_mesh.halfedge(u, w);
        if(h != Work_mesh::null_halfedge() && exempt(h))
          return true;
      }
      return false;
    };
    boost::container::small_vector<Vector_3d, 16> fan;
    for(Halfedge g : link)
    {
      fan.push_back(area_vector(position(m_mesh.source(g)), position(m_mesh.target(g)), x));
      const Halfedge across = m_mesh.opposite(g);
      if(!m_mesh.is_border(across) && is_folded_pair(fan.back(), face_area_vector(m_mesh, across)) && !exempt(g))
        return false;
    }
    for(std::size_t k = 0; k < link.size(); ++k)
      for(std::size_t j = 0; j < link.size(); ++j)
        if(m_mesh.target(link[k]) == m_mesh.source(link[j]) && is_folded_pair(fan[k], fan[j]) &&
           !exempt_at_x(m_mesh.target(link[k])))
          return false;
    return true;
  }

  // --- collapses of short edges in flat regions: the smallest angle must grow ---

  double collapse_gain(Edge e, Vector_3d& new_point) const
  {
    const Halfedge h = m_mesh.halfedge(e), o = m_mesh.opposite(h);
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
    if(!is_free(a) || !is_free(b) || m_mesh.is_border(e))
      return 0;
    const Vertex c = m_mesh.target(m_mesh.next(h)), d = m_mesh.target(m_mesh.next(o));
    const Vector_3d pa = position(a), pb = position(b);
    if(!((pa - pb).norm() < 4.0 / 5.0 * edge_length_target(a, b)))
      return 0;
    if(m_mesh.degree(c) < 4 || m_mesh.degree(d) < 4)
      return 0;
    const int merged = int(m_mesh.degree(a) + m_mesh.degree(b)) - 4;
    const int change = std::abs(merged - 6) - std::abs(int(m_mesh.degree(a)) - 6) -
                       std::abs(int(m_mesh.degree(b)) - 6) + deviation_change(c, -1) +
                       deviation_change(d, -1);
    if(change >= 0 || merged < 4)
      return 0;
    if(!(dihedral_angle(m_mesh, e) < flat_dihedral))
      return 0;
    if(!CGAL::Euler::does_satisfy_link_condition(e, m_mesh))
      return 0;
    // The triangles that stay, around a and b, before and after; the merged vertex goes to a, b
    // or the midpoint brought onto the reference, whichever gives the largest smallest angle.
    const double old_min = smallest_angle_around(a, b);
    double best = -1;
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
      if(ok && new_min - old_min > best)
      {
        best = new_min - old_min;
        new_point = x;
      }
    }
    return best;
  }

  std::size_t collapse_edges()
  {
    if(m_sizing.resamples())
      return resampling_collapses();
    std::size_t done = 0;
    Vector_3d p;
    run_queue([&](Edge e) { return collapse_gain(e, p); },
              [&](Edge e) {
                Vector_3d q;
                return collapse_gain(e, q);
              },
              [&](Edge e) {
                const Vertex v = CGAL::Euler::collapse_edge(e, m_mesh);
                m_mesh.point(v) = Work_kernel::Point_3(p.x(), p.y(), p.z());
                bind_new_vertex(v, v);
                std::vector<Vertex> touched{v};
                for(Halfedge g : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
                {
                  touched.push_back(m_mesh.source(g));
                  m_state.face_hint[std::size_t(m_mesh.face(g))] = m_state.vertex_hint[std::size_t(v)];
                }
                ++done;
                return touched;
              });
    return done;
  }

  // --- re-sampling collapses: edges shorter than 4/5 of their target, also where the surface is
  // curved and along feature lines, as long as the new triangles stay near the reference ---

  struct Collapse
  {
    Vertex removed, kept;
    Vector_3d point; // where the kept vertex goes
    bool to_line_midpoint = false; // the kept vertex slides to `on_line`, the point of its line
    Location on_line{};
  };

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

  // A feature edge shortens its line by removing an end that slides on it, where the line runs
  // on: the end has no other feature edge than the next one along, the line turns there by less
  // than the corner angle, and the shortened line keeps within the tolerance of the reference
  // polyline between its ends.
  bool feature_collapse_ends(Edge e, Collapse& c) const
  {
    const double min_cosine = std::cos(m_sizing.corner_angle * pi / 180);
    const Halfedge h = m_mesh.halfedge(e);
    double best = min_cosine;
    bool found = false;
    for(const auto& ends : {std::make_pair(m_mesh.source(h), m_mesh.target(h)),
                            std::make_pair(m_mesh.target(h), m_mesh.source(h))})
    {
      const Vertex r = ends.first, k = ends.second;
      Vertex x;
      if(m_state.kind[std::size_t(r)] != Vertex_kind::feature_vertex || feature_degree(r, e, x) != 2 || x == k)
        continue;
      // A user's constrained edge keeps its ends.
      if(m_state.feature_edge[std::size_t(m_mesh.edge(m_mesh.halfedge(r, x)))] == Tracking_state::constrained_edge)
        continue;
      const Vector_3d pr = position(r), pk = position(k), px = position(x);
      const double turn = (pr - pk).normalized().dot((px - pr).normalized());
      if(!(turn > best) || (pk - px).norm() > 4.0 / 3.0 * edge_length_target(k, x))
        continue;
      if(!(m_polylines->chord_deviation(feature_location(k), feature_location(x), 2 * (pk - px).norm()) <=
           tolerance_for((pk - px).norm(), edge_length_target(k, x))))
        continue;
      best = turn;
      found = true;
      c = Collapse{r, k, pk};
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
  bool feature_collapse_midpoint(Edge e, Collapse& c) const
  {
    const double min_cosine = std::cos(m_sizing.corner_angle * pi / 180);
    const Halfedge h = m_mesh.halfedge(e);
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
    Vertex xa = a, xb = b;
    for(Vertex v : {a, b})
      if(m_state.kind[std::size_t(v)] != Vertex_kind::feature_vertex)
        return false;
    if(feature_degree(a, e, xa) != 2 || feature_degree(b, e, xb) != 2 || xa == b || xb == a || xa == xb)
      return false;
    const Vector_3d pa = position(a), pb = position(b), pxa = position(xa), pxb = position(xb);
    if(!((pa - pxa).normalized().dot((pb - pa).normalized()) > min_cosine) ||
       !((pb - pa).normalized().dot((pxb - pb).normalized()) > min_cosine))
      return false;
    // As for a split of a sharp edge: the polyline between a and b may be far from straight, and
    // the point must still fall well inside the segment's span.
    const Location middle = feature_midpoint(a, b);
    const Vector_3d pm = m_polylines->point(middle);
    const double length = (pa - pb).norm();
    if(!((pm - pa).norm() > length / 4 && (pm - pb).norm() > length / 4))
      return false;
    for(const auto& end : {std::make_pair(a, xa), std::make_pair(b, xb)})
    {
      // A user's constrained edge keeps its ends.
      if(m_state.feature_edge[std::size_t(m_mesh.edge(m_mesh.halfedge(end.first, end.second)))] ==
         Tracking_state::constrained_edge)
        return false;
      const double chord = (pm - position(end.second)).norm(), target = edge_length_target(end.first, end.second);
      if(chord > 4.0 / 3.0 * target ||
         !(m_polylines->chord_deviation(middle, feature_location(end.second), 2 * chord) <= tolerance_for(chord, target)))
        return false;
    }
    c = Collapse{a, b, pm, true, middle};
    return true;
  }

  // The smallest angle of the triangles around a and b.
  double smallest_angle_around(Vertex a, Vertex b) const
  {
    double smallest = pi;
    for(Vertex u : {a, b})
      for(Halfedge g : halfedges_around_target(m_mesh.halfedge(u), m_mesh))
        if(!m_mesh.is_border(g))
          smallest = (std::min)(smallest, smallest_angle(position(u), position(m_mesh.target(m_mesh.next(g))),
                                                         position(m_mesh.source(g))));
    return smallest;
  }

  // The smallest angle of the triangles around c.removed and c.kept that stay, with both at
  // c.point, or -1 when one of them is not acceptable, leaves the reference by more than the
  // tolerance or has an edge longer than 4/3 of its target (a split would undo the collapse).
  // When the user asked for a length (whose tolerance grows with the triangles, see
  // tolerance_for()), the removed vertex, and the kept one where it was when it moves, must also
  // stay within the tolerance of one of the new triangles: their centroids alone may keep near
  // the surface while a tip or a rim between them is cut off.
  double collapsed_smallest_angle(const Collapse& c) const
  {
    double smallest = pi;
    const Vector_3d gone = position(c.removed), was = position(c.kept);
    bool gone_covered = !m_sizing.target_asked_for, was_covered = !m_sizing.target_asked_for || was == c.point;
    boost::container::small_vector<Halfedge, 16> link;
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
        const double allowed = tolerance_for(longest, target);
        if((c.point - pp).norm() > 4.0 / 3.0 * target || !acceptable(c.point, pq, pp, u, area_vector(position(u), pq, pp)) ||
           distance_to_reference((c.point + pp + pq) / 3, c.kept) > allowed)
          return -1;
        smallest = (std::min)(smallest, smallest_angle(c.point, pq, pp));
        std::array<double, 3> barycentric;
        gone_covered = gone_covered || (gone - closest_point_on_triangle(gone, c.point, pq, pp, barycentric)).norm() <= allowed;
        was_covered = was_covered || (was - closest_point_on_triangle(was, c.point, pq, pp, barycentric)).norm() <= allowed;
      }
    return gone_covered && was_covered && fan_unfolded(link, c.point, {c.removed, c.kept}) ? smallest : -1;
  }

  double resampling_collapse_gain(Edge e, Collapse& c) const
  {
    const char feature = m_state.feature_edge[std::size_t(e)];
    const Halfedge h = m_mesh.halfedge(e);
    const Vertex a = m_mesh.source(h), b = m_mesh.target(h);
    if(feature == Tracking_state::constrained_edge || is_frozen(a) || is_frozen(b))
      return 0;
    const Vector_3d pa = position(a), pb = position(b);
    const double length = (pa - pb).norm(), target = edge_length_target(a, b);
    if(!(length < 4.0 / 5.0 * target))
      return 0;
    // When the user asked for a density: a free edge with one end on a feature line or fixed, the
    // free end goes to the other, which stays where it is. A coarse target needs these collapses
    // (without them the lines' neighbours hold their vertices: cow at twice its mean edge length
    // kept 1616 vertices, 1500 with them); at the input's density they only thin the triangles
    // next to the lines (handle: 1.3 % of its triangles below 30 degrees instead of 0.4 %).
    const bool into_feature = m_sizing.into_lines && !feature && is_free(a) != is_free(b);
    // The ways to collapse e: where the kept vertex goes.
    boost::container::small_vector<Collapse, 3> trials;
    if(into_feature)
      trials.push_back(is_free(a) ? Collapse{a, b, pb} : Collapse{b, a, pa});
    else if(feature)
    {
      Collapse f;
      if(m_polylines && feature_collapse_ends(e, f))
        trials.push_back(f);
      if(m_sizing.into_lines && m_polylines && feature_collapse_midpoint(e, f))
        trials.push_back(f);
    }
    else if(!(is_free(a) && is_free(b)))
      return 0;
    if(feature && trials.empty())
      return 0;
    // The triangles on e go; their far vertices keep three edges (two on a border, where one
    // triangle is enough, when the user asked for a density: a strip two triangles wide is made
    // of such vertices), and no two feature edges merge (the free end of a collapse into a line
    // has none). When the user asked for a density, a feature edge's triangle may have one
    // feature edge beside it, which the merged edge carries on: a line leaving a corner next to a
    // short segment (fandisk at four times its mean edge length kept 15 such segments shorter
    // than half their target), or the next segment of the line at an ear.
    for(Halfedge g : {h, m_mesh.opposite(h)})
      if(!m_mesh.is_border(g))
      {
        const int wings = (m_state.feature_edge[std::size_t(m_mesh.edge(m_mesh.next(g)))] ? 1 : 0) +
                          (m_state.feature_edge[std::size_t(m_mesh.edge(m_mesh.prev(g)))] ? 1 : 0);
        const Vertex far = m_mesh.target(m_mesh.next(g));
        if(m_mesh.degree(far) < (m_sizing.into_lines && m_mesh.is_border(far) ? 3u : 4u) ||
           (!into_feature && wings > (m_sizing.into_lines && feature ? 1 : 0)))
          return 0;
      }
    if(!CGAL::Euler::does_satisfy_link_condition(e, m_mesh))
      return 0;
    if(trials.empty())
      // A free edge becomes its end or its midpoint on the reference.
      for(const Vector_3d& p : {pb, pa, project((pa + pb) / 2, a)})
        trials.push_back(Collapse{a, b, p});
    const double old_min = smallest_angle_around(a, b);
    // The way that keeps the best triangles; the new ones may be thinner than the old by half at
    // most.
    double best = -1;
    for(const Collapse& trial : trials)
    {
      const double smallest = collapsed_smallest_angle(trial);
      if(smallest > best)
      {
        best = smallest;
        c = trial;
      }
    }
    if(!(best >= 0.5 * old_min))
      return 0;
    return 1 - length / (4.0 / 5.0 * target);
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
    for(Halfedge g : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      if(!m_mesh.is_border(g))
        m_state.face_hint[std::size_t(m_mesh.face(g))] = m_state.vertex_hint[std::size_t(v)];
    return v;
  }

  std::size_t resampling_collapses()
  {
    std::size_t done = 0;
    Collapse c;
    run_queue([&](Edge e) { return resampling_collapse_gain(e, c); },
              [&](Edge e) {
                Collapse d;
                return resampling_collapse_gain(e, d);
              },
              [&](Edge e) {
                const Vertex v = collapse(e, c);
                std::vector<Vertex> touched{v};
                for(Vertex w : vertices_around_target(m_mesh.halfedge(v), m_mesh))
                  touched.push_back(w);
                ++done;
                return touched;
              });
    return done;
  }

  // --- vertex splits: the global valence deviation must fall ---

  // The best split of v: its ring (in the order of its incident triangles) is cut at wings i and j;
  // one new vertex takes the ring from i to j, the other from j to i, and both see the wings.
  struct Vertex_split
  {
    int change = 0;
    std::size_t i = 0, j = 0;
    Vector_3d first, second;
  };

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

  bool best_vertex_split(Vertex v, Vertex_split& best) const
  {
    if(!is_free(v) || m_mesh.degree(v) < 7)
      return false;
    std::vector<Vertex> ring;
    for(Halfedge g : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      ring.push_back(m_mesh.source(g));
    std::reverse(ring.begin(), ring.end()); // counterclockwise: faces (v, ring[k], ring[k+1])
    const std::size_t n = ring.size();
    for(Vertex r : ring)
    {
      // The fan of v is removed and rebuilt: each ring vertex must keep a triangle of its own.
      const std::size_t faces_of_r = m_mesh.degree(r) - (m_mesh.is_border(r) ? 1 : 0);
      if(is_frozen(r) || faces_of_r < 3)
        return false;
    }
    const Vector_3d x = position(v);
    Vector_3d fan = Vector_3d::Zero();
    for(std::size_t k = 0; k < n; ++k)
      fan += area_vector(x, position(ring[k]), position(ring[(k + 1) % n]));
    bool found = false;
    double best_angle = 0;
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
      found = best_angle >= (std::min)(old_min, 30 * pi / 180);
    }
    return found;
  }

  std::size_t split_vertices()
  {
    std::size_t done = 0;
    std::vector<Vertex> todo(m_mesh.vertices().begin(), m_mesh.vertices().end());
    for(Vertex v : todo)
    {
      if(m_mesh.is_removed(v))
        continue;
      Vertex_split s;
      if(!best_vertex_split(v, s))
        continue;
      std::vector<Vertex> ring;
      for(Halfedge g : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
        ring.push_back(m_mesh.source(g));
      std::reverse(ring.begin(), ring.end());
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
      fit_arrays();
      for(Vertex w : {p, q})
      {
        m_state.kind[std::size_t(w)] = kind;
        m_state.closest[std::size_t(w)] = closest;
        m_state.vertex_hint[std::size_t(w)] = hint;
        m_state.frozen[std::size_t(w)] = 0;
      }
      const std::size_t span = (s.j + n - s.i) % n;
      auto add = [&](Vertex u, Vertex w, Vertex z) {
        const Face f = m_mesh.add_face(u, w, z);
        CGAL_assertion(f != Work_mesh::null_face());
        fit_arrays();
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
      ++done;
    }
    return done;
  }

  // --- section 3.2: angle-based, else Laplacian, tangential smoothing without fold-over ---

  std::size_t relax()
  {
    std::size_t moved = 0;
    for(Vertex v : m_mesh.vertices())
    {
      if(!is_free(v) || is_frozen(v))
        continue;
      const Vector_3d x = position(v);
      Link link;
      boost::container::small_vector<Vector_3d, 12> ring;
      boost::container::small_vector<Vector_3d, 12> normals;
      for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      {
        const Vector_3d p = position(m_mesh.source(h)), q = position(m_mesh.target(m_mesh.next(h)));
        ring.push_back(p);
        link.emplace_back(q, p);
        normals.push_back(area_vector(x, q, p));
      }
      const Vector_3d normal = m_reference.frame(m_state.closest[std::size_t(v)]).normal;
      const bool within_tolerance_rule = m_sizing.resamples() && !next_to_feature(v);
      double energy_here = std::numeric_limits<double>::quiet_NaN(); // once a move is acceptable
      auto try_move = [&](const Vector_3d& target) {
        Face hint = m_state.vertex_hint[std::size_t(v)];
        const Vector_3d y = m_reference.closest_point(x + tangential(target - x, normal), hint);
        for(std::size_t k = 0; k < link.size(); ++k)
          if(!is_acceptable_triangle(y, link[k].first, link[k].second, normals[k], min_turn_cosine) ||
             !is_acceptable_triangle(y, link[k].first, link[k].second, m_reference.normal(hint)))
            return false;
        if(!keeps_fit(within_tolerance_rule, v, x, y, link, energy_here))
          return false;
        m_mesh.point(v) = Work_kernel::Point_3(y.x(), y.y(), y.z());
        return true;
      };
      // A vertex already where it should be stays: it is not counted as moved.
      if((try_move(angle_based_target(x, link)) || try_move(laplacian_target(x, ring))) && position(v) != x)
        ++moved;
    }
    return moved;
  }

  // Beyond the paper: whether the relaxation may move v from x to y. Plain smoothing undoes the
  // fit of the relocation where the surface is curved, so a move that raises the local energy is
  // not kept. When the surface is re-sampled, a move away from feature lines is kept as long as
  // its triangles stay within the sizing tolerance of the reference (at their centroids), as a
  // collapse's must: the energy rule would keep the thin triangles of a coarse tube.
  bool keeps_fit(bool within_tolerance_rule, Vertex v, const Vector_3d& x, const Vector_3d& y, const Link& link,
                 double& energy_here) const
  {
    if(within_tolerance_rule)
    {
      for(const auto& side : link)
        if(distance_to_reference((y + side.first + side.second) / 3, v) > m_sizing.tolerance)
          return false;
      return true;
    }
    if(!m_local_energy)
      return true;
    if(std::isnan(energy_here))
      energy_here = m_local_energy(v, x, std::numeric_limits<double>::infinity());
    return m_local_energy(v, y, std::nextafter(energy_here, std::numeric_limits<double>::infinity())) <= energy_here;
  }

  bool next_to_feature(Vertex v) const
  {
    for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      if(m_state.kind[std::size_t(m_mesh.source(h))] != Vertex_kind::free_vertex)
        return true;
    return false;
  }

  // Grows the per-element arrays to the mesh's capacity (removed elements included).
  void fit_arrays()
  {
    const std::size_t nv = m_mesh.num_vertices(), ne = m_mesh.num_edges(), nf = m_mesh.num_faces();
    if(m_state.kind.size() < nv)
    {
      m_state.kind.resize(nv, Vertex_kind::free_vertex);
      m_state.closest.resize(nv);
      m_state.vertex_hint.resize(nv);
      m_state.frozen.resize(nv, 0);
      m_state.location.resize(nv);
    }
    if(m_state.feature_edge.size() < ne)
    {
      m_state.feature_edge.resize(ne, 0);
      m_state.edge_hint.resize(ne);
    }
    if(m_state.face_hint.size() < nf)
      m_state.face_hint.resize(nf);
  }

private:
  Vector_3d position(Vertex v) const { return to_vector(m_mesh.point(v)); }

  bool is_free(Vertex v) const
  {
    return m_state.kind[std::size_t(v)] == Vertex_kind::free_vertex && !is_frozen(v);
  }
  bool is_frozen(Vertex v) const { return m_state.frozen[std::size_t(v)] != 0; }

  // The halfedge of e on a face (e's own halfedge unless that one is on the border).
  Halfedge face_side(Edge e) const
  {
    const Halfedge h = m_mesh.halfedge(e);
    return m_mesh.is_border(h) ? m_mesh.opposite(h) : h;
  }

  bool flippable(Edge e) const
  {
    if(m_state.feature_edge[std::size_t(e)] || m_mesh.is_border(e))
      return false;
    const Halfedge h = m_mesh.halfedge(e);
    for(Vertex u : {m_mesh.source(h), m_mesh.target(h), m_mesh.target(m_mesh.next(h)),
                    m_mesh.target(m_mesh.next(m_mesh.opposite(h)))})
      if(is_frozen(u))
        return false;
    return true;
  }

  // How |valence - 6| (4 on a border) changes when v's valence changes by `delta`.
  int deviation_change(Vertex v, int delta) const
  {
    const int target = m_mesh.is_border(v) ? 4 : 6;
    const int d = int(m_mesh.degree(v));
    return std::abs(d + delta - target) - std::abs(d - target);
  }

  // A triangle an operation may create in place of triangles of area vector `replaced`: not
  // degenerate, not turned by more than 60 degrees from them, not turned over against the
  // reference (its normal where the triangle's centroid is closest to it, searched from `near`'s
  // triangle).
  bool acceptable(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c, Vertex near,
                  const Vector_3d& replaced) const
  {
    if(!is_acceptable_triangle(a, b, c, replaced, min_turn_cosine))
      return false;
    Face hint = m_state.vertex_hint[std::size_t(near)];
    m_reference.closest_point((a + b + c) / 3, hint);
    return is_acceptable_triangle(a, b, c, m_reference.normal(hint));
  }

  Vector_3d project(const Vector_3d& x, Vertex near) const
  {
    Face hint = m_state.vertex_hint[std::size_t(near)];
    return m_reference.closest_point(x, hint);
  }

  Location feature_location(Vertex v) const { return line_location(m_state, *m_polylines, v); }

  // The point of the reference polyline halfway, along it, from a to b, the ends of a sharp edge.
  Location feature_midpoint(Vertex a, Vertex b) const
  {
    return m_polylines->move(feature_location(a), (position(b) - position(a)) / 2);
  }

  double distance_to_reference(const Vector_3d& x, Vertex near) const
  {
    return (x - project(x, near)).norm();
  }

  // How far a triangle or a chord whose longest side is `length` may leave the reference where
  // the target is `target`: the sizing tolerance, how far a triangle of the target length does.
  // When the user asked for the length, a triangle longer than its target (up to 4/3 of it: a
  // coarsening collapse makes such triangles) may leave it as far as its length implies, the
  // sagitta growing as the length squared; else the curved parts keep the short edges that make
  // the fit.
  double tolerance_for(double length, double target) const
  {
    const double ratio = length / target;
    return m_sizing.target_asked_for ? m_sizing.tolerance * (std::max)(1.0, ratio * ratio) : m_sizing.tolerance;
  }

  double edge_length_target(Vertex a, Vertex b) const
  {
    if(m_sizing.resamples())
      return (std::min)(m_sizing.length(m_state.closest[std::size_t(a)]),
                        m_sizing.length(m_state.closest[std::size_t(b)]));
    return (std::min)(m_sizing.length(m_reference.frame(m_state.closest[std::size_t(a)])),
                      m_sizing.length(m_reference.frame(m_state.closest[std::size_t(b)])));
  }

  // A new or moved vertex is tracked from its neighbour's reference elements, then by the same
  // local searches as every vertex.
  void bind_new_vertex(Vertex v, Vertex from, Vertex_kind kind = Vertex_kind::free_vertex)
  {
    m_state.kind[std::size_t(v)] = kind;
    m_state.frozen[std::size_t(v)] = 0;
    m_state.closest[std::size_t(v)] = m_state.closest[std::size_t(from)];
    m_state.vertex_hint[std::size_t(v)] = m_state.vertex_hint[std::size_t(from)];
    const Vector_3d x = position(v);
    m_state.closest[std::size_t(v)] = m_reference.closest_vertex(x, m_state.closest[std::size_t(v)]);
    m_reference.closest_point(x, m_state.vertex_hint[std::size_t(v)]);
  }

  // A priority queue of edges by gain, best first: an entry is stale once its edge has been
  // pushed again, and the gain of the top entry is computed anew (an operation may have changed
  // the valence of a vertex opposite the edge) before `apply`, which may use what `gain` found.
  // `apply` returns the vertices whose edges must be looked at again. `initial_gain`, the same
  // gain without what `apply` uses, gives the first gains of all edges in parallel.
  template <typename Gain, typename Initial_gain, typename Apply>
  void run_queue(Gain gain, Initial_gain initial_gain, Apply apply)
  {
    struct Entry
    {
      double gain;
      Edge e;
      std::size_t stamp;
      bool operator<(const Entry& other) const
      {
        return gain < other.gain || (gain == other.gain && other.e < e);
      }
    };
    std::vector<std::size_t> stamp(m_mesh.num_edges(), 0);
    std::priority_queue<Entry> queue;
    auto push_gain = [&](Edge e, double g) {
      if(stamp.size() <= std::size_t(e))
        stamp.resize(m_mesh.num_edges(), 0);
      ++stamp[std::size_t(e)];
      if(g > 0)
        queue.push(Entry{g, e, stamp[std::size_t(e)]});
    };
    auto push = [&](Edge e) { push_gain(e, gain(e)); };
    {
      std::vector<double> first(m_mesh.num_edges(), 0);
      for_each_edge(m_mesh, [&](Edge e) { first[std::size_t(e)] = initial_gain(e); });
      for(Edge e : m_mesh.edges())
        push_gain(e, first[std::size_t(e)]);
    }
    // Every operation improves its criterion, but over a whole queue that is no proof of an end:
    // a bound on the number of operations is.
    const std::size_t budget = 4 * m_mesh.number_of_edges() + 16;
    std::size_t applied = 0;
    while(!queue.empty() && applied < budget)
    {
      const Entry top = queue.top();
      queue.pop();
      if(m_mesh.is_removed(top.e) || stamp[std::size_t(top.e)] != top.stamp)
        continue;
      const double g = gain(top.e);
      if(!(g > 0))
        continue;
      if(g < top.gain)
      {
        queue.push(Entry{g, top.e, top.stamp});
        continue;
      }
      const std::vector<Vertex> touched = apply(top.e);
      ++applied;
      std::vector<Edge> again;
      for(Vertex u : touched)
        if(!m_mesh.is_removed(u))
          for(Halfedge h : halfedges_around_target(m_mesh.halfedge(u), m_mesh))
            again.push_back(m_mesh.edge(h));
      std::sort(again.begin(), again.end());
      again.erase(std::unique(again.begin(), again.end()), again.end());
      for(Edge e : again)
        push(e);
    }
  }

  Work_mesh& m_mesh;
  const Reference_surface<Work_mesh>& m_reference;
  Tracking_state& m_state;
  const Sizing& m_sizing;
  const Feature_polylines<Work_mesh>* m_polylines;
  Local_energy m_local_energy;
  Connectivity_operations m_operations;
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_CONNECTIVITY_H
