// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// User-constrained edges: the edges that detect_sharp_edges() finds are given to the remesher
// as an edge_is_constrained_map. They are never flipped, split or collapsed (their vertices may
// slide along them), and the map is updated when the connectivity changes. The remesher finds
// sharp edges by itself too (see sharp_angle_bounds) but may split them; an edge_is_constrained_map
// also keeps edges that are not sharp, such as the seams of a texture atlas.
//
// usage: graphcut_remeshing_constrained_edges_example [INPUT] [ANGLE_IN_DEGREES] [ITERATIONS]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/graphcut_isotropic_remeshing.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_report.h>

#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
typedef boost::graph_traits<Mesh>::edge_descriptor          edge_descriptor;

namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

std::size_t number_of_constrained_edges(const Mesh& mesh, const Mesh::Property_map<edge_descriptor, bool>& ecm)
{
  std::size_t n = 0;
  for(edge_descriptor e : edges(mesh))
    if(get(ecm, e))
      ++n;
  return n;
}

} // namespace

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : std::string(GRAPHCUT_REMESHING_DATA_DIR) + "/fandisk.off";
  const double angle = (argc > 2) ? std::stod(argv[2]) : 60.0;
  const std::size_t nb_iterations = (argc > 3) ? std::stoul(argv[3]) : 50;

  Mesh mesh;
  if(!PMP::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // An edge is constrained when its dihedral angle is sharper than `angle`.
  Mesh::Property_map<edge_descriptor, bool> is_constrained =
    mesh.add_property_map<edge_descriptor, bool>("e:is_constrained", false).first;
  PMP::detect_sharp_edges(mesh, angle, is_constrained);
  const std::size_t constrained_before = number_of_constrained_edges(mesh, is_constrained);

  const double mean_min_angle_before = PMP::mesh_quality_report(mesh).mean_min_angle;
  PMP::graphcut_isotropic_remeshing(mesh, CGAL::parameters::edge_is_constrained_map(is_constrained)
                                                           .number_of_iterations(nb_iterations));
  const double mean_min_angle_after = PMP::mesh_quality_report(mesh).mean_min_angle;

  // The property map lives in the mesh, which the remesher rebuilds element by element: it still
  // marks the same edges.
  const std::size_t constrained_after = number_of_constrained_edges(mesh, is_constrained);
  std::cout << "constrained edges (dihedral angle above " << angle << " degrees): " << constrained_before
            << " before, " << constrained_after << " after" << std::endl;
  std::cout << "mean min angle: " << mean_min_angle_before << " -> " << mean_min_angle_after << " degrees"
            << std::endl;

  return (constrained_after == constrained_before) ? EXIT_SUCCESS : EXIT_FAILURE;
}
