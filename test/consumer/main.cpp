// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The consumer of the installed package: remeshes a jittered icosphere built here, as a
// Surface_mesh and as a Polyhedron_3, once with the defaults and once with CGAL's named parameters
// (and one of the package's), and checks the figures. Exit code 0 when every check holds.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/graphcut_isotropic_remeshing.h>
#include <CGAL/Polygon_mesh_processing/graphcut_remeshing_validation.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_report.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3                                          Point;
typedef CGAL::Surface_mesh<Point>                           Surface_mesh;
typedef CGAL::Polyhedron_3<K>                               Polyhedron;
typedef std::array<std::size_t, 3>                          Triangle;

namespace PMP = CGAL::Polygon_mesh_processing;
namespace GP = PMP::graphcut_parameters;

namespace {

// An icosahedron split in four three times (642 vertices) whose vertices are moved at random by up
// to 0.05 along each axis (edges are 0.11 to 0.15 long) and put back on the unit sphere: uneven
// triangles, none turned over.
void jittered_icosphere(std::vector<Point>& points, std::vector<Triangle>& triangles)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2;
  std::vector<std::array<double, 3> > p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                           {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                           {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<Triangle> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                             {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                             {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                             {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for(int level = 0; level < 3; ++level)
  {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> middle_of;
    auto middle = [&](std::size_t a, std::size_t b) {
      const std::pair<std::size_t, std::size_t> key((std::min)(a, b), (std::max)(a, b));
      const auto found = middle_of.find(key);
      if(found != middle_of.end())
        return found->second;
      p.push_back({{(p[a][0] + p[b][0]) / 2, (p[a][1] + p[b][1]) / 2, (p[a][2] + p[b][2]) / 2}});
      middle_of.emplace(key, p.size() - 1);
      return p.size() - 1;
    };
    std::vector<Triangle> g;
    for(const Triangle& tri : f)
    {
      const std::size_t ab = middle(tri[0], tri[1]), bc = middle(tri[1], tri[2]), ca = middle(tri[2], tri[0]);
      g.push_back({{tri[0], ab, ca}});
      g.push_back({{tri[1], bc, ab}});
      g.push_back({{tri[2], ca, bc}});
      g.push_back({{ab, bc, ca}});
    }
    f.swap(g);
  }
  CGAL::Random random(5);
  points.clear();
  for(const std::array<double, 3>& q : p)
  {
    const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    const double x = q[0] / norm + 0.05 * random.get_double(-1, 1);
    const double y = q[1] / norm + 0.05 * random.get_double(-1, 1);
    const double z = q[2] / norm + 0.05 * random.get_double(-1, 1);
    const double r = std::sqrt(x * x + y * y + z * z);
    points.emplace_back(x / r, y / r, z / r);
  }
  triangles = f;
}

template <typename Mesh>
long euler_characteristic(const Mesh& mesh)
{
  return long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
}

// Remeshes the sphere as a `Mesh`, with the defaults or with named parameters, and checks it.
template <typename Mesh>
bool remesh_and_check(const std::string& name, bool with_named_parameters, double required_angle_gain)
{
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  jittered_icosphere(points, triangles);
  for(const Triangle& tri : triangles)
    if(CGAL::scalar_product(CGAL::normal(points[tri[0]], points[tri[1]], points[tri[2]]),
                            CGAL::centroid(points[tri[0]], points[tri[1]], points[tri[2]]) - CGAL::ORIGIN) <= 0)
    {
      std::cerr << name << ": the jittered sphere has a triangle turned inwards" << std::endl;
      return false;
    }
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);

  const PMP::Mesh_quality_report before = PMP::mesh_quality_report(mesh);
  const auto start = std::chrono::steady_clock::now();
  PMP::Graphcut_remeshing_statistics stats;
  if(with_named_parameters)
    stats = PMP::graphcut_isotropic_remeshing(mesh, GP::combine(CGAL::parameters::number_of_iterations(5).random_seed(1),
                                                                GP::number_of_greedy_iterations(5)));
  else
    stats = PMP::graphcut_isotropic_remeshing(mesh);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const PMP::Mesh_quality_report after = PMP::mesh_quality_report(mesh);

  std::cout << name << (with_named_parameters ? ", 5 + 5 iterations: " : ", defaults: ") << before.number_of_vertices
            << " -> " << after.number_of_vertices << " vertices, mean min angle " << before.mean_min_angle << " -> "
            << after.mean_min_angle << " degrees, " << stats.number_of_iterations << " iterations, " << seconds
            << " s" << std::endl;

  bool ok = true;
  auto check = [&](bool condition, const char* what) {
    if(!condition)
    {
      std::cout << name << ": FAILED: " << what << std::endl;
      ok = false;
    }
  };
  check(CGAL::is_valid_polygon_mesh(mesh), "a valid polygon mesh");
  check(CGAL::is_triangle_mesh(mesh), "a triangle mesh");
  check(CGAL::is_closed(mesh), "closed");
  check(PMP::validate_graphcut_remeshing_input(mesh).is_valid(), "no degenerate triangle or non-manifold vertex");
  check(euler_characteristic(mesh) == 2, "the sphere's Euler characteristic");
  check(after.mean_min_angle >= before.mean_min_angle + required_angle_gain, "the mean minimum angle rises enough");
  check(stats.number_of_iterations == (with_named_parameters ? 10u : 85u), "the number of iterations asked for");
  return ok;
}

} // namespace

int main()
{
  // Measured from the sphere's 40.93 degrees: 44.83 with the defaults, 44.19 after 5 + 5
  // iterations. The bar, a gain of 2 degrees, leaves room for changes of the method's schedule.
  const double required_angle_gain = 2.0;
  bool ok = true;
  ok = remesh_and_check<Surface_mesh>("Surface_mesh", false, required_angle_gain) && ok;
  ok = remesh_and_check<Surface_mesh>("Surface_mesh", true, required_angle_gain) && ok;
  ok = remesh_and_check<Polyhedron>("Polyhedron_3", false, required_angle_gain) && ok;
  ok = remesh_and_check<Polyhedron>("Polyhedron_3", true, required_angle_gain) && ok;
  std::cout << (ok ? "all checks passed" : "some checks FAILED") << std::endl;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
