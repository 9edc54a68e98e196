// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the command-line tools share: reading and checking a mesh file, printing quality figures.

#ifndef CGAL_GRAPHCUT_REMESHING_TOOL_SUPPORT_H
#define CGAL_GRAPHCUT_REMESHING_TOOL_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/graphcut_remeshing_validation.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_report.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace graphcut_remeshing_tools {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

// A refusal of the input: its message is the one line a tool prints before exiting with code 1.
struct Input_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// Why CGAL's reader refused an OFF file, when the file says it plainly: a coordinate that is not
// a finite number, or a face that refers to a vertex the file does not have. Empty if neither.
inline std::string diagnose_off(const std::string& path)
{
  std::ifstream in(path);
  std::vector<std::string> tokens;
  std::string line;
  while(std::getline(in, line))
  {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::string w;
    while(words >> w)
      tokens.push_back(w);
  }
  if(tokens.size() < 4 || tokens[0] != "OFF")
    return std::string();
  std::size_t nv = 0, nf = 0;
  try
  {
    nv = std::stoul(tokens[1]);
    nf = std::stoul(tokens[2]);
  }
  catch(const std::exception&)
  {
    return std::string();
  }
  std::size_t k = 4;
  for(std::size_t v = 0; v < nv; ++v, k += 3)
  {
    if(k + 3 > tokens.size())
      return std::string();
    for(std::size_t c = 0; c < 3; ++c)
    {
      double x = 0;
      try
      {
        x = std::stod(tokens[k + c]);
      }
      catch(const std::exception&)
      {
        return "vertex " + std::to_string(v) + " has a coordinate that is not a number: " + tokens[k + c];
      }
      if(!std::isfinite(x))
        return "vertex " + std::to_string(v) + " has a non-finite coordinate";
    }
  }
  for(std::size_t f = 0; f < nf && k < tokens.size(); ++f)
  {
    std::size_t sides = 0;
    try
    {
      sides = std::stoul(tokens[k++]);
      for(std::size_t i = 0; i < sides && k < tokens.size(); ++i, ++k)
        if(std::stoul(tokens[k]) >= nv)
          return "face " + std::to_string(f) + " refers to vertex " + tokens[k] + ", but there are " +
                 std::to_string(nv) + " vertices";
    }
    catch(const std::exception&)
    {
      return std::string();
    }
  }
  return std::string();
}

// Reads a polygon mesh (OFF, OBJ, PLY, STL) as a polygon soup and checks it before making the
// mesh: every refusal is an Input_error whose message names the defect and where it is. Repairs
// that lose nothing are made and told in `notices`: faces with more than three sides are
// triangulated (`triangulate`), faces given with inconsistent orientations are reoriented, and
// points on no face are dropped. The mesh is then checked as graphcut_isotropic_remeshing() does.
inline Mesh read_mesh(const std::string& path, bool triangulate, std::vector<std::string>* notices = nullptr)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  auto notice = [&](const std::string& text) {
    if(notices != nullptr)
      notices->push_back(path + ": " + text);
  };
  if(!std::ifstream(path))
    throw Input_error(path + ": cannot open file");
  std::vector<Kernel::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  bool ok = false;
  try
  {
    ok = CGAL::IO::read_polygon_soup(path, points, polygons);
  }
  catch(const std::exception&)
  {
    ok = false;
  }
  if(!ok)
  {
    const std::string reason = diagnose_off(path);
    throw Input_error(path + ": " + (reason.empty() ? "not a readable polygon mesh (OFF, OBJ, PLY or STL expected)" : reason));
  }
  if(polygons.empty())
    throw Input_error(path + ": the mesh has no faces");
  // Here, not only in the validation below, so that vertices are numbered as in the file (points
  // on no face are dropped before the mesh is made).
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const Kernel::Point_3& p = points[i];
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Input_error(path + ": vertex " + std::to_string(i) + " has a non-finite coordinate");
  }
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    const std::vector<std::size_t>& polygon = polygons[f];
    if(polygon.size() < 3)
      throw Input_error(path + ": face " + std::to_string(f) + " has fewer than three vertices");
    for(std::size_t v : polygon)
      if(v >= points.size())
        throw Input_error(path + ": face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                          ", but there are " + std::to_string(points.size()) + " vertices");
    for(std::size_t a = 0; a < polygon.size(); ++a)
      for(std::size_t b = a + 1; b < polygon.size(); ++b)
        if(polygon[a] == polygon[b])
          throw Input_error(path + ": face " + std::to_string(f) + " repeats vertex " + std::to_string(polygon[a]));
  }
  // An edge of more than two faces cannot be in a halfedge structure.
  {
    std::vector<std::pair<std::pair<std::size_t, std::size_t>, std::size_t> > edges;
    for(std::size_t f = 0; f < polygons.size(); ++f)
      for(std::size_t a = 0; a < polygons[f].size(); ++a)
      {
        const std::size_t u = polygons[f][a], v = polygons[f][(a + 1) % polygons[f].size()];
        edges.push_back({{(std::min)(u, v), (std::max)(u, v)}, f});
      }
    std::sort(edges.begin(), edges.end());
    for(std::size_t k = 0; k + 2 < edges.size(); ++k)
      if(edges[k].first == edges[k + 2].first)
        throw Input_error(path + ": edge (" + std::to_string(edges[k].first.first) + ", " +
                          std::to_string(edges[k].first.second) + ") is non-manifold (on more than two faces)");
  }
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
  {
    // Orienting fails only where it must duplicate a vertex: a non-manifold vertex.
    std::vector<Kernel::Point_3> oriented_points = points;
    std::vector<std::vector<std::size_t> > oriented = polygons;
    if(!PMP::orient_polygon_soup(oriented_points, oriented) || oriented_points.size() != points.size())
      throw Input_error(path + ": the mesh has a non-manifold vertex (its faces form more than one fan)");
    polygons.swap(oriented);
    notice("faces reoriented consistently");
  }
  std::vector<char> used(points.size(), 0);
  for(const std::vector<std::size_t>& polygon : polygons)
    for(std::size_t v : polygon)
      used[v] = 1;
  const std::size_t unused = std::size_t(std::count(used.begin(), used.end(), 0));
  if(unused > 0)
  {
    std::vector<std::size_t> renumber(points.size());
    std::vector<Kernel::Point_3> kept;
    for(std::size_t i = 0; i < points.size(); ++i)
      if(used[i])
      {
        renumber[i] = kept.size();
        kept.push_back(points[i]);
      }
    for(std::vector<std::size_t>& polygon : polygons)
      for(std::size_t& v : polygon)
        v = renumber[v];
    points.swap(kept);
    notice(std::to_string(unused) + " vertices on no face dropped");
  }
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if(!CGAL::is_triangle_mesh(mesh))
  {
    if(!triangulate)
      throw Input_error(path + ": not a triangle mesh (some faces have more than three sides)");
    std::size_t polygons_split = 0;
    for(auto f : faces(mesh))
      polygons_split += CGAL::halfedges_around_face(halfedge(f, mesh), mesh).size() > 3 ? 1 : 0;
    if(!PMP::triangulate_faces(mesh))
      throw Input_error(path + ": a face with more than three sides could not be triangulated");
    notice(std::to_string(polygons_split) + " faces with more than three sides triangulated");
  }
  const PMP::Graphcut_remeshing_input_validation validation = PMP::validate_graphcut_remeshing_input(mesh);
  if(!validation.is_valid())
    throw Input_error(path + ": " + validation.reason);
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
