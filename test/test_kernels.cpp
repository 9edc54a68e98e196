// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The remesher on the mesh types and kernels a CGAL user has at hand: Surface_mesh over
// Simple_cartesian<double> and over Exact_predicates_inexact_constructions_kernel, and
// Polyhedron_3 over the latter. The method works in doubles whatever the input, so the two
// Surface_mesh results must agree.

#include <CGAL/Polygon_mesh_processing/graphcut_isotropic_remeshing.h>
#include <CGAL/Polygon_mesh_processing/graphcut_remeshing_validation.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_report.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <string>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace GP = PMP::graphcut_parameters;

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Cartesian = CGAL::Simple_cartesian<double>;
using Epick_surface_mesh = CGAL::Surface_mesh<Epick::Point_3>;
using Cartesian_surface_mesh = CGAL::Surface_mesh<Cartesian::Point_3>;
using Epick_polyhedron = CGAL::Polyhedron_3<Epick>;

// Fandisk's mean minimum angle is 43.46 degrees; 20 + 5 iterations take it to 48.26 (measured for
// the three types alike). Asking for a gain of 3 degrees leaves room for changes of the method's
// schedule while still failing if the remesher does little on a mesh type.
const double required_angle_gain = 3.0;
// Both Surface_mesh types hand the remesher the same doubles in the same order, so the results
// are expected to be identical; the tolerance only allows for a last-bit difference in the quality
// report's arithmetic.
const double same_angle_tolerance = 1e-9;

struct Kernel_run
{
  PMP::Mesh_quality_report before;
  PMP::Mesh_quality_report after;
  long euler_before = 0;
  long euler_after = 0;
  bool valid = false;
  double seconds = 0;
};

template <typename Mesh>
long euler_characteristic(const Mesh& mesh)
{
  return long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
}

// Fandisk, read into `Mesh`, remeshed with 20 relocation and 5 greedy iterations.
template <typename Mesh>
Kernel_run remesh_fandisk(const std::string& name)
{
  Kernel_run run;
  Mesh mesh;
  const std::string path = std::string(GRAPHCUT_REMESHING_DATA_DIR) + "/fandisk.off";
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || num_faces(mesh) == 0)
  {
    ADD_FAILURE() << "cannot read " << path << " into " << name;
    return run;
  }
  run.before = PMP::mesh_quality_report(mesh);
  run.euler_before = euler_characteristic(mesh);

  const auto start = std::chrono::steady_clock::now();
  PMP::graphcut_isotropic_remeshing(mesh, GP::combine(CGAL::parameters::number_of_iterations(20).random_seed(0),
                                                      GP::number_of_greedy_iterations(5)));
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  run.valid = CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_triangle_mesh(mesh) &&
              PMP::validate_graphcut_remeshing_input(mesh).is_valid();
  run.after = PMP::mesh_quality_report(mesh);
  run.euler_after = euler_characteristic(mesh);
  std::cout.precision(10);
  std::cout << name << ": " << run.before.number_of_vertices << " -> " << run.after.number_of_vertices
            << " vertices, mean min angle " << run.before.mean_min_angle << " -> " << run.after.mean_min_angle
            << " degrees, Euler characteristic " << run.euler_before << " -> " << run.euler_after << ", "
            << run.seconds << " s" << std::endl;
  return run;
}

void expect_remeshed(const Kernel_run& run)
{
  EXPECT_TRUE(run.valid);
  EXPECT_EQ(run.euler_after, run.euler_before);
  EXPECT_GE(run.after.mean_min_angle, run.before.mean_min_angle + required_angle_gain);
  EXPECT_GT(run.after.min_angle, 0.0);
}

} // namespace

TEST(Kernels, SurfaceMeshOverSimpleCartesian)
{
  expect_remeshed(remesh_fandisk<Cartesian_surface_mesh>("Surface_mesh<Simple_cartesian<double>>"));
}

TEST(Kernels, SurfaceMeshOverEpick)
{
  expect_remeshed(remesh_fandisk<Epick_surface_mesh>("Surface_mesh<Epick>"));
}

TEST(Kernels, PolyhedronOverEpick)
{
  expect_remeshed(remesh_fandisk<Epick_polyhedron>("Polyhedron_3<Epick>"));
}

TEST(Kernels, SurfaceMeshResultDoesNotDependOnTheKernel)
{
  const Kernel_run cartesian = remesh_fandisk<Cartesian_surface_mesh>("Surface_mesh<Simple_cartesian<double>>");
  const Kernel_run epick = remesh_fandisk<Epick_surface_mesh>("Surface_mesh<Epick>");
  EXPECT_EQ(cartesian.after.number_of_vertices, epick.after.number_of_vertices);
  EXPECT_EQ(cartesian.after.number_of_faces, epick.after.number_of_faces);
  EXPECT_NEAR(cartesian.after.mean_min_angle, epick.after.mean_min_angle, same_angle_tolerance);
  EXPECT_NEAR(cartesian.after.mean_max_angle, epick.after.mean_max_angle, same_angle_tolerance);
}
