// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The distance bound of graphcut_parameters::distance_bound(): whether the triangles an operation
// makes stay within the bound of the input, and whether the input near the triangles it removes
// stays within the bound of the ones that replace them. Both questions are answered by one
// argument. The distance to a triangle is a convex function, so over a convex polygon it is
// largest at a corner; a triangle cut into convex cells, each given a triangle of the other
// surface, is within the bound of that surface when every corner of every cell is within the bound
// of its cell's triangle. Any cutting and any choice of triangles bound the distance from above;
// cells cut where the other surface's triangles lie below, along the normal, bound it tightly. A
// cell that no triangle lies below is given the nearest one, and cut smaller when that is not
// enough. The answer errs only towards "no": a cell still undecided after `max_depth` halvings
// refuses the operation. Distance_bound asks both questions of an operation on the working mesh
// (a move, a split, a collapse, any triangles in place of others).

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_DISTANCE_BOUND_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_DISTANCE_BOUND_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/boost/graph/iterator.h>
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
#include <iterator>
#include <limits>
#include <memory>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

using Triangle_3d = std::array<Vector_3d, 3>;
using Convex_polygon = boost::container::small_vector<Vector_3d, 8>;

inline double distance_to_triangle(const Vector_3d& p, const Triangle_3d& t)
{
  std::array<double, 3> barycentric;
  return (p - closest_point_on_triangle(p, t[0], t[1], t[2], barycentric)).norm();
}

// Splits the convex polygon `in` by the plane n.x = offset: `inside` gets the part where
// n.x >= offset, `outside` the rest (either empty when the plane misses the polygon).
inline void split_polygon(const Convex_polygon& in, const Vector_3d& n, double offset, Convex_polygon& inside,
                          Convex_polygon& outside)
{
  inside.clear();
  outside.clear();
  const std::size_t k = in.size();
  for(std::size_t i = 0; i < k; ++i)
  {
    const Vector_3d& p = in[i];
    const Vector_3d& q = in[(i + 1) % k];
    const double sp = n.dot(p) - offset, sq = n.dot(q) - offset;
    if(sp >= 0)
      inside.push_back(p);
    if(sp <= 0)
      outside.push_back(p);
    if((sp > 0 && sq < 0) || (sp < 0 && sq > 0))
    {
      const Vector_3d x = p + (sp / (sp - sq)) * (q - p);
      inside.push_back(x);
      outside.push_back(x);
    }
  }
  if(inside.size() < 3)
    inside.clear();
  if(outside.size() < 3)
    outside.clear();
}

// The centre of the polygon's corners and the largest distance from it to a corner: every point
// of the polygon is within that radius of the centre.
inline double polygon_radius(const Convex_polygon& p, Vector_3d& centre)
{
  centre = Vector_3d::Zero();
  for(const Vector_3d& x : p)
    centre += x;
  centre /= double(p.size());
  double radius = 0;
  for(const Vector_3d& x : p)
    radius = (std::max)(radius, (x - centre).norm());
  return radius;
}

inline double distance_to_triangles(const Vector_3d& p, const std::vector<Triangle_3d>& triangles, std::size_t* nearest = nullptr)
{
  double best = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < triangles.size(); ++i)
  {
    const double d = distance_to_triangle(p, triangles[i]);
    if(d < best)
    {
      best = d;
      if(nearest)
        *nearest = i;
    }
  }
  return best;
}

// A convex cell of a piece and the triangle of the cover it is measured to (none: no cover
// triangle lies below it).
struct Bounded_cell
{
  Convex_polygon polygon;
  std::size_t triangle;
};

// Cuts the convex polygon `piece` into cells, each below one triangle of `cover` along `up` (the
// part of the piece inside that triangle's prism), and what is below none.
inline std::vector<Bounded_cell> cells_below(const Convex_polygon& piece, const std::vector<Triangle_3d>& cover,
                                             const Vector_3d& up)
{
  // A triangle seen nearly edge-on along `up` has a prism too thin to hold a cell.
  constexpr double edge_on_sine = 1e-3;
  // Slivers this thin, in the unit box, are left out: the distance moves by less across them.
  constexpr double sliver_width = 1e-12;
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  std::vector<Bounded_cell> cells;
  std::vector<Convex_polygon> uncovered(1, piece), next;
  Convex_polygon inside, outside;
  for(std::size_t i = 0; i < cover.size() && !uncovered.empty(); ++i)
  {
    const Triangle_3d& t = cover[i];
    const Vector_3d normal = (t[1] - t[0]).cross(t[2] - t[0]);
    if(!(std::abs(normal.dot(up)) > edge_on_sine * normal.norm()))
      continue;
    // The prism's sides, facing in.
    std::array<Vector_3d, 3> side;
    std::array<double, 3> offset;
    for(int j = 0; j < 3; ++j)
    {
      side[j] = (t[(j + 1) % 3] - t[j]).cross(up);
      if(side[j].dot(t[(j + 2) % 3] - t[j]) < 0)
        side[j] = -side[j];
      offset[j] = side[j].dot(t[j]);
    }
    next.clear();
    for(Convex_polygon in : uncovered)
    {
      // Most polygons lie wholly outside one side: left as they are.
      bool apart = false;
      for(int j = 0; j < 3 && !apart; ++j)
        apart = std::all_of(in.begin(), in.end(), [&](const Vector_3d& x) { return side[j].dot(x) < offset[j]; });
      if(apart)
      {
        next.push_back(in);
        continue;
      }
      for(int j = 0; j < 3 && !in.empty(); ++j)
      {
        split_polygon(in, side[j], offset[j], inside, outside);
        Vector_3d centre;
        if(!outside.empty() && polygon_radius(outside, centre) > sliver_width)
          next.push_back(outside);
        in = inside;
      }
      if(!in.empty())
        cells.push_back(Bounded_cell{in, i});
    }
    uncovered.swap(next);
  }
  for(const Convex_polygon& u : uncovered)
    cells.push_back(Bounded_cell{u, none});
  return cells;
}

inline CGAL::Bbox_3 polygon_box(const Convex_polygon& p, double grown_by)
{
  CGAL::Bbox_3 box;
  for(const Vector_3d& x : p)
    box += CGAL::Bbox_3(x.x() - grown_by, x.y() - grown_by, x.z() - grown_by, x.x() + grown_by, x.y() + grown_by,
                        x.z() + grown_by);
  return box;
}

inline bool triangle_meets_box(const Triangle_3d& t, const CGAL::Bbox_3& box)
{
  for(int k = 0; k < 3; ++k)
    if((std::max)({t[0][k], t[1][k], t[2][k]}) < box.min(k) || (std::min)({t[0][k], t[1][k], t[2][k]}) > box.max(k))
      return false;
  return true;
}

// The triangles that reach into the box.
inline std::vector<Triangle_3d> triangles_in(const std::vector<Triangle_3d>& triangles, const CGAL::Bbox_3& box)
{
  std::vector<Triangle_3d> in;
  for(const Triangle_3d& t : triangles)
    if(triangle_meets_box(t, box))
      in.push_back(t);
  return in;
}

inline CGAL::Bbox_3 triangles_box(const std::vector<Triangle_3d>& triangles, double grown_by)
{
  CGAL::Bbox_3 box;
  for(const Triangle_3d& t : triangles)
    for(const Vector_3d& p : t)
      box += CGAL::Bbox_3(p.x(), p.y(), p.z(), p.x(), p.y(), p.z());
  return CGAL::Bbox_3(box.xmin() - grown_by, box.ymin() - grown_by, box.zmin() - grown_by, box.xmax() + grown_by,
                      box.ymax() + grown_by, box.zmax() + grown_by);
}

// The part of the convex polygon inside the box (empty when it has no area there).
inline Convex_polygon clipped_to_box(const Convex_polygon& polygon, const CGAL::Bbox_3& box)
{
  Convex_polygon in = polygon, inside, outside;
  for(int k = 0; k < 3 && !in.empty(); ++k)
  {
    const Vector_3d axis = Vector_3d::Unit(k);
    split_polygon(in, axis, box.min(k), inside, outside);
    split_polygon(inside, -axis, -box.max(k), in, outside);
  }
  return in;
}

// Whether every point of the convex polygon is beyond `bound` of t: along t's normal, or along the
// way from t's point nearest the polygon's centre to that centre, the two lie more than the bound
// apart.
inline bool beyond_bound(const Convex_polygon& polygon, const Triangle_3d& t, double bound)
{
  Vector_3d centre;
  polygon_radius(polygon, centre);
  std::array<double, 3> barycentric;
  std::array<Vector_3d, 2> axis{{(t[1] - t[0]).cross(t[2] - t[0]),
                                 centre - closest_point_on_triangle(centre, t[0], t[1], t[2], barycentric)}};
  for(Vector_3d u : axis)
  {
    const double length = u.norm();
    if(!(length > 0))
      continue;
    u /= length;
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for(const Vector_3d& x : polygon)
    {
      low = (std::min)(low, u.dot(x));
      high = (std::max)(high, u.dot(x));
    }
    const double t_low = (std::min)({u.dot(t[0]), u.dot(t[1]), u.dot(t[2])});
    const double t_high = (std::max)({u.dot(t[0]), u.dot(t[1]), u.dot(t[2])});
    if(low - t_high > bound || t_low - high > bound)
      return true;
  }
  return false;
}

// The part of the convex polygon that can be within `bound` of the triangle t: inside the prism
// of t grown sideways by the bound, within the bound of t's plane (all of it for a degenerate t).
inline Convex_polygon clipped_to_neighbourhood(const Convex_polygon& polygon, const Triangle_3d& t, double bound)
{
  Vector_3d n = (t[1] - t[0]).cross(t[2] - t[0]);
  const double length = n.norm();
  if(!(length > 0))
    return polygon;
  n /= length;
  Convex_polygon in = polygon, inside, outside;
  split_polygon(in, n, n.dot(t[0]) - bound, inside, outside);
  split_polygon(inside, -n, -n.dot(t[0]) - bound, in, outside);
  for(int j = 0; j < 3 && !in.empty(); ++j)
  {
    const Vector_3d& a = t[j];
    Vector_3d side = (t[(j + 1) % 3] - a).cross(n);
    if(side.dot(t[(j + 2) % 3] - a) > 0)
      side = -side;
    side.normalize();
    split_polygon(in, -side, -side.dot(a) - bound, inside, outside);
    in = inside;
  }
  return in;
}

// Which corners and sides of a removed triangle are also corners and sides of the cover (exactly:
// they stayed where they were).
struct Shared_parts
{
  std::array<bool, 3> corner{{false, false, false}};
  std::array<bool, 3> side{{false, false, false}}; // side k joins corners k and k + 1
};

inline Shared_parts shared_parts(const Triangle_3d& t, const std::vector<Triangle_3d>& cover)
{
  Shared_parts shared;
  for(const Triangle_3d& c : cover)
  {
    std::array<bool, 3> in{{false, false, false}};
    for(int k = 0; k < 3; ++k)
      in[k] = t[k] == c[0] || t[k] == c[1] || t[k] == c[2];
    for(int k = 0; k < 3; ++k)
    {
      shared.corner[k] = shared.corner[k] || in[k];
      shared.side[k] = shared.side[k] || (in[k] && in[(k + 1) % 3]);
    }
  }
  return shared;
}

// Whether the point of t nearest to any point of the convex polygon lies on a shared part of t
// (then the cover, which holds that part, is at least as near), or every point of the polygon is
// beyond `bound` of t. Each test is one Voronoi region of t, convex: the corners decide.
inline bool nearest_on_shared_parts(const Convex_polygon& polygon, const Triangle_3d& t, const Shared_parts& shared,
                                    double bound)
{
  Vector_3d centre;
  const double radius = polygon_radius(polygon, centre);
  if(distance_to_triangle(centre, t) - radius > bound)
    return true;
  const Vector_3d normal = (t[1] - t[0]).cross(t[2] - t[0]);
  const auto all = [&](const auto& in_region) { return std::all_of(polygon.begin(), polygon.end(), in_region); };
  for(int k = 0; k < 3; ++k)
  {
    const Vector_3d &a = t[k], &b = t[(k + 1) % 3], &c = t[(k + 2) % 3];
    if(shared.corner[k] && all([&](const Vector_3d& x) { return (x - a).dot(b - a) <= 0 && (x - a).dot(c - a) <= 0; }))
      return true;
    Vector_3d out = (b - a).cross(normal);
    if(out.dot(c - a) > 0)
      out = -out;
    if(shared.side[k] && normal.squaredNorm() > 0 &&
       all([&](const Vector_3d& x) { return (x - a).dot(out) >= 0 && (x - a).dot(b - a) >= 0 && (x - b).dot(a - b) >= 0; }))
      return true;
    // With no obtuse angle at a or b, beyond the side's line the nearest point is on the side.
    if(shared.side[k] && normal.squaredNorm() > 0 && (b - a).dot(c - a) >= 0 && (a - b).dot(c - b) >= 0 &&
       all([&](const Vector_3d& x) { return (x - a).dot(out) >= 0; }))
      return true;
  }
  return false;
}

// The triangles whose neighbourhood matters (the removed ones) and which of their parts the cover
// keeps.
struct Relevant_triangles
{
  std::vector<Triangle_3d> triangles;
  std::vector<Shared_parts> shared;

  // Those that reach into the box.
  Relevant_triangles in(const CGAL::Bbox_3& box) const
  {
    Relevant_triangles here;
    for(std::size_t i = 0; i < triangles.size(); ++i)
      if(triangle_meets_box(triangles[i], box))
      {
        here.triangles.push_back(triangles[i]);
        here.shared.push_back(shared[i]);
      }
    return here;
  }
};

// Whether no point of the cell is within `bound` of a relevant triangle: by the centre and radius,
// or a separating axis for each.
inline bool out_of_reach(const Convex_polygon& cell, const Relevant_triangles& relevant, double bound)
{
  Vector_3d centre;
  const double radius = polygon_radius(cell, centre);
  return distance_to_triangles(centre, relevant.triangles) - radius > bound ||
         std::all_of(relevant.triangles.begin(), relevant.triangles.end(),
                     [&](const Triangle_3d& r) { return beyond_bound(cell, r, bound); });
}

inline bool corners_within(const Convex_polygon& polygon, const Triangle_3d& t, double bound)
{
  return std::all_of(polygon.begin(), polygon.end(), [&](const Vector_3d& x) { return distance_to_triangle(x, t) <= bound; });
}

// Whether the part of the cell each relevant triangle can reach (clipped_to_neighbourhood()) lies
// within `bound` of one cover triangle: the cell's own (`below`) or the one nearest that part.
inline bool reach_covered(const Convex_polygon& cell, const Relevant_triangles& relevant,
                          const std::vector<Triangle_3d>& cover, std::size_t below, double bound)
{
  return std::all_of(relevant.triangles.begin(), relevant.triangles.end(), [&](const Triangle_3d& r) {
    const Convex_polygon reach = clipped_to_neighbourhood(cell, r, bound);
    if(reach.empty())
      return true;
    Vector_3d centre;
    polygon_radius(reach, centre);
    std::size_t nearest = 0;
    distance_to_triangles(centre, cover, &nearest);
    return (below < cover.size() && corners_within(reach, cover[below], bound)) ||
           corners_within(reach, cover[nearest], bound);
  });
}

// Whether, for each relevant triangle, the cell is beyond `bound` of it or nearest to it on parts
// the cover keeps (then the cover is as near).
inline bool nearest_on_kept_parts(const Convex_polygon& cell, const Relevant_triangles& relevant, double bound)
{
  for(std::size_t k = 0; k < relevant.triangles.size(); ++k)
    if(!nearest_on_shared_parts(cell, relevant.triangles[k], relevant.shared[k], bound))
      return false;
  return true;
}

// The cell cut into smaller triangles: a fan, each cut into four at its midpoints.
inline std::vector<Triangle_3d> halved(const Convex_polygon& cell)
{
  std::vector<Triangle_3d> parts;
  for(std::size_t k = 1; k + 1 < cell.size(); ++k)
  {
    const Vector_3d &a = cell[0], &b = cell[k], &c = cell[k + 1];
    const Vector_3d ab = (a + b) / 2, bc = (b + c) / 2, ca = (c + a) / 2;
    parts.insert(parts.end(), {Triangle_3d{{a, ab, ca}}, Triangle_3d{{ab, b, bc}}, Triangle_3d{{ca, bc, c}},
                               Triangle_3d{{ab, bc, ca}}});
  }
  return parts;
}

inline bool within_bound(const Convex_polygon& whole_piece, const std::vector<Triangle_3d>& all_cover,
                         const Vector_3d& up, double bound, const Relevant_triangles* all_relevant, int depth,
                         bool first_try);

// within_bound() for the cells below the triangles of `cover` along `up`, each measured first at its
// corners, then by the settling tests, then halved (up to six times: still undecided, it fails).
inline bool cells_within_bound(const Convex_polygon& piece, const std::vector<Triangle_3d>& cover,
                               const Vector_3d& up, double bound, const Relevant_triangles* relevant, int depth)
{
  constexpr int max_depth = 6;
  for(Bounded_cell& cell : cells_below(piece, cover, up))
  {
    Vector_3d centre;
    const double radius = polygon_radius(cell.polygon, centre);
    if(relevant && out_of_reach(cell.polygon, *relevant, bound))
      continue;
    const double at_centre =
      distance_to_triangles(centre, cover, cell.triangle >= cover.size() ? &cell.triangle : nullptr);
    if(at_centre + radius <= bound || corners_within(cell.polygon, cover[cell.triangle], bound))
      continue; // the distance to the cover changes by at most the radius across the cell
    if(relevant && (reach_covered(cell.polygon, *relevant, cover, cell.triangle, bound) ||
                    nearest_on_kept_parts(cell.polygon, *relevant, bound)))
      continue;
    // A centre beyond the bound that matters refutes the piece; one that does not, settles nothing.
    if((at_centre > bound && (!relevant || distance_to_triangles(centre, relevant->triangles) <= bound)) ||
       depth == max_depth)
      return false;
    for(const Triangle_3d& q : halved(cell.polygon))
      if(!within_bound(Convex_polygon(q.begin(), q.end()), cover, up, bound, relevant, depth + 1, true))
        return false;
  }
  return true;
}

// within_bound() for the cells below the cover triangle nearest the piece's centre and those nearest
// its corners beyond the bound of that one; what those leave goes to all of the cover.
inline bool within_bound_of_nearest(const Convex_polygon& piece, const std::vector<Triangle_3d>& cover,
                                    std::size_t nearest, const Vector_3d& up, double bound,
                                    const Relevant_triangles* relevant, int depth)
{
  std::vector<std::size_t> taken(1, nearest);
  for(const Vector_3d& x : piece)
    if(distance_to_triangle(x, cover[nearest]) > bound)
    {
      std::size_t k = 0;
      distance_to_triangles(x, cover, &k);
      if(std::find(taken.begin(), taken.end(), k) == taken.end())
        taken.push_back(k);
    }
  std::vector<Triangle_3d> nearest_to_corners;
  for(std::size_t k : taken)
    nearest_to_corners.push_back(cover[k]);
  for(const Bounded_cell& cell : cells_below(piece, nearest_to_corners, up))
  {
    // A cell below none of them is measured to the triangle nearest its centre.
    std::size_t below = cell.triangle < taken.size() ? taken[cell.triangle] : 0;
    if(cell.triangle >= taken.size())
    {
      Vector_3d centre;
      polygon_radius(cell.polygon, centre);
      distance_to_triangles(centre, cover, &below);
    }
    if(!corners_within(cell.polygon, cover[below], bound) &&
       !within_bound(cell.polygon, cover, up, bound, relevant, depth, false))
      return false;
  }
  return true;
}

// Whether every point of the convex polygon `piece` is within `bound` of the triangles of `cover`
// (with `relevant`, only the points within `bound` of those triangles need be: the others are
// within it of triangles that stay). `up` is the direction along which cells are cut. Only the
// triangles within `bound` of the piece's box count.
inline bool within_bound(const Convex_polygon& whole_piece, const std::vector<Triangle_3d>& all_cover,
                         const Vector_3d& up, double bound, const Relevant_triangles* all_relevant,
                         int depth = 0, bool first_try = true)
{
  Relevant_triangles relevant_here;
  Convex_polygon piece = whole_piece;
  if(all_relevant)
  {
    // Only the part of the piece within the bound of a relevant triangle matters.
    relevant_here = all_relevant->in(polygon_box(whole_piece, bound));
    if(relevant_here.triangles.empty())
      return true;
    piece = clipped_to_box(whole_piece, triangles_box(relevant_here.triangles, bound));
    if(piece.empty())
      return true;
  }
  const Relevant_triangles* relevant = all_relevant ? &relevant_here : nullptr;
  const std::vector<Triangle_3d> cover = triangles_in(all_cover, polygon_box(piece, bound));
  Vector_3d centre;
  const double radius = polygon_radius(piece, centre);
  if(relevant && distance_to_triangles(centre, relevant->triangles) - radius > bound)
    return true;
  if(cover.empty())
    return false;
  // Most pieces lie within the bound of the one triangle nearest their centre.
  std::size_t nearest = 0;
  if(distance_to_triangles(centre, cover, &nearest) + radius <= bound || corners_within(piece, cover[nearest], bound))
    return true;
  // Most others lie within it of that triangle and of those nearest the corners beyond it.
  return first_try ? within_bound_of_nearest(piece, cover, nearest, up, bound, relevant, depth)
                   : cells_within_bound(piece, cover, up, bound, relevant, depth);
}

inline Vector_3d triangle_normal(const Triangle_3d& t)
{
  const Vector_3d n = (t[1] - t[0]).cross(t[2] - t[0]);
  const double length = n.norm();
  return length > 0 ? Vector_3d(n / length) : Vector_3d(0, 0, 1);
}

// The symmetric distance bound between the working mesh and the input (`input`, in the working
// mesh's units). Inactive, and every answer yes, with a bound of zero.
class Distance_bound
{
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<Work_mesh>;
#if CGAL_VERSION_NR >= 1060000000
  using Traits = CGAL::AABB_traits_3<Work_kernel, Primitive>;
#else
  using Traits = CGAL::AABB_traits<Work_kernel, Primitive>;
#endif
  using Tree = CGAL::AABB_tree<Traits>;
  using Vertex = Work_mesh::Vertex_index;
  using Halfedge = Work_mesh::Halfedge_index;
  using Face = Work_mesh::Face_index;

public:
  Distance_bound() = default;

  Distance_bound(const Work_mesh& input, double bound) : m_input(&input), m_bound(bound)
  {
    if(bound > 0)
      m_tree = std::make_unique<Tree>(faces(input).first, faces(input).second, input);
  }

  bool active() const { return m_bound > 0; }
  double bound() const { return m_bound; }

  // The input's triangles that reach into the box.
  std::vector<Triangle_3d> input_triangles_in(const CGAL::Bbox_3& box) const
  {
    std::vector<Work_mesh::Face_index> found;
    m_tree->all_intersected_primitives(box, std::back_inserter(found));
    std::vector<Triangle_3d> triangles;
    triangles.reserve(found.size());
    for(Work_mesh::Face_index f : found)
    {
      const auto v = face_vertices(*m_input, f);
      triangles.push_back(Triangle_3d{{to_vector(m_input->point(v[0])), to_vector(m_input->point(v[1])),
                                       to_vector(m_input->point(v[2]))}});
    }
    return triangles;
  }

  // Whether every point of the triangles is within the bound of the input.
  bool near_input(const std::vector<Triangle_3d>& triangles) const
  {
    if(!active() || triangles.empty())
      return true;
    const std::vector<Triangle_3d> input = input_triangles_in(triangles_box(triangles, m_bound));
    for(const Triangle_3d& t : triangles)
      if(!within_bound(Convex_polygon(t.begin(), t.end()), input, triangle_normal(t), m_bound, nullptr))
        return false;
    return true;
  }

  // Whether the input stays within the bound of the mesh when the triangles `removed` make way for
  // `created`, `around` (triangles that stay, next to them) staying as they are: every point of the
  // input within the bound of a removed triangle is within it of a created or kept one. The mesh
  // kept the bound before.
  bool input_covered(const std::vector<Triangle_3d>& removed, const std::vector<Triangle_3d>& created,
                     const std::vector<Triangle_3d>& around) const
  {
    if(!active() || removed.empty())
      return true;
    std::vector<Triangle_3d> cover = created;
    cover.insert(cover.end(), around.begin(), around.end());
    // A removed triangle made again as it was changes nothing.
    std::vector<Triangle_3d> changed;
    for(const Triangle_3d& r : removed)
      if(std::none_of(created.begin(), created.end(), [&](const Triangle_3d& c) {
           return std::all_of(r.begin(), r.end(), [&](const Vector_3d& x) { return x == c[0] || x == c[1] || x == c[2]; });
         }))
        changed.push_back(r);
    if(changed.empty())
      return true;
    Relevant_triangles relevant;
    relevant.triangles = changed;
    for(const Triangle_3d& r : changed)
      relevant.shared.push_back(shared_parts(r, cover));
    for(const Triangle_3d& t : input_triangles_in(triangles_box(changed, m_bound)))
      if(!within_bound(Convex_polygon(t.begin(), t.end()), cover, triangle_normal(t), m_bound, &relevant))
        return false;
    return true;
  }

  // Both of the above.
  bool allows(const std::vector<Triangle_3d>& removed, const std::vector<Triangle_3d>& created,
              const std::vector<Triangle_3d>& around) const
  {
    return near_input(created) && input_covered(removed, created, around);
  }

  // Whether the triangles `created`, made in the mesh `m` in place of its faces `removed`, keep
  // the bound (allows()), the faces around them staying.
  template <typename Faces>
  bool allows_replacing(const Work_mesh& m, const Faces& removed, const std::vector<Triangle_3d>& created) const
  {
    if(!active())
      return true;
    std::vector<Triangle_3d> gone;
    for(Face f : removed)
      gone.push_back(triangle(m, f));
    return allows(gone, created, triangles_around(m, removed));
  }

  // Whether the faces around v keep the bound now that their vertices, and those of the faces
  // around them, moved from where `before(u)` says they were to where `m` has them. A face with a
  // single moved vertex was checked alone when that vertex's move was (allows_move()), and its
  // triangle is the same: only the faces with two or more moved vertices are checked again.
  template <typename Before>
  bool allows_moved_star(const Work_mesh& m, Vertex v, const Before& before) const
  {
    if(!active())
      return true;
    boost::container::small_vector<Face, 16> star;
    std::vector<Triangle_3d> gone, created, jointly_moved;
    for(Halfedge g : halfedges_around_target(m.halfedge(v), m))
      if(!m.is_border(g))
      {
        star.push_back(m.face(g));
        created.push_back(triangle(m, m.face(g)));
        const auto u = face_vertices(m, m.face(g));
        gone.push_back(Triangle_3d{{before(u[0]), before(u[1]), before(u[2])}});
        int moved = 0;
        for(int k = 0; k < 3; ++k)
          moved += gone.back()[k] != created.back()[k] ? 1 : 0;
        if(moved > 1)
          jointly_moved.push_back(created.back());
      }
    return near_input(jointly_moved) && input_covered(gone, created, triangles_around(m, star));
  }

  // The same for v moved to x.
  bool allows_move(const Work_mesh& m, Vertex v, const Vector_3d& x) const
  {
    if(!active())
      return true;
    boost::container::small_vector<Face, 16> star;
    std::vector<Triangle_3d> created;
    for(Halfedge g : halfedges_around_target(m.halfedge(v), m))
      if(!m.is_border(g))
      {
        star.push_back(m.face(g));
        created.push_back(Triangle_3d{{x, position(m, m.target(m.next(g))), position(m, m.source(g))}});
      }
    return allows_replacing(m, star, created);
  }

  // The same for the edge of h (h on a face) split at p.
  bool allows_split(const Work_mesh& m, Halfedge h, const Vector_3d& p) const
  {
    if(!active())
      return true;
    boost::container::small_vector<Face, 2> removed;
    std::vector<Triangle_3d> created;
    for(Halfedge g : {h, m.opposite(h)})
      if(!m.is_border(g))
      {
        const Vector_3d a = position(m, m.source(g)), b = position(m, m.target(g));
        const Vector_3d c = position(m, m.target(m.next(g)));
        removed.push_back(m.face(g));
        created.push_back(Triangle_3d{{a, p, c}});
        created.push_back(Triangle_3d{{p, b, c}});
      }
    return allows_replacing(m, removed, created);
  }

  // The same for the edge from `removed` to `kept` collapsed into `kept` at x.
  bool allows_collapse(const Work_mesh& m, Vertex removed, Vertex kept, const Vector_3d& x) const
  {
    if(!active())
      return true;
    boost::container::small_vector<Face, 24> gone;
    std::vector<Triangle_3d> created;
    for(Vertex u : {removed, kept})
      for(Halfedge g : halfedges_around_target(m.halfedge(u), m))
      {
        if(m.is_border(g) || std::find(gone.begin(), gone.end(), m.face(g)) != gone.end())
          continue;
        gone.push_back(m.face(g));
        const Vertex p = m.source(g), q = m.target(m.next(g));
        if(p != removed && p != kept && q != removed && q != kept)
          created.push_back(Triangle_3d{{x, position(m, q), position(m, p)}});
      }
    return allows_replacing(m, gone, created);
  }

private:
  static Vector_3d position(const Work_mesh& m, Vertex v) { return to_vector(m.point(v)); }

  static Triangle_3d triangle(const Work_mesh& m, Face f)
  {
    const auto v = face_vertices(m, f);
    return Triangle_3d{{position(m, v[0]), position(m, v[1]), position(m, v[2])}};
  }

  // The faces within two rings of `faces` (sharing a vertex with one of them, or with one of
  // those) and not among them. One ring is too few where the mesh's two sides of a thin part lie
  // within the bound of each other (blade's trailing edge, manual).
  template <typename Faces>
  static std::vector<Triangle_3d> triangles_around(const Work_mesh& m, const Faces& faces)
  {
    std::vector<Triangle_3d> around;
    std::vector<Face> seen(faces.begin(), faces.end());
    std::size_t ring_begin = 0;
    for(int ring = 0; ring < 2; ++ring)
    {
      const std::size_t ring_end = seen.size();
      for(std::size_t i = ring_begin; i < ring_end; ++i)
        for(Vertex u : face_vertices(m, seen[i]))
          for(Halfedge g : halfedges_around_target(m.halfedge(u), m))
          {
            const Face h = m.face(g);
            if(h != Work_mesh::null_face() && std::find(seen.begin(), seen.end(), h) == seen.end())
            {
              seen.push_back(h);
              around.push_back(triangle(m, h));
            }
          }
      ring_begin = ring_end;
    }
    return around;
  }

  const Work_mesh* m_input = nullptr;
  double m_bound = 0;
  std::unique_ptr<Tree> m_tree;
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_DISTANCE_BOUND_H
