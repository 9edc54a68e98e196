// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// mesh_quality [--json] [--samples N] [--seed N] ORIGINAL [REMESHED]
// mesh_quality --check ORIGINAL REMESHED
// Prints the quality figures of one mesh, or of two meshes and the distances between them; or
// checks that REMESHED keeps what graphcut_isotropic_remeshing promises about ORIGINAL.

#include "remeshing_check.h"
#include "tool_support.h"

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace tools = graphcut_remeshing_tools;

namespace {

const char* const usage =
  "usage: mesh_quality [--json] [--samples N] [--seed N] ORIGINAL [REMESHED]\n"
  "       mesh_quality --check ORIGINAL REMESHED\n"
  "\n"
  "Prints vertex and face counts, the percentage of irregular vertices, the mean per-face\n"
  "minimum and maximum angles and the extreme angles of ORIGINAL (and REMESHED). With two\n"
  "meshes it also prints the symmetric Hausdorff distance and the larger one-sided RMS\n"
  "distance, divided by ORIGINAL's bounding-box diagonal, from a Metro-style sampling, and\n"
  "how well REMESHED kept ORIGINAL's sharp lines: the largest distance from a point of an\n"
  "edge of ORIGINAL with a dihedral angle of 45 degrees or more to an edge of REMESHED with\n"
  "25 degrees or more, in the same unit (inf, null in JSON: REMESHED has no such edge).\n"
  "\n"
  "  --check       check that REMESHED, read as it was written, is a valid triangle mesh\n"
  "                without degenerate faces, with ORIGINAL's topology (Euler characteristic,\n"
  "                components, border cycles), no intersecting pair of triangles away from\n"
  "                ORIGINAL's own (both within the box of one of its intersecting pairs, grown\n"
  "                by its mean edge length), and ORIGINAL's corners at their exact\n"
  "                coordinates; prints one line for each broken promise and exits with 1\n"
  "                if there is one, prints \"ok\" otherwise\n"
  "  --json        print a JSON object instead of a table (distances as plain ratios)\n"
  "  --samples N   face samples per mesh for the distances (default 300000)\n"
  "  --seed N      seed of the sampling (default 0)\n"
  "  --help        print this help\n";

bool parse_unsigned(const std::string& text, unsigned long& value)
{
  if(text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
    return false;
  try { value = std::stoul(text); } catch(const std::exception&) { return false; }
  return true;
}

} // namespace

int main(int argc, char** argv)
{
  bool json = false, check = false;
  unsigned long samples = 300000, seed = 0;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(arg == "--help" || arg == "-h")
    {
      std::cout << usage;
      return EXIT_SUCCESS;
    }
    if(arg == "--json")
      json = true;
    else if(arg == "--check")
      check = true;
    else if(arg == "--samples" || arg == "--seed")
    {
      unsigned long& target = (arg == "--samples") ? samples : seed;
      if(i + 1 >= argc || !parse_unsigned(argv[i + 1], target))
      {
        std::cerr << "mesh_quality: " << arg << " needs a non-negative integer\n";
        return EXIT_FAILURE;
      }
      ++i;
    }
    else if(arg.size() > 1 && arg[0] == '-')
    {
      std::cerr << "mesh_quality: unknown option " << arg << " (see --help)\n";
      return EXIT_FAILURE;
    }
    else
      files.push_back(arg);
  }
  if(files.empty() || files.size() > 2)
  {
    std::cerr << "mesh_quality: expected ORIGINAL [REMESHED] (see --help)\n";
    return EXIT_FAILURE;
  }

  if(check && files.size() != 2)
  {
    std::cerr << "mesh_quality: --check expects ORIGINAL REMESHED (see --help)\n";
    return EXIT_FAILURE;
  }

  try
  {
    if(check)
    {
      std::vector<std::string> notices;
      const tools::Mesh original = tools::read_mesh(files[0], true, &notices);
      const std::vector<std::string> broken =
        tools::broken_promises(original, tools::read_mesh_as_written(files[1]));
      for(const std::string& b : broken)
        std::cout << files[1] << ": " << b << '\n';
      if(broken.empty())
        std::cout << "ok\n";
      return broken.empty() ? EXIT_SUCCESS : EXIT_FAILURE;
    }
    std::vector<tools::Mesh> meshes;
    std::vector<PMP::Mesh_quality_report> reports;
    std::vector<std::string> titles;
    for(const std::string& f : files)
    {
      std::vector<std::string> notices;
      meshes.push_back(tools::read_mesh(f, false, &notices));
      for(const std::string& n : notices)
        std::cerr << "mesh_quality: " << n << '\n';
      reports.push_back(PMP::mesh_quality_report(meshes.back()));
      titles.push_back(std::filesystem::path(f).filename().string());
    }

    PMP::Relative_surface_distance distance;
    double sharp_lines = 0;
    if(meshes.size() == 2)
    {
      distance = PMP::relative_surface_distance(
        meshes[0], meshes[1],
        CGAL::parameters::number_of_points_on_faces(std::size_t(samples))
                         .random_seed(static_cast<unsigned int>(seed)));
      // None to measure: n/a (null in the JSON), not a perfect 0.
      sharp_lines = PMP::internal::Graphcut_remeshing::sharp_edge_segments(meshes[0], get(CGAL::vertex_point, meshes[0]), 45).empty()
                      ? std::numeric_limits<double>::quiet_NaN()
                      : PMP::relative_sharp_edge_distance(meshes[0], meshes[1], 45, 25);
    }

    if(json)
    {
      if(meshes.size() == 1)
        tools::write_json(std::cout, reports[0]);
      else
      {
        std::cout << "{\"original\": ";
        tools::write_json(std::cout, reports[0]);
        std::cout << ", \"remeshed\": ";
        tools::write_json(std::cout, reports[1]);
        std::cout << ", \"distance\": ";
        tools::write_json(std::cout, distance);
        std::cout << ", \"sharp_lines\": " << tools::json_number(sharp_lines) << "}";
      }
      std::cout << std::endl;
    }
    else
      tools::write_table(std::cout, titles, reports, meshes.size() == 2 ? &distance : nullptr,
                         meshes.size() == 2 ? &sharp_lines : nullptr);
  }
  catch(const tools::Input_error& e)
  {
    std::cerr << "mesh_quality: " << e.what() << '\n';
    return EXIT_FAILURE;
  }
  catch(const std::exception& e)
  {
    std::cerr << "mesh_quality: error: " << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
