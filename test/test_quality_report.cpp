// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The quality report: angles and valences on analytic cases and on fandisk, Metro-style distances
// on cases with a known answer and against CGAL's own samplers.

#include "test_meshes.h"

#include <CGAL/Polygon_mesh_processing/mesh_quality_report.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/Aff_transformation_3.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
using namespace graphcut_remeshing_test;

namespace {

const double angle_tolerance = 1e-9; // degrees

Mesh translated(const Mesh& mesh, const Vector& t)
{
  Mesh copy = mesh;
  PMP::transform(Kernel::Aff_transformation_3(CGAL::TRANSLATION, t), copy);
  return copy;
}

} // namespace

TEST(QualityReport, EquilateralTriangleIsSixtyEverywhere)
{
  for(double scale : {1e-6, 1.0, 1e6})
  {
    const Mesh m = make_triangle(Point(0, 0, 0), Point(scale, 0, 0),
                                 Point(scale / 2, scale * std::sqrt(3.0) / 2, 0));
    const PMP::Mesh_quality_report q = PMP::mesh_quality_report(m);
    EXPECT_EQ(q.number_of_vertices, 3u);
    EXPECT_EQ(q.number_of_faces, 1u);
    EXPECT_NEAR(q.mean_min_angle, 60, angle_tolerance) << "scale " << scale;
    EXPECT_NEAR(q.mean_max_angle, 60, angle_tolerance) << "scale " << scale;
    EXPECT_NEAR(q.min_angle, 60, angle_tolerance);
    EXPECT_NEAR(q.max_angle, 60, angle_tolerance);
    // Three border vertices of valence 2: all irregular.
    EXPECT_DOUBLE_EQ(q.irregular_vertex_percentage, 100);
  }
}

TEST(QualityReport, RightIsoscelesTriangleIs45And90)
{
  for(double scale : {1e-6, 1.0, 1e6})
  {
    const Mesh m = make_triangle(Point(0, 0, 0), Point(scale, 0, 0), Point(0, 0, scale));
    const PMP::Mesh_quality_report q = PMP::mesh_quality_report(m);
    EXPECT_NEAR(q.mean_min_angle, 45, angle_tolerance) << "scale " << scale;
    EXPECT_NEAR(q.mean_max_angle, 90, angle_tolerance) << "scale " << scale;
    EXPECT_NEAR(q.min_angle, 45, angle_tolerance);
    EXPECT_NEAR(q.max_angle, 90, angle_tolerance);
  }
}

TEST(QualityReport, NeedleTriangleAnglesStayAccurate)
{
  // A 1e-7 rad sliver: acos-based angles lose this, atan2 keeps it.
  const Mesh m = make_triangle(Point(0, 0, 0), Point(1, 0, 0), Point(0.5, 0.5e-7, 0));
  const PMP::Mesh_quality_report q = PMP::mesh_quality_report(m);
  const double expected_min = 2 * std::atan(1e-7) * 180 / pi;
  EXPECT_NEAR(q.min_angle, expected_min / 2, 1e-12);
  EXPECT_NEAR(q.max_angle, 180 - expected_min, 1e-9);
}

TEST(QualityReport, RegularLatticePatchIsRegularInsideAndOnItsBorder)
{
  // Interior valence 6 and border valence 4 are regular; only the 4 corners are not.
  for(std::size_t n : {3u, 5u, 9u, 17u})
    for(double h : {1e-3, 1.0, 1e3})
    {
      const Mesh m = make_equilateral_patch(n, h);
      const PMP::Mesh_quality_report q = PMP::mesh_quality_report(m);
      EXPECT_EQ(q.number_of_vertices, n * n);
      EXPECT_EQ(q.number_of_faces, 2 * (n - 1) * (n - 1));
      EXPECT_NEAR(q.irregular_vertex_percentage, 400.0 / double(n * n), 1e-12) << "n = " << n;
      EXPECT_NEAR(q.mean_min_angle, 60, 1e-6);
      EXPECT_NEAR(q.mean_max_angle, 60, 1e-6);
    }
}

TEST(QualityReport, SquareGridHasRightIsoscelesTriangles)
{
  const Mesh m = make_grid(6, 4, [](std::size_t i, std::size_t j) { return Point(double(i), double(j), 0); });
  const PMP::Mesh_quality_report q = PMP::mesh_quality_report(m);
  EXPECT_NEAR(q.irregular_vertex_percentage, 100.0 * 4 / 24, 1e-12);
  EXPECT_NEAR(q.mean_min_angle, 45, angle_tolerance);
  EXPECT_NEAR(q.mean_max_angle, 90, angle_tolerance);
}

TEST(QualityReport, ClosedMeshesValences)
{
  // A torus grid: all vertices valence 6, none irregular.
  EXPECT_DOUBLE_EQ(PMP::mesh_quality_report(make_torus(24, 12, 2.0, 0.5)).irregular_vertex_percentage, 0);
  // An icosphere: the 12 original vertices have valence 5, all others 6.
  for(unsigned level : {0u, 1u, 2u, 3u})
  {
    const Mesh s = make_sphere(level);
    const PMP::Mesh_quality_report q = PMP::mesh_quality_report(s);
    EXPECT_NEAR(q.irregular_vertex_percentage, 1200.0 / double(num_vertices(s)), 1e-12);
    if(level == 0)
    {
      EXPECT_NEAR(q.mean_min_angle, 60, 1e-9);
      EXPECT_NEAR(q.max_angle, 60, 1e-9);
    }
  }
}

TEST(QualityReport, FandiskFigures)
{
  const Mesh fandisk = load_sample_mesh("fandisk");
  const PMP::Mesh_quality_report q = PMP::mesh_quality_report(fandisk);
  EXPECT_EQ(q.number_of_vertices, 6475u);
  EXPECT_EQ(q.number_of_faces, 12946u);
  EXPECT_NEAR(q.irregular_vertex_percentage, 19.83, 0.005);
  EXPECT_NEAR(q.mean_min_angle, 43.46, 0.005);
  EXPECT_NEAR(q.mean_max_angle, 85.98, 0.005);
  EXPECT_GT(q.min_angle, 0);
  EXPECT_LT(q.min_angle, q.mean_min_angle);
  EXPECT_GT(q.max_angle, q.mean_max_angle);
  EXPECT_LT(q.max_angle, 180);
}

TEST(QualityReport, RemovedButUncollectedElementsAreNotCounted)
{
  // isotropic_remeshing() leaves removed elements in a Surface_mesh; the report must see the mesh
  // as it is, the same as after collect_garbage().
  Mesh m = make_sphere(2);
  CGAL::Euler::remove_face(halfedge(*faces(m).begin(), m), m);
  CGAL::Euler::remove_face(halfedge(*std::next(faces(m).begin(), 7), m), m);
  ASSERT_TRUE(m.has_garbage());
  Mesh collected = m;
  collected.collect_garbage();
  const PMP::Mesh_quality_report q = PMP::mesh_quality_report(m), c = PMP::mesh_quality_report(collected);
  EXPECT_EQ(q.number_of_vertices, c.number_of_vertices);
  EXPECT_EQ(q.number_of_faces, c.number_of_faces);
  EXPECT_EQ(q.number_of_faces, num_faces(make_sphere(2)) - 2);
  EXPECT_DOUBLE_EQ(q.irregular_vertex_percentage, c.irregular_vertex_percentage);
  EXPECT_DOUBLE_EQ(q.mean_min_angle, c.mean_min_angle);
  EXPECT_DOUBLE_EQ(q.mean_max_angle, c.mean_max_angle);
}

TEST(SurfaceDistance, MeshToItselfIsZero)
{
  for(const Mesh& m : {load_sample_mesh("fandisk"), make_sphere(3), make_torus(30, 10, 1, 0.3)})
  {
    const PMP::Relative_surface_distance d =
      PMP::relative_surface_distance(m, m, CGAL::parameters::number_of_points_on_faces(20000));
    EXPECT_LT(d.hausdorff, 1e-12);
    EXPECT_LT(d.rms, 1e-12);
  }
}

TEST(SurfaceDistance, TranslatedSquareIsAtTheTranslationDistance)
{
  // Every point of the square z = 0 is exactly 1 above its copy at z = -1, and conversely.
  for(double side : {0.5, 2.0, 100.0})
  {
    const Mesh square = make_grid(5, 5, [side](std::size_t i, std::size_t j) {
      return Point(side * double(i) / 4, side * double(j) / 4, 0);
    });
    const Mesh moved = translated(square, Vector(0, 0, -1));
    const PMP::Relative_surface_distance d = PMP::relative_surface_distance(
      square, moved, CGAL::parameters::number_of_points_on_faces(5000));
    const double expected = 1.0 / (side * std::sqrt(2.0));
    EXPECT_NEAR(d.hausdorff, expected, 1e-12 * expected) << "side " << side;
    EXPECT_NEAR(d.rms, expected, 1e-12 * expected) << "side " << side;
  }
}

TEST(SurfaceDistance, TranslatedSphereIsNearTheTranslationDistance)
{
  // Two unit spheres a distance t apart are at Hausdorff distance t; the RMS is smaller.
  const Mesh sphere = make_sphere(5);
  const double diagonal = 2 * std::sqrt(3.0);
  for(double t : {0.01, 0.1, 0.5})
  {
    const Mesh moved = translated(sphere, Vector(t, 0, 0));
    const PMP::Relative_surface_distance d = PMP::relative_surface_distance(
      sphere, moved, CGAL::parameters::number_of_points_on_faces(50000));
    EXPECT_NEAR(d.hausdorff * diagonal, t, 0.02 * t) << "t = " << t;
    EXPECT_LT(d.rms, d.hausdorff);
    // For a unit sphere moved by t, the distance at polar angle a is about t|cos a|, whose RMS
    // over the sphere is t / sqrt(3).
    EXPECT_NEAR(d.rms * diagonal, t / std::sqrt(3.0), 0.03 * t) << "t = " << t;
  }
}

TEST(SurfaceDistance, SameSeedSameResult)
{
  const Mesh a = make_sphere(3);
  const Mesh b = translated(make_sphere(2), Vector(0.01, 0.02, 0));
  const auto np = CGAL::parameters::number_of_points_on_faces(10000).random_seed(7);
  const PMP::Relative_surface_distance d1 = PMP::relative_surface_distance(a, b, np);
  const PMP::Relative_surface_distance d2 = PMP::relative_surface_distance(a, b, np);
  EXPECT_EQ(d1.hausdorff, d2.hausdorff);
  EXPECT_EQ(d1.rms, d2.rms);
}

// fandisk against a CGAL isotropic remeshing of it: our figures against a Metro-style reference
// made of CGAL's own samplers with 300k samples a side.
TEST(SurfaceDistance, FandiskAgreesWithMetroStyleReference)
{
  const Mesh fandisk = load_sample_mesh("fandisk");
  Mesh remeshed = fandisk;
  {
    auto is_sharp = remeshed.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
    PMP::detect_sharp_edges(remeshed, 35.0, is_sharp);
    double length = 0;
    for(auto e : edges(remeshed))
      length += PMP::edge_length(e, remeshed);
    length /= double(num_edges(remeshed));
    PMP::isotropic_remeshing(faces(remeshed), length, remeshed,
                             CGAL::parameters::number_of_iterations(5).edge_is_constrained_map(is_sharp));
  }

  const PMP::Relative_surface_distance ours = PMP::relative_surface_distance(fandisk, remeshed);

  const std::size_t n = 300000;
  const auto sampling = CGAL::parameters::number_of_points_on_faces(n).random_seed(42);
  const double h12 = PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(fandisk, remeshed, sampling, CGAL::parameters::default_values());
  const double h21 = PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(remeshed, fandisk, sampling, CGAL::parameters::default_values());

  auto rms = [&](const Mesh& from, const Mesh& to) {
    std::vector<Point> samples;
    PMP::sample_triangle_mesh(from, std::back_inserter(samples),
                              CGAL::parameters::number_of_points_on_faces(n).random_seed(42)
                                .do_sample_vertices(false).do_sample_edges(false));
    using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
    CGAL::AABB_tree<Tree_traits<Kernel, Primitive> > tree(faces(to).first, faces(to).second, to);
    double sum = 0;
    for(const Point& p : samples)
      sum += tree.squared_distance(p);
    return std::sqrt(sum / double(samples.size()));
  };
  const CGAL::Bbox_3 box = PMP::bbox(fandisk);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  const double reference_hausdorff = (std::max)(h12, h21) / diagonal;
  const double reference_rms = (std::max)(rms(fandisk, remeshed), rms(remeshed, fandisk)) / diagonal;

  ASSERT_GT(reference_hausdorff, 0);
  ASSERT_GT(reference_rms, 0);
  EXPECT_NEAR(ours.hausdorff, reference_hausdorff, 0.2 * reference_hausdorff);
  EXPECT_NEAR(ours.rms, reference_rms, 0.2 * reference_rms);
  std::cout << "fandisk vs isotropic_remeshing: Hausdorff " << ours.hausdorff << " (reference "
            << reference_hausdorff << "), RMS " << ours.rms << " (reference " << reference_rms << ")\n";
}

namespace {

// A triangulated axis-aligned cube of side `side` centred at `center`: its twelve edges are the
// sharp ones (90 degrees), the face diagonals are flat.
Mesh make_cube(double side, const Point& center)
{
  const double h = side / 2;
  auto p = [&](double x, double y, double z) { return center + Vector(h * x, h * y, h * z); };
  Mesh cube;
  CGAL::make_hexahedron(p(-1, -1, -1), p(1, -1, -1), p(1, 1, -1), p(-1, 1, -1), p(-1, 1, 1), p(-1, -1, 1),
                        p(1, -1, 1), p(1, 1, 1), cube);
  PMP::triangulate_faces(cube);
  return cube;
}

} // namespace

TEST(SharpEdgeDistance, ScaledCubeIsAtTheEdgeOffset)
{
  // Scaling a cube by k about its centre moves each edge by (k - 1) side / 2 along both of its
  // faces' normals: the nearest edge of the scaled cube is that offset times sqrt(2) away from
  // every point of the original edge, and the diagonal is side * sqrt(3).
  // Each of the cube's edges is sampled 1e5 / sqrt(3) times: one comparison a scale.
  const std::pair<double, double> cases[] = {{0.5, 1.2}, {100.0, 1.01}};
  for(const auto& [side, k] : cases)
  {
    const Point center(1, -2, 3);
    const Mesh cube = make_cube(side, center);
    EXPECT_LT(PMP::relative_sharp_edge_distance(cube, cube, 45, 25), 1e-15) << "side " << side;
    const double expected = (k - 1) / 2 * std::sqrt(2.0) / std::sqrt(3.0);
    EXPECT_NEAR(PMP::relative_sharp_edge_distance(cube, make_cube(k * side, center), 45, 25), expected, 1e-12)
      << "side " << side << ", k " << k;
  }
}

TEST(SharpEdgeDistance, ThresholdsSelectTheEdges)
{
  const Mesh cube = make_cube(1, Point(0, 0, 0));
  const Mesh sphere = make_sphere(3, 0.5);
  // The cube's edges are at 90 degrees: none counts above 95.
  EXPECT_EQ(PMP::relative_sharp_edge_distance(cube, cube, 95, 25), 0);
  EXPECT_TRUE(std::isinf(PMP::relative_sharp_edge_distance(cube, cube, 45, 95)));
  // A finely sampled sphere has no sharp edge: the cube's edges are nowhere near one.
  EXPECT_TRUE(std::isinf(PMP::relative_sharp_edge_distance(cube, sphere, 45, 25)));
  EXPECT_EQ(PMP::relative_sharp_edge_distance(sphere, cube, 45, 25), 0);
}

