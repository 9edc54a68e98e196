// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What graphcut_isotropic_remeshing promises about its output, checked from outside on the input
// and the output alone: a valid triangle mesh without degenerate triangles, the input's topology,
// no intersecting pair of triangles away from the input's own, and the input's corners at their
// exact coordinates. `mesh_quality --check` and the tests use it. (For a call on a range of faces the
// library takes the zones of intersections from the range alone; these are the whole mesh's.)

#ifndef CGAL_GRAPHCUT_REMESHING_REMESHING_CHECK_H
#define CGAL_GRAPHCUT_REMESHING_REMESHING_CHECK_H

#include "tool_support.h"

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/remeshing_options.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace graphcut_remeshing_tools {

// The dihedral angle at the edge of `h`, in degrees (0 where flat); `h` is not on the border.
inline double dihedral_degrees(const Mesh& m, Mesh::Halfedge_index h)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  const Kernel::Vector_3 a = PMP::compute_face_normal(m.face(h), m), b = PMP::compute_face_normal(m.face(m.opposite(h)), m);
  return std::acos((std::max)(-1.0, (std::min)(1.0, a * b))) * 180 / CGAL_PI;
}

// One degree above the largest default upper bound of the sharp-edge hysteresis (both modes), so
// that rounding cannot decide.
inline double sure_corner_angle()
{
  const CGAL::Polygon_mesh_processing::internal::Graphcut_remeshing::Remeshing_options defaults;
  return (std::max)(defaults.sharp_angle_bounds.second, defaults.paper_sharp_angle_bounds.second) + 1;
}

// The vertices that may never move, found without the library's own classification: three or
// more edges that are border edges or clearly sharp (dihedral angle above sure_corner_angle()), or
// a border that turns by more than that.
inline std::vector<Kernel::Point_3> sure_corners(const Mesh& m)
{
  const double sure = sure_corner_angle();
  std::vector<Kernel::Point_3> corners;
  for(Mesh::Vertex_index v : vertices(m))
  {
    int features = 0;
    double turn = 0;
    for(Mesh::Halfedge_index h : CGAL::halfedges_around_target(v, m))
    {
      if(m.is_border(m.edge(h)) || dihedral_degrees(m, h) > sure)
        ++features;
      if(m.is_border(h))
      {
        const Kernel::Vector_3 in = m.point(v) - m.point(m.source(h)), out = m.point(m.target(m.next(h))) - m.point(v);
        const double c = in * out / std::sqrt(in.squared_length() * out.squared_length());
        turn = std::acos((std::max)(-1.0, (std::min)(1.0, c))) * 180 / CGAL_PI;
      }
    }
    if(features >= 3 || turn > sure)
      corners.push_back(m.point(v));
  }
  return corners;
}

// How many of `points` are not exactly the point of a vertex of `m`.
inline std::size_t missing_points(const std::vector<Kernel::Point_3>& points, const Mesh& m)
{
  std::set<std::array<double, 3> > present;
  for(Mesh::Vertex_index v : vertices(m))
    present.insert({{m.point(v).x(), m.point(v).y(), m.point(v).z()}});
  std::size_t missing = 0;
  for(const Kernel::Point_3& p : points)
    missing += present.count({{p.x(), p.y(), p.z()}}) == 0 ? 1 : 0;
  return missing;
}

// The input's intersecting pairs of triangles, each as the box of its two triangles grown by the
// input's mean edge length: where the remesher lets intersections stay (1 % more, for the rounding
// of the unit box it works in).
inline std::vector<CGAL::Bbox_3> intersection_zones(const Mesh& input)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index> > pairs;
  PMP::self_intersections(input, std::back_inserter(pairs));
  const double r = 1.01 * mean_edge_length(input);
  std::vector<CGAL::Bbox_3> zones;
  for(const auto& p : pairs)
  {
    const CGAL::Bbox_3 b = PMP::face_bbox(p.first, input) + PMP::face_bbox(p.second, input);
    zones.emplace_back(b.xmin() - r, b.ymin() - r, b.zmin() - r, b.xmax() + r, b.ymax() + r, b.zmax() + r);
  }
  return zones;
}

// The intersecting pairs of triangles of `output` away from the input's: not both in one zone.
inline std::size_t new_intersecting_pairs(const Mesh& input, const Mesh& output)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  const std::vector<CGAL::Bbox_3> zones = intersection_zones(input);
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index> > pairs;
  PMP::self_intersections(output, std::back_inserter(pairs));
  std::size_t n = 0;
  for(const auto& p : pairs)
  {
    const CGAL::Bbox_3 a = PMP::face_bbox(p.first, output), b = PMP::face_bbox(p.second, output);
    n += std::none_of(zones.begin(), zones.end(),
                      [&](const CGAL::Bbox_3& z) { return CGAL::do_overlap(z, a) && CGAL::do_overlap(z, b); });
  }
  return n;
}

// One line for each promise `output` breaks as the remesh of `input`; empty if it keeps them all.
// `fixed` are points that must be kept too (constrained vertices).
inline std::vector<std::string> broken_promises(const Mesh& input, const Mesh& output,
                                                const std::vector<Kernel::Point_3>& fixed = {})
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<std::string> broken;
  const PMP::Graphcut_remeshing_input_validation validation = PMP::validate_graphcut_remeshing_input(output);
  if(!validation.is_valid())
  {
    broken.push_back("not a valid remesh: " + validation.reason);
    return broken; // the other checks assume a valid triangle mesh
  }
  const Topology a = topology(input), b = topology(output);
  if(!(a == b))
    broken.push_back("topology changed: " + a.text() + " in the input, " + b.text() + " in the output");
  const std::size_t fresh = new_intersecting_pairs(input, output);
  if(fresh > 0)
    broken.push_back(std::to_string(fresh) + " intersecting pairs of triangles away from the input's");
  const std::vector<Kernel::Point_3> corners = sure_corners(input);
  const std::size_t moved = missing_points(corners, output);
  if(moved > 0)
    broken.push_back(std::to_string(moved) + " of the input's " + std::to_string(corners.size()) + " corners moved");
  const std::size_t fixed_moved = missing_points(fixed, output);
  if(fixed_moved > 0)
    broken.push_back(std::to_string(fixed_moved) + " of " + std::to_string(fixed.size()) + " fixed points moved");
  return broken;
}

} // namespace graphcut_remeshing_tools

#endif // CGAL_GRAPHCUT_REMESHING_REMESHING_CHECK_H
