// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The call shaped as CGAL's isotropic_remeshing(faces, target_edge_length, mesh, np): the faces on
// one side of the mesh's centroid are re-sampled to edges of about a given multiple of the mean
// edge length; the other faces, and the seam between both, stay exactly as they were.
//
// usage: graphcut_remeshing_with_target_length_example [INPUT] [LENGTH_FACTOR] [ITERATIONS]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/graphcut_isotropic_remeshing.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
typedef boost::graph_traits<Mesh>::face_descriptor          face_descriptor;

namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : std::string(GRAPHCUT_REMESHING_DATA_DIR) + "/fandisk.off";
  const double factor = (argc > 2) ? std::stod(argv[2]) : 2.0;
  const std::size_t nb_iterations = (argc > 3) ? std::stoul(argv[3]) : 150;

  Mesh mesh;
  if(!PMP::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  double total_length = 0, mean_x = 0;
  for(Mesh::Edge_index e : edges(mesh))
    total_length += PMP::edge_length(e, mesh);
  for(Mesh::Vertex_index v : vertices(mesh))
    mean_x += mesh.point(v).x();
  const double target_edge_length = factor * total_length / double(num_edges(mesh));
  mean_x /= double(num_vertices(mesh));

  // The faces whose centroid lies on the low-x side.
  std::vector<face_descriptor> region;
  for(face_descriptor f : faces(mesh))
  {
    const Mesh::Halfedge_index h = mesh.halfedge(f);
    const K::Point_3 c = CGAL::centroid(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                                        mesh.point(mesh.target(mesh.next(h))));
    if(c.x() < mean_x)
      region.push_back(f);
  }

  const std::size_t faces_before = mesh.number_of_faces();
  PMP::graphcut_isotropic_remeshing(region, target_edge_length, mesh,
                                    CGAL::parameters::number_of_iterations(nb_iterations));
  mesh.collect_garbage();

  std::cout << region.size() << " of " << faces_before << " faces remeshed to edges of about "
            << target_edge_length << ": " << mesh.number_of_faces() << " faces now" << std::endl;
  if(!CGAL::IO::write_polygon_mesh("remeshed_region.off", mesh, CGAL::parameters::stream_precision(17)))
    return EXIT_FAILURE;
  return CGAL::is_valid_polygon_mesh(mesh) ? EXIT_SUCCESS : EXIT_FAILURE;
}
