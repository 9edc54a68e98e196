// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// graphcut_isotropic_remeshing as a whole: monotone energy, features kept, constraints honoured,
// repeatability, and the quality / fidelity bar on the paper's models.

#include "test_meshes.h"
#include "remeshing_check.h" // examples/tools

#include <CGAL/Polygon_mesh_processing/graphcut_isotropic_remeshing.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_report.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/tangential_relaxation.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace GP = PMP::graphcut_parameters;
namespace GR = PMP::internal::Graphcut_remeshing;
using namespace graphcut_remeshing_test;

namespace {

double distance_to_segment(const Point& p, const Point& a, const Point& b)
{
  return GR::distance_to_segment(GR::to_vector(p), GR::to_vector(a), GR::to_vector(b));
}

// The energy never rises from one iteration to the next, except across a connectivity pass,
// which changes the triangles the energy sums over. The remesher sums it after each cut and keeps
// the cut's choice only when that sum did not rise, so not even a rounding makes it rise.
void expect_monotone(const PMP::Graphcut_remeshing_statistics& stats, const std::string& name)
{
  const std::vector<double>& energies = stats.energies;
  ASSERT_GE(energies.size(), 2u);
  for(std::size_t i = 1; i < energies.size(); ++i)
  {
    if(std::find(stats.connectivity_passes.begin(), stats.connectivity_passes.end(), i) !=
       stats.connectivity_passes.end())
      continue;
    EXPECT_LE(energies[i], energies[i - 1]) << name << ": energy rose at iteration " << i;
  }
}

} // namespace

TEST(GraphcutRemeshing, EnergyNeverRises)
{
  struct Case { std::string name; Mesh mesh; };
  std::vector<Case> cases;
  cases.push_back({"fandisk", load_sample_mesh("fandisk")});
  cases.push_back({"noisy sphere", noisy_sphere(3, 0.03, 0.01, 1)});
  cases.push_back({"jittered box", jittered_box(1, 2, 0.5, 6, 2)});
  for(bool resampling : {true, false})
    for(const Case& c : cases)
    {
      Mesh m = c.mesh;
      const std::string name = c.name + (resampling ? "" : " (paper's mode)");
      const PMP::Graphcut_remeshing_statistics stats = PMP::graphcut_isotropic_remeshing(
        m, GP::combine(CGAL::parameters::number_of_iterations(40), GP::number_of_greedy_iterations(10),
                       GP::resampling(resampling)));
      EXPECT_EQ(stats.energies.size(), 51u) << name;
      EXPECT_EQ(stats.number_of_iterations, 50u) << name;
      expect_monotone(stats, name);
      EXPECT_EQ(stats.connectivity_passes.size(), 8u) << name;
      // The optimisation must actually work: moves taken, energy clearly lower (re-sampling
      // changes the number of triangles, each with its shape term: there, over the greedy phase).
      EXPECT_GT(stats.number_of_moves, num_vertices(m)) << name;
      const double start = resampling ? stats.energies[40] : stats.energies.front();
      EXPECT_LT(stats.energies.back(), (resampling ? 0.999 : 0.99) * start) << name;
    }
}

TEST(GraphcutRemeshing, BoxCornersStayAndEdgeVerticesStayOnEdges)
{
  for(double scale : {1e-3, 1.0, 1e3})
  {
    const Mesh input = jittered_box(1 * scale, 2 * scale, 0.5 * scale, 6, 3);
    Mesh m = input;
    // Vertex by vertex: the connectivity stays (test_connectivity checks the same with it).
    PMP::graphcut_isotropic_remeshing(m, GP::combine(CGAL::parameters::number_of_iterations(30),
                                                     GP::number_of_greedy_iterations(5),
                                                     GP::do_connectivity_optimization(false)));
    const double a = 1 * scale, b = 2 * scale, c = 0.5 * scale, tolerance = 1e-12 * scale;
    std::size_t corners = 0, on_edges = 0, moved = 0;
    for(auto v : vertices(m))
    {
      const Point& p = input.point(v);
      const Point& q = m.point(v);
      // How many coordinates are on the box's boundary decides corner / edge / face.
      const double x[3] = {p.x(), p.y(), p.z()}, size[3] = {a, b, c};
      int bounded = 0;
      for(int d = 0; d < 3; ++d)
        bounded += (x[d] == 0 || std::abs(x[d] - size[d]) < 1e-12 * scale) ? 1 : 0;
      const double y[3] = {q.x(), q.y(), q.z()};
      int still = 0;
      for(int d = 0; d < 3; ++d)
        if(x[d] == 0 || std::abs(x[d] - size[d]) < 1e-12 * scale)
          still += std::abs(y[d] - x[d]) <= tolerance ? 1 : 0;
      if(bounded == 3)
      {
        ++corners;
        EXPECT_EQ(p, q) << "a corner moved";
      }
      else if(bounded == 2)
      {
        ++on_edges;
        EXPECT_EQ(still, 2) << "an edge vertex left its edge: " << p << " -> " << q;
      }
      else
        EXPECT_EQ(still, 1) << "a face vertex left its face: " << p << " -> " << q;
      if(!(p == q))
        ++moved;
    }
    EXPECT_EQ(corners, 8u);
    EXPECT_EQ(on_edges, 12u * 5u);
    EXPECT_GT(moved, num_vertices(m) / 2);
    EXPECT_GT(PMP::mesh_quality_report(m).mean_min_angle, PMP::mesh_quality_report(input).mean_min_angle + 2);
  }
}

TEST(GraphcutRemeshing, FandiskFeaturesStayWhereTheyWere)
{
  const Mesh input = load_sample_mesh("fandisk");
  Mesh m = input;
  PMP::graphcut_isotropic_remeshing(m, GP::combine(CGAL::parameters::number_of_iterations(40),
                                                   GP::number_of_greedy_iterations(10),
                                                   GP::do_connectivity_optimization(false), GP::resampling(false)));
  // The input's sharp edges by the same hysteresis as the remesher in the paper's mode.
  const GR::Work_mesh w = to_work_mesh(input);
  const std::vector<char> sharp = GR::detect_sharp_edges(w, 20, 35);
  const std::vector<GR::Vertex_kind> kind = GR::classify_vertices(w, sharp, std::vector<char>(num_vertices(w), 0), 35);
  std::vector<std::pair<Point, Point> > segments;
  auto point = [&w](GR::Work_mesh::Vertex_index v) { return Point(w.point(v).x(), w.point(v).y(), w.point(v).z()); };
  for(auto e : w.edges())
    if(sharp[std::size_t(e)])
      segments.emplace_back(point(w.source(w.halfedge(e))), point(w.target(w.halfedge(e))));
  ASSERT_GT(segments.size(), 100u);

  const CGAL::Bbox_3 box = PMP::bbox(input);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  std::size_t fixed = 0, sliding = 0, slid = 0;
  for(auto v : vertices(m))
  {
    const GR::Vertex_kind k = kind[std::size_t(v)];
    if(k == GR::Vertex_kind::fixed_vertex)
    {
      ++fixed;
      EXPECT_EQ(m.point(v), input.point(v)) << "corner " << v << " moved";
    }
    else if(k == GR::Vertex_kind::feature_vertex)
    {
      ++sliding;
      double d = std::numeric_limits<double>::infinity();
      for(const auto& s : segments)
        d = (std::min)(d, distance_to_segment(m.point(v), s.first, s.second));
      EXPECT_LT(d, 1e-12 * diagonal) << "feature vertex " << v << " left the feature lines";
      if(!(m.point(v) == input.point(v)))
        ++slid;
    }
  }
  EXPECT_GT(fixed, 0u);
  EXPECT_GT(sliding, 100u);
  EXPECT_GT(slid, sliding / 4) << "feature vertices should slide, not freeze";
}

TEST(GraphcutRemeshing, UserConstraintsAreHonoured)
{
  Mesh m = noisy_sphere(3, 0.03, 0.0, 4);
  const Mesh input = m;
  auto vcm = m.add_property_map<Mesh::Vertex_index, bool>("v:constrained", false).first;
  auto ecm = m.add_property_map<Mesh::Edge_index, bool>("e:constrained", false).first;
  CGAL::Random rng(5);
  for(auto v : vertices(m))
    vcm[v] = rng.get_int(0, 10) == 0;
  const std::size_t constrained_edges = constrain_equator(m, ecm);
  ASSERT_GT(constrained_edges, 10u);
  PMP::graphcut_isotropic_remeshing(m, GP::combine(CGAL::parameters::number_of_iterations(30)
                                                     .vertex_is_constrained_map(vcm)
                                                     .edge_is_constrained_map(ecm),
                                                   GP::number_of_greedy_iterations(5),
                                                   GP::do_connectivity_optimization(false)));
  for(auto v : vertices(m))
  {
    if(vcm[v])
    {
      EXPECT_EQ(m.point(v), input.point(v)) << "constrained vertex " << v << " moved";
    }
  }
  // Vertices of constrained edges stay on the polyline of constrained input edges.
  for(auto e : edges(m))
  {
    if(!ecm[e])
      continue;
    for(auto v : {source(e, m), target(e, m)})
    {
      double d = std::numeric_limits<double>::infinity();
      for(auto g : edges(input))
        if(ecm[g])
          d = (std::min)(d, distance_to_segment(m.point(v), input.point(source(g, input)),
                                                input.point(target(g, input))));
      EXPECT_LT(d, 1e-12) << "vertex " << v << " left the constrained polyline";
    }
  }
}

TEST(GraphcutRemeshing, SameSeedSameResult)
{
  const Mesh input = noisy_sphere(3, 0.03, 0.01, 6);
  auto run = [&](unsigned seed) {
    Mesh m = input;
    PMP::graphcut_isotropic_remeshing(m, GP::combine(CGAL::parameters::number_of_iterations(20).random_seed(seed),
                                                     GP::number_of_greedy_iterations(5)));
    std::vector<Point> p;
    for(auto v : vertices(m))
      p.push_back(m.point(v));
    return p;
  };
  const std::vector<Point> a = run(1), b = run(1), c = run(2);
  EXPECT_TRUE(a == b);
  EXPECT_FALSE(a == c);
}

// The candidates, tables and intersection queries run on TBB's threads when CGAL is linked with
// TBB: the remesh must be the same, coordinate for coordinate and face for face, on one thread.
TEST(GraphcutRemeshing, SameResultOnOneThreadAndOnAll)
{
#ifndef CGAL_LINKED_WITH_TBB
  GTEST_SKIP() << "CGAL is not linked with TBB: the remesher runs on one thread";
#else
  std::vector<std::pair<std::string, Mesh> > cases;
  cases.push_back({"noisy sphere", noisy_sphere(3, 0.03, 0.01, 6)});
  cases.push_back({"jittered box", jittered_box(1, 2, 0.5, 6, 2)});
  cases.push_back({"fandisk", load_sample_mesh("fandisk")});
  auto run = [](const Mesh& input, std::size_t threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    Mesh m = input;
    PMP::graphcut_isotropic_remeshing(m, GP::combine(CGAL::parameters::number_of_iterations(15),
                                                     GP::number_of_greedy_iterations(5)));
    std::vector<double> out;
    for(auto v : vertices(m))
      out.insert(out.end(), {m.point(v).x(), m.point(v).y(), m.point(v).z()});
    for(auto f : faces(m))
      for(auto v : vertices_around_face(halfedge(f, m), m))
        out.push_back(double(v));
    return out;
  };
  for(const auto& c : cases)
  {
    const std::vector<double> one = run(c.second, 1), all = run(c.second, 2);
    EXPECT_EQ(one.size(), all.size()) << c.first;
    EXPECT_TRUE(one == all) << c.first;
  }
#endif
}

TEST(GraphcutRemeshing, VisitorSeesEveryIterationAndCanStop)
{
  Mesh m = noisy_sphere(2, 0.03, 0.01, 7);
  std::vector<PMP::Graphcut_remeshing_progress> seen;
  auto record = [&seen](const PMP::Graphcut_remeshing_progress& p) {
    seen.push_back(p);
    return true;
  };
  const auto all = PMP::graphcut_isotropic_remeshing(
    m, GP::combine(CGAL::parameters::number_of_iterations(6), GP::number_of_greedy_iterations(3), GP::visitor(std::ref(record))));
  ASSERT_EQ(seen.size(), 9u);
  EXPECT_FALSE(all.cancelled);
  for(std::size_t i = 0; i < 9; ++i)
  {
    EXPECT_EQ(seen[i].phase, i < 6 ? PMP::Graphcut_remeshing_progress::RELOCATION
                                   : PMP::Graphcut_remeshing_progress::GREEDY_FITTING);
    EXPECT_EQ(seen[i].iteration, i < 6 ? i + 1 : i - 5);
    EXPECT_DOUBLE_EQ(seen[i].energy, all.energies[i + 1]);
  }

  Mesh n = noisy_sphere(2, 0.03, 0.01, 7);
  std::size_t calls = 0;
  auto stop_after_three = [&calls](const PMP::Graphcut_remeshing_progress&) { return ++calls < 3; };
  const auto stopped = PMP::graphcut_isotropic_remeshing(
    n, GP::combine(CGAL::parameters::number_of_iterations(6), GP::visitor(std::ref(stop_after_three))));
  EXPECT_TRUE(stopped.cancelled);
  EXPECT_EQ(stopped.number_of_iterations, 3u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(n));
}

// The bar of part 1 on the paper's models, connectivity unchanged, the paper's mode: valid,
// same vertex count and Euler characteristic, no new self-intersection, a mean minimum angle at
// least 3 degrees above the input's, and a Hausdorff distance at most 0.8 times that of CGAL's
// tangential_relaxation (20 iterations, edges of 35 degrees or more constrained).
TEST(GraphcutRemeshing, PaperModelsBeatTangentialRelaxation)
{
#ifdef GRAPHCUT_REMESHING_SANITIZE
  // Full default runs on three models, 20 times slower under the sanitizers (4 minutes): the bars
  // need them. test_robustness runs these models briefly in that build.
  GTEST_SKIP() << "the paper's bars need full runs; skipped in the sanitizer build";
#endif
  for(const std::string name : {"fandisk", "cow", "triceratops"})
  {
    const Mesh input = load_sample_mesh(name);
    Mesh m = input;
    const auto stats =
      PMP::graphcut_isotropic_remeshing(m, GP::combine(GP::do_connectivity_optimization(false), GP::resampling(false)));
    expect_monotone(stats, name);

    Mesh relaxed = input;
    auto sharp = relaxed.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
    auto pinned = relaxed.add_property_map<Mesh::Vertex_index, bool>("v:pinned", false).first;
    PMP::detect_sharp_edges(relaxed, 35.0, sharp);
    for(auto e : edges(relaxed))
      if(sharp[e])
        pinned[source(e, relaxed)] = pinned[target(e, relaxed)] = true;
    PMP::tangential_relaxation(relaxed, CGAL::parameters::number_of_iterations(20)
                                          .edge_is_constrained_map(sharp).vertex_is_constrained_map(pinned));

    const PMP::Mesh_quality_report before = PMP::mesh_quality_report(input), after = PMP::mesh_quality_report(m);
    const double ours = PMP::relative_surface_distance(input, m).hausdorff;
    const double theirs = PMP::relative_surface_distance(input, relaxed).hausdorff;
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m)) << name;
    EXPECT_EQ(num_vertices(m), num_vertices(input)) << name;
    EXPECT_EQ(num_vertices(m) - num_edges(m) + num_faces(m), num_vertices(input) - num_edges(input) + num_faces(input)) << name;
    EXPECT_EQ(graphcut_remeshing_tools::new_intersecting_pairs(input, m), 0u) << name;
    EXPECT_GE(after.mean_min_angle, before.mean_min_angle + 3) << name;
    EXPECT_LE(ours, 0.8 * theirs) << name;
    std::cout << name << ": mean min angle " << before.mean_min_angle << " -> " << after.mean_min_angle
              << ", Hausdorff " << ours << " (tangential_relaxation " << theirs << ", ratio " << ours / theirs << ")\n";
  }
}

namespace {

// `input` remeshed by the plain call (re-sampling) at `seed`.
Mesh resampled(const Mesh& input, unsigned seed)
{
  Mesh m = input;
  PMP::graphcut_isotropic_remeshing(m, CGAL::parameters::random_seed(seed));
  return m;
}

} // namespace

// Issue 23's bar on fandisk's sharp lines with re-sampling, whose collapses and slides keep the
// lines within the sizing tolerance of the input's (the strong creases' turns are no corners
// there): every point of an input edge of 45 degrees or more within 0.1e-3 of the diagonal of an
// output edge of 25 degrees or more, at seeds 0 and 1; and a mean minimum angle 2 degrees above
// isotropic_remeshing's on fandisk.
TEST(GraphcutRemeshing, ResamplingKeepsFandisksSharpLines)
{
#ifdef GRAPHCUT_REMESHING_SANITIZE
  GTEST_SKIP() << "full runs on fandisk; skipped in the sanitizer build";
#endif
  const Mesh input = load_sample_mesh("fandisk");
  for(unsigned seed : {0u, 1u})
  {
    const Mesh m = resampled(input, seed);
    EXPECT_LE(PMP::relative_sharp_edge_distance(input, m, 45, 25), 0.1e-3) << "seed " << seed;
    EXPECT_GE(PMP::mesh_quality_report(m).mean_min_angle, 51.5) << "seed " << seed;
  }
}

// A coarse curved input (knot: a tube of 2080 vertices, no sharp edge) re-sampled: its sizing
// tolerance is large, and the data term, counted relative to it, no longer holds the vertices
// where the input's were. Mean minimum angle above isotropic_remeshing's (51.5 degrees at the
// mean edge length), 50.9-51.0 with the unit-box weight; still within two thirds of its Hausdorff
// distance (5.7e-3 of the diagonal), at seeds 0 and 1.
TEST(GraphcutRemeshing, ResamplingShapesACoarseTube)
{
#ifdef GRAPHCUT_REMESHING_SANITIZE
  GTEST_SKIP() << "full runs on knot; skipped in the sanitizer build";
#endif
  const Mesh input = load_sample_mesh("knot");
  for(unsigned seed : {0u, 1u})
  {
    const Mesh m = resampled(input, seed);
    EXPECT_GE(PMP::mesh_quality_report(m).mean_min_angle, 51.7) << "seed " << seed;
    EXPECT_LE(PMP::relative_surface_distance(input, m).hausdorff, 3.5e-3) << "seed " << seed;
  }
}

// Issue 24's call, shaped as isotropic_remeshing's: a noisy sphere re-sampled at half and twice its
// mean edge length, at two scales. The vertex count follows the inverse square of the length (16
// times as many at a quarter of the length), whatever the scale; the triangles are good and the
// surface kept.
TEST(GraphcutRemeshing, TargetLengthSetsTheDensity)
{
  const Mesh sphere = noisy_sphere(3, 0.02, 0.0, 7);
  for(double scale : {1.0, 1000.0})
  {
    Mesh input = sphere;
    PMP::transform(CGAL::Aff_transformation_3<Kernel>(CGAL::SCALING, scale), input);
    const double mean = mean_edge_length(input);
    std::vector<double> count;
    for(double factor : {0.5, 2.0})
    {
      Mesh m = input;
      PMP::graphcut_isotropic_remeshing(faces(m), factor * mean, m, CGAL::parameters::number_of_iterations(30));
      // Surface_mesh keeps the removed elements until collect_garbage(): count the others.
      count.push_back(double(m.number_of_vertices()));
      EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
      EXPECT_EQ(m.number_of_vertices() - m.number_of_edges() + m.number_of_faces(), 2u) << factor;
      EXPECT_GE(PMP::mesh_quality_report(m).mean_min_angle, 45) << "scale " << scale << ", factor " << factor;
      EXPECT_LE(PMP::relative_surface_distance(input, m).hausdorff, 0.02) << "scale " << scale << ", factor " << factor;
    }
    EXPECT_NEAR(count[0] / count[1], 16, 4) << "scale " << scale << ": " << count[0] << " and " << count[1];
  }
}

namespace {

// isotropic_remeshing() at `target` as issue 24 compares with it: 5 iterations, the edges of 35
// degrees or more constrained.
Mesh isotropically_remeshed(const Mesh& input, double target)
{
  Mesh theirs = input;
  auto constrained = get(CGAL::edge_is_feature, theirs);
  PMP::detect_sharp_edges(theirs, 35, constrained);
  PMP::isotropic_remeshing(faces(theirs), target, theirs,
                           CGAL::parameters::number_of_iterations(5).edge_is_constrained_map(constrained));
  return theirs;
}

} // namespace

// Four times coarser than the input, the count comes near isotropic_remeshing's at the same length
// (edges of 35 degrees or more constrained): on triceratops the sharp lines of its fine sampling,
// short at that scale, once held a quarter more vertices; on ALSTOM_TEST4, a CAD strip, the regions
// left alone after a pass had made triangles intersect once held 3.5 times as many, and its
// borders' close corners and vertices in a single triangle 1.17 times (issue 24's bar is 1.15).
TEST(GraphcutRemeshing, CoarseTargetComesNearIsotropicRemeshingsCount)
{
  for(const auto& [name, bound] : {std::make_pair("triceratops", 1.2), std::make_pair("ALSTOM_TEST4", 1.15)})
  {
    const Mesh input = load_sample_mesh(name);
    const double target = 4 * mean_edge_length(input);
    const Mesh theirs = isotropically_remeshed(input, target);
    Mesh ours = input;
    PMP::graphcut_isotropic_remeshing(faces(ours), target, ours);
    EXPECT_LE(double(ours.number_of_vertices()), bound * double(theirs.number_of_vertices()))
      << name << ": " << ours.number_of_vertices() << " against " << theirs.number_of_vertices();
    EXPECT_GE(PMP::mesh_quality_report(ours).mean_min_angle, PMP::mesh_quality_report(theirs).mean_min_angle) << name;
  }
}

// A coarser target re-samples the feature lines too: a box's edges, cut into ten segments, at a
// target of 1.4 and 1.6 segments. Removing a line's vertex alone merges two segments, beyond 4/3
// of the target; the lines' segments stayed at 0.78 and 0.80 times the target on average. The
// kept end also slides to the middle of the collapsed segment: 0.87 to 0.88 times.
TEST(GraphcutRemeshing, CoarseTargetResamplesFeatureLines)
{
  for(double scale : {1e-3, 1.0, 1e3})
    for(double factor : {1.4, 1.6})
    {
      Mesh m = jittered_box(scale, scale, scale, 10, 3);
      const double target = factor * scale / 10;
      PMP::graphcut_isotropic_remeshing(faces(m), target, m, CGAL::parameters::number_of_iterations(30));
      std::size_t corners = 0, on_edges = 0;
      for(auto v : vertices(m))
      {
        const Point& p = m.point(v);
        int bounded = 0;
        for(double x : {p.x(), p.y(), p.z()})
          bounded += (std::abs(x) <= 1e-12 * scale || std::abs(x - scale) <= 1e-12 * scale) ? 1 : 0;
        corners += bounded == 3 ? 1 : 0;
        on_edges += bounded == 2 ? 1 : 0;
      }
      EXPECT_EQ(corners, 8u);
      // The twelve edges of length `scale` are cut into on_edges + 12 segments.
      const double mean_segment = 12 * scale / double(on_edges + 12);
      EXPECT_GE(mean_segment, 0.83 * target) << "scale " << scale << ", factor " << factor << ": " << on_edges;
      EXPECT_LE(mean_segment, 1.05 * target) << "scale " << scale << ", factor " << factor << ": " << on_edges;
    }
}

// A user's constrained edges are never collapsed (nor split) at a coarse target, also where their
// run goes on as a sharp line whose segments collapse: a run of them in the middle of each edge of
// a box.
TEST(GraphcutRemeshing, CoarseTargetKeepsTheUsersConstrainedEdges)
{
  for(double scale : {1e-3, 1.0, 1e3})
  {
    Mesh m = jittered_box(scale, scale, scale, 10, 3);
    auto ecm = m.add_property_map<Mesh::Edge_index, bool>("e:constrained", false).first;
    // Where p is on an edge of the box: its coordinate along that edge, else -1.
    const auto along_box_edge = [&](const Point& p) {
      int bounded = 0;
      double free = -1;
      for(double x : {p.x(), p.y(), p.z()})
        if(x == 0 || x == scale)
          ++bounded;
        else
          free = x;
      return bounded == 2 ? free : -1.0;
    };
    std::size_t run = 0;
    for(auto e : edges(m))
    {
      const Point &p = m.point(source(e, m)), &q = m.point(target(e, m));
      const double s = along_box_edge(p), t = along_box_edge(q);
      const bool same_edge = (p.x() == q.x()) + (p.y() == q.y()) + (p.z() == q.z()) == 2;
      if(same_edge && (std::min)(s, t) > 0.3 * scale && (std::max)(s, t) < 0.7 * scale)
      {
        ecm[e] = true;
        ++run;
      }
    }
    ASSERT_GE(run, 24u);
    PMP::graphcut_isotropic_remeshing(faces(m), 0.16 * scale, m,
                                      CGAL::parameters::number_of_iterations(30).edge_is_constrained_map(ecm));
    std::size_t constrained = 0;
    for(auto e : edges(m))
      constrained += ecm[e] ? 1 : 0;
    EXPECT_EQ(constrained, run) << "scale " << scale;
  }
}

// At a coarse target the relocation slides the vertices of thin parts down their sides, and the
// coarse triangles cut a tip off while every vertex and centroid stays near the surface; the
// reference vertices that stand out farthest from the mesh get a vertex. cow at four times its
// mean edge length, at the seeds where the teats under its belly were cut off (above 20e-3 of the
// diagonal without the rule; the README has the figures): within 0.7 times isotropic_remeshing's
// 25.7e-3, issue 24's bar.
TEST(GraphcutRemeshing, CoarseTargetKeepsThinTips)
{
#ifdef GRAPHCUT_REMESHING_SANITIZE
  GTEST_SKIP() << "full runs on cow; skipped in the sanitizer build";
#endif
  const Mesh input = load_sample_mesh("cow");
  for(unsigned seed : {1u, 3u})
  {
    Mesh m = input;
    PMP::graphcut_isotropic_remeshing(faces(m), 4 * mean_edge_length(input), m, CGAL::parameters::random_seed(seed));
    EXPECT_LE(PMP::relative_surface_distance(input, m).hausdorff, 18e-3) << "seed " << seed;
  }
}

// At twice triceratops's mean edge length, edges cut across the creases and hollows of its horn and
// legs while their ends stay on the surface; once the relocation is over, the edges whose
// midpoints stand out get a vertex below them. The Hausdorff distance then keeps within issue 24's
// bar, 0.7 times isotropic_remeshing's at the same length (seeds 0 and 1: 0.81 and 0.82 times
// before).
TEST(GraphcutRemeshing, CoarseTargetCoversChordsAcrossCreases)
{
#ifdef GRAPHCUT_REMESHING_SANITIZE
  GTEST_SKIP() << "full runs on triceratops; skipped in the sanitizer build";
#endif
  const Mesh input = load_sample_mesh("triceratops");
  const double target = 2 * mean_edge_length(input);
  const double theirs = PMP::relative_surface_distance(input, isotropically_remeshed(input, target)).hausdorff;
  for(unsigned seed : {0u, 1u})
  {
    Mesh m = input;
    PMP::graphcut_isotropic_remeshing(faces(m), target, m, CGAL::parameters::random_seed(seed));
    EXPECT_LE(PMP::relative_surface_distance(input, m).hausdorff, 0.7 * theirs) << "seed " << seed;
  }
}

// At a coarse target knot's tube is a few triangles round, which turn far from one to the next: no
// operation may fold one onto its neighbour (the guarantee the debug builds check after every
// run; knot's runs are too long for the sanitizer build). Before the collapses and the relocation
// checked, knot at four times its mean edge length ended with 26 folded edges, at twice with one.
TEST(GraphcutRemeshing, CoarseTargetFoldsNoTriangle)
{
#ifdef GRAPHCUT_REMESHING_SANITIZE
  GTEST_SKIP() << "full runs on knot; skipped in the sanitizer build";
#endif
  const Mesh input = load_sample_mesh("knot");
  for(double factor : {2.0, 4.0})
  {
    Mesh m = input;
    PMP::graphcut_isotropic_remeshing(faces(m), factor * mean_edge_length(input), m);
    std::size_t folded = 0;
    for(auto e : edges(m))
      folded += PMP::internal::Graphcut_remeshing::is_folded_edge(m, halfedge(e, m)) ? 1 : 0;
    EXPECT_EQ(folded, 0u) << "at " << factor << " times the mean edge length";
  }
}

// Where the input's triangles intersect, the remesher works as elsewhere: two overlapping spheres
// refined to half their mean edge length get about four times the vertices in the zones around the
// curve where they cross (the boxes of the intersecting pairs, grown by the mean edge length; about
// half of the vertices), as everywhere (when the triangles there were frozen, twice), and no
// intersection away from the input's.
TEST(GraphcutRemeshing, SelfIntersectingInputIsRemeshedWhereItIntersects)
{
  Mesh input = make_sphere(2);
  CGAL::copy_face_graph(make_sphere(2, 0.8, Point(0.5, 0, 0)), input);
  const std::vector<CGAL::Bbox_3> zones = graphcut_remeshing_tools::intersection_zones(input);
  ASSERT_FALSE(zones.empty());
  const auto near_crossing = [&](const Mesh& m) {
    std::size_t n = 0;
    for(Mesh::Vertex_index v : m.vertices())
      n += std::any_of(zones.begin(), zones.end(),
                       [&](const CGAL::Bbox_3& z) { return CGAL::do_overlap(z, m.point(v).bbox()); });
    return double(n);
  };
  Mesh m = input;
  PMP::graphcut_isotropic_remeshing(faces(m), 0.5 * mean_edge_length(input), m, CGAL::parameters::number_of_iterations(30));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
  EXPECT_EQ(graphcut_remeshing_tools::new_intersecting_pairs(input, m), 0u);
  EXPECT_GE(near_crossing(m), 3 * near_crossing(input)) << near_crossing(m) << " of " << m.number_of_vertices();
  EXPECT_GE(double(m.number_of_vertices()), 3 * double(input.number_of_vertices()));
}

// Issue 24: an error bound instead of a count. A fine sphere of radius r (edges of 0.075 r) asked
// for at a long target length with a sizing tolerance e gets, coarsened, the edges whose
// equilateral triangles keep within e at their centroids, sqrt(6 e r) = 0.134 r, and its triangles'
// centroids stay within about e of the sphere (a triangle up to 4/3 of its target leaves it by
// (4/3)^2 e); at two scales. The longest edge length bound shortens the field; values outside
// their domain are refused and leave the mesh as it was.
TEST(GraphcutRemeshing, SizingToleranceBoundsTheChords)
{
  const Mesh sphere = make_sphere(4);
  const auto parameters = CGAL::parameters::number_of_iterations(30);
  auto deepest_centroid = [](const Mesh& m, double radius) {
    double depth = 0;
    for(auto f : faces(m))
    {
      CGAL::Vector_3<Kernel> c = CGAL::NULL_VECTOR;
      for(auto v : vertices_around_face(halfedge(f, m), m))
        c = c + (m.point(v) - CGAL::ORIGIN) / 3;
      depth = (std::max)(depth, radius - std::sqrt(c.squared_length()));
    }
    return depth;
  };
  for(double scale : {1.0, 1000.0})
  {
    Mesh m = sphere;
    PMP::transform(CGAL::Aff_transformation_3<Kernel>(CGAL::SCALING, scale), m);
    const double tolerance = 0.003 * scale, chord = std::sqrt(6 * tolerance * scale);
    PMP::graphcut_isotropic_remeshing(faces(m), 0.5 * scale, m, GP::combine(parameters, GP::sizing_tolerance(tolerance)));
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
    EXPECT_NEAR(mean_edge_length(m) / chord, 1, 0.25) << "scale " << scale;
    EXPECT_LE(deepest_centroid(m, scale), 2 * tolerance) << "scale " << scale;
    EXPECT_GE(PMP::mesh_quality_report(m).mean_min_angle, 45) << "scale " << scale;
  }
  Mesh bounded = sphere;
  PMP::graphcut_isotropic_remeshing(faces(bounded), 0.5, bounded,
                                    GP::combine(parameters, GP::sizing_tolerance(0.003),
                                                GP::edge_length_bounds(std::make_pair(0.05, 0.1))));
  EXPECT_NEAR(mean_edge_length(bounded) / 0.1, 1, 0.25);
  Mesh refused = sphere;
  EXPECT_THROW(PMP::graphcut_isotropic_remeshing(faces(refused), 0.5, refused, GP::sizing_tolerance(0.0)),
               std::invalid_argument);
  EXPECT_THROW(PMP::graphcut_isotropic_remeshing(faces(refused), 0.5, refused,
                                                 GP::combine(GP::sizing_tolerance(0.01),
                                                             GP::edge_length_bounds(std::make_pair(0.2, 0.1)))),
               std::invalid_argument);
  EXPECT_EQ(refused.number_of_vertices(), sphere.number_of_vertices());
  for(auto v : vertices(sphere))
    EXPECT_EQ(refused.point(v), sphere.point(v));
}

// Issue 49: with a distance bound, the output stays within it of the input, both ways, by CGAL's
// own sampled Hausdorff distance and by the call's measure; without it, the same runs leave the
// input by more (so the bound is what keeps them). A noisy sphere and a CAD part with sharp edges,
// at three scales.
TEST(GraphcutRemeshing, DistanceBoundIsKept)
{
  const auto parameters = GP::combine(CGAL::parameters::number_of_iterations(10), GP::number_of_greedy_iterations(2));
  struct Case
  {
    std::string name;
    Mesh mesh;
    double least_mean_min_angle;
  };
  // The sphere's noise is up to three times the bound: the bound keeps it. joint's input (9.35
  // degrees) is made of slivers across its rounds, which isotropic_remeshing() mends by leaving it
  // by 76 times the bound, and the bound by shorter edges.
  std::vector<Case> cases{{"noisy sphere", noisy_sphere(3, 0.03, 0.01, 7), 49}};
  std::vector<double> scales{1.0};
#ifndef GRAPHCUT_REMESHING_SANITIZE
  cases.push_back({"joint", load_sample_mesh("joint"), 30});
  scales = {1e-2, 1.0, 1e2};
#endif
  for(const Case& c : cases)
    for(double scale : scales)
    {
      Mesh input = c.mesh;
      PMP::transform(CGAL::Aff_transformation_3<Kernel>(CGAL::SCALING, scale), input);
      const CGAL::Bbox_3 box = PMP::bbox(input);
      const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                        CGAL::square(box.zmax() - box.zmin()));
      const double bound = 1e-3 * diagonal;
      auto sampled_distance = [&](const Mesh& m) {
        const auto dense = CGAL::parameters::number_of_points_on_faces(30000);
        return PMP::approximate_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(input, m, dense, dense);
      };
      Mesh free = input;
      PMP::graphcut_isotropic_remeshing(free, parameters);
      EXPECT_GT(sampled_distance(free), 1.5 * bound) << c.name << ", scale " << scale;
      Mesh m = input;
      const PMP::Graphcut_remeshing_statistics stats =
        PMP::graphcut_isotropic_remeshing(m, GP::combine(parameters, GP::distance_bound(bound)));
      EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
      EXPECT_LE(sampled_distance(m), bound) << c.name << ", scale " << scale;
      EXPECT_GT(stats.hausdorff_distance, 0.3 * bound) << c.name << ", scale " << scale;
      EXPECT_LE(stats.hausdorff_distance, bound) << c.name << ", scale " << scale;
      EXPECT_GE(PMP::mesh_quality_report(m).mean_min_angle, c.least_mean_min_angle) << c.name << ", scale " << scale;
    }
  Mesh refused = noisy_sphere(2, 0.03, 0.01, 7);
  for(double bound : {-1.0, std::numeric_limits<double>::infinity()})
    EXPECT_THROW(PMP::graphcut_isotropic_remeshing(refused, GP::distance_bound(bound)), std::invalid_argument);
  Mesh none = refused, zero = refused;
  PMP::graphcut_isotropic_remeshing(none, parameters);
  EXPECT_LT(PMP::graphcut_isotropic_remeshing(zero, GP::combine(parameters, GP::distance_bound(0.0))).hausdorff_distance, 0);
  ASSERT_EQ(none.number_of_vertices(), zero.number_of_vertices());
  for(auto v : vertices(none))
    EXPECT_EQ(none.point(v), zero.point(v));
}

// Issue 24: remeshing some faces only. The faces of a noisy sphere below its equator are re-sampled
// at the mean edge length: every face above keeps its vertices and their exact points, the mesh
// stays valid and closed, and the region's triangles are as good as a whole run makes them there.
TEST(GraphcutRemeshing, TargetLengthRemeshesOnlyTheRegion)
{
  const Mesh input = noisy_sphere(3, 0.02, 0.0, 3);
  const double mean = mean_edge_length(input);
  auto below = [](const Mesh& m, Mesh::Face_index f) {
    double z = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m))
      z += m.point(v).z();
    return z < 0;
  };
  std::vector<Mesh::Face_index> region;
  for(auto f : faces(input))
    if(below(input, f))
      region.push_back(f);
  const auto parameters = CGAL::parameters::number_of_iterations(30);
  Mesh m = input, whole = input;
  PMP::graphcut_isotropic_remeshing(region, mean, m, parameters);
  PMP::graphcut_isotropic_remeshing(faces(whole), mean, whole, parameters);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
  EXPECT_EQ(m.number_of_vertices() - m.number_of_edges() + m.number_of_faces(), 2u);
  std::size_t kept = 0;
  for(auto f : faces(input))
  {
    if(below(input, f))
      continue;
    ASSERT_FALSE(m.is_removed(f));
    auto before = input.halfedge(f), after = m.halfedge(f);
    while(m.target(after) != input.target(before))
      after = m.next(after);
    for(int k = 0; k < 3; ++k, before = input.next(before), after = m.next(after))
      kept += m.target(after) == input.target(before) && m.point(m.target(after)) == input.point(input.target(before));
  }
  EXPECT_EQ(kept, 3 * (num_faces(input) - region.size()));
  // The region's triangles: the faces of m that are not the input's faces above.
  auto mean_min_angle_below = [&](const Mesh& r, bool new_faces_only) {
    double sum = 0;
    std::size_t n = 0;
    for(auto f : faces(r))
      if(new_faces_only ? (std::size_t(f) >= num_faces(input) || below(input, f)) : below(r, f))
      {
        const auto h = halfedge(f, r);
        const auto a = r.point(source(h, r)), b = r.point(target(h, r)), c = r.point(target(next(h, r), r));
        sum += (std::min)({CGAL::approximate_angle(b, a, c), CGAL::approximate_angle(a, b, c), CGAL::approximate_angle(a, c, b)});
        ++n;
      }
    return sum / double(n);
  };
  EXPECT_GE(mean_min_angle_below(m, true), mean_min_angle_below(whole, false) - 1);
  // No length, no faces: refused, or nothing to do.
  Mesh untouched = input;
  EXPECT_THROW(PMP::graphcut_isotropic_remeshing(faces(untouched), 0.0, untouched), std::invalid_argument);
  PMP::graphcut_isotropic_remeshing(std::vector<Mesh::Face_index>(), mean, untouched);
  EXPECT_EQ(untouched.number_of_faces(), input.number_of_faces());
  for(auto v : vertices(input))
    EXPECT_EQ(untouched.point(v), input.point(v));
}

// The paper's Table 1 ("our" rows) at seed 0, measured as Metro does (300k samples a side): the
// whole method must do at least as well, in both modes. In the paper's mode (resampling(false),
// its connectivity stage and sharp-angle bounds) the vertex count stays within 15 % of the
// input's; in the default mode, which re-samples at the input's mean edge length, it is at most
// 1.15 times isotropic_remeshing's at that length (5 iterations, edges of 35 degrees or more
// constrained), and fandisk's irregular vertices at most its share.
TEST(GraphcutRemeshing, PaperModelsMeetTable1)
{
#ifdef GRAPHCUT_REMESHING_SANITIZE
  // Full default runs on three models, 20 times slower under the sanitizers (4 minutes): the bars
  // need them. test_robustness runs these models briefly in that build.
  GTEST_SKIP() << "the paper's bars need full runs; skipped in the sanitizer build";
#endif
  struct Row
  {
    std::string name;
    double irregular, min_angle, max_angle, hausdorff, rms; // percent, degrees, ratios to the diagonal
    // On fandisk: every point of an input edge of 45 degrees or more within this of an output edge
    // of 25 degrees or more (a ratio to the diagonal).
    double sharp_lines = std::numeric_limits<double>::infinity();
  };
  for(bool resampling : {false, true})
  for(const Row& row : {Row{"fandisk", 14, 48.2, 77.4, 1.3e-3, 0.03e-3, 0.1e-3}, Row{"cow", 36, 40.7, 83.8, 5.0e-3, 0.7e-3},
                        Row{"triceratops", 37, 41.0, 83.9, 3.9e-3, 0.5e-3}})
  {
    const Mesh input = load_sample_mesh(row.name);
    Mesh m = input;
    const auto stats = PMP::graphcut_isotropic_remeshing(m, GP::resampling(resampling));
    const PMP::Mesh_quality_report before = PMP::mesh_quality_report(input), after = PMP::mesh_quality_report(m);
    const PMP::Relative_surface_distance d = PMP::relative_surface_distance(input, m);
    std::cout << row.name << (resampling ? "" : " (paper's mode)") << ": " << after.number_of_vertices << " vertices, " << after.irregular_vertex_percentage
              << " % irregular, angles " << after.mean_min_angle << " / " << after.mean_max_angle << ", Hausdorff "
              << d.hausdorff << ", RMS " << d.rms << "; " << stats.number_of_flips << " flips, "
              << stats.number_of_splits << " splits, " << stats.number_of_collapses << " collapses, "
              << stats.number_of_vertex_splits << " vertex splits\n";
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m)) << row.name;
    if(resampling)
    {
      const PMP::Mesh_quality_report theirs =
        PMP::mesh_quality_report(isotropically_remeshed(input, mean_edge_length(input)));
      std::cout << "  isotropic_remeshing: " << theirs.number_of_vertices << " vertices, "
                << theirs.irregular_vertex_percentage << " % irregular\n";
      EXPECT_LE(double(after.number_of_vertices), 1.15 * double(theirs.number_of_vertices)) << row.name;
      // On fandisk the bar asked for is isotropic_remeshing's share of irregular vertices.
      EXPECT_LE(after.irregular_vertex_percentage,
                row.name == "fandisk" ? theirs.irregular_vertex_percentage : row.irregular)
        << row.name;
    }
    else
    {
      EXPECT_NEAR(double(after.number_of_vertices), double(before.number_of_vertices),
                  0.15 * double(before.number_of_vertices)) << row.name;
      EXPECT_LE(after.irregular_vertex_percentage, row.irregular) << row.name;
    }
    EXPECT_GE(after.mean_min_angle, row.min_angle) << row.name;
    EXPECT_LE(after.mean_max_angle, row.max_angle) << row.name;
    EXPECT_LE(d.hausdorff, row.hausdorff) << row.name;
    EXPECT_LE(d.rms, row.rms) << row.name;
    if(std::isfinite(row.sharp_lines))
    {
      EXPECT_LE(PMP::relative_sharp_edge_distance(input, m, 45, 25), row.sharp_lines) << row.name;
    }
    // Surface_mesh keeps the removed elements until collect_garbage(): count the others.
    EXPECT_EQ(m.number_of_vertices() - m.number_of_edges() + m.number_of_faces(),
              num_vertices(input) - num_edges(input) + num_faces(input)) << row.name;
    std::vector<std::size_t> ids_in(num_faces(input)), ids_out(num_faces(m));
    EXPECT_EQ(PMP::connected_components(m, CGAL::make_property_map(ids_out)),
              PMP::connected_components(input, CGAL::make_property_map(ids_in))) << row.name;
    EXPECT_EQ(graphcut_remeshing_tools::new_intersecting_pairs(input, m), 0u) << row.name << ": new self-intersections";
  }
}

// --- CGAL's named parameters of isotropic_remeshing(), honoured (the refused ones: see
// refused_parameter.cpp) ---

// CGAL's `visitor`, the same callable as the package's, and CGAL's `callback`, told the fraction
// of the iterations done: both see the run and either can end it.
TEST(GraphcutRemeshing, CgalsVisitorAndCallbackSeeTheRunAndCanEndIt)
{
  const Mesh input = noisy_sphere(2, 0.03, 0.0, 1);
  Mesh m = input;
  std::vector<double> fractions;
  std::size_t visits = 0;
  const auto all = PMP::graphcut_isotropic_remeshing(
    m, GP::combine(CGAL::parameters::number_of_iterations(4)
                     .visitor([&visits](const PMP::Graphcut_remeshing_progress&) { return ++visits > 0; })
                     .callback([&fractions](double f) { fractions.push_back(f); return true; }),
                   GP::number_of_greedy_iterations(2)));
  EXPECT_EQ(visits, 6u);
  ASSERT_EQ(fractions.size(), 6u);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_DOUBLE_EQ(fractions.front(), 1.0 / 6);
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
  EXPECT_FALSE(all.cancelled);

  Mesh n = input;
  const auto by_callback = PMP::graphcut_isotropic_remeshing(
    n, GP::combine(CGAL::parameters::number_of_iterations(10).callback([](double f) { return f < 0.25; }),
                   GP::number_of_greedy_iterations(2)));
  EXPECT_TRUE(by_callback.cancelled);
  EXPECT_EQ(by_callback.number_of_iterations, 3u); // 3 of 12 is the first fraction at 0.25
  Mesh o = input;
  const auto by_visitor = PMP::graphcut_isotropic_remeshing(
    o, CGAL::parameters::number_of_iterations(10).visitor(
         [](const PMP::Graphcut_remeshing_progress& p) { return p.iteration < 2; }));
  EXPECT_TRUE(by_visitor.cancelled);
  EXPECT_EQ(by_visitor.number_of_iterations, 2u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(n) && CGAL::is_valid_polygon_mesh(o));
}

// do_split, do_collapse and do_flip switch the operations of the connectivity passes off, one at a
// time; number_of_relaxation_steps sets the relaxation sweeps that end a pass.
TEST(GraphcutRemeshing, CgalsOperationSwitchesAreHonoured)
{
  const Mesh input = noisy_sphere(3, 0.2, 0.0, 2);
  auto run = [&](const auto& np, bool resampling = false) {
    Mesh m = input;
    const auto stats = PMP::graphcut_isotropic_remeshing(
      m, GP::combine(np, GP::number_of_greedy_iterations(0), GP::resampling(resampling)));
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
    return std::make_pair(stats, m);
  };
  const auto with_all = run(CGAL::parameters::number_of_iterations(10));
  EXPECT_GT(with_all.first.number_of_splits + with_all.first.number_of_vertex_splits, 0u);
  EXPECT_GT(with_all.first.number_of_collapses, 0u);
  EXPECT_GT(with_all.first.number_of_flips, 0u);
  const auto no_split = run(CGAL::parameters::number_of_iterations(10).do_split(false));
  EXPECT_EQ(no_split.first.number_of_splits + no_split.first.number_of_vertex_splits, 0u);
  EXPECT_LE(no_split.second.number_of_vertices(), input.number_of_vertices());
  EXPECT_EQ(run(CGAL::parameters::number_of_iterations(10).do_collapse(false)).first.number_of_collapses, 0u);
  EXPECT_EQ(run(CGAL::parameters::number_of_iterations(10).do_flip(false)).first.number_of_flips, 0u);

  // With no operation, a re-sampling pass only relaxes: without a sweep, the relocation alone
  // moves vertices.
  const auto still = CGAL::parameters::number_of_iterations(5).do_split(false).do_collapse(false).do_flip(false);
  const Mesh none = run(still.number_of_relaxation_steps(0), true).second;
  const Mesh three = run(still.number_of_relaxation_steps(3), true).second;
  std::size_t different = 0;
  for(auto v : vertices(none))
    different += none.point(v) != three.point(v) ? 1 : 0;
  EXPECT_GT(different, 20u) << "the sweeps moved no vertex";
}

// relax_constraints(false): the vertices of the user's constrained edges stay where they are
// (by default they slide along the edges).
TEST(GraphcutRemeshing, RelaxConstraintsFalseKeepsConstrainedEdgesVertices)
{
  for(bool relax : {true, false})
  {
    Mesh m = noisy_sphere(3, 0.03, 0.0, 4);
    const Mesh input = m;
    auto ecm = m.add_property_map<Mesh::Edge_index, bool>("e:constrained", false).first;
    ASSERT_GT(constrain_equator(m, ecm), 10u);
    PMP::graphcut_isotropic_remeshing(m, GP::combine(CGAL::parameters::number_of_iterations(20)
                                                       .edge_is_constrained_map(ecm).relax_constraints(relax),
                                                     GP::number_of_greedy_iterations(5),
                                                     GP::do_connectivity_optimization(false)));
    std::size_t moved = 0, on_constraints = 0;
    for(auto e : edges(input))
      if(ecm[e])
        for(auto v : {source(e, input), target(e, input)})
        {
          ++on_constraints;
          moved += m.point(v) != input.point(v) ? 1 : 0;
        }
    if(relax)
      EXPECT_GT(moved, on_constraints / 4);
    else
      EXPECT_EQ(moved, 0u);
  }
}

// A face_patch_map's patch borders are feature lines: a flat square in two patches along the
// zigzag of its grid near x = 0.37 keeps that line (every output edge between the patches lies on
// it), and the output's faces carry the patch they lie in. Without the map, the plane's smoothing
// leaves fewer vertices on that line.
TEST(GraphcutRemeshing, FacePatchBordersAreFeatureLines)
{
  const double line = 0.37;
  Mesh input = make_grid(19, 19, [](std::size_t i, std::size_t j) {
    const double x = double(i) / 19, y = double(j) / 19;
    return Point(x + 0.2 * y * (1 - y) * x * (1 - x), y + 0.1 * std::sin(7 * x) * y * (1 - y), 0);
  });
  auto centroid_x = [](const Mesh& m, Mesh::Face_index f) {
    double x = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m))
      x += m.point(v).x() / 3;
    return x;
  };
  auto input_patch = input.add_property_map<Mesh::Face_index, int>("f:patch", 0).first;
  for(auto f : faces(input))
    input_patch[f] = centroid_x(input, f) < line ? 0 : 1;
  std::vector<std::pair<Point, Point> > border;
  for(auto e : edges(input))
    if(!is_border(e, input) &&
       input_patch[face(halfedge(e, input), input)] != input_patch[face(opposite(halfedge(e, input), input), input)])
      border.emplace_back(input.point(source(e, input)), input.point(target(e, input)));
  ASSERT_GT(border.size(), 10u);
  auto on_border = [&](const Point& p) {
    for(const auto& s : border)
      if(distance_to_segment(p, s.first, s.second) < 1e-9)
        return true;
    return false;
  };
  auto vertices_on_border = [&](const Mesh& m) {
    std::size_t n = 0;
    for(auto v : vertices(m))
      n += on_border(m.point(v)) ? 1 : 0;
    return n;
  };

  Mesh m = input;
  auto patch = get(CGAL::dynamic_face_property_t<int>(), m);
  for(auto f : faces(m))
    put(patch, f, input_patch[f]);
  PMP::graphcut_isotropic_remeshing(m, CGAL::parameters::number_of_iterations(20).face_patch_map(patch));
  std::size_t between = 0, off_line = 0;
  for(auto e : edges(m))
    if(!is_border(e, m) && get(patch, face(halfedge(e, m), m)) != get(patch, face(opposite(halfedge(e, m), m), m)))
    {
      ++between;
      off_line += on_border(m.point(source(e, m))) && on_border(m.point(target(e, m))) ? 0 : 1;
    }
  EXPECT_GT(between, 5u);
  EXPECT_EQ(off_line, 0u) << "of " << between << " edges between the patches";
  for(auto f : faces(m))
    if(std::abs(centroid_x(m, f) - line) > 0.1)
    {
      EXPECT_EQ(get(patch, f), centroid_x(m, f) < line ? 0 : 1) << "face at x = " << centroid_x(m, f);
    }

  Mesh plain = input;
  PMP::graphcut_isotropic_remeshing(plain, CGAL::parameters::number_of_iterations(20));
  EXPECT_LT(vertices_on_border(plain), vertices_on_border(m) / 2)
    << vertices_on_border(plain) << " on the line without the map, " << vertices_on_border(m) << " with";
}
