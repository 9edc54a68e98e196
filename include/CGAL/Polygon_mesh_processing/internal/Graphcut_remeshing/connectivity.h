// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Section 3: smooth local changes of the connectivity (edge flips, splits, collapses, then vertex
// splits), each kept only when it improves its own criterion, and the relaxation of the vertex
// positions. Sharp, border and constrained edges are never flipped or collapsed and no collapse
// or relaxation touches a vertex on one; a long sharp edge may be split at a point of its
// reference polyline. With a re-sampling sizing field, edges are split and collapsed to their
// target lengths first, also where the surface is curved and along feature lines; with a length
// asked for coarser than the input, the reference vertices farthest from the mesh then get
// vertices. This file keeps the order of a pass; each operation has its own file.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_CONNECTIVITY_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_CONNECTIVITY_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/coverings.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/edge_collapses.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/edge_flips.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/edge_splits.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/local_operations.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/relaxation.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/remeshing_options.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/smallest_angle_repair.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/vertex_splits.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

struct Connectivity_counts
{
  std::size_t flips = 0;
  std::size_t splits = 0;
  std::size_t collapses = 0;
  std::size_t vertex_splits = 0;
  std::size_t relaxed = 0;
};

// One pass of section 3 (connectivity_pass()) or the coverings alone (cover_what_stands_out()),
// each operation in its own file.
class Connectivity_optimizer
{
public:
  using Local_energy = Relaxation::Local_energy;

  // `polylines`, the reference's feature polylines, lets long sharp edges be split (none are
  // without it); `local_energy(v, x)`, the terms of eq. (1) that depend on the position x of v
  // (eq. 7), lets the relaxation keep only the moves that do not raise it; no operation touches
  // the vertices v with frozen[v], and with `bound` every operation keeps it (Local_operations).
  Connectivity_optimizer(Work_mesh& mesh, const Reference_surface<Work_mesh>& reference,
                         Tracking_state& state, const Sizing_field& sizing,
                         const Feature_polylines<Work_mesh>* polylines = nullptr,
                         Local_energy local_energy = Local_energy(),
                         Connectivity_operations operations = Connectivity_operations(),
                         const std::vector<char>& frozen = Local_operations::nothing_frozen(),
                         const Distance_bound* bound = nullptr)
    : m_local(mesh, reference, state, sizing, polylines, frozen, bound), m_local_energy(std::move(local_energy)),
      m_operations(operations), m_resamples(sizing.resamples()), m_covers_reference(sizing.covers_reference)
  {}

  // One pass of section 3: flips, splits, collapses, vertex splits, then relaxation. When the
  // sizing re-samples the surface, the splits and collapses bring every edge within the sizing's
  // bounds first, as CGAL's incremental remesher does, the reference's farthest vertices get
  // vertices when the length asked for is coarser than the input's, and the flips follow.
  Connectivity_counts connectivity_pass()
  {
    Connectivity_counts counts;
    const Connectivity_operations& op = m_operations;
    if(m_resamples)
    {
      counts.splits = op.split ? Edge_splits(m_local).run() : 0;
      counts.collapses = op.collapse ? Edge_collapses(m_local).run() : 0;
      if(m_covers_reference && op.split)
        counts.splits += Coverings(m_local).cover_reference();
      counts.flips = op.flip ? Edge_flips(m_local).run() : 0;
    }
    else
    {
      counts.flips = op.flip ? Edge_flips(m_local).run() : 0;
      counts.splits = op.split ? Edge_splits(m_local).run() : 0;
      counts.collapses = op.collapse ? Edge_collapses(m_local).run() : 0;
    }
    counts.vertex_splits = op.split ? Vertex_splits(m_local).run() : 0;
    for(std::size_t k = 0; k < op.relaxation_steps; ++k)
      counts.relaxed += Relaxation(m_local, m_local_energy).run();
    return counts;
  }

  // The coverings alone, once the relocation is over (Graphcut_remesher::run()): where the
  // reference still stands out from the mesh (cover_reference()) and the mesh from the reference
  // (cover_chords()).
  Connectivity_counts cover_what_stands_out()
  {
    Connectivity_counts counts;
    if(!m_operations.split)
      return counts;
    Coverings coverings(m_local);
    counts.splits = coverings.cover_reference();
    counts.splits += coverings.cover_chords();
    return counts;
  }

  // The triangles with the smallest angles, once the relocation is over (smallest_angle_repair.h):
  // its flips and collapses count as such, its moves as relaxed vertices.
  Connectivity_counts repair_smallest_angles()
  {
    const Connectivity_operations& op = m_operations;
    const Smallest_angle_repair::Counts repaired =
      Smallest_angle_repair(m_local, op.flip, op.collapse, op.relaxation_steps > 0).run();
    Connectivity_counts counts;
    counts.flips = repaired.flips;
    counts.collapses = repaired.collapses;
    counts.relaxed = repaired.moves;
    return counts;
  }

private:
  Local_operations m_local;
  Relaxation::Local_energy m_local_energy;
  Connectivity_operations m_operations;
  bool m_resamples;
  bool m_covers_reference;
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_CONNECTIVITY_H
