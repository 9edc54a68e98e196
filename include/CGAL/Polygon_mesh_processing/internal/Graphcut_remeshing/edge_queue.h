// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The queue that orders the edge operations of the connectivity stage (flips, splits, collapses)
// by their gain, best first, as the paper's section 3 does.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_EDGE_QUEUE_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_EDGE_QUEUE_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <algorithm>
#include <cstddef>
#include <queue>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// Applies the operations `plan_of` plans on the edges of `mesh`, best gain first. `plan_of(e)`
// returns a plan with its `gain` (non-positive: nothing to do) and what `apply(e, plan)` needs;
// it is called on every edge in parallel first, then again on the top entry just before `apply`
// (an operation may have changed the valence of a vertex opposite the edge): an entry is stale
// once its edge has been pushed again. `apply` returns the vertices whose edges are queued
// again, by `estimate(e)`, a bound on plan_of(e).gain that costs less: an edge touched by several
// operations is planned once, when it comes to the top. Returns the number of operations applied.
template <typename Plan_of, typename Apply, typename Estimate>
std::size_t run_edge_queue(Work_mesh& mesh, const Plan_of& plan_of, const Apply& apply, const Estimate& estimate)
{
  using Edge = Work_mesh::Edge_index;
  struct Entry
  {
    double gain;
    Edge e;
    std::size_t stamp;
    bool operator<(const Entry& other) const { return gain < other.gain || (gain == other.gain && other.e < e); }
  };
  std::vector<std::size_t> stamp(mesh.num_edges(), 0);
  std::priority_queue<Entry> queue;
  auto push_gain = [&](Edge e, double g) {
    if(stamp.size() <= std::size_t(e))
      stamp.resize(mesh.num_edges(), 0);
    ++stamp[std::size_t(e)];
    if(g > 0)
      queue.push(Entry{g, e, stamp[std::size_t(e)]});
  };
  {
    std::vector<double> first(mesh.num_edges(), 0);
    for_each_edge(mesh, [&](Edge e) { first[std::size_t(e)] = plan_of(e).gain; });
    for(Edge e : mesh.edges())
      push_gain(e, first[std::size_t(e)]);
  }
  // Every operation improves its criterion, but over a whole queue that is no proof of an end:
  // a bound on the number of operations is.
  const std::size_t budget = 4 * mesh.number_of_edges() + 16;
  std::size_t applied = 0;
  while(!queue.empty() && applied < budget)
  {
    const Entry top = queue.top();
    queue.pop();
    if(mesh.is_removed(top.e) || stamp[std::size_t(top.e)] != top.stamp)
      continue;
    const auto plan = plan_of(top.e);
    if(!(plan.gain > 0))
      continue;
    if(plan.gain < top.gain)
    {
      queue.push(Entry{plan.gain, top.e, top.stamp});
      continue;
    }
    const std::vector<Work_mesh::Vertex_index> touched = apply(top.e, plan);
    ++applied;
    std::vector<Edge> again;
    for(Work_mesh::Vertex_index u : touched)
      if(!mesh.is_removed(u))
        for(Work_mesh::Halfedge_index h : halfedges_around_target(mesh.halfedge(u), mesh))
          again.push_back(mesh.edge(h));
    std::sort(again.begin(), again.end());
    again.erase(std::unique(again.begin(), again.end()), again.end());
    for(Edge e : again)
      push_gain(e, estimate(e));
  }
  return applied;
}

// The same, the edges queued again by their plan's gain.
template <typename Plan_of, typename Apply>
std::size_t run_edge_queue(Work_mesh& mesh, const Plan_of& plan_of, const Apply& apply)
{
  return run_edge_queue(mesh, plan_of, apply, [&plan_of](Work_mesh::Edge_index e) { return plan_of(e).gain; });
}

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_EDGE_QUEUE_H
