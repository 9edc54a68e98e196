// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Section 3, the connectivity optimisation: each local operator on meshes built to need it, the
// guarantees of a pass (valid, manifold, same topology, no degenerate or folded triangle,
// features untouched) on several meshes, and the whole method with connectivity changes.

#include "test_meshes.h"

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/graphcut_isotropic_remeshing.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/connectivity.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/edge_collapses.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/edge_flips.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/edge_splits.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/relaxation.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/vertex_splits.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/guarantees.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/intersections.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_report.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <set>
#include <string>
#include <vector>

using namespace graphcut_remeshing_test;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace GP = PMP::graphcut_parameters;
namespace GR = PMP::internal::Graphcut_remeshing;
using Work = GR::Work_mesh;

namespace {

// The sharp-edge hysteresis bounds of eq. (8) these tests use (the library's defaults).
const double theta_false = 20, theta_true = 35;

// Random flips that keep the triangles sound, to make the valences irregular.
void scramble(Work& m, const std::vector<char>& feature, unsigned seed, std::size_t flips)
{
  CGAL::Random rng(seed);
  std::vector<Work::Edge_index> edges(m.edges().begin(), m.edges().end());
  for(std::size_t k = 0; k < flips; ++k)
  {
    const Work::Edge_index e = edges[rng.get_int(0, int(edges.size()))];
    if(feature[std::size_t(e)] || m.is_border(e))
      continue;
    const auto h = m.halfedge(e), o = m.opposite(h);
    const auto a = m.source(h), b = m.target(h), c = m.target(m.next(h)), d = m.target(m.next(o));
    if(m.halfedge(c, d) != Work::null_halfedge() || m.degree(a) < 5 || m.degree(b) < 5)
      continue;
    auto p = [&m](Work::Vertex_index v) { return GR::to_vector(m.point(v)); };
    const GR::Vector_3d n = GR::area_vector(p(a), p(b), p(c)) + GR::area_vector(p(b), p(a), p(d));
    if(!GR::is_acceptable_triangle(p(a), p(d), p(c), n) || !GR::is_acceptable_triangle(p(d), p(b), p(c), n) ||
       GR::smallest_angle(p(a), p(d), p(c)) < 0.3 || GR::smallest_angle(p(d), p(b), p(c)) < 0.3)
      continue;
    CGAL::Euler::flip_edge(h, m);
  }
}

// A working mesh with its unchanged reference copy and the tracking state of a fresh remesher:
// what the connectivity operators work on.
class Pass_setup
{
public:
  explicit Pass_setup(const Work& m, double length_factor = 1.0, bool sharp_features = true)
    : mesh(m), reference_mesh(m), reference(reference_mesh, theta_false),
      reference_feature_edge(features_of(m, sharp_features)),
      reference_kind(GR::classify_vertices(m, reference_feature_edge, std::vector<char>(m.num_vertices(), 0), theta_true)),
      polylines(reference_mesh, reference_feature_edge, reference_kind)
  {
    state.feature_edge = reference_feature_edge;
    state.kind = reference_kind;
    state.location.resize(mesh.num_vertices());
    state.edge_hint.resize(mesh.num_edges());
    for(auto v : mesh.vertices())
      if(state.kind[std::size_t(v)] == GR::Vertex_kind::feature_vertex)
        state.location[std::size_t(v)] = polylines.at_vertex(v);
    for(auto e : mesh.edges())
    {
      const auto h = mesh.halfedge(e);
      state.edge_hint[std::size_t(e)] = mesh.face(mesh.is_border(h) ? mesh.opposite(h) : h);
    }
    state.closest.resize(mesh.num_vertices());
    state.vertex_hint.resize(mesh.num_vertices());
    for(auto v : mesh.vertices())
    {
      state.closest[std::size_t(v)] = v;
      state.vertex_hint[std::size_t(v)] = reference.incident_face(v);
    }
    state.face_hint.resize(mesh.num_faces());
    for(auto f : mesh.faces())
      state.face_hint[std::size_t(f)] = f;
    double total = 0;
    for(auto e : mesh.edges())
      total += (point(mesh.source(mesh.halfedge(e))) - point(mesh.target(mesh.halfedge(e)))).norm();
    sizing.longest = length_factor * total / double(mesh.number_of_edges());
    sizing.tolerance = 3e-3;
    input_feature_edges = feature_edges();
  }

  static std::vector<char> features_of(const Work& m, bool sharp_features)
  {
    std::vector<char> f = sharp_features ? GR::detect_sharp_edges(m, 20, 35) : std::vector<char>(m.num_edges(), 0);
    for(auto e : m.edges())
      if(m.is_border(e))
        f[std::size_t(e)] = 1;
    return f;
  }

  // Without the polylines, as most tests here: no sharp edge is split.
  GR::Local_operations operations() { return GR::Local_operations(mesh, reference, state, sizing); }
  GR::Local_operations operations_with_features() { return GR::Local_operations(mesh, reference, state, sizing, &polylines); }
  GR::Connectivity_optimizer optimizer() { return GR::Connectivity_optimizer(mesh, reference, state, sizing); }
  GR::Connectivity_optimizer optimizer_with_features()
  {
    return GR::Connectivity_optimizer(mesh, reference, state, sizing, &polylines);
  }

  GR::Vector_3d point(Work::Vertex_index v) const { return GR::to_vector(mesh.point(v)); }

  // The feature edges as pairs of vertex indices.
  std::set<std::pair<std::size_t, std::size_t> > feature_edges() const
  {
    std::set<std::pair<std::size_t, std::size_t> > s;
    for(auto e : mesh.edges())
      if(state.feature_edge[std::size_t(e)])
      {
        const std::size_t a = std::size_t(mesh.source(mesh.halfedge(e))), b = std::size_t(mesh.target(mesh.halfedge(e)));
        s.emplace((std::min)(a, b), (std::max)(a, b));
      }
    return s;
  }

  // The reference triangle nearest to x, by brute force, and its distance: an oracle.
  Work::Face_index nearest_reference_face(const GR::Vector_3d& x, double& distance) const
  {
    distance = std::numeric_limits<double>::infinity();
    Work::Face_index nearest;
    for(auto f : reference_mesh.faces())
    {
      const auto t = GR::face_vertices(reference_mesh, f);
      std::array<double, 3> w;
      const double d = (x - GR::closest_point_on_triangle(x, GR::to_vector(reference_mesh.point(t[0])),
                                                          GR::to_vector(reference_mesh.point(t[1])),
                                                          GR::to_vector(reference_mesh.point(t[2])), w)).norm();
      if(d < distance)
      {
        distance = d;
        nearest = f;
      }
    }
    return nearest;
  }

  // For the fold-over check.
  GR::Vector_3d reference_normal(const GR::Vector_3d& x) const
  {
    double d;
    const auto t = GR::face_vertices(reference_mesh, nearest_reference_face(x, d));
    return GR::area_vector(GR::to_vector(reference_mesh.point(t[0])), GR::to_vector(reference_mesh.point(t[1])),
                           GR::to_vector(reference_mesh.point(t[2]))).normalized();
  }

  double reference_distance(const GR::Vector_3d& x) const
  {
    double d;
    nearest_reference_face(x, d);
    return d;
  }

  Work mesh;
  const Work reference_mesh;
  GR::Reference_surface<Work> reference;
  const std::vector<char> reference_feature_edge;
  const std::vector<GR::Vertex_kind> reference_kind;
  GR::Feature_polylines<Work> polylines;
  GR::Tracking_state state;
  GR::Sizing_field sizing;
  std::set<std::pair<std::size_t, std::size_t> > input_feature_edges;
};

int valence_deviation(const Work& m)
{
  int d = 0;
  for(auto v : m.vertices())
    d += std::abs(int(m.degree(v)) - (m.is_border(v) ? 4 : 6));
  return d;
}

int euler_characteristic(const Work& m)
{
  return int(m.number_of_vertices()) - int(m.number_of_edges()) + int(m.number_of_faces());
}

std::size_t components(const Work& m)
{
  std::vector<std::size_t> ids(m.num_faces(), 0);
  return PMP::connected_components(m, CGAL::make_property_map(ids));
}

std::size_t border_halfedges(const Work& m)
{
  std::size_t n = 0;
  for(auto h : m.halfedges())
    n += m.is_border(h) ? 1 : 0;
  return n;
}

// What every pass must keep: a valid manifold mesh of the same topology, no degenerate triangle,
// none turned over against the reference, the vertices on feature edges untouched and each
// feature edge still there, or split into feature edges.
void expect_pass_guarantees(const Pass_setup& s, const Work& before, const std::string& name)
{
  const Work& m = s.mesh;
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m)) << name;
  EXPECT_TRUE(CGAL::is_triangle_mesh(m)) << name;
  EXPECT_EQ(euler_characteristic(m), euler_characteristic(before)) << name;
  EXPECT_EQ(components(m), components(before)) << name;
  EXPECT_EQ(border_halfedges(m), border_halfedges(before)) << name;
  // Manifold: no two edges join the same two vertices.
  std::set<std::pair<std::size_t, std::size_t> > seen;
  for(auto e : m.edges())
  {
    const std::size_t a = std::size_t(m.source(m.halfedge(e))), b = std::size_t(m.target(m.halfedge(e)));
    EXPECT_TRUE(seen.emplace((std::min)(a, b), (std::max)(a, b)).second) << name << ": duplicated edge";
  }
  std::size_t degenerate = 0, folded = 0;
  for(auto f : m.faces())
  {
    const auto t = GR::face_vertices(m, f);
    const GR::Vector_3d a = s.point(t[0]), b = s.point(t[1]), c = s.point(t[2]);
    const GR::Vector_3d n = GR::area_vector(a, b, c);
    if(!(GR::smallest_angle(a, b, c) > 1e-3))
      ++degenerate;
    else if(!(n.dot(s.reference_normal((a + b + c) / 3)) > 0))
      ++folded;
  }
  EXPECT_EQ(degenerate, 0u) << name;
  EXPECT_EQ(folded, 0u) << name;
  std::set<std::size_t> input_feature_vertices;
  for(const auto& e : s.input_feature_edges)
    input_feature_vertices.insert({e.first, e.second});
  // a and b joined by feature edges, through vertices that splits put on the feature.
  auto joined = [&](Work::Vertex_index a, Work::Vertex_index b) {
    std::vector<Work::Vertex_index> todo{a};
    std::set<std::size_t> seen_vertices{std::size_t(a)};
    while(!todo.empty())
    {
      const Work::Vertex_index u = todo.back();
      todo.pop_back();
      for(auto h : halfedges_around_source(u, m))
      {
        const Work::Vertex_index w = m.target(h);
        if(!s.state.feature_edge[std::size_t(m.edge(h))] || !seen_vertices.insert(std::size_t(w)).second)
          continue;
        if(w == b)
          return true;
        if(!input_feature_vertices.count(std::size_t(w)))
          todo.push_back(w);
      }
    }
    return false;
  };
  for(const auto& e : s.input_feature_edges)
  {
    const Work::Vertex_index a(static_cast<Work::size_type>(e.first)), b(static_cast<Work::size_type>(e.second));
    ASSERT_FALSE(m.is_removed(a) || m.is_removed(b)) << name << ": a feature vertex was removed";
    EXPECT_TRUE(joined(a, b)) << name << ": a feature edge was flipped or collapsed";
    EXPECT_EQ(m.point(a), before.point(a)) << name << ": a feature vertex moved in a pass";
    EXPECT_EQ(m.point(b), before.point(b)) << name << ": a feature vertex moved in a pass";
  }
}

struct Named_mesh
{
  std::string name;
  Work mesh;
};

// Closed, open, curved, flat, with and without sharp features, genus 0 and 1.
std::vector<Named_mesh> scrambled_meshes()
{
  std::vector<Named_mesh> meshes;
  meshes.push_back({"noisy sphere", to_work_mesh(noisy_sphere(3, 0.02, 0.0, 11))});
  meshes.push_back({"torus", to_work_mesh(make_torus(36, 14, 1.0, 0.35))});
  meshes.push_back({"jittered box", to_work_mesh(jittered_box(1, 2, 0.5, 6, 12))});
  meshes.push_back({"flat grid", to_work_mesh(make_grid(14, 12, [](std::size_t i, std::size_t j) {
                      return Point(double(i) + 0.3 * std::sin(3.0 * double(j)), double(j) + 0.2 * std::cos(2.0 * double(i)), 0);
                    }))});
  unsigned seed = 1;
  for(Named_mesh& m : meshes)
  {
    const std::vector<char> sharp = GR::detect_sharp_edges(m.mesh, 20, 35);
    scramble(m.mesh, sharp, seed++, m.mesh.number_of_edges());
  }
  return meshes;
}

// --- re-sampling (Sizing_field::resamples()): splits and collapses to a curvature-adapted sizing ---

std::size_t border_cycles(const Work& m)
{
  std::set<std::size_t> seen;
  std::size_t cycles = 0;
  for(auto h : m.halfedges())
    if(m.is_border(h) && !seen.count(std::size_t(h)))
    {
      ++cycles;
      for(auto g : CGAL::halfedges_around_face(h, m))
        seen.insert(std::size_t(g));
    }
  return cycles;
}

double distance_to_feature_edges(const GR::Vector_3d& x, const Work& m, const std::vector<char>& feature)
{
  double best = std::numeric_limits<double>::infinity();
  for(auto e : m.edges())
    if(feature[std::size_t(e)])
      best = (std::min)(best, GR::distance_to_segment(x, GR::to_vector(m.point(m.source(m.halfedge(e)))),
                                                      GR::to_vector(m.point(m.target(m.halfedge(e))))));
  return best;
}

// What a re-sampling pass must keep: a valid manifold mesh of the same topology (as many border
// cycles), no degenerate or folded triangle, the corners where they were, and the feature lines:
// every input feature edge's midpoint near an output feature edge, and the reverse.
void expect_resampling_guarantees(const Pass_setup& s, const Work& before, double near, const std::string& name)
{
  const Work& m = s.mesh;
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m)) << name;
  EXPECT_TRUE(CGAL::is_triangle_mesh(m)) << name;
  EXPECT_EQ(euler_characteristic(m), euler_characteristic(before)) << name;
  EXPECT_EQ(components(m), components(before)) << name;
  EXPECT_EQ(border_cycles(m), border_cycles(before)) << name;
  std::set<std::pair<std::size_t, std::size_t> > seen;
  std::size_t duplicated = 0, degenerate = 0, folded = 0;
  for(auto e : m.edges())
  {
    const std::size_t a = std::size_t(m.source(m.halfedge(e))), b = std::size_t(m.target(m.halfedge(e)));
    duplicated += seen.emplace((std::min)(a, b), (std::max)(a, b)).second ? 0 : 1;
  }
  for(auto f : m.faces())
  {
    const auto t = GR::face_vertices(m, f);
    const GR::Vector_3d a = s.point(t[0]), b = s.point(t[1]), c = s.point(t[2]);
    if(!(GR::smallest_angle(a, b, c) > 1e-3))
      ++degenerate;
    else if(!(GR::area_vector(a, b, c).dot(s.reference_normal((a + b + c) / 3)) > 0))
      ++folded;
  }
  EXPECT_EQ(duplicated, 0u) << name;
  EXPECT_EQ(degenerate, 0u) << name;
  EXPECT_EQ(folded, 0u) << name;
  for(auto v : s.reference_mesh.vertices())
    if(s.reference_kind[std::size_t(v)] == GR::Vertex_kind::fixed_vertex)
    {
      ASSERT_FALSE(m.is_removed(v)) << name << ": a corner was removed";
      EXPECT_EQ(m.point(v), s.reference_mesh.point(v)) << name << ": a corner moved";
    }
  auto midpoint = [](const Work& w, Work::Edge_index e) -> GR::Vector_3d {
    return (GR::to_vector(w.point(w.source(w.halfedge(e)))) + GR::to_vector(w.point(w.target(w.halfedge(e))))) / 2;
  };
  for(auto e : s.reference_mesh.edges())
    if(s.reference_feature_edge[std::size_t(e)])
    {
      EXPECT_LT(distance_to_feature_edges(midpoint(s.reference_mesh, e), m, s.state.feature_edge), near)
        << name << ": an input feature edge is lost";
    }
  for(auto e : m.edges())
    if(s.state.feature_edge[std::size_t(e)])
    {
      EXPECT_LT(distance_to_feature_edges(midpoint(m, e), s.reference_mesh, s.reference_feature_edge), near)
        << name << ": a feature edge where the input has none";
    }
}

} // namespace

// Coarsening drops the sharp lines that are short at the target's scale: spurs, short lines and
// small loops go; a long line cut in two by a spur's junction stays whole once the spur is gone
// (its halves, 4 and 5 long, would go with it), and lines between cones (a box's corners) stay
// whatever their length. Several scales.
TEST(Features, ShortSharpLinesAreDroppedButNotAtCones)
{
  for(double scale : {1e-3, 1.0, 1e3})
  {
    const std::string name = "scale " + std::to_string(scale);
    const Work grid = to_work_mesh(make_grid(12, 12, [scale](std::size_t i, std::size_t j) {
      return Point(scale * double(i), scale * double(j), 0);
    }));
    auto vertex = [&](std::size_t i, std::size_t j) { return Work::Vertex_index(Work::size_type(12 * j + i)); };
    auto edge = [&](std::size_t i, std::size_t j, std::size_t k, std::size_t l) {
      return std::size_t(grid.edge(grid.halfedge(vertex(i, j), vertex(k, l))));
    };
    std::vector<std::size_t> long_line, spur{edge(5, 5, 5, 6)}, short_line{edge(2, 9, 3, 9), edge(3, 9, 4, 9)},
      loop{edge(8, 1, 9, 1), edge(9, 1, 9, 2), edge(9, 2, 8, 1)};
    for(std::size_t i = 1; i < 10; ++i)
      long_line.push_back(edge(i, 5, i + 1, 5));
    std::vector<char> sharp(grid.number_of_edges(), 0);
    for(const auto* line : {&long_line, &spur, &short_line, &loop})
      for(std::size_t e : *line)
        sharp[e] = 1;
    auto kept = [&](const std::vector<std::size_t>& line, const std::vector<char>& after) {
      return std::all_of(line.begin(), line.end(), [&](std::size_t e) { return after[e] != 0; });
    };
    std::vector<char> coarse = sharp, finer = sharp;
    GR::drop_short_sharp_lines(grid, 5.5 * scale, coarse); // the loop is 3.41 long, the line 9
    EXPECT_TRUE(kept(long_line, coarse)) << name;
    EXPECT_EQ(std::count(coarse.begin(), coarse.end(), 1), std::ptrdiff_t(long_line.size())) << name;
    GR::drop_short_sharp_lines(grid, 1.5 * scale, finer);
    EXPECT_TRUE(kept(long_line, finer) && kept(short_line, finer) && kept(loop, finer)) << name;
    EXPECT_FALSE(kept(spur, finer)) << name;

    const Work box = to_work_mesh(jittered_box(scale, 2 * scale, 3 * scale, 3, 7));
    std::vector<char> box_sharp = GR::detect_sharp_edges(box, 20, 35);
    const std::vector<char> box_before = box_sharp;
    GR::drop_short_sharp_lines(box, 100 * scale, box_sharp);
    EXPECT_EQ(std::count(box_before.begin(), box_before.end(), 1), 36) << name; // 12 edges in 3 each
    EXPECT_TRUE(box_sharp == box_before) << name;
  }
}

// Coarsening merges the border's corners that are close at the target's scale: a square notch
// one cell deep in the border of a flat grid turns by 90 degrees at four vertices, three cells
// along the border from first to last; a quarter of a coarse target longer than that leaves one of
// them a corner (the user's vertex among them, if any, whatever its turn) and the grid's own
// corners; one shorter than a cell all. Several scales.
TEST(Features, CloseBorderCornersMergeAtCoarseTargets)
{
  for(double scale : {1e-3, 1.0, 1e3})
  {
    const std::string name = "scale " + std::to_string(scale);
    std::vector<Point> points;
    std::vector<std::array<std::size_t, 3> > triangles;
    for(std::size_t j = 0; j < 12; ++j)
      for(std::size_t i = 0; i < 12; ++i)
        points.push_back(Point(scale * double(i), scale * double(j), 0));
    auto id = [](std::size_t i, std::size_t j) { return 12 * j + i; };
    for(std::size_t j = 0; j + 1 < 12; ++j)
      for(std::size_t i = 0; i + 1 < 12; ++i)
        if(i != 5 || j != 0) // the notch
        {
          triangles.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
          triangles.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
        }
    const Work grid = to_work_mesh(mesh_from_soup(points, triangles));
    std::vector<char> border(grid.number_of_edges(), 0);
    for(auto e : grid.edges())
      border[std::size_t(e)] = grid.is_border(e) ? 1 : 0;
    auto corners = [&](const std::vector<char>& constrained, double shortest) {
      std::vector<GR::Vertex_kind> kind = GR::classify_vertices(grid, border, constrained, 35);
      EXPECT_EQ(std::count(kind.begin(), kind.end(), GR::Vertex_kind::fixed_vertex), 8) << name;
      GR::merge_close_border_corners(grid, border, constrained, shortest, kind);
      std::set<std::size_t> fixed;
      for(auto v : grid.vertices())
        if(kind[std::size_t(v)] == GR::Vertex_kind::fixed_vertex)
          fixed.insert(std::size_t(v));
      return fixed;
    };
    const std::vector<char> none(grid.number_of_vertices(), 0);
    const std::set<std::size_t> grid_corners{id(0, 0), id(11, 0), id(0, 11), id(11, 11)};
    std::set<std::size_t> coarse = corners(none, 3.5 * scale);
    EXPECT_EQ(coarse.size(), 5u) << name;
    EXPECT_TRUE(std::includes(coarse.begin(), coarse.end(), grid_corners.begin(), grid_corners.end())) << name;
    EXPECT_EQ(corners(none, 0.5 * scale).size(), 8u) << name;
    std::vector<char> user = none;
    user[id(5, 1)] = 1;
    std::set<std::size_t> with_user = corners(user, 3.5 * scale);
    EXPECT_EQ(with_user.size(), 5u) << name;
    EXPECT_EQ(with_user.count(id(5, 1)), 1u) << name;
  }
}

// The field spends the budget of the mean length: flat parts get longer edges, curved parts
// shorter ones, and a surface curved alike everywhere (or flat) the mean length itself.
TEST(Sizing, CurvatureSizingKeepsTheBudgetOfTheMeanLength)
{
  const Work bent = to_work_mesh(make_grid(16, 10, [](std::size_t i, std::size_t j) {
    const double x = double(i) / 15;
    return Point(x, double(j) / 15, x > 0.5 ? 1.2 * (x - 0.5) * (x - 0.5) : 0.0);
  }));
  const Work sphere = to_work_mesh(noisy_sphere(3, 0.0, 0.0, 1));
  for(const Work* m : {&bent, &sphere})
  {
    const double mean = GR::mean_edge_length(*m);
    const GR::Sizing_field sizing = GR::curvature_sizing(*m, Pass_setup::features_of(*m, true), mean, 35,
                                                         GR::longest_to_mean_length, GR::gradation_at_mean_length, true);
    ASSERT_TRUE(sizing.resamples());
    const std::vector<double> area = GR::vertex_areas(*m);
    double budget = 0, spent = 0;
    for(auto v : m->vertices())
    {
      budget += area[std::size_t(v)] / (mean * mean);
      spent += area[std::size_t(v)] / (sizing.target[std::size_t(v)] * sizing.target[std::size_t(v)]);
      EXPECT_GE(sizing.target[std::size_t(v)], 0.45 * mean);
      EXPECT_LE(sizing.target[std::size_t(v)], 2.2 * mean);
    }
    EXPECT_NEAR(spent, budget, 1e-6 * budget);
    if(m == &sphere)
    {
      for(auto v : m->vertices())
        EXPECT_NEAR(sizing.target[std::size_t(v)], mean, 0.1 * mean);
    }
  }
  // The steeper grading of a length asked for: the gentle one of the mean length spreads the short
  // edges over most of this small sheet.
  const GR::Sizing_field sizing = GR::curvature_sizing(bent, Pass_setup::features_of(bent, true), GR::mean_edge_length(bent),
                                                       35, GR::longest_to_mean_length, GR::sizing_gradation, false);
  double flat = 0, curved = 0;
  for(auto v : bent.vertices())
  {
    const double x = bent.point(v).x();
    if(x < 0.2)
      flat = (std::max)(flat, sizing.target[std::size_t(v)]);
    if(x > 0.8)
      curved = (std::max)(curved, sizing.target[std::size_t(v)]);
  }
  EXPECT_LT(curved, 0.9 * flat);
}

// The width of the strip between feature lines at a vertex: the distances along the edges to the
// two lines that bound it, summed. On a sheet with lines along rows 0, 3 and 9 of its vertices, 3
// between the first two lines and 6 between the last two (row 0 is not seen across row 3); beyond
// the last line, no strip. On a thin plate, its side walls are strips as high as the plate; its
// top and bottom faces are no strips narrower than the plate's side, near their corners neither.
TEST(Sizing, StripWidthsAreMeasuredBetweenTheLinesThatBoundAStrip)
{
  for(double scale : {1e-3, 1.0, 1e3})
  {
    const Work sheet = to_work_mesh(make_grid(8, 12, [scale](std::size_t i, std::size_t j) {
      return Point(scale * double(i), scale * double(j), 0);
    }));
    auto row = [&](Work::Vertex_index v) { return std::lround(sheet.point(v).y() / scale); };
    std::vector<char> feature(sheet.num_edges(), 0);
    for(auto e : sheet.edges())
    {
      const long r = row(sheet.vertex(e, 0));
      feature[std::size_t(e)] = r == row(sheet.vertex(e, 1)) && (r == 0 || r == 3 || r == 9);
    }
    const std::vector<double> width = GR::feature_strip_widths(sheet, feature);
    for(auto v : sheet.vertices())
    {
      const long r = row(v);
      if(r > 9)
        EXPECT_FALSE(std::isfinite(width[std::size_t(v)])) << "row " << r;
      else
        EXPECT_NEAR(width[std::size_t(v)], scale * (r <= 3 ? 3 : 6), 1e-9 * scale) << "row " << r;
    }

    const double side = scale, height = 0.25 * scale;
    const Work plate = to_work_mesh(jittered_box(side, side, height, 6, 3));
    const std::vector<double> plate_width = GR::feature_strip_widths(plate, Pass_setup::features_of(plate, true));
    std::size_t walls = 0;
    for(auto v : plate.vertices())
    {
      const auto& p = plate.point(v);
      auto at = [scale](double x, double y) { return std::abs(x - y) < 1e-9 * scale; };
      const bool rim_x = at(p.x(), 0) || at(p.x(), side), rim_y = at(p.y(), 0) || at(p.y(), side);
      const bool rim_z = at(p.z(), 0) || at(p.z(), height);
      const double w = plate_width[std::size_t(v)];
      if(!rim_z && (rim_x != rim_y))
      {
        ++walls;
        EXPECT_GE(w, height * (1 - 1e-9));
        EXPECT_LE(w, 3 * height);
      }
      else if(rim_z && !rim_x && !rim_y)
      {
        EXPECT_GE(w, side * (1 - 1e-9));
      }
    }
    EXPECT_EQ(walls, std::size_t(4 * 5 * 5));
  }
}

// Re-sampling passes bring the edges near their targets, coarser or finer than the input (four
// times fewer or more vertices for twice or half the length), and keep every guarantee.
TEST(Connectivity_pass, ResamplingBringsTheEdgesToTheirTargets)
{
  for(const Named_mesh& input : scrambled_meshes())
    for(double factor : {0.5, 2.0})
    {
      Pass_setup s(input.mesh);
      const double mean = GR::mean_edge_length(s.reference_mesh);
      s.sizing = GR::curvature_sizing(s.reference_mesh, s.reference_feature_edge, factor * mean, 35,
                                      GR::longest_to_mean_length, GR::gradation_at_mean_length, false);
      const std::string name = input.name + " x" + std::to_string(factor);
      for(int pass = 0; pass < 4; ++pass)
      {
        const Work before = s.mesh;
        s.optimizer_with_features().connectivity_pass();
        expect_resampling_guarantees(s, before, 0.6 * factor * mean, name + " pass " + std::to_string(pass));
      }
      std::size_t in_band = 0;
      for(auto e : s.mesh.edges())
      {
        const auto a = s.mesh.source(s.mesh.halfedge(e)), b = s.mesh.target(s.mesh.halfedge(e));
        const double target =
          s.sizing.edge_target(s.state.closest[std::size_t(a)], s.state.closest[std::size_t(b)], s.reference);
        const double l = (s.point(a) - s.point(b)).norm();
        in_band += l > 0.5 * target && l < 1.5 * target ? 1 : 0;
      }
      // Coarsening stops where feature lines are dense (the scrambled torus) or at a border's
      // corners (the grid): passes without relocation keep more of those edges out of the band.
      EXPECT_GT(double(in_band), (factor < 1 ? 0.9 : 0.5) * double(s.mesh.number_of_edges())) << name;
      const double ratio = double(s.mesh.number_of_vertices()) / double(s.reference_mesh.number_of_vertices());
      EXPECT_GT(ratio, factor < 1 ? 2.0 : 0.15) << name;
      EXPECT_LT(ratio, factor < 1 ? 6.0 : 0.9) << name;
    }
}

// With a target length asked for, a collapse keeps what it removes near the new triangles: on a
// flat grid with single raised vertices (bumps 0.2 times the grid's spacing high, 11 degrees of
// slope: no sharp edge), asked for four times the spacing with a tolerance of 0.6 times a bump's
// height, every collapse the re-sampling would make leaves the removed vertex (and the kept one
// where it was, when it moves) within the tolerance of a new triangle (widened as the square of
// its longest edge over the target). The new triangles' centroids alone stay within it while a
// bump between them is cut off. Several scales.
TEST(Connectivity_pass, CoarseCollapsesKeepWhatTheyRemoveNearTheNewTriangles)
{
  for(double scale : {1e-3, 1.0, 1e3})
  {
    const double spacing = scale / 11, height = 0.2 * spacing;
    const std::set<std::pair<std::size_t, std::size_t> > bumps{{3, 3}, {3, 8}, {8, 3}, {8, 8}, {5, 6}};
    const Work grid = to_work_mesh(make_grid(12, 12, [&](std::size_t i, std::size_t j) {
      return Point(spacing * double(i), spacing * double(j), bumps.count({i, j}) ? height : 0.0);
    }));
    Pass_setup s(grid);
    ASSERT_EQ(s.input_feature_edges.size(), 44u) << "scale " << scale; // the border's only
    s.sizing.longest = 4 * spacing;
    s.sizing.tolerance = 0.6 * height;
    s.sizing.corner_angle = 35;
    s.sizing.target.assign(grid.num_vertices(), 4 * spacing);
    s.sizing.target_asked_for = s.sizing.into_lines = true;
    const GR::Edge_collapses collapses(s.operations_with_features());
    std::size_t made = 0;
    for(auto e : s.mesh.edges())
    {
      const GR::Edge_collapses::Plan plan = collapses.resampling_plan(e);
      if(!(plan.gain > 0))
        continue;
      const GR::Collapse& c = plan.collapse;
      ++made;
      const GR::Vector_3d was = s.point(c.kept);
      double gone_excess = std::numeric_limits<double>::infinity(), was_excess = was == c.point ? 0 : gone_excess;
      for(auto u : {c.removed, c.kept})
        for(auto g : halfedges_around_target(s.mesh.halfedge(u), s.mesh))
        {
          const auto p = s.mesh.source(g), q = s.mesh.target(s.mesh.next(g));
          if(s.mesh.is_border(g) || p == c.removed || p == c.kept || q == c.removed || q == c.kept)
            continue;
          const double longest =
            (std::max)({(c.point - s.point(p)).norm(), (c.point - s.point(q)).norm(), (s.point(p) - s.point(q)).norm()});
          const double ratio = longest / (4 * spacing);
          const double allowed = s.sizing.tolerance * (std::max)(1.0, ratio * ratio);
          std::array<double, 3> barycentric;
          auto excess = [&](const GR::Vector_3d& x) {
            return (x - GR::closest_point_on_triangle(x, c.point, s.point(q), s.point(p), barycentric)).norm() - allowed;
          };
          gone_excess = (std::min)(gone_excess, excess(s.point(c.removed)));
          was_excess = (std::min)(was_excess, excess(was));
        }
      EXPECT_LE((std::max)(gone_excess, was_excess), 1e-9 * scale)
        << "scale " << scale << ": collapse of " << c.removed << " into " << c.kept;
    }
    EXPECT_GT(made, grid.number_of_edges() / 4) << "scale " << scale;
  }
}

TEST(Connectivity_pass, KeepsTheGuaranteesOnSeveralMeshes)
{
  for(const Named_mesh& input : scrambled_meshes())
    for(double length_factor : {0.7, 1.0, 1.5})
    {
      Pass_setup s(input.mesh, length_factor);
      const int deviation = valence_deviation(s.mesh);
      const std::string name = input.name + " x" + std::to_string(length_factor);
      GR::Connectivity_counts total;
      for(int pass = 0; pass < 3; ++pass)
      {
        const Work before = s.mesh;
        const GR::Connectivity_counts c = s.optimizer().connectivity_pass();
        expect_pass_guarantees(s, before, name + " pass " + std::to_string(pass));
        total.flips += c.flips;
        total.splits += c.splits;
        total.collapses += c.collapses;
        total.vertex_splits += c.vertex_splits;
        total.relaxed += c.relaxed;
      }
      EXPECT_GT(total.flips, 0u) << name;
      EXPECT_GT(total.relaxed, 0u) << name;
      EXPECT_LT(valence_deviation(s.mesh), deviation) << name;
    }
}

// Flips lower the sum of |valence - 6|; some keep it and raise the smallest angle instead.
TEST(Connectivity_pass, FlipsLowerTheValenceDeviation)
{
  for(const Named_mesh& input : scrambled_meshes())
  {
    Pass_setup s(input.mesh);
    const int before = valence_deviation(s.mesh);
    const std::size_t flips = GR::Edge_flips(s.operations()).run();
    EXPECT_GT(flips, 10u) << input.name;
    EXPECT_LT(valence_deviation(s.mesh), before - int(flips) / 2) << input.name;
  }
}

// The rule of each flip, against an independent evaluation of every edge: a flip that would make
// the valence less regular is never offered; one that keeps it as regular is offered only when
// the smallest of the six angles grows.
TEST(Connectivity_pass, FlipRuleOnEveryEdge)
{
  std::size_t neutral_offered = 0;
  for(const Named_mesh& input : scrambled_meshes())
  {
    Pass_setup s(input.mesh);
    const GR::Edge_flips flips(s.operations());
    const Work& m = s.mesh;
    auto deviation = [&m](Work::Vertex_index v, int delta) {
      const int target = m.is_border(v) ? 4 : 6;
      return std::abs(int(m.degree(v)) + delta - target);
    };
    std::size_t worse = 0;
    for(auto e : m.edges())
    {
      if(m.is_border(e))
        continue;
      const auto h = m.halfedge(e), o = m.opposite(h);
      const auto a = m.source(h), b = m.target(h), c = m.target(m.next(h)), d = m.target(m.next(o));
      const int change = deviation(a, -1) + deviation(b, -1) + deviation(c, 1) + deviation(d, 1) -
                         deviation(a, 0) - deviation(b, 0) - deviation(c, 0) - deviation(d, 0);
      const double gain = flips.flip_gain(e);
      if(change > 0)
      {
        ++worse;
        EXPECT_LE(gain, 0) << input.name << ": a flip against the valence is offered";
      }
      else if(change == 0 && gain > 0)
      {
        ++neutral_offered;
        const double before = (std::min)(GR::smallest_angle(s.point(a), s.point(b), s.point(c)),
                                         GR::smallest_angle(s.point(b), s.point(a), s.point(d)));
        const double after = (std::min)(GR::smallest_angle(s.point(a), s.point(d), s.point(c)),
                                        GR::smallest_angle(s.point(d), s.point(b), s.point(c)));
        EXPECT_GT(after, before) << input.name;
        EXPECT_NEAR(gain, after - before - GR::Edge_flips::min_angle_margin, 1e-12) << input.name;
      }
    }
    EXPECT_GT(worse, 0u) << input.name;
  }
  // The scrambled torus's triangles are too regular for a neutral flip to help; the others' are not.
  EXPECT_GT(neutral_offered, 0u);
}

// The repair of the worst triangles: the smallest angle of the mesh never falls, and most
// triangles below 30 degrees go, on meshes scrambled by flips.
TEST(Connectivity_pass, SmallestAngleRepairRaisesTheWorstAngle)
{
  const auto angles = [](const Pass_setup& s, std::size_t& poor) {
    double worst = GR::pi;
    poor = 0;
    for(auto f : s.mesh.faces())
    {
      const auto t = GR::face_vertices(s.mesh, f);
      const double a = GR::smallest_angle(s.point(t[0]), s.point(t[1]), s.point(t[2]));
      worst = (std::min)(worst, a);
      poor += a < GR::Smallest_angle_repair::poor_angle ? 1 : 0;
    }
    return worst;
  };
  std::size_t poor_total_before = 0, poor_total_after = 0;
  for(const Named_mesh& input : scrambled_meshes())
  {
    Pass_setup s(input.mesh, 1.0, false);
    s.sizing.tolerance = 0.02; // the coarse torus's chords leave it by 0.01
    const Work before = s.mesh;
    std::size_t poor_before = 0, poor_after = 0;
    const double worst_before = angles(s, poor_before);
    const GR::Smallest_angle_repair::Counts counts = GR::Smallest_angle_repair(s.operations(), true, true, true).run();
    const double worst_after = angles(s, poor_after);
    EXPECT_GT(counts.flips, 0u) << input.name;
    EXPECT_GE(worst_after, worst_before) << input.name;
    EXPECT_LT(poor_after, poor_before) << input.name;
    poor_total_before += poor_before;
    poor_total_after += poor_after;
    expect_pass_guarantees(s, before, input.name + " repair");
  }
  // 1220 before; the torus, whose scrambled strips are too coarse to flip back, keeps most of its
  // own.
  EXPECT_LE(poor_total_after, poor_total_before / 2);
}

// A vertex of a box's edge slid up to a corner (as the relocation can slide one) is slid back along
// its line by the repair: its smallest angle grows and it stays on the line, at every scale.
TEST(Connectivity_pass, SmallestAngleRepairSlidesAVertexAwayFromACorner)
{
  for(double scale : {1e-3, 1.0, 1e3})
  {
    const std::string name = "box at scale " + std::to_string(scale);
    // Targets twice the mean edge length: the box's edges are then within their bounds.
    Pass_setup s(to_work_mesh(jittered_box(scale, scale, scale, 4, 7)), 2.0);
    Work::Vertex_index v, corner;
    for(auto h : s.mesh.halfedges())
      if(s.state.feature_edge[std::size_t(s.mesh.edge(h))] &&
         s.state.kind[std::size_t(s.mesh.source(h))] == GR::Vertex_kind::fixed_vertex &&
         s.state.kind[std::size_t(s.mesh.target(h))] == GR::Vertex_kind::feature_vertex)
      {
        corner = s.mesh.source(h);
        v = s.mesh.target(h);
        break;
      }
    ASSERT_NE(v, Work::null_vertex()) << name;
    const GR::Vector_3d towards = 0.95 * (s.point(corner) - s.point(v));
    s.state.location[std::size_t(v)] = s.polylines.move(s.state.location[std::size_t(v)], towards);
    const GR::Vector_3d slid = s.polylines.point(s.state.location[std::size_t(v)]);
    s.mesh.point(v) = Work::Point(slid.x(), slid.y(), slid.z());
    GR::Local_operations operations = s.operations_with_features();
    const double before_angle = operations.smallest_angle_around(v, v);
    const GR::Smallest_angle_repair::Counts counts = GR::Smallest_angle_repair(operations, false, false, true).run();
    EXPECT_GE(counts.moves, 1u) << name;
    EXPECT_GT(operations.smallest_angle_around(v, v), 3 * before_angle) << name;
    EXPECT_LT((s.polylines.point(s.state.location[std::size_t(v)]) - s.point(v)).norm(), 1e-12 * scale) << name;
    // No triangle turns (the pass guarantees hold but for the feature vertex that slides).
    for(auto h : halfedges_around_target(s.mesh.halfedge(v), s.mesh))
    {
      const GR::Vector_3d a = s.point(s.mesh.source(h)), b = s.point(v), c = s.point(s.mesh.target(s.mesh.next(h)));
      EXPECT_GT(GR::area_vector(a, b, c).dot(s.reference_normal((a + b + c) / 3)), 0) << name;
    }
  }
}

// Two thin triangles that only the repair's own rules mend, at every scale: a free vertex crowded
// against a vertex of a box's edge goes into it (the re-sampling at the input's density keeps
// free ends off the lines), and a flat quad's long diagonal is flipped though its ends, on the
// border, are then left with one triangle each.
TEST(Connectivity_pass, SmallestAngleRepairCollapsesIntoLinesAndFlipsAtBorders)
{
  const auto worst_angle = [](const Pass_setup& s) {
    double worst = GR::pi;
    for(auto f : s.mesh.faces())
    {
      const auto t = GR::face_vertices(s.mesh, f);
      worst = (std::min)(worst, GR::smallest_angle(s.point(t[0]), s.point(t[1]), s.point(t[2])));
    }
    return worst;
  };
  for(double scale : {1e-3, 1.0, 1e3})
  {
    const std::string name = "at scale " + std::to_string(scale);
    // Targets three times the mean edge length: v's far neighbours may then join w.
    Pass_setup box(to_work_mesh(jittered_box(scale, scale, scale, 4, 7)), 3.0);
    Work::Vertex_index v, w;
    for(auto h : box.mesh.halfedges())
      if(box.state.kind[std::size_t(box.mesh.source(h))] == GR::Vertex_kind::free_vertex &&
         box.state.kind[std::size_t(box.mesh.target(h))] == GR::Vertex_kind::feature_vertex)
      {
        v = box.mesh.source(h);
        w = box.mesh.target(h);
        break;
      }
    ASSERT_NE(v, Work::null_vertex()) << name;
    // Along the edge to w, in the plane of v's face: still on the reference.
    const GR::Vector_3d crowded = box.point(w) + 0.05 * (box.point(v) - box.point(w));
    box.mesh.point(v) = Work::Point(crowded.x(), crowded.y(), crowded.z());
    const Work before = box.mesh;
    const double worst_before = worst_angle(box);
    GR::Local_operations operations = box.operations_with_features();
    EXPECT_GE(GR::Smallest_angle_repair(operations, false, true, false).run().collapses, 1u) << name;
    EXPECT_TRUE(box.mesh.is_removed(v) || box.mesh.is_removed(w)) << name;
    EXPECT_GT(worst_angle(box), 3 * worst_before) << name;
    expect_pass_guarantees(box, before, "box " + name);

    // The quad (a, d, b, c), its diagonal ab ten times its height: 11.3 degrees at a and b.
    Work m;
    const auto a = m.add_vertex(Work::Point(0, 0, 0)), b = m.add_vertex(Work::Point(2 * scale, 0, 0));
    const auto c = m.add_vertex(Work::Point(scale, 0.2 * scale, 0)), d = m.add_vertex(Work::Point(scale, -0.2 * scale, 0));
    m.add_face(a, b, c);
    m.add_face(b, a, d);
    Pass_setup quad(m);
    const double quad_before = worst_angle(quad);
    EXPECT_EQ(GR::Smallest_angle_repair(quad.operations(), true, false, false).run().flips, 1u) << name;
    EXPECT_NE(quad.mesh.halfedge(c, d), Work::null_halfedge()) << name;
    EXPECT_GT(worst_angle(quad), 1.9 * quad_before) << name;
  }
}

// Collapses happen only on short edges whose both ends are off features and in flat regions.
TEST(Connectivity_pass, CollapsesStayAwayFromFeaturesAndCurvedParts)
{
  // The box: its faces are flat, its edges sharp; scrambled, so that collapses can make the
  // valences more regular. Every edge is short for a target twice the mean.
  Work box = to_work_mesh(jittered_box(1, 1, 1, 8, 3));
  scramble(box, GR::detect_sharp_edges(box, 20, 35), 4, box.number_of_edges());
  Pass_setup s(box, 2.0);
  // The vertices of the sharp edges and the degrees they had.
  std::vector<std::size_t> on_feature(s.mesh.num_vertices(), 0);
  for(auto e : s.mesh.edges())
    if(s.state.feature_edge[std::size_t(e)])
      for(auto v : {s.mesh.source(s.mesh.halfedge(e)), s.mesh.target(s.mesh.halfedge(e))})
        on_feature[std::size_t(v)] = s.mesh.degree(v);
  const std::size_t n = s.mesh.number_of_vertices();
  const Work before = s.mesh;
  const std::size_t collapses = GR::Edge_collapses(s.operations()).run();
  EXPECT_GT(collapses, 0u);
  expect_pass_guarantees(s, before, "box collapses");
  EXPECT_EQ(s.mesh.number_of_vertices(), n - collapses);
  // A collapse of an edge with an end on a sharp edge would raise that end's degree (it takes
  // the other end's neighbours); collapses elsewhere can only lower it.
  for(std::size_t i = 0; i < on_feature.size(); ++i)
  {
    if(on_feature[i])
    {
      const Work::Vertex_index v(static_cast<Work::size_type>(i));
      ASSERT_FALSE(s.mesh.is_removed(v));
      EXPECT_LE(s.mesh.degree(v), on_feature[i]) << "an edge next to a sharp edge was collapsed";
    }
  }

  // A sphere is curved everywhere: no dihedral angle below 10 degrees at this resolution.
  Pass_setup sphere(to_work_mesh(make_sphere(2)), 2.0);
  EXPECT_EQ(GR::Edge_collapses(sphere.operations()).run(), 0u);
}

// A vertex of valence 10 in the middle of a disc: its ring of 10 vertices of valence 5, then a
// border ring of 10 vertices of valence 4. One vertex split makes two vertices of valence 7 and
// brings two ring vertices to 6.
// A flat disc: a centre of valence n, a ring of n vertices, and an outer ring of n between them;
// the ring's angular steps vary by up to `unevenness` of the regular one.
Work fan_disc(std::size_t n, double scale, double unevenness = 0)
{
  std::vector<Point> points{Point(0, 0, 0)};
  std::vector<std::array<std::size_t, 3> > triangles;
  for(std::size_t k = 0; k < n; ++k)
  {
    auto angle = [&](std::size_t i) { return 2 * pi / double(n) * (double(i) + unevenness * std::sin(3.0 * double(i % n))); };
    const double a = angle(k), b = (a + angle(k + 1)) / 2;
    points.emplace_back(scale * std::cos(a), scale * std::sin(a), 0);
    points.emplace_back(2 * scale * std::cos(b), 2 * scale * std::sin(b), 0);
  }
  auto inner = [n](std::size_t k) { return 1 + 2 * (k % n); };
  auto outer = [n](std::size_t k) { return 2 + 2 * (k % n); };
  for(std::size_t k = 0; k < n; ++k)
  {
    triangles.push_back({{0, inner(k), inner(k + 1)}});
    triangles.push_back({{inner(k), outer(k), inner(k + 1)}});
    triangles.push_back({{inner(k + 1), outer(k), outer(k + 1)}});
  }
  return to_work_mesh(mesh_from_soup(points, triangles));
}

TEST(Connectivity_pass, VertexSplitLowersTheValenceDeviation)
{
  for(double scale : {1e-3, 1.0, 1e3})
  {
    const std::size_t n = 10;
    Pass_setup s(fan_disc(n, scale));
    const Work before = s.mesh;
    const int deviation = valence_deviation(s.mesh);
    const std::string name = "disc at scale " + std::to_string(scale);
    EXPECT_EQ(GR::Vertex_splits(s.operations()).run(), 1u) << name;
    expect_pass_guarantees(s, before, name);
    EXPECT_EQ(s.mesh.number_of_vertices(), 2 * n + 2) << name;
    EXPECT_EQ(s.mesh.number_of_faces(), 3 * n + 2) << name;
    EXPECT_EQ(valence_deviation(s.mesh), deviation - 4) << name;
    std::size_t split_halves = 0;
    for(auto v : s.mesh.vertices())
      if(s.mesh.degree(v) == 7)
      {
        ++split_halves;
        EXPECT_EQ(s.state.kind[std::size_t(v)], GR::Vertex_kind::free_vertex) << name;
        EXPECT_NE(s.state.vertex_hint[std::size_t(v)], Work::null_face()) << name << ": not bound to the reference";
      }
    EXPECT_EQ(split_halves, 2u) << name;
  }
}

// Above valence 12 a vertex is split into near-halves: every split into sides of valence 6 or
// more lowers the deviation alike, and trying them all cost valence^4.
TEST(Connectivity_pass, HighValenceIsSplitIntoNearHalves)
{
  for(std::size_t n : {13, 20, 40, 96})
  {
    // Uneven: on a regular fan the worst new triangle is a little worse than the fan's own, and
    // the split is refused.
    Pass_setup s(fan_disc(n, 1.0, 0.4));
    const Work before = s.mesh;
    const std::string name = "fan of " + std::to_string(n);
    EXPECT_EQ(GR::Vertex_splits(s.operations()).run(), 1u) << name;
    expect_pass_guarantees(s, before, name);
    // The two new vertices, inside the inner ring, share its n edges and the two triangles
    // between them.
    std::vector<std::size_t> halves;
    for(auto v : s.mesh.vertices())
      if(GR::to_vector(s.mesh.point(v)).norm() < 0.9)
        halves.push_back(s.mesh.degree(v));
    ASSERT_EQ(halves.size(), 2u) << name;
    EXPECT_EQ(halves[0] + halves[1], n + 4) << name;
    EXPECT_LE((std::max)(halves[0], halves[1]), (n + 1) / 2 + 3) << name;
  }
}

// Long edges between obtuse triangles are split where the split quality improves: a row of flat
// diamonds whose long diagonals are shared by two triangles with a 130 degree angle.
TEST(Connectivity_pass, LongEdgesBetweenObtuseTrianglesAreSplit)
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  const std::size_t n = 4;
  for(std::size_t k = 0; k <= n; ++k)
    points.emplace_back(4.0 * double(k), 0, 0); // p_k = k
  for(std::size_t k = 0; k < n; ++k)
  {
    points.emplace_back(4.0 * double(k) + 2, 0.9, 0);  // t_k = n + 1 + 2k
    points.emplace_back(4.0 * double(k) + 2, -0.9, 0); // b_k = n + 2 + 2k
  }
  auto t = [n](std::size_t k) { return n + 1 + 2 * k; };
  auto b = [n](std::size_t k) { return n + 2 + 2 * k; };
  for(std::size_t k = 0; k < n; ++k)
  {
    triangles.push_back({{k, k + 1, t(k)}});
    triangles.push_back({{k + 1, k, b(k)}});
    if(k + 1 < n)
    {
      triangles.push_back({{t(k), k + 1, t(k + 1)}});
      triangles.push_back({{b(k), b(k + 1), k + 1}});
    }
  }
  Pass_setup s(to_work_mesh(mesh_from_soup(points, triangles)));
  s.sizing.longest = 1.0;
  auto mean_quality = [&s] {
    double q = 0;
    for(auto f : s.mesh.faces())
    {
      const auto t = GR::face_vertices(s.mesh, f);
      q += GR::split_quality(s.point(t[0]), s.point(t[1]), s.point(t[2]));
    }
    return q / double(s.mesh.number_of_faces());
  };
  const Work before = s.mesh;
  const double q0 = mean_quality();
  const std::size_t splits = GR::Edge_splits(s.operations()).run();
  EXPECT_GE(splits, n);
  expect_pass_guarantees(s, before, "diamonds");
  EXPECT_EQ(s.mesh.number_of_vertices(), before.number_of_vertices() + splits);
  EXPECT_GT(mean_quality(), q0);
  // No long diagonal (length 4, between two triangles) is left.
  for(auto e : s.mesh.edges())
    if(!s.mesh.is_border(e))
    {
      EXPECT_LT((s.point(s.mesh.source(s.mesh.halfedge(e))) - s.point(s.mesh.target(s.mesh.halfedge(e)))).norm(), 3)
        << "a long diagonal was not split";
    }
}

// Section 3.2: relaxation improves the triangles and never turns one over, even next to a vertex
// pushed almost onto its ring's border.
// The debug-build postcondition sees a fold: an interior vertex of a flat patch pushed past its
// neighbour turns triangles over against theirs (120 degrees or more), unless the edges are sharp
// or the input had as many folds.
TEST(Guarantees, AFoldOffTheSharpEdgesIsABrokenGuarantee)
{
  for(double push : {1.5, 2.5})
  {
    const Work flat = to_work_mesh(make_equilateral_patch(9, 1.0));
    Work m = flat;
    const Work::Vertex_index v(40), w(41);
    const GR::Vector_3d p = GR::to_vector(m.point(v)) + push * (GR::to_vector(m.point(w)) - GR::to_vector(m.point(v)));
    m.point(v) = GR::Work_kernel::Point_3(p.x(), p.y(), p.z());
    const std::string name = "pushed " + std::to_string(push);
    const std::vector<char> no_feature(m.num_edges(), 0), all_features(m.num_edges(), 1);
    EXPECT_EQ(GR::folded_edges(flat), 0u) << name;
    const std::size_t folds = GR::folded_edges(m);
    EXPECT_GE(folds, 2u) << name;
    EXPECT_EQ(GR::folded_edges(m, &all_features), 0u) << name;
    const GR::Topology_summary topology = GR::topology_summary(flat);
    EXPECT_EQ(GR::broken_guarantee(flat, topology, {}, {}, 0, no_feature), "") << name;
    EXPECT_EQ(GR::broken_guarantee(m, topology, {}, {}, 0, no_feature), "a triangle is folded over onto a neighbour") << name;
    EXPECT_EQ(GR::broken_guarantee(m, topology, {}, {}, folds, no_feature), "") << name;
    EXPECT_EQ(GR::broken_guarantee(m, topology, {}, {}, 0, all_features), "") << name;
  }
}

TEST(Connectivity_pass, RelaxationImprovesWithoutFolding)
{
  for(double push : {0.3, 0.45, 0.49})
  {
    Work m = to_work_mesh(make_equilateral_patch(9, 1.0));
    // Push an interior vertex towards a neighbour.
    const Work::Vertex_index v(40), w(41);
    const GR::Vector_3d p = GR::to_vector(m.point(v)) + 2 * push * (GR::to_vector(m.point(w)) - GR::to_vector(m.point(v)));
    m.point(v) = GR::Work_kernel::Point_3(p.x(), p.y(), p.z());
    Pass_setup s(m);
    const Work before = s.mesh;
    const double angle_before = PMP::mesh_quality_report(s.mesh).min_angle;
    EXPECT_GT(GR::Relaxation(s.operations(), {}).run(), 0u);
    expect_pass_guarantees(s, before, "pushed " + std::to_string(push));
    EXPECT_GT(PMP::mesh_quality_report(s.mesh).min_angle, angle_before);
  }
}

// Long sharp edges are split at a point of their reference polyline: on a long box whose faces
// are grids of cells cut around their centres, the triangles on the long edges are flat and
// obtuse, and splitting the edges makes them right-angled. The new vertices lie on the box's
// edges, slide along them, and the halves of a sharp edge are sharp.
TEST(Connectivity_pass, LongSharpEdgesAreSplitOnTheirPolyline)
{
  for(double scale : {1e-3, 1.0, 1e3})
  {
    const std::string name = "box at scale " + std::to_string(scale);
    Mesh box = jittered_box(4 * scale, scale, scale, 3, 41, true);
    Pass_setup s(to_work_mesh(box));
    const std::size_t sharp_before = s.feature_edges().size();
    {
      // Without the polylines, sharp edges are left whole.
      Pass_setup plain(to_work_mesh(box));
      GR::Edge_splits(plain.operations()).run();
      EXPECT_EQ(plain.feature_edges().size(), sharp_before) << name;
    }
    const Work before = s.mesh;
    const std::size_t splits = GR::Edge_splits(s.operations_with_features()).run();
    EXPECT_GT(splits, 0u) << name;
    expect_pass_guarantees(s, before, name);
    const std::size_t sharp_after = s.feature_edges().size();
    EXPECT_GT(sharp_after, sharp_before) << name;
    std::size_t new_on_feature = 0;
    for(auto v : s.mesh.vertices())
    {
      if(s.state.kind[std::size_t(v)] != GR::Vertex_kind::feature_vertex || std::size_t(v) < before.num_vertices())
        continue;
      ++new_on_feature;
      // On a box edge: two coordinates at their bounds.
      const GR::Vector_3d p = s.point(v);
      const double bounds[3] = {4 * scale, scale, scale};
      int at_bound = 0;
      for(int d = 0; d < 3; ++d)
        at_bound += (std::abs(p[d]) < 1e-12 * scale || std::abs(p[d] - bounds[d]) < 1e-12 * scale) ? 1 : 0;
      EXPECT_GE(at_bound, 2) << name << ": new vertex " << p.transpose() << " is off the box's edges";
      EXPECT_LT((s.polylines.point(s.state.location[std::size_t(v)]) - p).norm(), 1e-12 * scale) << name;
      std::size_t sharp_around = 0;
      for(auto h : halfedges_around_target(s.mesh.halfedge(v), s.mesh))
        sharp_around += s.state.feature_edge[std::size_t(s.mesh.edge(h))] ? 1 : 0;
      EXPECT_EQ(sharp_around, 2u) << name;
    }
    EXPECT_EQ(sharp_after - sharp_before, new_on_feature) << name;
  }
}

// A triangle just off the wall of a concave crease is tested against the wall, even when its
// vertex on the crease is tracked from the floor: the descent from the floor stops inside it, as
// high below the centroid as the centroid is (at the bottom of a hole drilled into a part, the
// wall's triangles then seemed turned over and were never split).
TEST(Connectivity_pass, ATriangleOffTheWallOfAConcaveCreaseFacesTheWall)
{
  for(double scale : {1e-3, 1.0, 1e3})
  {
    const std::string name = "crease at scale " + std::to_string(scale);
    // Columns 0 to 4: the wall x = 0, z from 1 down to 0; columns 4 to 8: the floor z = 0, x from
    // 0 to 1. The normals are +x and +z: the crease along y is concave.
    const Mesh crease = make_grid(9, 5, [scale](std::size_t i, std::size_t j) {
      const double t = double(i) / 4, y = double(j) / 4;
      return i <= 4 ? Point(0, scale * y, scale * (1 - t)) : Point(scale * (t - 1), scale * y, 0);
    });
    Pass_setup s(to_work_mesh(crease));
    Work::Vertex_index v;
    for(auto u : s.mesh.vertices())
      if((s.point(u) - GR::Vector_3d(0, 0.5 * scale, 0)).norm() < 1e-12 * scale)
        v = u;
    ASSERT_NE(v, Work::null_vertex()) << name;
    for(auto h : halfedges_around_target(s.mesh.halfedge(v), s.mesh))
    {
      const auto f = s.mesh.face(h);
      if(f != Work::null_face() && s.reference.normal(f).z() > 0.5)
        s.state.vertex_hint[std::size_t(v)] = f; // on the floor
    }
    ASSERT_GT(s.reference.normal(s.state.vertex_hint[std::size_t(v)]).z(), 0.5) << name;
    // On the plane x = 0.01 + 0.1 z, in front of the wall, facing (1, 0, -0.1): towards the wall's
    // side, away from the floor's.
    const auto on_plane = [scale](double y, double z) { return GR::Vector_3d(scale * (0.01 + 0.1 * z), scale * y, scale * z); };
    const GR::Vector_3d a = on_plane(0.4, 0.3), b = on_plane(0.6, 0.3), c = on_plane(0.4, 0.5);
    double centroid_distance = -1;
    EXPECT_TRUE(s.operations().faces_reference(a, b, c, v, centroid_distance)) << name;
    EXPECT_NEAR(centroid_distance, ((a + b + c) / 3).x(), 1e-9 * scale) << name;
  }
}

// Beyond the paper, the relaxation keeps only the moves that do not raise the local energy.
TEST(Connectivity_pass, RelaxationKeepsOnlyMovesThatDoNotRaiseTheLocalEnergy)
{
  Work m = to_work_mesh(make_equilateral_patch(9, 1.0));
  const Work::Vertex_index v(40), w(41);
  const GR::Vector_3d p = GR::to_vector(m.point(v)) + 0.8 * (GR::to_vector(m.point(w)) - GR::to_vector(m.point(v)));
  m.point(v) = GR::Work_kernel::Point_3(p.x(), p.y(), p.z());
  {
    // Every move raises the distance to the starting positions: nothing moves.
    Pass_setup s(m);
    const Work start = s.mesh;
    const std::size_t moved = GR::Relaxation(s.operations_with_features(), [&start](Work::Vertex_index u, const GR::Vector_3d& x, double) {
      return (x - GR::to_vector(start.point(u))).squaredNorm();
    }).run();
    EXPECT_EQ(moved, 0u);
    for(auto u : s.mesh.vertices())
      EXPECT_EQ(s.mesh.point(u), start.point(u));
  }
  {
    // An energy that only the pushed vertex's way back lowers: only it moves.
    Pass_setup s(m);
    const GR::Vector_3d home = GR::to_vector(to_work_mesh(make_equilateral_patch(9, 1.0)).point(v));
    const std::size_t moved = GR::Relaxation(s.operations_with_features(), [&](Work::Vertex_index u, const GR::Vector_3d& x, double) {
      return u == v ? (x - home).squaredNorm() : (x - s.point(u)).squaredNorm();
    }).run();
    EXPECT_EQ(moved, 1u);
    EXPECT_LT((s.point(v) - home).norm(), (p - home).norm());
  }
}

// With re-sampling, a move away from feature lines is kept while its triangles stay within the
// sizing tolerance of the reference, whatever the energy says; next to a feature line the energy
// rule still holds. The energy here rises with any move.
TEST(Connectivity_pass, ResamplingRelaxationKeepsTheTrianglesWithinTheTolerance)
{
  // A sheet folded by 45 degrees along the grid line i = 6: a sharp line across it.
  const Work folded = to_work_mesh(make_grid(12, 12, [](std::size_t i, std::size_t j) {
    return Point(double(i) / 11, double(j) / 11, i > 6 ? double(i - 6) / 11 : 0.0);
  }));
  const Work torus = to_work_mesh(make_torus(30, 12, 1.0, 0.35));
  for(const Work* input : {&torus, &folded})
  {
    Pass_setup s(*input);
    s.sizing = GR::curvature_sizing(s.reference_mesh, s.reference_feature_edge, GR::mean_edge_length(s.reference_mesh), 35,
                                    GR::longest_to_mean_length, GR::gradation_at_mean_length, true);
    const Work start = s.mesh;
    const std::size_t moved = GR::Relaxation(s.operations_with_features(), [&start](Work::Vertex_index u, const GR::Vector_3d& x, double) {
      return (x - GR::to_vector(start.point(u))).squaredNorm();
    }).run();
    ASSERT_EQ(s.input_feature_edges.size(), input == &folded ? 44u + 11u : 0u); // the border's and the fold's
    EXPECT_GT(moved, s.mesh.number_of_vertices() / 5);
    for(auto f : s.mesh.faces())
    {
      GR::Vector_3d centroid(0, 0, 0);
      for(auto u : vertices_around_face(s.mesh.halfedge(f), s.mesh))
        centroid += s.point(u) / 3;
      EXPECT_LE(s.reference_distance(centroid), s.sizing.tolerance * (1 + 1e-9));
    }
    for(auto v : s.mesh.vertices())
      for(auto h : halfedges_around_target(s.mesh.halfedge(v), s.mesh))
        if(s.state.kind[std::size_t(s.mesh.source(h))] != GR::Vertex_kind::free_vertex)
        {
          EXPECT_EQ(s.mesh.point(v), start.point(v)) << "a vertex next to a feature line moved";
        }
  }
}

// The whole method with its connectivity passes, on meshes with and without features, closed
// and open: valid, same topology, no new self-intersection, corners kept, better triangles.
TEST(GraphcutRemeshing, ConnectivityKeepsTheGuarantees)
{
  struct Case
  {
    std::string name;
    Mesh mesh;
    bool regular; // every valence 6 and even triangles: no operation is needed
  };
  std::vector<Case> cases;
  cases.push_back({"noisy sphere", noisy_sphere(3, 0.03, 0.005, 21), false});
  cases.push_back({"jittered box", jittered_box(1, 2, 0.5, 6, 22), false});
  cases.push_back({"torus", make_torus(40, 12, 1.0, 0.3), true});
  cases.push_back({"fandisk", load_sample_mesh("fandisk"), false});
  for(bool resampling : {false, true})
  for(Case c : cases)
  {
    const Mesh input = c.mesh;
    const Work w = to_work_mesh(input);
    c.name += resampling ? " (re-sampled)" : "";
    c.regular = c.regular && !resampling; // re-sampling follows the curvature, not the input
    const auto stats = PMP::graphcut_isotropic_remeshing(
      c.mesh, GP::combine(CGAL::parameters::number_of_iterations(20), GP::number_of_greedy_iterations(3),
                          GP::resampling(resampling)));
    const Work out = to_work_mesh(c.mesh);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(c.mesh)) << c.name;
    EXPECT_EQ(euler_characteristic(out), euler_characteristic(w)) << c.name;
    EXPECT_EQ(components(out), components(w)) << c.name;
    EXPECT_EQ(stats.connectivity_passes.size(), 4u) << c.name;
    const std::size_t operations = stats.number_of_flips + stats.number_of_splits + stats.number_of_collapses;
    if(c.regular)
      EXPECT_LE(valence_deviation(out), valence_deviation(w)) << c.name;
    else
      EXPECT_GT(operations, 0u) << c.name;
    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index> > pairs;
    PMP::self_intersections(c.mesh, std::back_inserter(pairs));
    EXPECT_TRUE(pairs.empty()) << c.name << ": " << pairs.size() << " intersecting pairs";
    const auto q0 = PMP::mesh_quality_report(input), q1 = PMP::mesh_quality_report(c.mesh);
    EXPECT_GT(q1.mean_min_angle, q0.mean_min_angle) << c.name;
    EXPECT_GT(q1.min_angle, 1.0) << c.name << ": degenerate triangle";
    // The same order of vertices; the box's cells differ fourfold in size from face to face, so
    // that its sizing is far from the input's there.
    EXPECT_NEAR(double(q1.number_of_vertices), double(q0.number_of_vertices), 0.25 * double(q0.number_of_vertices))
      << c.name;
    // Corners (three or more sharp edges, turns of strong creases) stay where they were, as
    // vertices of the output; re-sampling keeps the turns beyond the upper bound only.
    const std::vector<char> sharp = GR::detect_sharp_edges(w, 20, 35);
    const std::vector<GR::Vertex_kind> kind =
      GR::classify_vertices(w, sharp, std::vector<char>(w.num_vertices(), 0), theta_true,
                            resampling ? theta_true : GR::strong_crease_turn_angle);
    std::set<std::array<double, 3> > output_points;
    for(auto v : vertices(c.mesh))
      output_points.insert({{c.mesh.point(v).x(), c.mesh.point(v).y(), c.mesh.point(v).z()}});
    for(auto v : w.vertices())
    {
      if(kind[std::size_t(v)] == GR::Vertex_kind::fixed_vertex)
      {
        EXPECT_EQ(output_points.count({{w.point(v).x(), w.point(v).y(), w.point(v).z()}}), 1u)
          << c.name << ": corner " << w.point(v) << " lost";
      }
    }
  }
}

// The user's constrained edges survive a rebuilt connectivity, and the maps say which they are.
TEST(GraphcutRemeshing, ConstrainedMapsAreUpdatedWhenTheConnectivityChanges)
{
  // A sphere whose valences were scrambled, so that the passes flip edges.
  Work scrambled = to_work_mesh(noisy_sphere(3, 0.03, 0.0, 31));
  scramble(scrambled, std::vector<char>(scrambled.num_edges(), 0), 33, scrambled.number_of_edges());
  Mesh m;
  CGAL::copy_face_graph(scrambled, m);
  auto ecm = m.add_property_map<Mesh::Edge_index, bool>("e:constrained", false).first;
  auto vcm = m.add_property_map<Mesh::Vertex_index, bool>("v:constrained", false).first;
  std::set<std::pair<std::array<double, 3>, std::array<double, 3> > > constrained;
  auto key = [&m](Mesh::Vertex_index v) { return std::array<double, 3>{{m.point(v).x(), m.point(v).y(), m.point(v).z()}}; };
  constrain_equator(m, ecm);
  std::set<std::array<double, 3> > pinned;
  CGAL::Random rng(32);
  for(auto v : vertices(m))
    if(rng.get_int(0, 20) == 0)
    {
      vcm[v] = true;
      pinned.insert(key(v));
    }
  std::size_t constrained_count = 0;
  for(auto e : edges(m))
    constrained_count += ecm[e] ? 1 : 0;
  const auto stats = PMP::graphcut_isotropic_remeshing(
    m, GP::combine(CGAL::parameters::number_of_iterations(15).edge_is_constrained_map(ecm).vertex_is_constrained_map(vcm),
                   GP::number_of_greedy_iterations(2)));
  ASSERT_GT(stats.number_of_flips, 0u);
  std::size_t after = 0;
  for(auto e : edges(m))
    after += ecm[e] ? 1 : 0;
  EXPECT_EQ(after, constrained_count);
  std::size_t pinned_after = 0;
  for(auto v : vertices(m))
    if(vcm[v])
    {
      ++pinned_after;
      EXPECT_EQ(pinned.count(key(v)), 1u) << "a constrained vertex moved";
    }
  EXPECT_EQ(pinned_after, pinned.size());
}

// The self-intersection check of the relocation (internal/Graphcut_remeshing/intersections.h)
// against CGAL's self_intersections, on whole meshes, after moves of a few vertices at a time and
// after connectivity changes.
namespace {

using Face_pair = GR::Triangle_intersections::Face_pair;

// CGAL's answer on an exact-predicates copy of w, in w's indices (w may have removed elements).
std::vector<Face_pair> cgal_self_intersections(const Work& w)
{
  Mesh m;
  for(std::size_t i = 0; i < w.num_vertices(); ++i)
  {
    const auto& p = w.point(Work::Vertex_index(static_cast<Work::size_type>(i)));
    m.add_vertex(Point(p.x(), p.y(), p.z())); // removed ones too, isolated: indices stay
  }
  std::vector<Work::Face_index> face_of; // by face of m
  for(auto f : w.faces())
  {
    const auto t = GR::face_vertices(w, f);
    m.add_face(Mesh::Vertex_index(std::size_t(t[0])), Mesh::Vertex_index(std::size_t(t[1])),
               Mesh::Vertex_index(std::size_t(t[2])));
    face_of.push_back(f);
  }
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index> > found;
  PMP::self_intersections(m, std::back_inserter(found));
  std::vector<Face_pair> pairs;
  for(const auto& p : found)
  {
    const Work::Face_index f = face_of[std::size_t(p.first)], g = face_of[std::size_t(p.second)];
    pairs.push_back(f < g ? Face_pair(f, g) : Face_pair(g, f));
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

// CGAL's pairs with a triangle incident to a vertex v with touched[v].
std::vector<Face_pair> cgal_self_intersections_touching(const Work& w, const std::vector<char>& touched)
{
  std::vector<Face_pair> pairs;
  for(const Face_pair& p : cgal_self_intersections(w))
  {
    bool incident = false;
    for(auto f : {p.first, p.second})
      for(auto v : GR::face_vertices(w, f))
        incident = incident || touched[std::size_t(v)];
    if(incident)
      pairs.push_back(p);
  }
  return pairs;
}

// Two spheres that overlap, in one mesh: pairs that share no vertex.
Mesh overlapping_spheres()
{
  Mesh m = make_sphere(3, 1.0);
  Mesh other = make_sphere(3, 0.8, Point(1.1, 0.2, 0.1));
  CGAL::copy_face_graph(other, m);
  return m;
}

// A flat fan of n triangles around the origin, the k-th rim vertex at angle k * 60 degrees: with
// `closed`, n = 12 goes twice around; open, n = 7 goes past a full turn. Each triangle alone is
// positively oriented; the turns overlap.
Mesh winding_fan(std::size_t n, bool closed)
{
  std::vector<Point> points{Point(0, 0, 0)};
  const std::size_t rim = closed ? n : n + 1;
  for(std::size_t k = 0; k < rim; ++k)
  {
    const double a = double(k) * pi / 3, r = 1 + 0.1 * double(k);
    points.emplace_back(r * std::cos(a), r * std::sin(a), 0);
  }
  std::vector<std::array<std::size_t, 3> > triangles;
  for(std::size_t k = 0; k < n; ++k)
    triangles.push_back({{0, 1 + k, 1 + (k + 1) % rim}});
  return mesh_from_soup(points, triangles);
}

// A flat grid: every fan is exactly coplanar, so folds overlap in the plane.
Mesh flat_grid() { return make_grid(12, 9, [](std::size_t i, std::size_t j) { return Point(0.1 * i, 0.1 * j, 0); }); }

double mean_edge_length(const Work& w)
{
  double total = 0;
  for(auto e : w.edges())
    total += std::sqrt(CGAL::squared_distance(w.point(w.source(w.halfedge(e))), w.point(w.target(w.halfedge(e)))));
  return total / double(w.number_of_edges());
}

} // namespace

TEST(Triangle_intersections, AllPairsAsCgalFindsThem)
{
  const std::vector<std::pair<std::string, Mesh> > meshes = {
    {"sphere", make_sphere(3)},
    {"jittered sphere", noisy_sphere(3, 0.25, 0.08, 7)},
    {"overlapping spheres", overlapping_spheres()},
    {"flat grid", flat_grid()},
    {"torus", make_torus(24, 12, 1.0, 0.3)},
    {"fandisk", load_sample_mesh("fandisk")},
    {"fan going twice around", winding_fan(12, true)},
    {"open fan past a full turn", winding_fan(7, false)}};
  std::size_t intersecting_meshes = 0;
  for(const auto& named : meshes)
  {
    SCOPED_TRACE(named.first);
    Work w = to_work_mesh(named.second);
    const std::vector<Face_pair> expected = cgal_self_intersections(w);
    EXPECT_EQ(GR::Triangle_intersections(w).all_pairs(), expected);
    intersecting_meshes += expected.empty() ? 0 : 1;
  }
  // The jittered sphere, the overlapping spheres and the two fans.
  EXPECT_EQ(intersecting_meshes, 4u);
}

TEST(Triangle_intersections, AfterMovesOfAFewVerticesAsCgalFindsThem)
{
  // Moves small and large (beyond the margin of the candidate list), in space and, on the flat
  // grid, in the plane only; half of them undone, as the relocation does when its cut made
  // intersections.
  const std::vector<std::pair<std::string, Mesh> > meshes = {
    {"sphere", make_sphere(3)}, {"flat grid", flat_grid()}, {"overlapping spheres", overlapping_spheres()}};
  std::size_t found_some = 0;
  for(const auto& named : meshes)
  {
    SCOPED_TRACE(named.first);
    Work w = to_work_mesh(named.second);
    const bool planar = named.first == "flat grid";
    const double h = mean_edge_length(w);
    GR::Triangle_intersections intersections(w);
    intersections.all_pairs();
    CGAL::Random rng(11);
    for(int round = 0; round < 40; ++round)
    {
      SCOPED_TRACE(round);
      const double step = h * std::vector<double>{0.02, 0.2, 0.8}[std::size_t(round % 3)];
      std::vector<char> touched(w.num_vertices(), 0);
      std::vector<std::pair<Work::Vertex_index, GR::Work_kernel::Point_3> > before;
      for(auto v : w.vertices())
        if(rng.get_double() < 0.05)
        {
          touched[std::size_t(v)] = 1;
          before.emplace_back(v, w.point(v));
          const auto& p = w.point(v);
          w.point(v) = GR::Work_kernel::Point_3(p.x() + step * rng.get_double(-1, 1), p.y() + step * rng.get_double(-1, 1),
                                                planar ? p.z() : p.z() + step * rng.get_double(-1, 1));
        }
      const std::vector<Face_pair> expected = cgal_self_intersections_touching(w, touched);
      EXPECT_EQ(intersections.pairs_touching(touched), expected);
      found_some += expected.empty() ? 0 : 1;
      if(round % 2 == 1)
        for(const auto& b : before)
          w.point(b.first) = b.second;
    }
  }
  EXPECT_GT(found_some, 20u);
}

TEST(Triangle_intersections, AfterConnectivityChangesAsCgalFindsThem)
{
  // Rounds of a few flips, splits and collapses and moves, small and beyond the margin of the
  // candidate list, which is updated for the changed triangles; one round in eight changes a
  // quarter of the edges, and the list is made again. A round that leaves a degenerate triangle,
  // which the remesher never makes and exact predicates are not asked about, is undone.
  const std::vector<std::pair<std::string, Mesh> > meshes = {
    {"sphere", make_sphere(3)}, {"flat grid", flat_grid()}, {"overlapping spheres", overlapping_spheres()}};
  std::size_t found_some = 0, checked = 0;
  for(const auto& named : meshes)
  {
    SCOPED_TRACE(named.first);
    Work w = to_work_mesh(named.second);
    const double h = mean_edge_length(w);
    GR::Triangle_intersections intersections(w);
    intersections.all_pairs();
    CGAL::Random rng(5);
    for(int round = 0; round < 48; ++round)
    {
      SCOPED_TRACE(round);
      const Work before = w;
      const std::size_t operations = round % 8 == 7 ? w.number_of_edges() / 4 : 3;
      for(std::size_t k = 0; k < operations; ++k)
      {
        const Work::Edge_index e(static_cast<Work::size_type>(rng.get_int(0, int(w.num_edges()))));
        if(w.is_removed(e) || w.is_border(e))
          continue;
        const auto hh = w.halfedge(e), o = w.opposite(hh);
        const int kind = rng.get_int(0, 3);
        if(kind == 0 && w.halfedge(w.target(w.next(hh)), w.target(w.next(o))) == Work::null_halfedge() &&
           w.degree(w.source(hh)) > 3 && w.degree(w.target(hh)) > 3)
          CGAL::Euler::flip_edge(hh, w);
        else if(kind == 1)
        {
          const auto p = w.point(w.source(hh)), q = w.point(w.target(hh));
          // n goes from source(hh) to the new vertex, hh now from there to its old target. The
          // new vertex is off the edge: a later flip may make a triangle of the edge's halves.
          const auto n = CGAL::Euler::split_edge(hh, w);
          const auto m = CGAL::midpoint(p, q);
          const double r = 0.05 * h;
          w.point(w.target(n)) = GR::Work_kernel::Point_3(m.x() + r * rng.get_double(-1, 1), m.y() + r * rng.get_double(-1, 1),
                                                          m.z() + r * rng.get_double(-1, 1));
          CGAL::Euler::split_face(n, w.next(w.next(n)), w);
          const auto o = w.opposite(hh); // into the new vertex, on the other side
          if(!w.is_border(o))
            CGAL::Euler::split_face(o, w.next(w.next(o)), w);
        }
        else if(kind == 2 && CGAL::Euler::does_satisfy_link_condition(e, w))
          CGAL::Euler::collapse_edge(e, w);
      }
      for(auto v : w.vertices())
        if(rng.get_double() < 0.03)
        {
          const double step = h * std::vector<double>{0.02, 0.2, 0.8}[std::size_t(rng.get_int(0, 3))];
          const auto& p = w.point(v);
          w.point(v) = GR::Work_kernel::Point_3(p.x() + step * rng.get_double(-1, 1), p.y() + step * rng.get_double(-1, 1),
                                                p.z() + step * rng.get_double(-1, 1));
        }
      // Touched: new or moved vertices, and the vertices of new or reconnected triangles.
      const std::vector<char> touched = GR::changed_vertices(before, w);
      ASSERT_TRUE(CGAL::is_valid_polygon_mesh(w));
      bool degenerate = false;
      for(auto f : w.faces())
      {
        const auto t = GR::face_vertices(w, f);
        auto p = [&w](Work::Vertex_index v) { return Point(w.point(v).x(), w.point(v).y(), w.point(v).z()); };
        degenerate = degenerate || CGAL::collinear(p(t[0]), p(t[1]), p(t[2]));
      }
      if(degenerate)
      {
        w = before; // as the list last saw it
        continue;
      }
      intersections.connectivity_changed();
      const std::vector<Face_pair> found = intersections.pairs_touching(touched);
      const std::vector<Face_pair> expected = cgal_self_intersections_touching(w, touched);
      EXPECT_EQ(found, expected);
      EXPECT_EQ(found, GR::Triangle_intersections(w).pairs_touching(touched)); // as a list made anew
      ++checked;
      found_some += found.empty() ? 0 : 1;
    }
  }
  EXPECT_GT(found_some, 20u);
  EXPECT_GT(checked, 120u);
}

// A vertex a fraction of an ulp above another triangle in the unit box is written onto it when the
// box is far from the origin: the exact tests decide on the points as written, as CGAL does on the
// output. Both ways for the two triangles to meet: sharing no vertex, and sharing one.
TEST(Triangle_intersections, DecidedOnThePointsAsWritten)
{
  // (lowest corner, side) of the box: far from the origin, at three scales.
  const std::vector<std::pair<double, double> > boxes = {{1000, 1}, {3e4, 0.37}, {1e6, 3.1}};
  for(const auto& box : boxes)
    for(bool share_vertex : {false, true})
    {
      SCOPED_TRACE(std::to_string(box.first) + (share_vertex ? ", sharing a vertex" : ", sharing none"));
      const std::vector<GR::Vector_3d> corners = {GR::Vector_3d::Constant(box.first),
                                                  GR::Vector_3d::Constant(box.first + box.second)};
      const GR::Unit_box_normalization normalization(corners);
      // The triangle's vertices are input points, the apex a new vertex just above its plane.
      const std::vector<GR::Vector_3d> input = {normalization.from_unit({-0.3, -0.3, 0.25}),
                                                normalization.from_unit({0.3, -0.3, 0.25}),
                                                normalization.from_unit({0, 0.3, 0.25})};
      Work w;
      std::vector<Work::Vertex_index> v;
      for(const GR::Vector_3d& q : input)
      {
        const GR::Vector_3d p = normalization.to_unit(q);
        v.push_back(w.add_vertex(Work::Point(p.x(), p.y(), p.z())));
      }
      const double z = w.point(v[0]).z();
      ASSERT_TRUE(z == w.point(v[1]).z() && z == w.point(v[2]).z()); // a horizontal triangle
      v.push_back(w.add_vertex(Work::Point(0, -0.1, std::nextafter(z, 1.0))));
      v.push_back(w.add_vertex(Work::Point(0.2, 0.1, 0.45)));
      w.add_face(v[0], v[1], v[2]);
      w.add_face(v[3], v[4], share_vertex ? v[1] : w.add_vertex(Work::Point(-0.2, 0.1, 0.45)));
      const GR::Output_points output(normalization, input);
      for(std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(output(i, GR::to_vector(w.point(v[i]))), input[i]); // the input's exact point
      Work written = w;
      for(Work::Vertex_index u : written.vertices())
      {
        const GR::Vector_3d p = output(std::size_t(u), GR::to_vector(w.point(u)));
        written.point(u) = Work::Point(p.x(), p.y(), p.z());
      }
      ASSERT_EQ(written.point(v[3]).z(), written.point(v[0]).z()); // the apex written onto the plane
      EXPECT_TRUE(GR::Triangle_intersections(w).all_pairs().empty());
      const std::vector<Face_pair> expected = cgal_self_intersections(written);
      EXPECT_EQ(expected.size(), 1u);
      EXPECT_EQ(GR::Triangle_intersections(w, output).all_pairs(), expected);
    }
}
