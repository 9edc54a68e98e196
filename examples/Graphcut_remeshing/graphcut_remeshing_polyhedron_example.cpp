// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Remeshes a CGAL::Polyhedron_3: any triangle mesh that models the BGL graph concepts can be
// given to graphcut_isotropic_remeshing.
//
// usage: graphcut_remeshing_polyhedron_example [INPUT] [ITERATIONS]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/graphcut_isotropic_remeshing.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_report.h>
#include <CGAL/boost/graph/helpers.h>

#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Polyhedron_3<K>                               Polyhedron;

namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char* argv[])
{
  // The sample mesh CMake extracted into the build tree, or the file given.
  const std::string filename = (argc > 1) ? argv[1] : std::string(GRAPHCUT_REMESHING_DATA_DIR) + "/fandisk.off";
  const std::size_t nb_iterations = (argc > 2) ? std::stoul(argv[2]) : 50;

  Polyhedron poly;
  if(!PMP::IO::read_polygon_mesh(filename, poly) || !CGAL::is_triangle_mesh(poly))
  {
    std::cerr << "Invalid input: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  const PMP::Mesh_quality_report before = PMP::mesh_quality_report(poly);
  PMP::graphcut_isotropic_remeshing(poly, CGAL::parameters::number_of_iterations(nb_iterations));
  const PMP::Mesh_quality_report after = PMP::mesh_quality_report(poly);

  std::cout << "Polyhedron_3: " << before.number_of_vertices << " -> " << after.number_of_vertices
            << " vertices, mean min angle " << before.mean_min_angle << " -> " << after.mean_min_angle
            << " degrees" << std::endl;

  if(!CGAL::is_valid_polygon_mesh(poly) || !CGAL::is_triangle_mesh(poly))
  {
    std::cerr << "The remeshed polyhedron is not a valid triangle mesh." << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
