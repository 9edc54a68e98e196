// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The driver: the paper's Algorithm 1, run twice (section 4.1), on a working copy of the mesh
// scaled into the unit box, the input kept as the reference surface.
//
//   for each phase (relocation: T(i) = T(1) K^(i-1); greedy fitting: along the gradient)
//     for i = 1 .. number of iterations of the phase
//       track the closest reference vertex y_s0 of every vertex          (tracking.h)
//       give every vertex a candidate that lowers its local evidence     (candidates.h)
//       decide by one minimum s-t cut which vertices take their candidate (relocation_cut.h)
//       if the choice makes triangles intersect, keep their vertices and decide again
//       in the first phase, every connectivity_period iterations:
//         flips, splits, collapses, vertices where the reference is far,
//         vertex splits, relaxation            (connectivity.h, one file per operation)
//   with a length coarser than the input's, twice: vertices where the reference stands out
//   from the mesh, and where the mesh's edges stand out from the reference    (coverings.h)
//   re-sampling at the input's density, the triangles with the smallest angles (smallest_angle_repair.h)
//
// The energy of eq. (1) is in energy.h, the reference surface and its frames in
// reference_surface.h, the feature lines in features.h, the target edge length in sizing.h, the
// parameters and their defaults in remeshing_options.h.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_REMESHER_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_REMESHER_H

#include <CGAL/Polygon_mesh_processing/graphcut_remeshing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/candidates.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/connectivity.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/distance_bound.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/energy.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/features.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/guarantees.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/intersections.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/parallel.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/reference_surface.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/relocation_cut.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/remeshing_options.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/sizing.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/surface_distance.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/tracking.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Random.h>

#include <algorithm>
#include <array>
#ifdef CGAL_GRAPHCUT_REMESHING_VERBOSE
#include <iostream>
#include <limits>
#endif
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

class Graphcut_remesher
{
  using Vertex = Work_mesh::Vertex_index;
  using Halfedge = Work_mesh::Halfedge_index;
  using Edge = Work_mesh::Edge_index;
  using Face = Work_mesh::Face_index;
  using Location = Feature_polylines<Work_mesh>::Location;

public:
  // `mesh` is the working mesh, already in the unit box, whose mean edge length is
  // `input_mean_length`; `feature_edge` (by edge index) holds the sharp, border and
  // user-constrained edges, `kind` (by vertex index) what each vertex may do; `output`, where the
  // vertices will be written (the guarantees hold there).
  Graphcut_remesher(Work_mesh& mesh, double input_mean_length, std::vector<char> feature_edge,
                    std::vector<Vertex_kind> kind, const Remeshing_options& options,
                    Output_points output = Output_points())
    : m_mesh(mesh), m_reference_mesh(mesh), m_bound(m_reference_mesh, options.distance_bound),
      m_reference(m_reference_mesh, options.sharp_angle_bounds.first),
      m_reference_feature_edge(std::move(feature_edge)), m_reference_kind(std::move(kind)),
      m_polylines(m_reference_mesh, m_reference_feature_edge, m_reference_kind), m_options(options),
      m_input_mean_length(input_mean_length),
      m_sizing(make_sizing_field(m_reference_mesh, m_reference_feature_edge, options, input_mean_length)),
      m_tracking(m_mesh, m_reference, m_polylines, m_state),
      m_energy(m_mesh, m_reference, m_state,
               m_sizing.resamples() ? resampling_weights(options.weights, m_sizing.tolerance, !m_sizing.target_asked_for)
                                   : options.weights),
      m_candidates(m_mesh, m_reference, m_polylines, m_state, m_energy, options.smoothing_step),
      m_cut(m_mesh, m_energy), m_intersections(mesh, std::move(output))
  {
    // The working mesh starts as the reference, index for index.
    m_tracking.start(m_reference_feature_edge, m_reference_kind);
    m_energy.collect_feature_edges();
    // Intersections the input already has are not the optimisation's doing: where they are, the
    // remesher works as elsewhere, and intersections stay allowed there (see
    // new_self_intersections()). Freezing those triangles instead kept the input's slivers around
    // them (cow's tail, ALSTOM_TEST4's strips).
    for(const auto& p : m_intersections.all_pairs())
      m_input_intersection_zones.push_back(box_around(m_mesh, p.first, p.second, m_input_mean_length));
    // With re-sampling the strong creases' turns are not corners: their lines keep near them as
    // the surface does, and so do the borders at the input's density. At a length asked for the
    // borders slide freely: held to that tolerance, a coarse length's keep too many vertices.
    if(m_sizing.resamples())
      m_polylines.set_line_tolerance(m_sizing.tolerance, !m_sizing.target_asked_for);
    m_energy.compute_terms();
  }

  // eq. (1) at the current positions.
  double energy() const { return m_energy.energy(); }

  const Reference_surface<Work_mesh>& reference() const { return m_reference; }

  // The symmetric Hausdorff distance between the working mesh and the reference (unit box),
  // Metro-style (surface_distance.h): the vertices and `face_samples` random points of each
  // surface, to the other.
  double measured_distance(std::size_t face_samples = 100000) const
  {
    CGAL::Random rng(m_options.random_seed);
    const auto one_way = [&](const Work_mesh& from, const Work_mesh& to) {
      return distance_to_mesh(sample_surface(from, get(CGAL::vertex_point, from), face_samples, rng), to,
                              get(CGAL::vertex_point, to), Work_kernel()).max;
    };
    return (std::max)(one_way(m_mesh, m_reference_mesh), one_way(m_reference_mesh, m_mesh));
  }

  // Runs both phases; `visitor(progress)` is called after each iteration and stops the run when it
  // returns false.
  template <typename Visitor>
  Graphcut_remeshing_statistics run(Visitor& visitor)
  {
    Graphcut_remeshing_statistics stats;
    stats.energies.push_back(energy());
    const std::array<std::pair<Graphcut_remeshing_progress::Phase, std::size_t>, 2> phases{{
      {Graphcut_remeshing_progress::RELOCATION, m_options.number_of_iterations},
      {Graphcut_remeshing_progress::GREEDY_FITTING, m_options.number_of_greedy_iterations}}};
    for(const auto& phase : phases)
    {
      const bool greedy = phase.first == Graphcut_remeshing_progress::GREEDY_FITTING;
      if(greedy && m_options.number_of_iterations == 0 && connectivity_due(0))
        connectivity_pass_between_iterations(stats);
      for(std::size_t k = 1; k <= phase.second; ++k)
      {
        const double t = temperature(m_options.initial_temperature, m_options.cooling_factor, k);
        stats.number_of_moves += relocate(t, greedy);
        ++stats.number_of_iterations;
        if(!greedy && connectivity_due(k))
          connectivity_pass_between_iterations(stats);
        stats.energies.push_back(energy());

        Graphcut_remeshing_progress progress;
        progress.phase = phase.first;
        progress.iteration = k;
        progress.number_of_iterations = phase.second;
        progress.energy = stats.energies.back();
        if(!visitor(progress))
        {
          stats.cancelled = true;
          return stats;
        }
      }
    }
    // Beyond the paper: with a length coarser than the input's (Sizing_field::covers_reference), what
    // still stands out once the relocation is over gets vertices, which then stay where they are
    // put, on the reference (the energies above are those of the iterations).
    if(m_options.do_connectivity_optimization && m_sizing.covers_reference)
      for(std::size_t k = 0; k < final_coverings; ++k)
      {
        m_cut.release();
        covering_pass(stats);
        m_energy.compute_terms();
        m_tracking.mark_all();
      }
    // Beyond the paper: when re-sampling at the input's density, the triangles with the smallest
    // angles last. At a length asked for, whose tolerance grows with the triangles, the pass cut
    // coarse hollows and tips off (see the manual).
    if(m_options.do_connectivity_optimization && m_sizing.resamples() && !m_sizing.target_asked_for)
    {
      m_cut.release();
      safe_pass(stats, [](Connectivity_optimizer& optimizer) { return optimizer.repair_smallest_angles(); });
      m_energy.compute_terms();
      m_tracking.mark_all();
    }
    return stats;
  }

  void connectivity_pass_between_iterations(Graphcut_remeshing_statistics& stats)
  {
    m_cut.release();
    connectivity_pass(stats);
    m_energy.compute_terms();
    m_tracking.mark_all(); // new triangles, relaxed vertices
    stats.connectivity_passes.push_back(stats.number_of_iterations);
  }

  // Section 3, every connectivity_period iterations of the first phase, and once at its end when
  // it is shorter than the period (before the greedy phase when it has no iteration), so that the
  // density asked for is reached whatever the count.
  bool connectivity_due(std::size_t k) const
  {
    const std::size_t period = m_options.connectivity_period, n = m_options.number_of_iterations;
    return m_options.do_connectivity_optimization && period > 0 && (k % period == 0 || (n < period && k == n));
  }

  // One iteration of Algorithm 1's inner loop: track the closest reference vertices, propose a
  // candidate per vertex, let the graph cut decide. Returns the number of vertices moved.
  std::size_t relocate(double temperature, bool greedy)
  {
    m_tracking.update(m_energy.feature_edges());
    ++m_round;
    Candidate_set c = propose_candidates(temperature, greedy);
    if(c.moving.empty())
      return 0;
    // The cut decides; should its choice make triangles that were apart intersect, or fold a
    // triangle onto a neighbour, the vertices of those triangles keep their positions and the cut
    // decides again over fewer candidates. The cut never does worse than keeping everything but
    // for the rounding of its single-precision capacities: a choice that would raise the energy
    // of eq. (1) is undone whole, so that the energy never rises.
    std::vector<char> excluded(c.moving.size(), 0), checked(c.moving.size(), 0), checked_labels(c.moving.size(), 0);
    for(;;)
    {
      const std::vector<char> labels = m_cut.decide(c.moving, c.point, c.data, c.variable, excluded);
      std::vector<Vector_3d> previous(c.moving.size());
      std::size_t moved = 0;
      for(std::size_t i = 0; i < c.moving.size(); ++i)
      {
        previous[i] = position(c.moving[i]);
        if(labels[i])
        {
          set_position(c.moving[i], c.point[i]);
          ++moved;
        }
      }
      std::vector<char> touched(m_mesh.num_vertices(), 0);
      for(std::size_t i = 0; i < c.moving.size(); ++i)
        touched[std::size_t(c.moving[i])] = labels[i];
      const bool intersecting = exclude_new_intersections(c, labels, touched, excluded);
      const bool folding = exclude_new_folds(c, labels, previous, excluded);
      const bool breaking = exclude_distance_breaks(c, labels, previous, excluded, checked, checked_labels);
      checked_labels = labels;
      const bool decided = !intersecting && !folding && !breaking;
      if(decided && take_candidates(c, labels, touched))
        return moved;
      for(std::size_t i = 0; i < c.moving.size(); ++i)
        set_position(c.moving[i], previous[i]);
      if(decided)
        return 0;
    }
  }

  // By face of the mesh: the reference triangle nearest its centroid, the nearest found from the
  // reference triangles of its three vertices (a face next to a sharp edge may have a vertex
  // tracked on the other side); none for a removed face.
  std::vector<Face> reference_faces_below() const
  {
    std::vector<Face> below(m_mesh.num_faces(), Work_mesh::null_face());
    for(Face f : m_mesh.faces())
    {
      const auto v = face_vertices(m_mesh, f);
      const Vector_3d c = (position(v[0]) + position(v[1]) + position(v[2])) / 3;
      double nearest = std::numeric_limits<double>::infinity();
      for(Vertex u : v)
      {
        Face hint = m_state.vertex_hint[std::size_t(u)];
        const double d = (m_reference.closest_point(c, hint) - c).squaredNorm();
        if(d < nearest)
        {
          nearest = d;
          below[std::size_t(f)] = hint;
        }
      }
    }
    return below;
  }

  // The first guarantee the working mesh breaks (guarantees.h), or an empty string; also no
  // intersecting pair of triangles away from the input's own intersections.
  std::string broken_guarantee()
  {
    std::vector<Vertex> fixed;
    std::vector<Vector_3d> fixed_point;
    for(Vertex v : m_reference_mesh.vertices())
      if(m_reference_kind[std::size_t(v)] == Vertex_kind::fixed_vertex)
      {
        fixed.push_back(v);
        fixed_point.push_back(m_reference.point(v));
      }
    const std::string broken =
      Graphcut_remeshing::broken_guarantee(m_mesh, topology_summary(m_reference_mesh), fixed, fixed_point,
                                           folded_edges(m_reference_mesh), m_state.feature_edge);
    if(!broken.empty())
      return broken;
    m_intersections.invalidate();
    return new_self_intersections().empty() ? std::string() : std::string("two triangles intersect away from the input's intersections");
  }

  // Section 3 once: local changes then relaxation.
  void connectivity_pass(Graphcut_remeshing_statistics& stats)
  {
    safe_pass(stats, [](Connectivity_optimizer& optimizer) { return optimizer.connectivity_pass(); });
  }

  // The coverings alone (Connectivity_optimizer::cover_what_stands_out()).
  void covering_pass(Graphcut_remeshing_statistics& stats)
  {
    safe_pass(stats, [](Connectivity_optimizer& optimizer) { return optimizer.cover_what_stands_out(); });
  }

private:
  // Runs `pass` on an optimizer of the working mesh. Should the pass make the mesh self-intersect,
  // it is undone and tried again with the region around the new intersections left alone (a wider
  // one after a second failure: twice the input's mean edge length, not the target's, which a
  // coarse target makes large enough to freeze a coarsening), in this pass and the next
  // (keep_out_lifetime); later passes try there again, the relocation having moved the triangles
  // since (regions kept for the whole run froze most of ALSTOM_TEST4 at a coarse target).
  template <typename Pass>
  void safe_pass(Graphcut_remeshing_statistics& stats, const Pass& pass)
  {
    ++m_passes;
    m_keep_out.erase(std::remove_if(m_keep_out.begin(), m_keep_out.end(),
                                    [this](const Keep_out& k) { return k.pass + keep_out_lifetime < m_passes; }),
                     m_keep_out.end());
    for(int attempt = 0; attempt < 3; ++attempt)
    {
      const Work_mesh mesh_before = m_mesh;
      const Tracking_state state_before = m_state;
      const std::size_t folds_before = folded_edges(m_mesh, &m_state.feature_edge);
      std::vector<char> frozen(m_mesh.num_vertices(), 0);
      for(Vertex v : m_mesh.vertices())
        for(const Keep_out& k : m_keep_out)
          if(CGAL::do_overlap(k.box, m_mesh.point(v).bbox()))
            frozen[std::size_t(v)] = 1;
      Connectivity_optimizer optimizer(m_mesh, m_reference, m_state, m_sizing, &m_polylines,
                                       [this](Vertex v, const Vector_3d& x, double bound) {
                                         return m_energy.local_evidence(v, x, bound);
                                       },
                                       m_options.operations, frozen, &m_bound);
      const Connectivity_counts counts = pass(optimizer);
      m_energy.collect_feature_edges();
      // The mesh had no new intersections before the pass: only triangles it changed or moved
      // can have made some.
      m_intersections.connectivity_changed();
      const std::vector<char> changed = changed_vertices(mesh_before, m_mesh);
      std::vector<std::pair<Face, Face> > fresh = new_self_intersections(&changed);
      if(folded_edges(m_mesh, &m_state.feature_edge) > folds_before)
        for(const auto& pair : folds_among(changed))
          fresh.push_back(pair);
#ifdef CGAL_GRAPHCUT_REMESHING_VERBOSE
      std::cerr << "connectivity pass, attempt " << attempt << ": " << counts.flips << " flips, "
                << counts.splits << " splits, " << counts.collapses << " collapses, "
                << counts.vertex_splits << " vertex splits, " << counts.relaxed << " relaxed, "
                << fresh.size() << " new intersecting pairs\n";
#endif
      if(fresh.empty())
      {
        // The mesh's arrays grew by doubling as the pass added elements: the cuts until the next
        // pass, where the memory peaks, should not carry the empty half.
        m_mesh.shrink_to_fit();
        stats.number_of_flips += counts.flips;
        stats.number_of_splits += counts.splits;
        stats.number_of_collapses += counts.collapses;
        stats.number_of_vertex_splits += counts.vertex_splits;
        return;
      }
      // First around the vertices of the new pairs only, where they are and where they were
      // before the pass (a collapse's kept vertex may have moved), then around their whole
      // triangles: at a coarse target a triangle spans many input edges, and its box froze most of
      // ALSTOM_TEST4.
      for(const auto& pair : fresh)
        for(Face f : {pair.first, pair.second})
          if(attempt == 0)
            for(Vertex u : face_vertices(m_mesh, f))
            {
              const double r = 0.5 * m_input_mean_length;
              m_keep_out.push_back(Keep_out{grown_by(m_mesh.point(u).bbox(), r), m_passes});
              if(std::size_t(u) < mesh_before.num_vertices() && !mesh_before.is_removed(u))
                m_keep_out.push_back(Keep_out{grown_by(mesh_before.point(u).bbox(), r), m_passes});
            }
          else
            m_keep_out.push_back(Keep_out{box_around(m_mesh, f, f, 2 * m_input_mean_length), m_passes});
      m_mesh = mesh_before;
      m_state = state_before;
      m_intersections.invalidate();
      m_energy.collect_feature_edges(); // the undone pass may have split feature edges
      ++stats.number_of_undone_passes;
    }
  }

  // The candidates of one relocation, by variable: the vertices with a candidate, in the order of
  // the vertices.
  struct Candidate_set
  {
    std::vector<std::size_t> variable; // by vertex: its variable, or Relocation_cut::none
    std::vector<Vertex> moving;
    std::vector<Vector_3d> point;
    std::vector<Location> location;    // a feature vertex's candidate, on its polyline
    std::vector<Face> face;            // a free vertex's candidate lies on this reference triangle
    std::vector<double> data;          // the data term at the candidate
    std::vector<double> data_by_vertex;
  };

  Vector_3d position(Vertex v) const { return to_vector(m_mesh.point(v)); }

  void set_position(Vertex v, const Vector_3d& p) { m_mesh.point(v) = Work_kernel::Point_3(p.x(), p.y(), p.z()); }

  // A candidate for each vertex, each vertex on its own with its own random numbers; then the
  // vertices with a candidate become the cut's variables, their candidates moved down in place.
  Candidate_set propose_candidates(double temperature, bool greedy)
  {
    const std::size_t n = m_mesh.num_vertices();
    Candidate_set c;
    std::vector<char> proposed(n, 0);
    c.point.resize(n);
    c.location.resize(n);
    c.face.resize(n);
    c.data_by_vertex.assign(n, 0);
    std::vector<double>& face_term = m_energy.proposal_face_term();
    grow_by_elements(face_term, m_mesh.num_halfedges());
    for_each_vertex(m_mesh, [&](Vertex v) {
      const std::size_t i = std::size_t(v);
      CGAL::Random rng(item_seed(m_options.random_seed, m_round, i));
      proposed[i] = m_candidates.propose(v, temperature, greedy, rng, c.point[i], c.location[i], c.face[i], face_term);
      // A candidate that would break the distance bound costs infinitely much: it is not offered.
      proposed[i] = proposed[i] && m_bound.allows_move(m_mesh, v, c.point[i]);
      if(proposed[i])
        c.data_by_vertex[i] = m_energy.data_energy(v, c.point[i], c.face[i]);
    });
    c.variable.assign(n, Relocation_cut::none);
    for(Vertex v : m_mesh.vertices())
      if(proposed[std::size_t(v)])
      {
        const std::size_t i = std::size_t(v), k = c.moving.size();
        c.variable[i] = k;
        c.moving.push_back(v);
        c.point[k] = c.point[i];
        c.location[k] = c.location[i];
        c.face[k] = c.face[i];
        c.data.push_back(c.data_by_vertex[i]);
      }
    c.point.resize(c.moving.size());
    c.location.resize(c.moving.size());
    c.face.resize(c.moving.size());
    return c;
  }

  // With the labelled candidates taken (touched[v] for the vertices that moved): false when no
  // new pair of triangles intersects, else the candidates of the vertices of those triangles
  // excluded and true.
  bool exclude_new_intersections(const Candidate_set& c, const std::vector<char>& labels,
                                 const std::vector<char>& touched, std::vector<char>& excluded)
  {
    bool found = false;
    for(const auto& pair : new_self_intersections(&touched))
      for(Face f : {pair.first, pair.second})
        for(Vertex u : face_vertices(m_mesh, f))
        {
          const std::size_t i = c.variable[std::size_t(u)];
          if(i != Relocation_cut::none && labels[i])
          {
            excluded[i] = 1;
            found = true;
          }
        }
    return found;
  }

  // With the labelled candidates taken (`previous` the positions before): false when no triangle
  // around the vertices that moved has folded onto a neighbour (guarantees.h) across an edge off
  // the features, else the candidates of the moved vertices of those triangles excluded and true.
  // (The triangle terms of the cut see one triangle at a time, never a pair.) Each edge is looked
  // at once, the edges in parallel.
  bool exclude_new_folds(const Candidate_set& c, const std::vector<char>& labels,
                         const std::vector<Vector_3d>& previous, std::vector<char>& excluded)
  {
    const auto moved = [&](Vertex u) {
      const std::size_t i = c.variable[std::size_t(u)];
      return i != Relocation_cut::none && labels[i];
    };
    const auto before = [&](Vertex u) { return moved(u) ? previous[c.variable[std::size_t(u)]] : position(u); };
    const auto area_before = [&](Halfedge h) {
      return area_vector(before(m_mesh.source(h)), before(m_mesh.target(h)), before(m_mesh.target(m_mesh.next(h))));
    };
    std::vector<Halfedge> folds;
    collect_by_blocks(m_mesh.num_edges(), folds, [&](std::size_t i, std::vector<Halfedge>& found) {
      const Edge e(static_cast<Edge::size_type>(i));
      if(m_mesh.is_removed(e) || m_state.feature_edge[i])
        return;
      const Halfedge h = m_mesh.halfedge(e), o = m_mesh.opposite(h);
      if(m_mesh.is_border(h) || m_mesh.is_border(o))
        return;
      const bool near_a_move = moved(m_mesh.source(h)) || moved(m_mesh.target(h)) ||
                               moved(m_mesh.target(m_mesh.next(h))) || moved(m_mesh.target(m_mesh.next(o)));
      if(near_a_move && is_folded_edge(m_mesh, h) && !is_folded_pair(area_before(h), area_before(o)))
        found.push_back(h);
    });
    bool found = false;
    for(Halfedge k : folds)
      for(Halfedge side : {k, m_mesh.opposite(k)})
        for(Vertex u : face_vertices(m_mesh, m_mesh.face(side)))
          if(moved(u) && !excluded[c.variable[std::size_t(u)]])
            excluded[c.variable[std::size_t(u)]] = found = true;
    return found;
  }

  // With the labelled candidates taken (`previous` the positions before): false when the faces
  // around every vertex that moved keep the distance bound, else the candidates of the moved
  // vertices of those faces excluded and true. Each candidate kept it alone, the faces around its
  // own staying (propose_candidates()): only a vertex with another move among the vertices of those
  // faces needs a look. `checked` (by variable) flags the moves found to keep the bound under
  // `checked_labels`, the labels of the last decision: while no label among those vertices changes,
  // the answer stands.
  bool exclude_distance_breaks(const Candidate_set& c, const std::vector<char>& labels,
                               const std::vector<Vector_3d>& previous, std::vector<char>& excluded,
                               std::vector<char>& checked, const std::vector<char>& checked_labels)
  {
    if(!m_bound.active())
      return false;
    const auto moved = [&](Vertex u) {
      const std::size_t i = c.variable[std::size_t(u)];
      return i != Relocation_cut::none && labels[i];
    };
    const auto relabelled = [&](Vertex u) {
      const std::size_t i = c.variable[std::size_t(u)];
      return i != Relocation_cut::none && labels[i] != checked_labels[i];
    };
    const auto before = [&](Vertex u) { return moved(u) ? previous[c.variable[std::size_t(u)]] : position(u); };
    std::vector<Vertex> breaking;
    collect_by_blocks(c.moving.size(), breaking, [&](std::size_t i, std::vector<Vertex>& found) {
      const Vertex v = c.moving[i];
      const bool was_checked = checked[i];
      checked[i] = labels[i];
      if(!labels[i])
        return;
      bool near_a_move = false, changed = !was_checked;
      // The faces around a star are two rings wide (Distance_bound::triangles_around()): their
      // vertices are within three rings of v.
      for(Vertex w : vertices_around_target(m_mesh.halfedge(v), m_mesh))
        for(Vertex x : vertices_around_target(m_mesh.halfedge(w), m_mesh))
          for(Vertex u : vertices_around_target(m_mesh.halfedge(x), m_mesh))
          {
            near_a_move = near_a_move || (u != v && moved(u));
            changed = changed || relabelled(u);
          }
      if(near_a_move && changed && !m_bound.allows_moved_star(m_mesh, v, before))
      {
        checked[i] = 0;
        found.push_back(v);
      }
    });
    for(Vertex v : breaking)
    {
      excluded[c.variable[std::size_t(v)]] = 1;
      for(Vertex w : vertices_around_target(m_mesh.halfedge(v), m_mesh))
        if(moved(w))
          excluded[c.variable[std::size_t(w)]] = 1;
    }
    return !breaking.empty();
  }

  // The pairs of triangles folded onto each other (guarantees.h) across an edge off the features,
  // with a vertex that `changed` flags.
  std::vector<std::pair<Face, Face> > folds_among(const std::vector<char>& changed) const
  {
    std::vector<std::pair<Face, Face> > folds;
    for(Edge e : m_mesh.edges())
    {
      const Halfedge h = m_mesh.halfedge(e), o = m_mesh.opposite(h);
      if(m_state.feature_edge[std::size_t(e)] || !is_folded_edge(m_mesh, h))
        continue;
      for(Vertex u : {m_mesh.source(h), m_mesh.target(h), m_mesh.target(m_mesh.next(h)), m_mesh.target(m_mesh.next(o))})
        if(std::size_t(u) < changed.size() && changed[std::size_t(u)])
        {
          folds.emplace_back(m_mesh.face(h), m_mesh.face(o));
          break;
        }
    }
    return folds;
  }

  // The vertices of label 1 are at their candidates: their places on the reference follow (so
  // that the data terms kept are the ones the cut was given) and so do the terms of what moved,
  // unless the energy of eq. (1) would rise; then both stay as they were and the caller puts the
  // vertices back. Whether the candidates were taken.
  bool take_candidates(const Candidate_set& c, const std::vector<char>& labels, const std::vector<char>& touched)
  {
    const double before = m_energy.energy();
    Mesh_energy::Saved_terms terms = m_energy.saved_terms();
    std::vector<Location> location(c.moving.size());
    std::vector<Face> hint(c.moving.size());
    for(std::size_t i = 0; i < c.moving.size(); ++i)
    {
      const std::size_t v = std::size_t(c.moving[i]);
      location[i] = m_state.location[v];
      hint[i] = m_state.vertex_hint[v];
      if(labels[i] && m_state.kind[v] == Vertex_kind::feature_vertex)
        m_state.location[v] = c.location[i];
      else if(labels[i] && m_state.kind[v] == Vertex_kind::free_vertex)
        m_state.vertex_hint[v] = c.face[i];
    }
    m_energy.update_terms_after_relocation(touched, c.data_by_vertex);
    if(!(m_energy.energy() <= before))
    {
      m_energy.restore_terms(std::move(terms));
      for(std::size_t i = 0; i < c.moving.size(); ++i)
      {
        m_state.location[std::size_t(c.moving[i])] = location[i];
        m_state.vertex_hint[std::size_t(c.moving[i])] = hint[i];
      }
      return false;
    }
    for(std::size_t i = 0; i < c.moving.size(); ++i)
      if(labels[i])
        m_tracking.mark_moved(c.moving[i]);
    return true;
  }

  // Pairs of intersecting triangles (exact predicates) away from the input's own intersections
  // (the input's intersecting pairs grown by its mean edge length, the zone where its
  // intersections may stay):
  // a pair whose two triangles both reach into the zone of one intersecting pair of the input is
  // the input's. With `touched` (by vertex), only pairs with a triangle incident to a touched
  // vertex, which are all the new ones when the mesh had none before those vertices moved.
  std::vector<std::pair<Face, Face> > new_self_intersections(const std::vector<char>* touched = nullptr)
  {
    std::vector<std::pair<Face, Face> > fresh;
    for(const auto& p : touched ? m_intersections.pairs_touching(*touched) : m_intersections.all_pairs())
    {
      const CGAL::Bbox_3 first = box_around(m_mesh, p.first, p.first, 0), second = box_around(m_mesh, p.second, p.second, 0);
      if(std::none_of(m_input_intersection_zones.begin(), m_input_intersection_zones.end(),
                      [&](const CGAL::Bbox_3& z) { return CGAL::do_overlap(z, first) && CGAL::do_overlap(z, second); }))
        fresh.push_back(p);
    }
    return fresh;
  }

  Work_mesh& m_mesh;
  const Work_mesh m_reference_mesh;
  Distance_bound m_bound; // of the working mesh to m_reference_mesh
  Reference_surface<Work_mesh> m_reference;
  const std::vector<char> m_reference_feature_edge;   // by reference edge
  const std::vector<Vertex_kind> m_reference_kind;    // by reference vertex
  Feature_polylines<Work_mesh> m_polylines;
  Remeshing_options m_options;
  double m_input_mean_length;
  Sizing_field m_sizing;
  std::size_t m_round = 0; // relocations so far: with the vertex, it seeds the vertex's random numbers
  Tracking_state m_state;  // kinds, y_s0 (its frame gives the tangent plane and rho), hints
  Reference_tracking m_tracking;
  Mesh_energy m_energy;
  Candidate_generator m_candidates;
  Relocation_cut m_cut;
  // A region where a connectivity pass made triangles intersect, left alone by the pass that
  // made it (its next attempts) and by the next `keep_out_lifetime` passes.
  struct Keep_out
  {
    CGAL::Bbox_3 box;
    std::size_t pass;
  };
  static constexpr std::size_t keep_out_lifetime = 1;
  // The coverings after the relocation: each covers one place per neighbourhood, and the second
  // what stood out next to the first one's places.
  static constexpr std::size_t final_coverings = 2;
  std::vector<Keep_out> m_keep_out;
  std::size_t m_passes = 0; // connectivity passes so far
  std::vector<CGAL::Bbox_3> m_input_intersection_zones; // see new_self_intersections()
  Triangle_intersections m_intersections;  // of the working mesh; told when its connectivity changes
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_REMESHER_H
