// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the command-line tools share: reading and checking a mesh file, printing quality figures.

#ifndef CGAL_GRAPHCUT_REMESHING_TOOL_SUPPORT_H
#define CGAL_GRAPHCUT_REMESHING_TOOL_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/graphcut_remeshing_validation.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_report.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/version.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include "declared_counts.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <iomanip>
#include <map>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace graphcut_remeshing_tools {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

// Reads a whole non-negative finite number from `text` into `value` (an integral T only when the
// number is whole); false otherwise.
template <typename T>
bool parse_number(const std::string& text, T& value)
{
  try
  {
    std::size_t used = 0;
    const double d = std::stod(text, &used);
    if(used != text.size() || !std::isfinite(d) || d < 0)
      return false;
    value = static_cast<T>(d);
    return double(value) == d || !std::is_integral<T>::value;
  }
  catch(const std::exception&)
  {
    return false;
  }
}

// The mean length of the edges of `mesh`: the target length the remeshers default to
// (num_edges() would also count the removed edges).
inline double mean_edge_length(const Mesh& mesh)
{
  double sum = 0;
  for(auto e : edges(mesh))
    sum += CGAL::Polygon_mesh_processing::edge_length(halfedge(e, mesh), mesh);
  return mesh.number_of_edges() == 0 ? 0 : sum / double(mesh.number_of_edges());
}

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

// The topology that remeshing keeps.
struct Topology
{
  long euler = 0;
  std::size_t components = 0;
  std::size_t border_cycles = 0;
  bool operator==(const Topology& t) const
  {
    return euler == t.euler && components == t.components && border_cycles == t.border_cycles;
  }
  std::string text() const
  {
    return "Euler characteristic " + std::to_string(euler) + ", " + std::to_string(components) + " components, " +
           std::to_string(border_cycles) + " border cycles";
  }
};

inline Topology topology(const Mesh& m)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  Topology t;
  t.euler = long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces());
  std::vector<std::size_t> component(m.number_of_faces() + m.number_of_removed_faces());
  t.components = PMP::connected_components(m, boost::make_iterator_property_map(component.begin(), get(boost::face_index, m)));
  std::vector<char> seen(m.number_of_halfedges() + m.number_of_removed_halfedges(), 0);
  for(Mesh::Halfedge_index h : halfedges(m))
    if(m.is_border(h) && !seen[std::size_t(h)])
    {
      ++t.border_cycles;
      for(Mesh::Halfedge_index g = h; !seen[std::size_t(g)]; g = m.next(g))
        seen[std::size_t(g)] = 1;
    }
  return t;
}

// The polygon soup of a file, refused when a count it declares cannot be (declared_counts.h),
// when CGAL cannot read it, when it has no faces, a point that is not finite or a face that refers
// to a point it does not have.
inline void read_soup(const std::string& path, std::vector<Kernel::Point_3>& points,
                      std::vector<std::vector<std::size_t> >& polygons)
{
  if(!std::ifstream(path))
    throw Input_error(path + ": cannot open file");
  const std::string impossible = impossible_declared_count(path);
  if(!impossible.empty())
    throw Input_error(path + ": " + impossible);
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
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const Kernel::Point_3& p = points[i];
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Input_error(path + ": vertex " + std::to_string(i) + " has a non-finite coordinate");
  }
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t v : polygons[f])
      if(v >= points.size())
        throw Input_error(path + ": face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                          ", but there are " + std::to_string(points.size()) + " vertices");
}

// How many polygons orient_polygon_soup() turned: `given` are the polygons before, over points
// that are all distinct (merged), and the copies it added after the first `distinct` points are
// copies of one of those.
inline std::size_t turned_polygons(const std::vector<Kernel::Point_3>& points, std::size_t distinct,
                                   const std::vector<std::vector<std::size_t> >& given,
                                   const std::vector<std::vector<std::size_t> >& oriented)
{
  std::map<Kernel::Point_3, std::size_t> original;
  for(std::size_t i = 0; i < distinct; ++i)
    original.emplace(points[i], i);
  std::size_t turned = 0;
  for(std::size_t f = 0; f < given.size() && f < oriented.size(); ++f)
  {
    std::vector<std::size_t> p = oriented[f];
    for(std::size_t& v : p)
      v = v < distinct ? v : original[points[v]];
    // The same cycle read backwards: turned.
    const std::vector<std::size_t>& q = given[f];
    const std::size_t n = q.size();
    const std::size_t j = std::size_t(std::find(q.begin(), q.end(), p.empty() ? 0 : p[0]) - q.begin());
    bool backwards = p.size() == n && n >= 3 && j < n;
    for(std::size_t i = 0; backwards && i < n; ++i)
      backwards = p[i] == q[(j + n - i) % n];
    turned += backwards ? 1 : 0;
  }
  return turned;
}

// The soup made a polygon mesh as CGAL::IO::read_polygon_mesh() makes it, each change told:
// repeated points merged, then repair_polygon_soup() (faces with repeated or too few points,
// repeated faces, points on no face), then orient_polygon_soup(), which orients the faces
// consistently and gives a non-manifold vertex or edge one copy per fan of faces.
template <typename Notice>
void repair_soup(const std::string& path, std::vector<Kernel::Point_3>& points,
                 std::vector<std::vector<std::size_t> >& polygons, const Notice& notice)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  const std::size_t merged = PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  if(merged > 0)
    notice(std::to_string(merged) + " repeated points merged");
  const std::size_t points_before = points.size(), polygons_before = polygons.size();
  PMP::repair_polygon_soup(points, polygons);
  if(polygons.size() != polygons_before)
    notice("repair_polygon_soup: " + std::to_string(polygons_before) + " faces made " + std::to_string(polygons.size()) +
           " (faces with repeated points or fewer than three, pinched or repeated faces)");
  if(points.size() != points_before)
    notice(std::to_string(points_before - points.size()) + " vertices on no face dropped");
  if(polygons.empty())
    throw Input_error(path + ": the mesh has no faces with three distinct points");
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
  {
    const std::size_t before = points.size();
    const std::vector<std::vector<std::size_t> > given = polygons;
    PMP::orient_polygon_soup(points, polygons);
    if(points.size() > before)
      notice(std::to_string(points.size() - before) +
             " vertices added to split non-manifold vertices and edges, one copy per fan of faces");
    const std::size_t turned = turned_polygons(points, before, given, polygons);
    if(turned > 0)
      notice(std::to_string(turned) + " faces reoriented consistently (orient_polygon_soup)");
    if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
      throw Input_error(path + ": orient_polygon_soup could not make the faces a polygon mesh");
  }
}

inline std::size_t count_degenerate_faces(const Mesh& mesh)
{
  std::size_t degenerate = 0;
  for(Mesh::Face_index f : faces(mesh))
    degenerate += CGAL::Polygon_mesh_processing::is_degenerate_triangle_face(f, mesh) ? 1 : 0;
  return degenerate;
}

// Whether `repaired` is a valid triangle mesh without degenerate faces and with `t`'s topology.
inline bool is_repair(Mesh& repaired, const Topology& t)
{
  repaired.collect_garbage();
  return !repaired.is_empty() && CGAL::is_valid_polygon_mesh(repaired) && CGAL::is_triangle_mesh(repaired) &&
         count_degenerate_faces(repaired) == 0 && topology(repaired) == t;
}

// Degenerate triangles repaired by CGAL where that keeps the topology: first by flipping the
// longest edge of those whose three points are distinct (a cap of 180 degrees: CGAL's
// remove_almost_degenerate_faces, with a threshold that only such caps reach), which keeps every
// point; else by remove_degenerate_faces, which collapses and removes. Otherwise the mesh is left
// as it is, for the validation to refuse.
template <typename Notice>
void repair_degenerate_faces(Mesh& mesh, const Notice& notice)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  const std::size_t degenerate = count_degenerate_faces(mesh);
  if(degenerate == 0)
    return;
  const Topology t = topology(mesh);
  const double cap_cosine = std::cos(179.9 * CGAL_PI / 180), no_needle = 1e300, no_collapse = 0;
  Mesh flipped = mesh;
#if CGAL_VERSION_NR < 1060000000
  PMP::experimental::remove_almost_degenerate_faces(flipped, cap_cosine, no_needle, no_collapse);
#else
  PMP::remove_almost_degenerate_faces(faces(flipped), flipped, CGAL::parameters::cap_threshold(cap_cosine)
                                                                 .needle_threshold(no_needle)
                                                                 .collapse_length_threshold(no_collapse));
#endif
  if(is_repair(flipped, t))
  {
    notice(std::to_string(degenerate) + " degenerate faces repaired by edge flips (remove_almost_degenerate_faces), "
           "the topology kept");
    mesh = std::move(flipped);
    return;
  }
  Mesh removed = mesh;
  if(PMP::remove_degenerate_faces(removed) && is_repair(removed, t))
  {
    notice(std::to_string(degenerate) + " degenerate faces removed (remove_degenerate_faces), the topology kept");
    mesh = std::move(removed);
  }
}

// Reads a polygon mesh (OFF, OBJ, PLY, STL) as CGAL::IO::read_polygon_mesh() does and checks it:
// every refusal is an Input_error whose message names the defect and where it is. The repairs
// are told in `notices`: those of read_polygon_mesh (repair_soup), faces with more than three
// sides triangulated (`triangulate`), degenerate faces removed where that keeps the topology.
// The mesh is then checked as graphcut_isotropic_remeshing() does.
inline Mesh read_mesh(const std::string& path, bool triangulate, std::vector<std::string>* notices = nullptr)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  auto notice = [&](const std::string& text) {
    if(notices != nullptr)
      notices->push_back(path + ": " + text);
  };
  std::vector<Kernel::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  read_soup(path, points, polygons);
  repair_soup(path, points, polygons, notice);
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
  repair_degenerate_faces(mesh, notice);
  const PMP::Graphcut_remeshing_input_validation validation = PMP::validate_graphcut_remeshing_input(mesh);
  if(!validation.is_valid())
    throw Input_error(path + ": " + validation.reason);
  return mesh;
}

// A mesh file read as it was written, without any repair: for checking what a tool wrote.
inline Mesh read_mesh_as_written(const std::string& path)
{
  std::vector<Kernel::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  read_soup(path, points, polygons);
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
    throw Input_error(path + ": not a polygon mesh as written (non-manifold, badly oriented or repeated points)");
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return mesh;
}

inline std::string json_number(double x)
{
  if(!std::isfinite(x))
    return "null"; // JSON has no infinity
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

// A readable table: one column a mesh, then the distances (x 1e-3 of the first mesh's diagonal),
// and the sharp lines' one when given.
inline void write_table(std::ostream& out, const std::vector<std::string>& titles,
                        const std::vector<CGAL::Polygon_mesh_processing::Mesh_quality_report>& q,
                        const CGAL::Polygon_mesh_processing::Relative_surface_distance* d = nullptr,
                        const double* sharp_lines = nullptr,
                        const std::vector<std::pair<std::string, std::string> >& settings = {})
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
    out << std::setw(column) << (t.size() < std::size_t(column) ? t : "..." + t.substr(t.size() - column + 4));
  out << '\n';
  row("vertices", [](const auto& r) { return std::to_string(r.number_of_vertices); });
  row("faces", [](const auto& r) { return std::to_string(r.number_of_faces); });
  row("irregular vertices (%)", [&](const auto& r) { return fixed(r.irregular_vertex_percentage, 2); });
  row("mean min angle (deg)", [&](const auto& r) { return fixed(r.mean_min_angle, 2); });
  row("mean max angle (deg)", [&](const auto& r) { return fixed(r.mean_max_angle, 2); });
  row("min angle (deg)", [&](const auto& r) { return fixed(r.min_angle, 2); });
  row("max angle (deg)", [&](const auto& r) { return fixed(r.max_angle, 2); });
  for(const auto& setting : settings)
    out << std::left << std::setw(label) << setting.first << std::right << std::setw(column * int(q.size()))
        << setting.second << '\n';
  if(d != nullptr)
  {
    out << std::left << std::setw(label) << "Hausdorff / diag (1e-3)" << std::right
        << std::setw(column * int(q.size())) << fixed(1e3 * d->hausdorff, 4) << '\n';
    out << std::left << std::setw(label) << "RMS / diag (1e-3)" << std::right
        << std::setw(column * int(q.size())) << fixed(1e3 * d->rms, 4) << '\n';
  }
  // NaN: the first mesh has no sharp line to measure.
  if(sharp_lines != nullptr)
    out << std::left << std::setw(label) << "sharp lines / diag (1e-3)" << std::right
        << std::setw(column * int(q.size())) << (std::isnan(*sharp_lines) ? "n/a" : fixed(1e3 * *sharp_lines, 4))
        << '\n';
}

} // namespace graphcut_remeshing_tools

#endif // CGAL_GRAPHCUT_REMESHING_TOOL_SUPPORT_H
