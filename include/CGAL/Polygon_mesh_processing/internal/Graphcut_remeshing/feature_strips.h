// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The strips between feature lines: how wide the surface is, at each vertex, between the two
// nearest lines of sharp edges that face each other across it. A gear's tooth flank or a fillet
// cut into strips is narrower than the target length, and the count-matched sizing field
// (sizing.h) counts its vertices from that.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_FEATURE_STRIPS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_FEATURE_STRIPS_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/features.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// The lines of sharp edges of a mesh, as walk_sharp_line() follows them: feature edges meeting at
// a vertex that has exactly two of them (a line passing through) are on one line; lines part at
// corners and ends, the vertices with another number of feature edges, which are the lines' ends.
struct Feature_lines
{
  static constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

  Feature_lines(const Work_mesh& m, const std::vector<char>& feature_edge) : label(m.num_edges(), none)
  {
    std::vector<int> feature_degree(m.num_vertices(), 0);
    for(Work_mesh::Edge_index e : m.edges())
      if(feature_edge[std::size_t(e)])
        for(Work_mesh::Vertex_index v : {m.vertex(e, 0), m.vertex(e, 1)})
          ++feature_degree[std::size_t(v)];
    const auto degree = [&](Work_mesh::Vertex_index v) { return feature_degree[std::size_t(v)]; };
    for_each_sharp_line(m, feature_edge, degree, [&](const Sharp_line<Work_mesh>& line) {
      std::array<std::size_t, 2> line_ends{{none, none}};
      const Work_mesh::Vertex_index first = m.source(line.halfedges.front()), last = m.target(line.halfedges.back());
      if(degree(first) != 2)
        line_ends = {{std::size_t(first), std::size_t(last)}}; // an open line
      for(Work_mesh::Halfedge_index h : line.halfedges)
        label[std::size_t(m.edge(h))] = ends.size();
      ends.push_back(line_ends);
    });
  }

  // Whether lines a and b end at one vertex: two sides of a corner, not two sides of a strip.
  bool share_an_end(std::size_t a, std::size_t b) const
  {
    for(std::size_t x : ends[a])
      for(std::size_t y : ends[b])
        if(x != none && x == y)
          return true;
    return false;
  }

  std::vector<std::size_t> label;                // of each feature edge, `none` for the others
  std::vector<std::array<std::size_t, 2> > ends; // of each line, by label: vertices
};

// At each vertex of m, the distances along its edges to the nearest two feature lines that bound
// the strip it lies on, summed: the strip's width (infinite where there is no such pair). A
// multi-source Dijkstra from all the lines at once, in which the vertices of a line pass on only
// that line, so that the distances are measured within a strip, not across its lines. A vertex
// takes its nearest line, then the lines that share an end with it (near a corner, its sides are
// the nearest lines, and they make no strip), until one does not: that one bounds the strip on
// the other side. The width is the smallest sum of the distances to two of its lines that do not
// share an end.
inline std::vector<double> feature_strip_widths(const Work_mesh& m, const std::vector<char>& feature_edge)
{
  using Vertex = Work_mesh::Vertex_index;
  constexpr int carried = 6; // lines a vertex takes at most
  const Feature_lines lines(m, feature_edge);
  using Entry = std::tuple<double, std::size_t, std::size_t>; // distance, vertex, line
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
  std::vector<char> on_a_line(m.num_vertices(), 0);
  for(Work_mesh::Edge_index e : m.edges())
    if(feature_edge[std::size_t(e)])
      for(Vertex v : {m.vertex(e, 0), m.vertex(e, 1)})
      {
        queue.emplace(0., std::size_t(v), lines.label[std::size_t(e)]);
        on_a_line[std::size_t(v)] = 1;
      }
  struct Nearest { std::array<double, carried> distance; std::array<std::size_t, carried> line; int count = 0; bool bounded = false; };
  std::vector<Nearest> nearest(m.num_vertices());
  auto takes = [&](std::size_t v, std::size_t line) {
    const Nearest& n = nearest[v];
    return !n.bounded && n.count < carried &&
           std::find(n.line.begin(), n.line.begin() + n.count, line) == n.line.begin() + n.count;
  };
  while(!queue.empty())
  {
    const auto [d, v, line] = queue.top();
    queue.pop();
    if(!takes(v, line))
      continue;
    Nearest& n = nearest[v];
    n.bounded = n.count > 0 && !lines.share_an_end(n.line[0], line);
    n.distance[std::size_t(n.count)] = d;
    n.line[std::size_t(n.count++)] = line;
    if(on_a_line[v] && d > 0) // a line other than its own
      continue;
    const Vertex vv(static_cast<Work_mesh::size_type>(v));
    for(Vertex w : vertices_around_target(m.halfedge(vv), m))
      if(takes(std::size_t(w), line))
        queue.emplace(d + (to_vector(m.point(vv)) - to_vector(m.point(w))).norm(), std::size_t(w), line);
  }
  std::vector<double> width(m.num_vertices(), std::numeric_limits<double>::infinity());
  for(std::size_t v = 0; v < width.size(); ++v)
    for(int i = 0; i < nearest[v].count; ++i)
      for(int j = i + 1; j < nearest[v].count; ++j)
        if(!lines.share_an_end(nearest[v].line[std::size_t(i)], nearest[v].line[std::size_t(j)]))
          width[v] = (std::min)(width[v], nearest[v].distance[std::size_t(i)] + nearest[v].distance[std::size_t(j)]);
  return width;
}

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_FEATURE_STRIPS_H
