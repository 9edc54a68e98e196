// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the command-line tools share: reading and checking a mesh file, printing quality figures.

#ifndef CGAL_GRAPHCUT_REMESHING_TOOL_SUPPORT_H
#define CGAL_GRAPHCUT_REMESHING_TOOL_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_report.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace graphcut_remeshing_tools {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

// A refusal of the input: its message is the one line a tool prints before exiting with code 1.
struct Input_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// Reads a polygon mesh (OFF, OBJ, PLY, STL) and checks it has faces and finite coordinates.
// Faces may be polygons: `require_triangles` decides whether that is a refusal.
inline Mesh read_mesh(const std::string& path, bool require_triangles)
{
  if(!std::ifstream(path))
    throw Input_error(path + ": cannot open file");
  Mesh mesh;
  bool ok = false;
  try
  {
    ok = CGAL::IO::read_polygon_mesh(path, mesh);
  }
  catch(const std::exception&)
  {
    ok = false;
  }
  if(!ok)
    throw Input_error(path + ": not a readable polygon mesh (OFF, OBJ, PLY or STL expected)");
  if(num_faces(mesh) == 0)
    throw Input_error(path + ": the mesh has no faces");
  for(auto v : vertices(mesh))
  {
    const auto& p = mesh.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Input_error(path + ": vertex " + std::to_string(std::size_t(v)) +
                        " has a non-finite coordinate");
  }
  if(require_triangles && !CGAL::is_triangle_mesh(mesh))
    throw Input_error(path + ": not a triangle mesh (some faces have more than three sides)");
  return mesh;
}

inline std::string json_number(double x)
{
  std::ostringstream out;
  out << std::setprecision(10) << x;
  return out.str();
}

// The quality figures as a flat JSON object.
inline void write_json(std::ostream& out, const CGAL::Polygon_mesh_processing::Mesh_quality_report& q)
{
  out << "{\"vertices\": " << q.number_of_vertices
      << ", \"faces\": " << q.number_of_faces
      << ", \"irregular_percent\": " << json_number(q.irregular_vertex_percentage)
      << ", \"mean_min_angle\": " << json_number(q.mean_min_angle)
      << ", \"mean_max_angle\": " << json_number(q.mean_max_angle)
      << ", \"min_angle\": " << json_number(q.min_angle)
      << ", \"max_angle\": " << json_number(q.max_angle) << "}";
}

inline void write_json(std::ostream& out,
                       const CGAL::Polygon_mesh_processing::Relative_surface_distance& d)
{
  out << "{\"hausdorff\": " << json_number(d.hausdorff) << ", \"rms\": " << json_number(d.rms) << "}";
}

// A readable table: one column a mesh, then the distances (x 1e-3 of the first mesh's diagonal).
inline void write_table(std::ostream& out, const std::vector<std::string>& titles,
                        const std::vector<CGAL::Polygon_mesh_processing::Mesh_quality_report>& q,
                        const CGAL::Polygon_mesh_processing::Relative_surface_distance* d = nullptr)
{
  const int label = 26, column = 16;
  auto row = [&](const std::string& name, auto value_of) {
    out << std::left << std::setw(label) << name << std::right;
    for(const auto& r : q)
      out << std::setw(column) << value_of(r);
    out << '\n';
  };
  auto fixed = [](double x, int digits) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << x;
    return s.str();
  };
  out << std::left << std::setw(label) << "" << std::right;
  for(const auto& t : titles)
    out << std::setw(column) << (t.size() < std::size_t(column) ? t : t.substr(t.size() - column + 1));
  out << '\n';
  row("vertices", [](const auto& r) { return std::to_string(r.number_of_vertices); });
  row("faces", [](const auto& r) { return std::to_string(r.number_of_faces); });
  row("irregular vertices (%)", [&](const auto& r) { return fixed(r.irregular_vertex_percentage, 2); });
  row("mean min angle (deg)", [&](const auto& r) { return fixed(r.mean_min_angle, 2); });
  row("mean max angle (deg)", [&](const auto& r) { return fixed(r.mean_max_angle, 2); });
  row("min angle (deg)", [&](const auto& r) { return fixed(r.min_angle, 2); });
  row("max angle (deg)", [&](const auto& r) { return fixed(r.max_angle, 2); });
  if(d != nullptr)
  {
    out << std::left << std::setw(label) << "Hausdorff / diag (1e-3)" << std::right
        << std::setw(column * int(q.size())) << fixed(1e3 * d->hausdorff, 4) << '\n';
    out << std::left << std::setw(label) << "RMS / diag (1e-3)" << std::right
        << std::setw(column * int(q.size())) << fixed(1e3 * d->rms, 4) << '\n';
  }
}

} // namespace graphcut_remeshing_tools

#endif // CGAL_GRAPHCUT_REMESHING_TOOL_SUPPORT_H
