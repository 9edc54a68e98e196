// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A visitor follows the iterations and stops the run early by returning false; the mesh is then
// still a valid triangle mesh that can be remeshed again.
//
// usage: graphcut_remeshing_progress_example [INPUT] [STOP_AFTER_ITERATIONS]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/graphcut_isotropic_remeshing.h>
#include <CGAL/Polygon_mesh_processing/graphcut_remeshing_validation.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_report.h>
#include <CGAL/boost/graph/helpers.h>

#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;

namespace PMP = CGAL::Polygon_mesh_processing;
namespace GP = PMP::graphcut_parameters;

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : std::string(GRAPHCUT_REMESHING_DATA_DIR) + "/fandisk.off";
  const std::size_t stop_after = (argc > 2) ? std::stoul(argv[2]) : 10;

  Mesh mesh;
  if(!PMP::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input: " << filename << std::endl;
    return EXIT_FAILURE;
  }
  const double mean_min_angle_before = PMP::mesh_quality_report(mesh).mean_min_angle;

  // Called after each iteration; a GUI would update a progress bar here and return false when
  // the user presses "cancel".
  std::size_t done = 0;
  auto progress = [&done, stop_after](const PMP::Graphcut_remeshing_progress& p) {
    ++done;
    std::cout << (p.phase == PMP::Graphcut_remeshing_progress::RELOCATION ? "relocation" : "greedy fitting")
              << " iteration " << p.iteration << "/" << p.number_of_iterations << ", energy " << p.energy
              << std::endl;
    return done < stop_after;
  };

  const PMP::Graphcut_remeshing_statistics stats = PMP::graphcut_isotropic_remeshing(mesh, GP::visitor(progress));

  // Stopped between two iterations: a valid triangle mesh, without the defects the remesher refuses.
  const bool valid = CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_triangle_mesh(mesh) &&
                     PMP::validate_graphcut_remeshing_input(mesh).is_valid();
  std::cout << (stats.cancelled ? "cancelled" : "finished") << " after " << stats.number_of_iterations
            << " iterations; mean min angle " << mean_min_angle_before << " -> "
            << PMP::mesh_quality_report(mesh).mean_min_angle << " degrees; the mesh is "
            << (valid ? "valid" : "NOT valid") << std::endl;

  return valid ? EXIT_SUCCESS : EXIT_FAILURE;
}
