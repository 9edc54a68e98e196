// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Sharp features (section 4.2): hysteresis detection of sharp edges, the kind of each vertex
// (free, sliding on a feature polyline, fixed), and sliding along the reference polylines.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_FEATURES_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_FEATURES_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <set>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// Values of a vector of feature edges, by edge; 0 for an edge that is not one.
constexpr char sharp_or_border_feature_edge = 1;
constexpr char constrained_feature_edge = 2; // the user's: kept as it is, never split

// Angle between the normals of the two faces of an edge, in degrees (0 where flat); 0 for a
// border edge.
template <typename Mesh>
double dihedral_angle(const Mesh& m, typename Mesh::Edge_index e)
{
  const auto h = m.halfedge(e), o = m.opposite(h);
  if(m.is_border(h) || m.is_border(o))
    return 0;
  return to_degrees(angle_between(face_area_vector(m, h), face_area_vector(m, o)));
}

// Beyond the paper: a crease fades (fandisk's curved creases fall from 64 to 42 degrees along
// their length), and where it falls below the upper bound eq. (8) ends it, although its edges
// are still creases. From the end of a sharp line, the edge that continues it most straightly
// becomes sharp when it turns by less than `max_turn` degrees and its dihedral is at least
// `theta_follow`, and so on along it: one edge a step and only straight ones, so that the zigzag
// of in-between edges on a coarse organic mesh does not spread.
// A fading crease runs on while its edges stay at 35 degrees or more (the paper's upper bound)
// and turn by less than 20. (Down to the middle of the bounds, it spread on cow and lion-head with
// the bounds (20, 35), and their triangles lost more than fandisk's lines gained.)
constexpr double fading_crease_angle = 35;     // degrees
constexpr double fading_crease_turn_angle = 20; // degrees

template <typename Mesh>
void follow_fading_creases(const Mesh& m, const std::vector<double>& theta, double theta_follow, double max_turn,
                           std::vector<char>& sharp)
{
  using Halfedge = typename Mesh::Halfedge_index;
  auto line_ends_at = [&](typename Mesh::Vertex_index v) {
    int n = 0;
    for(auto g : halfedges_around_target(m.halfedge(v), m))
      n += sharp[std::size_t(m.edge(g))] ? 1 : 0;
    return n == 1;
  };
  auto direction = [&](Halfedge h) {
    return Vector_3d((to_vector(m.point(m.target(h))) - to_vector(m.point(m.source(h)))).normalized());
  };
  const double min_cosine = std::cos(max_turn * (pi / 180));
  std::vector<Halfedge> ends; // halfedges along sharp lines, to their end
  for(auto e : m.edges())
    if(sharp[std::size_t(e)] && !m.is_border(e))
      ends.insert(ends.end(), {m.halfedge(e), m.opposite(m.halfedge(e))});
  while(!ends.empty())
  {
    const Halfedge h = ends.back();
    ends.pop_back();
    if(!line_ends_at(m.target(h)))
      continue;
    Halfedge next = Mesh::null_halfedge();
    double best = min_cosine;
    for(auto g : halfedges_around_source(m.target(h), m))
      if(m.edge(g) != m.edge(h) && !m.is_border(m.edge(g)) && theta[std::size_t(m.edge(g))] >= theta_follow &&
         direction(h).dot(direction(g)) > best)
      {
        best = direction(h).dot(direction(g));
        next = g;
      }
    if(next != Mesh::null_halfedge())
    {
      sharp[std::size_t(m.edge(next))] = 1;
      ends.push_back(next);
    }
  }
}

// eq. (8): sharp above theta_true, not sharp below theta_false, and in between sharp only when it
// continues edges above theta_true at both its ends: of the paper's "at least two neighbouring
// edges", one at each end. (Two at the same end would also make a noisy organic mesh's in-between
// edges sharp where strong ones meet, and their ends corners, which costs the triangles around
// them their quality.) With `follow_creases`, a crease also runs on while its edges stay above
// fading_crease_angle (follow_fading_creases()). Indexed by edge index.
template <typename Mesh>
std::vector<char> detect_sharp_edges(const Mesh& m, double theta_false, double theta_true, bool follow_creases = false)
{
  std::vector<double> theta(m.number_of_edges(), 0.);
  for(auto e : m.edges())
    theta[std::size_t(e)] = dihedral_angle(m, e);
  std::vector<char> sharp(m.number_of_edges(), 0);
  for(auto e : m.edges())
  {
    const double t = theta[std::size_t(e)];
    if(t > theta_true)
      sharp[std::size_t(e)] = 1;
    else if(t >= theta_false)
    {
      const auto h = m.halfedge(e);
      auto continued_at = [&](decltype(h) end) {
        for(auto g : halfedges_around_target(end, m))
          if(m.edge(g) != e && theta[std::size_t(m.edge(g))] > theta_true)
            return true;
        return false;
      };
      sharp[std::size_t(e)] = continued_at(h) && continued_at(m.opposite(h)) ? 1 : 0;
    }
  }
  if(follow_creases)
    follow_fading_creases(m, theta, fading_crease_angle, fading_crease_turn_angle, sharp);
  return sharp;
}

// How far v is from flat, in degrees: 360 (180 on a border) minus the angles of its triangles at v
// (a cube's corner 90, a horn's tip more; 0 inside a plane).
template <typename Mesh>
double angle_defect(const Mesh& m, typename Mesh::Vertex_index v)
{
  double sum = 0;
  for(auto g : halfedges_around_target(m.halfedge(v), m))
    if(!m.is_border(g))
      sum += angle(to_vector(m.point(v)), to_vector(m.point(m.source(g))), to_vector(m.point(m.target(m.next(g)))));
  return std::abs((m.is_border(v) ? 180 : 360) - to_degrees(sum));
}

// Beyond the paper, for a target coarser than the input: a line of sharp edges shorter than
// `shortest` from an end or junction to the next (or a closed one) shows nothing the target can
// keep, yet its ends hold vertices (a junction is a corner). It stops being sharp, unless one of
// its vertices where it ends (any of a closed one's) is a cone (angle defect of `cone_defect` or
// more: a horn's tip, a box's corner). By rounds, shortest first and one line a junction a round:
// a spur gone merges the two pieces it cut a crease into, which are then measured whole. Only
// sharp edges count: border and constrained edges are marked later, so a line runs on through a
// junction with them (it is measured longer, and kept more often).
constexpr double cone_defect = 45; // degrees
// The lines dropped when the target is coarser than the input are those shorter than this times
// the target: a quarter of an edge of the target's length is below what its triangles can show.
constexpr double short_sharp_line_to_target = 0.25;

template <typename Mesh>
struct Sharp_line
{
  std::vector<typename Mesh::Halfedge_index> halfedges;
  double length = 0;
  bool at_cone = false;
};

// The sharp line from `start` (whose source is an end or junction, or any vertex of a closed
// line) to its next end or junction; marks its edges `seen`.
template <typename Mesh, typename Degree>
Sharp_line<Mesh> walk_sharp_line(const Mesh& m, typename Mesh::Halfedge_index start, const std::vector<char>& sharp,
                                 const Degree& degree, std::vector<char>& seen)
{
  Sharp_line<Mesh> line;
  line.halfedges.push_back(start);
  seen[std::size_t(m.edge(start))] = 1;
  bool closed = false;
  for(auto h = start;; h = line.halfedges.back())
  {
    line.length += (to_vector(m.point(m.target(h))) - to_vector(m.point(m.source(h)))).norm();
    if(degree(m.target(h)) != 2)
      break;
    auto next = h;
    for(auto g : halfedges_around_source(m.target(h), m))
      if(m.edge(g) != m.edge(h) && sharp[std::size_t(m.edge(g))])
        next = g;
    if(seen[std::size_t(m.edge(next))])
    {
      closed = true; // back to its start
      break;
    }
    seen[std::size_t(m.edge(next))] = 1;
    line.halfedges.push_back(next);
  }
  const auto first = m.source(start), last = m.target(line.halfedges.back());
  if(closed)
    line.at_cone = std::any_of(line.halfedges.begin(), line.halfedges.end(),
                               [&](auto h) { return angle_defect(m, m.target(h)) >= cone_defect; });
  else
    line.at_cone = angle_defect(m, first) >= cone_defect || angle_defect(m, last) >= cone_defect;
  return line;
}

// Calls f on each sharp line of m (walk_sharp_line()): each open one from one of its ends or
// junctions, then the closed ones from anywhere.
template <typename Mesh, typename Degree, typename F>
void for_each_sharp_line(const Mesh& m, const std::vector<char>& sharp, const Degree& degree, const F& f)
{
  std::vector<char> seen(m.number_of_edges(), 0);
  for(bool closed : {false, true})
    for(auto start : m.halfedges())
      if(sharp[std::size_t(m.edge(start))] && !seen[std::size_t(m.edge(start))] &&
         (closed || degree(m.source(start)) != 2))
        f(walk_sharp_line(m, start, sharp, degree, seen));
}

template <typename Mesh>
void drop_short_sharp_lines(const Mesh& m, double shortest, std::vector<char>& sharp)
{
  auto degree = [&](typename Mesh::Vertex_index v) {
    int n = 0;
    for(auto g : halfedges_around_target(m.halfedge(v), m))
      n += sharp[std::size_t(m.edge(g))] ? 1 : 0;
    return n;
  };
  for(;;)
  {
    std::vector<Sharp_line<Mesh> > short_lines;
    for_each_sharp_line(m, sharp, degree, [&](Sharp_line<Mesh> line) {
      if(line.length < shortest && !line.at_cone)
        short_lines.push_back(std::move(line));
    });
    std::stable_sort(short_lines.begin(), short_lines.end(),
                     [](const Sharp_line<Mesh>& a, const Sharp_line<Mesh>& b) { return a.length < b.length; });
    std::vector<char> junction_used(m.number_of_vertices(), 0);
    bool dropped = false;
    for(const auto& line : short_lines)
    {
      const auto first = m.source(line.halfedges.front()), last = m.target(line.halfedges.back());
      if(junction_used[std::size_t(first)] || junction_used[std::size_t(last)])
        continue;
      for(auto v : {first, last})
        junction_used[std::size_t(v)] = degree(v) >= 3 ? 1 : 0;
      for(auto h : line.halfedges)
        sharp[std::size_t(m.edge(h))] = 0;
      dropped = true;
    }
    if(!dropped)
      return;
  }
}

enum class Vertex_kind : char
{
  free_vertex,    // moves on the surface
  feature_vertex, // slides along its feature polyline (one or two feature edges, section 4.2)
  fixed_vertex    // never moves: corners (three or more feature edges, or a feature line that
                  // turns sharply), user constraints
};

// Beyond the paper's corners (three or more feature edges): a vertex where the border turns by
// more than `corner_angle` degrees is a corner too. Sliding along the border would cut that turn
// off and the border would lose its shape (a single triangle would shrink). So is a vertex where
// a strong crease (both its edges at least `strong_crease_angle`) turns by more than
// `crease_turn_angle`: the crease's shape is carried by its input vertices, and a vertex that
// slid along it would cut the turn off (fandisk's curved creases, and its V-shaped one that turns
// by 160 degrees). Re-sampling, which removes and adds vertices on the lines, keeps only the
// turns beyond `corner_angle` (see its caller). Turns of weaker sharp lines are left to the
// paper's rule: on coarse organic models those lines zigzag along edges barely above the
// hysteresis bounds, and fixing their turns costs quality there.
constexpr double strong_crease_angle = 60;     // degrees
constexpr double strong_crease_turn_angle = 1; // degrees

template <typename Mesh>
std::vector<Vertex_kind> classify_vertices(const Mesh& m, const std::vector<char>& feature_edge,
                                           const std::vector<char>& constrained_vertex, double corner_angle,
                                           double crease_turn_angle = strong_crease_turn_angle)
{
  std::vector<Vertex_kind> kind(m.number_of_vertices(), Vertex_kind::free_vertex);
  for(auto v : m.vertices())
  {
    int count = 0, border = 0;
    double weakest = 180; // the smallest dihedral angle of v's feature edges
    std::array<Vector_3d, 2> ends;
    if(m.halfedge(v) != Mesh::null_halfedge())
      for(auto h : halfedges_around_target(m.halfedge(v), m))
        if(feature_edge[std::size_t(m.edge(h))])
        {
          if(count < 2)
            ends[count] = to_vector(m.point(m.source(h)));
          ++count;
          border += m.is_border(m.edge(h)) ? 1 : 0;
          weakest = (std::min)(weakest, dihedral_angle(m, m.edge(h)));
        }
    const double turn = count == 2 ? 180 - to_degrees(angle(to_vector(m.point(v)), ends[0], ends[1])) : 0;
    const bool turns = border == 2 ? turn > corner_angle : border == 0 && turn > crease_turn_angle && weakest >= strong_crease_angle;
    if(constrained_vertex[std::size_t(v)] || count >= 3 || turns ||
       m.halfedge(v) == Mesh::null_halfedge())
      kind[std::size_t(v)] = Vertex_kind::fixed_vertex;
    else if(count != 0)
      kind[std::size_t(v)] = Vertex_kind::feature_vertex;
  }
  return kind;
}

// Beyond the paper, for a target coarser than the input, as drop_short_sharp_lines(): two corners
// of a border closer than `shortest` along it make a notch or a step the target cannot show, yet
// each holds a vertex, and the edge between them stays short (ALSTOM_TEST4's borders at four
// times its mean edge length). A corner that is one only because the border turns there (not a
// junction, not the user's) slides instead when a corner that turns more, or one that is not of
// that kind, is kept closer than `shortest` along its border; the stronger turns are decided
// first, and of two equal turns the one met first along the border (from any of its halfedges).
template <typename Mesh>
void merge_close_border_corners(const Mesh& m, const std::vector<char>& feature_edge,
                                const std::vector<char>& constrained_vertex, double shortest,
                                std::vector<Vertex_kind>& kind)
{
  using Halfedge = typename Mesh::Halfedge_index;
  auto turn_only = [&](typename Mesh::Vertex_index v) {
    int count = 0, user = 0;
    for(auto h : halfedges_around_target(m.halfedge(v), m))
    {
      count += feature_edge[std::size_t(m.edge(h))] ? 1 : 0;
      user += feature_edge[std::size_t(m.edge(h))] == constrained_feature_edge ? 1 : 0;
    }
    return count == 2 && user == 0 && !constrained_vertex[std::size_t(v)];
  };
  std::vector<char> seen(m.number_of_halfedges(), 0);
  for(Halfedge start : m.halfedges())
  {
    if(!m.is_border(start) || seen[std::size_t(start)])
      continue;
    // The loop's corners: where along it (from `start`'s target), how much the border turns
    // there (the kept ones first), and whether they may slide.
    struct Corner
    {
      double at, turn;
      typename Mesh::Vertex_index v;
      bool may_slide;
    };
    std::vector<Corner> corners;
    double along = 0;
    for(Halfedge h = start;; )
    {
      seen[std::size_t(h)] = 1;
      const auto v = m.target(h);
      const Halfedge next = m.next(h);
      if(kind[std::size_t(v)] == Vertex_kind::fixed_vertex)
      {
        const Vector_3d p = to_vector(m.point(v));
        const double turn = 180 - to_degrees(angle(p, to_vector(m.point(m.source(h))), to_vector(m.point(m.target(next)))));
        const bool may_slide = turn_only(v);
        corners.push_back(Corner{along, may_slide ? turn : 360, v, may_slide});
      }
      along += (to_vector(m.point(m.target(next))) - to_vector(m.point(v))).norm();
      h = next;
      if(h == start)
        break;
    }
    const double perimeter = along;
    std::stable_sort(corners.begin(), corners.end(), [](const Corner& a, const Corner& b) { return a.turn > b.turn; });
    std::set<double> kept;
    for(const Corner& c : corners)
    {
      // The nearest kept corners before and after c along the loop, which is closed.
      bool near = false;
      if(!kept.empty())
      {
        auto after = kept.lower_bound(c.at);
        const double to_after = after == kept.end() ? *kept.begin() + perimeter - c.at : *after - c.at;
        const double to_before = after == kept.begin() ? c.at + perimeter - *kept.rbegin() : c.at - *std::prev(after);
        near = (std::min)(to_after, to_before) < shortest;
      }
      if(near && c.may_slide)
        kind[std::size_t(c.v)] = Vertex_kind::feature_vertex;
      else
        kept.insert(c.at);
    }
  }
}

// The feature polylines of the reference mesh, and positions on them: a point at parameter t of
// a feature halfedge, from its source (t = 0) to its target (t = 1).
template <typename Mesh>
class Feature_polylines
{
public:
  using Halfedge = typename Mesh::Halfedge_index;
  using Vertex = typename Mesh::Vertex_index;

  struct Location
  {
    Halfedge h;
    double t = 0;
  };

  Feature_polylines(const Mesh& reference, const std::vector<char>& feature_edge,
                    const std::vector<Vertex_kind>& kind)
    : m_mesh(reference), m_feature(feature_edge), m_kind(kind)
  {}

  // How far a line of the working mesh may leave its polyline (chord_deviation()) when its
  // vertices slide or go: infinite unless the connectivity stage re-samples the lines, where the
  // turns of the strong creases, and of the borders when `borders_too`, are not corners.
  double line_tolerance() const { return m_line_tolerance; }
  void set_line_tolerance(double tolerance, bool borders_too)
  {
    m_line_tolerance = tolerance;
    m_borders_hold_turns = borders_too;
  }

  bool is_feature(Halfedge h) const { return m_feature[std::size_t(m_mesh.edge(h))] != 0; }

  // Whether the segment of a location is on a line whose turns a sliding vertex may cut by no
  // more than the line tolerance: a strong crease, or a border (where the surface ends) when the
  // borders hold their turns.
  bool holds_turns(const Location& l) const
  {
    const auto e = m_mesh.edge(l.h);
    return m_mesh.is_border(e) ? m_borders_hold_turns : dihedral_angle(m_mesh, e) >= strong_crease_angle;
  }

  // The location of a reference vertex on a feature polyline.
  Location at_vertex(Vertex v) const
  {
    for(auto h : halfedges_around_source(v, m_mesh))
      if(is_feature(h))
        return Location{h, 0.};
    return Location{m_mesh.halfedge(v), 0.};
  }

  Vector_3d point(const Location& l) const
  {
    const Vector_3d a = to_vector(m_mesh.point(m_mesh.source(l.h)));
    const Vector_3d b = to_vector(m_mesh.point(m_mesh.target(l.h)));
    return (1 - l.t) * a + l.t * b;
  }

  // The reference vertex nearest to the location along its segment.
  Vertex nearest_vertex(const Location& l) const
  {
    return l.t < 0.5 ? m_mesh.source(l.h) : m_mesh.target(l.h);
  }

  // A unit tangent of the polyline at the location (at a polyline vertex, the direction that
  // bisects the way in and the way out).
  Vector_3d tangent(const Location& l) const
  {
    const Vector_3d u = direction(l.h);
    if(l.t > 0 && l.t < 1)
      return u;
    const Vertex v = l.t <= 0 ? m_mesh.source(l.h) : m_mesh.target(l.h);
    std::array<Vector_3d, 2> out{{Vector_3d::Zero(), Vector_3d::Zero()}};
    int n = 0;
    for(auto g : halfedges_around_source(v, m_mesh))
      if(is_feature(g) && n < 2)
        out[n++] = direction(g);
    const Vector_3d t = n == 2 ? Vector_3d(out[0] - out[1]) : out[0];
    return t.norm() > 0 ? Vector_3d(t.normalized()) : u;
  }

  // Slides from `l` along the polyline in the way `displacement` points, by the length of its
  // component along the polyline; stops at polyline ends and at fixed reference vertices.
  Location move(Location l, const Vector_3d& displacement) const
  {
    // Start on a segment that leaves the current point in the wanted way.
    if(l.t <= 0 || l.t >= 1)
    {
      const Vertex v = l.t <= 0 ? m_mesh.source(l.h) : m_mesh.target(l.h);
      Halfedge best = l.h;
      double best_dot = 0;
      for(auto g : halfedges_around_source(v, m_mesh))
        if(is_feature(g))
        {
          const double d = direction(g).dot(displacement);
          if(d > best_dot)
          {
            best_dot = d;
            best = g;
          }
        }
      if(!(best_dot > 0))
        return l;
      l = Location{best, 0.};
    }
    else if(direction(l.h).dot(displacement) < 0)
      l = Location{m_mesh.opposite(l.h), 1 - l.t};

    double remaining = std::abs(direction(l.h).dot(displacement));
    for(std::size_t guard = 0; guard < m_mesh.number_of_halfedges(); ++guard)
    {
      const double length = segment_length(l.h);
      const double available = (1 - l.t) * length;
      if(remaining < available)
      {
        l.t += remaining / length;
        return l;
      }
      remaining -= available;
      const Vertex v = m_mesh.target(l.h);
      l.t = 1;
      if(m_kind[std::size_t(v)] != Vertex_kind::feature_vertex || !(remaining > 0))
        return l;
      // Continue on the other feature edge of v.
      Halfedge next_h = l.h;
      for(auto g : halfedges_around_source(v, m_mesh))
        if(is_feature(g) && g != m_mesh.opposite(l.h))
          next_h = g;
      if(next_h == l.h)
        return l;
      l = Location{next_h, 0.};
    }
    return l;
  }

  // How far the polyline between `from` and `to` leaves the chord between their points: the
  // largest distance of its vertices there (a segment is farthest at an end); infinite when `to`
  // is not within `limit` of `from` along the polyline, or lies beyond a polyline end or corner.
  double chord_deviation(const Location& from, const Location& to, double limit) const
  {
    const Vector_3d a = point(from), b = point(to);
    const bool to_inside = to.t > 0 && to.t < 1;
    const Vertex to_vertex = to.t <= 0 ? m_mesh.source(to.h) : m_mesh.target(to.h);
    std::vector<Halfedge> starts{from.h, m_mesh.opposite(from.h)};
    if(from.t <= 0 || from.t >= 1)
    {
      starts.clear();
      for(auto g : halfedges_around_source(from.t <= 0 ? m_mesh.source(from.h) : m_mesh.target(from.h), m_mesh))
        if(is_feature(g))
          starts.push_back(g);
    }
    double best = std::numeric_limits<double>::infinity();
    for(const Halfedge start : starts)
    {
      double deviation = 0, length = 0;
      for(Halfedge g = start; length <= limit;)
      {
        if(to_inside ? (g == to.h || g == m_mesh.opposite(to.h)) : m_mesh.target(g) == to_vertex)
        {
          best = (std::min)(best, deviation);
          break;
        }
        const Vertex v = m_mesh.target(g);
        length += segment_length(g);
        deviation = (std::max)(deviation, distance_to_segment(to_vector(m_mesh.point(v)), a, b));
        Halfedge next = g;
        if(m_kind[std::size_t(v)] == Vertex_kind::feature_vertex)
          for(auto o : halfedges_around_source(v, m_mesh))
            if(is_feature(o) && o != m_mesh.opposite(g))
              next = o;
        if(next == g)
          break;
        g = next;
      }
    }
    return best;
  }

private:
  Vector_3d direction(Halfedge h) const
  {
    const Vector_3d d = to_vector(m_mesh.point(m_mesh.target(h))) - to_vector(m_mesh.point(m_mesh.source(h)));
    const double n = d.norm();
    return n > 0 ? Vector_3d(d / n) : Vector_3d::Zero();
  }

  double segment_length(Halfedge h) const
  {
    return (to_vector(m_mesh.point(m_mesh.target(h))) - to_vector(m_mesh.point(m_mesh.source(h)))).norm();
  }

  const Mesh& m_mesh;
  const std::vector<char>& m_feature;
  const std::vector<Vertex_kind>& m_kind;
  double m_line_tolerance = std::numeric_limits<double>::infinity();
  bool m_borders_hold_turns = false;
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_FEATURES_H
