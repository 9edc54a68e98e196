// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL's named parameters and the package's in one call, chained by graphcut_parameters::combine(),
// and the statistics the remesher returns.
//
// usage: graphcut_remeshing_with_parameters_example [INPUT] [ITERATIONS]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/graphcut_isotropic_remeshing.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_report.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <utility>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;

namespace PMP = CGAL::Polygon_mesh_processing;
namespace GP = PMP::graphcut_parameters;

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : std::string(GRAPHCUT_REMESHING_DATA_DIR) + "/fandisk.off";
  const std::size_t nb_iterations = (argc > 2) ? std::stoul(argv[2]) : 50;

  Mesh mesh;
  if(!PMP::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input: " << filename << std::endl;
    return EXIT_FAILURE;
  }
  const double mean_min_angle_before = PMP::mesh_quality_report(mesh).mean_min_angle;

  // CGAL 5.5 cannot be taught new parameters: the package's own live in graphcut_parameters,
  // and combine() makes one pack of CGAL's and the package's.
  const PMP::Graphcut_remeshing_statistics stats = PMP::graphcut_isotropic_remeshing(
    mesh,
    GP::combine(CGAL::parameters::number_of_iterations(nb_iterations).random_seed(7),
                GP::number_of_greedy_iterations(10),
                GP::lambda_data(1e6),                      // a looser fit than the default 1e7
                GP::sharp_angle_bounds(std::make_pair(25.0, 40.0))));

  const PMP::Mesh_quality_report after = PMP::mesh_quality_report(mesh);
  std::cout << "iterations: " << stats.number_of_iterations << ", vertex moves: " << stats.number_of_moves
            << ", energy: " << stats.energies.front() << " -> " << stats.energies.back() << std::endl;
  std::cout << "connectivity passes: " << stats.connectivity_passes.size() << " (" << stats.number_of_flips
            << " flips, " << stats.number_of_splits << " splits, " << stats.number_of_collapses
            << " collapses, " << stats.number_of_vertex_splits << " vertex splits)" << std::endl;
  std::cout << "vertices: " << after.number_of_vertices << ", mean min angle: " << mean_min_angle_before
            << " -> " << after.mean_min_angle << " degrees" << std::endl;

  return (after.mean_min_angle > mean_min_angle_before) ? EXIT_SUCCESS : EXIT_FAILURE;
}
