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

// Whether every point of the convex polygon `piece` is within `bound` of the triangles of `cover`
// (with `relevant`, only the points within `bound` of those triangles need be: the others are
// within it of triangles that stay). `up` is the direction along which cells are cut. Only the
// triangles within `bound` of the piece's box count.
inline bool within_bound(const Convex_polygon& whole_piece, const std::vector<Triangle_3d>& all_cover,
                         const Vector_3d& up, double bound, const std::vector<Triangle_3d>* all_relevant,
                         int depth = 0, bool first_try = true)
{
  constexpr int max_depth = 6;
  std::vector<Triangle_3d> relevant_here;
  Convex_polygon piece = whole_piece;
  if(all_relevant)
  {
    // Only the part of the piece within the bound of a relevant triangle matters.
    relevant_here = triangles_in(*all_relevant, polygon_box(whole_piece, bound));
    if(relevant_here.empty())
      return true;
    piece = clipped_to_box(whole_piece, triangles_box(relevant_here, bound));
    if(piece.empty())
      return true;
  }
  const CGAL::Bbox_3 box = polygon_box(piece, bound);
  const std::vector<Triangle_3d>* relevant = all_relevant ? &relevant_here : nullptr;
  const std::vector<Triangle_3d> cover = triangles_in(all_cover, box);
  Vector_3d centre;
  const double radius = polygon_radius(piece, centre);
  if(relevant && distance_to_triangles(centre, *relevant) - radius > bound)
    return true;
  if(cover.empty())
    return false;
  // Most pieces lie within the bound of the one triangle nearest their centre.
  std::size_t nearest = 0;
  if(distance_to_triangles(centre, cover, &nearest) + radius <= bound)
    return true;
  Convex_polygon far;
  for(const Vector_3d& x : piece)
    if(distance_to_triangle(x, cover[nearest]) > bound)
      far.push_back(x);
  if(far.empty())
    return true;
  // Most others lie within it of that triangle and of those nearest the corners beyond it: cells
  // below those first, the cells those leave to all triangles.
  if(first_try)
  {
    std::vector<Triangle_3d> nearest_to_corners(1, cover[nearest]);
    std::vector<std::size_t> taken(1, nearest);
    for(const Vector_3d& x : far)
    {
      std::size_t k = 0;
      distance_to_triangles(x, cover, &k);
      if(std::find(taken.begin(), taken.end(), k) == taken.end())
      {
        taken.push_back(k);
        nearest_to_corners.push_back(cover[k]);
      }
    }
    for(const Bounded_cell& cell : cells_below(piece, nearest_to_corners, up))
    {
      // A cell below none of them is measured to the triangle nearest its centre.
      const Triangle_3d* below = cell.triangle < nearest_to_corners.size() ? &nearest_to_corners[cell.triangle] : nullptr;
      if(!below)
      {
        Vector_3d cell_centre;
        polygon_radius(cell.polygon, cell_centre);
        std::size_t k = 0;
        distance_to_triangles(cell_centre, cover, &k);
        below = &cover[k];
      }
      if(!std::all_of(cell.polygon.begin(), cell.polygon.end(),
                      [&](const Vector_3d& x) { return distance_to_triangle(x, *below) <= bound; }) &&
         !within_bound(cell.polygon, cover, up, bound, relevant, depth, false))
        return false;
    }
    return true;
  }
  for(Bounded_cell& cell : cells_below(piece, cover, up))
  {
    const double cell_radius = polygon_radius(cell.polygon, centre);
    const double from_relevant = relevant ? distance_to_triangles(centre, *relevant) : 0;
    if(from_relevant - cell_radius > bound)
      continue;
    const double at_centre = distance_to_triangles(centre, cover, cell.triangle >= cover.size() ? &cell.triangle : nullptr);
    if(at_centre + cell_radius <= bound)
      continue; // the distance to the cover changes by at most the radius across the cell
    bool corners_within = true;
    for(const Vector_3d& x : cell.polygon)
      corners_within = corners_within && distance_to_triangle(x, cover[cell.triangle]) <= bound;
    if(corners_within)
      continue;
    // A centre beyond the bound that matters refutes the piece; one that does not, settles nothing.
    if((at_centre > bound && from_relevant <= bound) || depth == max_depth)
      return false;
    // Halve the cell: a fan of triangles, each cut into four at its midpoints.
    for(std::size_t k = 1; k + 1 < cell.polygon.size(); ++k)
    {
      const Vector_3d& a = cell.polygon[0];
      const Vector_3d& b = cell.polygon[k];
      const Vector_3d& c = cell.polygon[k + 1];
      const Vector_3d ab = (a + b) / 2, bc = (b + c) / 2, ca = (c + a) / 2;
      for(const Triangle_3d& q : {Triangle_3d{{a, ab, ca}}, Triangle_3d{{ab, b, bc}}, Triangle_3d{{ca, bc, c}},
                                  Triangle_3d{{ab, bc, ca}}})
        if(!within_bound(Convex_polygon(q.begin(), q.end()), cover, up, bound, relevant, depth + 1))
          return false;
    }
  }
  return true;
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
    for(const Triangle_3d& t : input_triangles_in(triangles_box(removed, m_bound)))
      if(!within_bound(Convex_polygon(t.begin(), t.end()), cover, triangle_normal(t), m_bound, &removed))
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

  // The faces that share a vertex with one of `faces` and are not among them.
  template <typename Faces>
  static std::vector<Triangle_3d> triangles_around(const Work_mesh& m, const Faces& faces)
  {
    std::vector<Triangle_3d> around;
    boost::container::small_vector<Face, 32> seen(faces.begin(), faces.end());
    for(Face f : faces)
      for(Vertex u : face_vertices(m, f))
        for(Halfedge g : halfedges_around_target(m.halfedge(u), m))
        {
          const Face h = m.face(g);
          if(h != Work_mesh::null_face() && std::find(seen.begin(), seen.end(), h) == seen.end())
          {
            seen.push_back(h);
            around.push_back(triangle(m, h));
          }
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
