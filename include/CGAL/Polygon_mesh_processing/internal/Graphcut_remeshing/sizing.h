// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sizing field of the connectivity stage (section 3.1: e_min and e_max follow the local
// curvature): a target edge length at each point of the reference surface.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_SIZING_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_SIZING_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/feature_strips.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/features.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/reference_surface.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/remeshing_options.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// The target edge lengths of the connectivity stage and the rules that compare an edge with them,
// as CGAL's Sizing_field_base: an edge is too long beyond 4/3 of its target and too short below
// 4/5 of it. Two fields re-sample the surface (a target by reference vertex): the count-matched
// curvature field (curvature_sizing()) and the error-bounded field (tolerance_sizing()). Without
// them (the paper's connectivity) the target is the longest length, shorter where the reference's
// frame is curved.
struct Sizing_field
{
  static constexpr double too_long_ratio = 4.0 / 3.0;
  static constexpr double too_short_ratio = 4.0 / 5.0;

  // The longest target: the mean edge length of the input or the length asked for (the paper's
  // field), the longest edge of the error-bounded field.
  double longest = 0;
  // How far a chord of the target length may leave the surface: the user's sizing tolerance, or,
  // with a curvature_sizing() field, the one that field was solved for.
  double tolerance = 1e-3;
  // The angle in degrees beyond which a dihedral is a crease rather than curvature, and a turn of
  // a feature line a corner that re-sampling keeps: the sharp edges' upper bound (eq. 8). Set,
  // with `target`, by curvature_sizing(); read only when re-sampling.
  double corner_angle = 0;
  std::vector<double> target; // by reference vertex; empty: the length comes from the frames
  // The user asked for the length (not the input's mean): the density comes first, see
  // tolerance_for().
  bool target_asked_for = false;
  // The user asked for a density (a length, with or without a tolerance): a free vertex may
  // collapse into a feature line (see Edge_collapses::resampling_gain()).
  bool into_lines = false;
  // The user asked for a length of at least covering_length_ratio times the input's mean edge
  // length: the triangles span several reference vertices and may cut a tip between them off, or
  // an edge cut across a crease, which the connectivity stage then covers (coverings.h). At a
  // finer length every reference vertex is near a vertex of the mesh, and a vertex put there only
  // makes thin triangles.
  bool covers_reference = false;

  // Whether the connectivity stage re-samples the surface to this field: the one place that
  // decides it once the field is made.
  bool resamples() const { return !target.empty(); }

  // The target at the reference vertex y.
  double at(Work_mesh::Vertex_index y, const Reference_surface<Work_mesh>& reference) const
  {
    return resamples() ? target[std::size_t(y)] : length(reference.frame(y));
  }

  // The target of an edge whose ends are tracked to the reference vertices ya and yb.
  double edge_target(Work_mesh::Vertex_index ya, Work_mesh::Vertex_index yb,
                     const Reference_surface<Work_mesh>& reference) const
  {
    return (std::min)(at(ya, reference), at(yb, reference));
  }

  static bool is_too_long(double length, double target) { return length > too_long_ratio * target; }
  static bool is_too_short(double length, double target) { return length < too_short_ratio * target; }
  // By how much an edge is too long or too short, relative to its target (positive when it is).
  static double excess(double length, double target) { return length / target - too_long_ratio; }
  static double shortfall(double length, double target) { return 1 - length / (too_short_ratio * target); }

  // How far a triangle or a chord whose longest side is `length` may leave the reference where
  // the target is `target`: the tolerance, how far a triangle of the target length does. When
  // the user asked for the length, a triangle longer than its target (up to 4/3 of it: a
  // coarsening collapse makes such triangles) may leave it as far as its length implies, the
  // sagitta growing as the length squared; else the curved parts keep the short edges that make
  // the fit.
  double tolerance_for(double length, double target) const
  {
    const double ratio = length / target;
    return target_asked_for ? tolerance * (std::max)(1.0, ratio * ratio) : tolerance;
  }

private:
  // The paper's field: the longest length, shorter where the surface is curved so that a chord
  // of that length stays within `tolerance` of it (l = sqrt(6 tolerance rho - 3 tolerance^2)),
  // never below half the longest.
  double length(const Local_frame& f) const
  {
    const double rho = f.min_radius();
    if(!std::isfinite(rho))
      return longest;
    const double l2 = 6 * tolerance * rho - 3 * tolerance * tolerance;
    const double curved = l2 > 0 ? std::sqrt(l2) : 0;
    return (std::max)(0.5 * longest, (std::min)(longest, curved));
  }
};

// The edge length of the re-sampling fields where the curvature radius is `rho`: the equilateral
// triangles keep within `tolerance` of a sphere of that radius, to first order in tolerance / rho
// (+inf where flat). The paper's field (Sizing_field::length()) keeps the exact length,
// sqrt(6 tolerance rho - 3 tolerance^2): in the count-matched field the exact one measured farther
// from the surface (the manual, "Re-sampling").
inline double resampling_chord(double tolerance, double rho)
{
  return std::sqrt(6 * tolerance * rho);
}

// The mean length of the edges of m (0 without edges).
inline double mean_edge_length(const Work_mesh& m)
{
  double total = 0;
  for(Work_mesh::Edge_index e : m.edges())
    total += (to_vector(m.point(m.source(m.halfedge(e)))) - to_vector(m.point(m.target(m.halfedge(e))))).norm();
  return m.number_of_edges() > 0 ? total / double(m.number_of_edges()) : 0;
}

// The radius of curvature a vertex of the reference shows across its smooth edges: for an edge of
// dihedral angle theta (below `smooth_dihedral` degrees, not a feature) between triangles of
// heights h1 and h2 over it, the circle through the two triangles' far sides has radius about
// (h1 + h2) / (2 theta); a vertex takes the smallest over its edges (infinite when flat). Unlike
// a jet fit, it sees neither the noise of a coarse sampling nor the creases next to the vertex.
inline std::vector<double> smooth_edge_radii(const Work_mesh& m, const std::vector<char>& feature_edge,
                                             double smooth_dihedral)
{
  std::vector<double> radius(m.num_vertices(), std::numeric_limits<double>::infinity());
  for(Work_mesh::Edge_index e : m.edges())
  {
    const Work_mesh::Halfedge_index h = m.halfedge(e), o = m.opposite(h);
    if(feature_edge[std::size_t(e)] || m.is_border(e))
      continue;
    const double theta = dihedral_angle(m, e) * pi / 180;
    if(!(theta > 0) || theta >= smooth_dihedral * pi / 180)
      continue;
    const Vector_3d a = to_vector(m.point(m.source(h))), b = to_vector(m.point(m.target(h)));
    const double h1 = distance_to_segment(to_vector(m.point(m.target(m.next(h)))), a, b);
    const double h2 = distance_to_segment(to_vector(m.point(m.target(m.next(o)))), a, b);
    const double r = (h1 + h2) / (2 * theta);
    for(Work_mesh::Vertex_index v : {m.source(h), m.target(h)})
      radius[std::size_t(v)] = (std::min)(radius[std::size_t(v)], r);
  }
  return radius;
}

// A third of the area of the triangles around each vertex: the part of the surface it samples.
inline std::vector<double> vertex_areas(const Work_mesh& m)
{
  std::vector<double> area(m.num_vertices(), 0);
  for(Work_mesh::Face_index f : m.faces())
  {
    const Work_mesh::Halfedge_index h = m.halfedge(f);
    const Work_mesh::Vertex_index u = m.source(h), v = m.target(h), w = m.target(m.next(h));
    const double third =
      area_vector(to_vector(m.point(u)), to_vector(m.point(v)), to_vector(m.point(w))).norm() / 6;
    for(Work_mesh::Vertex_index x : {u, v, w})
      area[std::size_t(x)] += third;
  }
  return area;
}

// How many vertices a vertex of the reference that samples `area` of the surface costs at the
// target length t when it lies on a strip `width` wide between two feature lines: area / t^2 where
// the strip is wider than t. On a narrower strip each of its lines keeps a vertex every t, so that
// the cost grows towards area / (t w); the field takes only a part of that growth, the exponent:
// the lines are shared between strips and the feature-line collapses merge their short segments
// (the manual, "Re-sampling"). The width counts as at least half the mean length.
constexpr double strip_count_exponent = 0.375;
inline double sampled_vertices(double area, double t, double width, double mean_length)
{
  const double across = (std::max)(0.5 * mean_length, (std::min)(t, width));
  return area / (t * t) * std::pow(t / across, strip_count_exponent);
}

// Lowers the target lengths so that they grow by at most `gradation` times the distance along
// the edges (a Dijkstra from the shortest): neighbouring triangles then differ little in size.
inline void grade_sizing(const Work_mesh& m, double gradation, std::vector<double>& length)
{
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
  for(Work_mesh::Vertex_index v : m.vertices())
    queue.emplace(length[std::size_t(v)], std::size_t(v));
  while(!queue.empty())
  {
    const Entry top = queue.top();
    queue.pop();
    if(top.first > length[top.second])
      continue;
    const Work_mesh::Vertex_index v(static_cast<Work_mesh::size_type>(top.second));
    for(Work_mesh::Vertex_index w : vertices_around_target(m.halfedge(v), m))
    {
      const double through = top.first + gradation * (to_vector(m.point(v)) - to_vector(m.point(w))).norm();
      if(through < length[std::size_t(w)])
      {
        length[std::size_t(w)] = through;
        queue.emplace(through, std::size_t(w));
      }
    }
  }
}

// The coarsest length, relative to the input's mean edge length, at which the input's own edges
// are all within the re-sampling's bounds on average: up to it the re-sampling keeps about the
// input's vertices, and nothing is covered (Sizing_field::covers_reference).
constexpr double covering_length_ratio = Sizing_field::too_long_ratio;

// Neighbouring target lengths differ by at most this times the distance between them: in the
// field of an error bound (tolerance_sizing()) and in the count-matched field at a length asked
// for, where the curved parts keep their short edges as the triangles coarsen.
constexpr double sizing_gradation = 0.5;
// The same in the count-matched field at the input's own density, gentler: each change of size
// takes vertices of valence 5 and 7 (fandisk's irregular vertices, the manual's re-sampling
// section), and the distance to the input has room there.
constexpr double gradation_at_mean_length = 0.05;

// The longest edges of the count-matched field (curvature_sizing()), in target lengths: at the
// input's own density, twice its mean edge length in the flat parts; with a length asked for,
// little beyond it, as isotropic_remeshing() keeps its edges below 4/3 of its target. At a coarse
// target, edges twice as long in the parts that look flat left the short ones crowded at the
// lines, and cut across the hollows that the coarse sampling hides.
constexpr double longest_to_mean_length = 2;
constexpr double longest_to_asked_target = 1.25;

// The sizing field of an error bound (graphcut_parameters::sizing_tolerance), as CGAL's
// Adaptive_sizing_field: at each vertex of the reference `m` the edge length whose equilateral
// triangles keep within `tolerance` of a sphere of the curvature radius at their centroids,
// between `shortest` and `longest`, graded. No count is matched: the tolerance, not a density, is
// what the user asked for, and the collapses keep to it.
inline Sizing_field tolerance_sizing(const Work_mesh& m, const std::vector<char>& feature_edge, double tolerance,
                                     double shortest, double longest, double corner_angle)
{
  const std::vector<double> radius = smooth_edge_radii(m, feature_edge, corner_angle);
  Sizing_field sizing;
  sizing.longest = longest;
  sizing.tolerance = tolerance;
  sizing.corner_angle = corner_angle;
  sizing.target.assign(m.num_vertices(), longest);
  for(Work_mesh::Vertex_index v : m.vertices())
    sizing.target[std::size_t(v)] =
      (std::max)(shortest, (std::min)(longest, resampling_chord(tolerance, radius[std::size_t(v)])));
  grade_sizing(m, sizing_gradation, sizing.target); // only from lengths of at least `shortest`
  return sizing;
}

// The sizing field of the re-sampling connectivity stage on the reference `m`: at each vertex the
// chord length that keeps within a tolerance of the curvature radius, between half and `longest`
// times the mean length, graded; the tolerance is chosen so that the field asks for as many
// triangles as the mean length would everywhere (sum of area / l^2), so that the vertex count
// stays the input's while the curved parts get the short edges and the flat parts the long ones.
// With `count_strips` (at the input's density), a strip between feature lines narrower than its
// target counts more (sampled_vertices()), so that the field lengthens its targets elsewhere.
inline Sizing_field curvature_sizing(const Work_mesh& m, const std::vector<char>& feature_edge, double mean_length,
                                     double corner_angle, double longest, double gradation, bool count_strips)
{
  const std::vector<double> radius = smooth_edge_radii(m, feature_edge, corner_angle);
  const std::vector<double> area = vertex_areas(m);
  const std::vector<double> width = count_strips ? feature_strip_widths(m, feature_edge)
                                                 : std::vector<double>(m.num_vertices(), std::numeric_limits<double>::infinity());
  double budget = 0;
  for(Work_mesh::Vertex_index v : m.vertices())
    budget += area[std::size_t(v)] / (mean_length * mean_length);
  Sizing_field sizing;
  sizing.longest = longest * mean_length;
  sizing.corner_angle = corner_angle;
  sizing.target.assign(m.num_vertices(), mean_length);
  auto fill = [&](double tolerance) {
    double count = 0;
    for(Work_mesh::Vertex_index v : m.vertices())
    {
      const double l = resampling_chord(tolerance, radius[std::size_t(v)]);
      double& t = sizing.target[std::size_t(v)];
      t = (std::max)(0.5 * mean_length, (std::min)(longest * mean_length, l));
      count += sampled_vertices(area[std::size_t(v)], t, width[std::size_t(v)], mean_length);
    }
    return count;
  };
  // The count falls as the tolerance grows: bisection on its logarithm.
  double low = std::log(1e-9 * mean_length), high = std::log(mean_length);
  for(int k = 0; k < 60; ++k)
  {
    const double mid = (low + high) / 2;
    (fill(std::exp(mid)) > budget ? low : high) = mid;
  }
  // The tolerance also bounds how far the collapses' triangles and shortened feature lines may
  // leave the input.
  sizing.tolerance = std::exp(high);
  fill(sizing.tolerance);
  grade_sizing(m, gradation, sizing.target);
  // Grading only shortens: scale the field back to the budget.
  double count = 0;
  for(Work_mesh::Vertex_index v : m.vertices())
    count += sampled_vertices(area[std::size_t(v)], sizing.target[std::size_t(v)], width[std::size_t(v)], mean_length);
  const double stretch = budget > 0 && count > 0 ? std::sqrt(count / budget) : 1;
  for(double& t : sizing.target)
    t *= stretch;
  return sizing;
}

// The target edge lengths of the connectivity stage: a curvature-adapted field around the
// target (or mean) length when it re-samples, else that length with the user's tolerance for
// the curved parts.
inline Sizing_field make_sizing_field(const Work_mesh& reference, const std::vector<char>& feature_edge,
                                      const Remeshing_options& options, double input_mean_length)
{
  const double length = options.target_edge_length > 0 ? options.target_edge_length : input_mean_length;
  if(options.resampling && options.error_bounded_sizing)
  {
    const double longest = options.edge_length_bounds.second > 0 ? options.edge_length_bounds.second : length;
    const double shortest =
      options.edge_length_bounds.first > 0 ? options.edge_length_bounds.first : Remeshing_options::shortest_to_target * longest;
    Sizing_field sizing = tolerance_sizing(reference, feature_edge, options.sizing_tolerance, shortest, longest,
                                           options.sharp_angle_bounds.second);
    sizing.into_lines = options.target_edge_length > 0;
    return sizing;
  }
  if(options.resampling)
  {
    const bool asked = options.target_edge_length > 0;
    Sizing_field sizing =
      curvature_sizing(reference, feature_edge, length, options.sharp_angle_bounds.second,
                       asked ? longest_to_asked_target : longest_to_mean_length,
                       asked ? sizing_gradation : gradation_at_mean_length, !asked);
    sizing.target_asked_for = sizing.into_lines = asked;
    sizing.covers_reference = asked && length >= covering_length_ratio * input_mean_length;
    return sizing;
  }
  Sizing_field sizing;
  sizing.longest = length;
  sizing.tolerance = options.sizing_tolerance;
  return sizing;
}

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_SIZING_H
