// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The driver: the paper's Algorithm 1, run twice (section 4.1), on a working copy of the mesh
// scaled into the unit box.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_REMESHER_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_REMESHER_H

#include <CGAL/Polygon_mesh_processing/graphcut_remeshing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/binary_graph_cut.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/candidates.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/connectivity.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/energy.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/features.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/guarantees.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/intersections.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/parallel.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/reference_surface.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <CGAL/Random.h>
#include <CGAL/property_map.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#ifdef CGAL_GRAPHCUT_REMESHING_VERBOSE
#include <iostream>
#endif
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

struct Remeshing_options
{
  Energy_weights weights;
  std::size_t number_of_iterations = 150;
  std::size_t number_of_greedy_iterations = 20;
  double initial_temperature = 10;
  double cooling_factor = 0.95;
  double smoothing_step = 0.06; // gamma of section 2.3
  unsigned int random_seed = 0;
  bool do_connectivity_optimization = true;
  std::size_t connectivity_period = 5;
  // The largest distance (unit box) a chord of the target edge length may keep from a curved
  // reference; it shortens the target length where the surface is curved (section 3.1's e_min,
  // e_max depend on the local curvature).
  double sizing_tolerance = 3e-3;
};

class Graphcut_remesher
{
  using Vertex = Work_mesh::Vertex_index;
  using Halfedge = Work_mesh::Halfedge_index;
  using Face = Work_mesh::Face_index;
  using Edge = Work_mesh::Edge_index;
  using Polylines = Feature_polylines<Work_mesh>;
  using Location = Polylines::Location;

public:
  // `mesh` is the working mesh, already in the unit box; `feature_edge` (by edge index) holds
  // the sharp, border and user-constrained edges, `kind` (by vertex index) what each vertex may do.
  Graphcut_remesher(Work_mesh& mesh, std::vector<char> feature_edge, std::vector<Vertex_kind> kind,
                    const Remeshing_options& options)
    : m_mesh(mesh), m_reference_mesh(mesh), m_reference(m_reference_mesh),
      m_reference_feature_edge(std::move(feature_edge)), m_reference_kind(std::move(kind)),
      m_polylines(m_reference_mesh, m_reference_feature_edge, m_reference_kind), m_options(options),
      m_round(0), m_intersections(mesh)
  {
    // The working mesh starts as the reference, index for index.
    m_state.feature_edge = m_reference_feature_edge;
    m_state.kind = m_reference_kind;
    const std::size_t n = m_mesh.num_vertices();
    m_state.closest.resize(n);
    m_state.location.resize(n);
    m_state.vertex_hint.resize(n);
    m_state.frozen.assign(n, 0);
    m_state.face_hint.resize(m_mesh.num_faces());
    for(Face f : m_mesh.faces())
      m_state.face_hint[std::size_t(f)] = f;
    m_state.edge_hint.resize(m_mesh.num_edges());
    for(Edge e : m_mesh.edges())
    {
      const Halfedge h = m_mesh.halfedge(e);
      m_state.edge_hint[std::size_t(e)] = m_mesh.face(m_mesh.is_border(h) ? m_mesh.opposite(h) : h);
    }
    collect_feature_edges();
    // Intersections the input already has are not the optimisation's doing.
    m_input_intersections = m_intersections.all_pairs();
    // Faces the input already made intersect are left to the relocation: no connectivity change
    // touches them, so their indices, and the list above, stay valid.
    m_intersection_frozen.assign(n, 0);
    for(const auto& p : m_input_intersections)
      for(Face f : {p.first, p.second})
        for(Vertex u : face_vertices(f))
          m_intersection_frozen[std::size_t(u)] = 1;
    double total = 0;
    for(Edge e : m_mesh.edges())
      total += (position(m_mesh.source(m_mesh.halfedge(e))) - position(m_mesh.target(m_mesh.halfedge(e)))).norm();
    m_sizing.mean_length = m_mesh.number_of_edges() > 0 ? total / double(m_mesh.number_of_edges()) : 0;
    m_sizing.tolerance = m_options.sizing_tolerance;
#ifdef CGAL_GRAPHCUT_REMESHING_VERBOSE
    {
      std::size_t count[3] = {0, 0, 0}, features = 0;
      for(Vertex v : m_mesh.vertices())
        ++count[int(kind_of(v))];
      for(Edge e : m_mesh.edges())
        features += m_state.feature_edge[std::size_t(e)] ? 1 : 0;
      std::cerr << count[0] << " free, " << count[1] << " feature, " << count[2] << " fixed vertices; "
                << features << " feature edges\n";
    }
#endif
    for(Vertex v : m_mesh.vertices())
    {
      m_state.closest[std::size_t(v)] = v;
      m_state.vertex_hint[std::size_t(v)] = m_reference.incident_face(v);
      if(kind_of(v) == Vertex_kind::feature_vertex)
        m_state.location[std::size_t(v)] = m_polylines.at_vertex(v);
    }
    compute_terms();
    m_untracked.assign(n, 1);
  }

  Vertex_kind kind_of(Vertex v) const { return m_state.kind[std::size_t(v)]; }

  Vector_3d position(Vertex v) const { return to_vector(m_mesh.point(v)); }

  // eq. (1), from the terms at the current positions.
  double energy() const
  {
    double u = 0;
    for(Face f : m_mesh.faces())
      u += m_face_term[std::size_t(f)];
    for(Vertex v : m_mesh.vertices())
      u += m_vertex_term[std::size_t(v)];
    for(double t : m_edge_term)
      u += t;
    return u;
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
      for(std::size_t k = 1; k <= phase.second; ++k)
      {
        const double t = temperature(m_options.initial_temperature, m_options.cooling_factor, k);
        stats.number_of_moves += relocate(t, greedy);
        ++stats.number_of_iterations;
        // Section 3, every connectivity_period iterations of the first phase.
        if(!greedy && m_options.do_connectivity_optimization && m_options.connectivity_period > 0 &&
           k % m_options.connectivity_period == 0)
        {
          connectivity_pass(stats);
          compute_terms();
          m_untracked.assign(m_mesh.num_vertices(), 1); // new triangles, relaxed vertices
          stats.connectivity_passes.push_back(stats.number_of_iterations);
        }
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
    return stats;
  }

  // One iteration of Algorithm 1's inner loop: track the closest reference vertices, propose a
  // candidate per vertex, let the graph cut decide. Returns the number of vertices moved.
  std::size_t relocate(double temperature, bool greedy)
  {
    update_tracking();
    ++m_round;

    // Candidates, each vertex on its own with its own random numbers.
    // The candidates, by vertex until the moving vertices are known, then by variable.
    const std::size_t n = m_mesh.num_vertices();
    std::vector<char> proposed(n, 0);
    std::vector<Vector_3d> candidate(n);
    std::vector<Location> candidate_location(n);
    std::vector<Face> candidate_face(n); // a free vertex's candidate lies on this reference triangle
    std::vector<double> proposal_data(n, 0); // by vertex
    m_proposal_face_term.resize(m_mesh.num_halfedges());
    for_each_vertex([&](Vertex v) {
      const std::size_t i = std::size_t(v);
      CGAL::Random rng(item_seed(m_options.random_seed, m_round, i));
      proposed[i] = propose(v, temperature, greedy, rng, candidate[i], candidate_location[i], candidate_face[i],
                            m_proposal_face_term);
      if(proposed[i])
        proposal_data[i] = data_energy(v, candidate[i], candidate_face[i]);
    });
    // The vertices with a candidate are the cut's variables, in the order of the vertices: their
    // candidates move down in place.
    std::vector<std::size_t> variable(n, Binary_graph_cut::none);
    std::vector<Vertex> moving;
    std::vector<double> candidate_data;
    for(Vertex v : m_mesh.vertices())
      if(proposed[std::size_t(v)])
      {
        const std::size_t i = std::size_t(v), k = moving.size();
        variable[i] = k;
        moving.push_back(v);
        candidate[k] = candidate[i];
        candidate_location[k] = candidate_location[i];
        candidate_face[k] = candidate_face[i];
        candidate_data.push_back(proposal_data[i]);
      }
    proposed = std::vector<char>();
    candidate.resize(moving.size());
    candidate_location.resize(moving.size());
    candidate_face.resize(moving.size());
    if(moving.empty())
      return 0;

    // The cut decides; should its choice make triangles that were apart intersect, the vertices of
    // those triangles keep their positions and the cut decides again (each cut is over fewer
    // candidates and never does worse than keeping everything, so the energy still does not rise).
    std::vector<char> excluded(moving.size(), 0);
    for(;;)
    {
      const std::vector<char> labels = decide(moving, candidate, candidate_data, variable, excluded);
      std::vector<Vector_3d> previous(moving.size());
      std::size_t moved = 0;
      for(std::size_t i = 0; i < moving.size(); ++i)
      {
        previous[i] = position(moving[i]);
        if(labels[i])
        {
          set_position(moving[i], candidate[i]);
          ++moved;
        }
      }
      std::vector<char> touched(n, 0);
      for(std::size_t i = 0; i < moving.size(); ++i)
        touched[std::size_t(moving[i])] = labels[i];
      bool clean = true;
      for(const auto& pair : new_self_intersections(&touched))
        for(Face f : {pair.first, pair.second})
          for(Vertex u : face_vertices(f))
          {
            const std::size_t i = variable[std::size_t(u)];
            if(i != Binary_graph_cut::none && labels[i])
            {
              excluded[i] = 1;
              clean = false;
            }
          }
      if(clean)
      {
        // Where the candidates were found on the reference, so that the data terms kept are the
        // ones the cut was given.
        for(std::size_t i = 0; i < moving.size(); ++i)
          if(labels[i] && kind_of(moving[i]) == Vertex_kind::feature_vertex)
            m_state.location[std::size_t(moving[i])] = candidate_location[i];
          else if(labels[i] && kind_of(moving[i]) == Vertex_kind::free_vertex)
            m_state.vertex_hint[std::size_t(moving[i])] = candidate_face[i];
        update_terms_after_relocation(touched, proposal_data);
        for(std::size_t i = 0; i < moving.size(); ++i)
          m_untracked[std::size_t(moving[i])] |= labels[i];
        return moved;
      }
      for(std::size_t i = 0; i < moving.size(); ++i)
        set_position(moving[i], previous[i]);
    }
  }

  // The variables of the moving vertices of a triangle and its energy for each choice of theirs:
  // bit j of the index of `table` says whether the j-th moving vertex takes its candidate.
  struct Triangle_table
  {
    int k = 0; // number of moving vertices
    std::array<std::size_t, 3> var{};
    std::array<double, 8> table{};
  };

  void fill_triangle_table(Face f, const std::vector<Vector_3d>& candidate, const std::vector<std::size_t>& variable,
                           double forbidden, Triangle_table& t) const
  {
    const std::array<Vertex, 3> v = face_vertices(f);
    const std::array<Halfedge, 3> to = halfedges_to_vertices(f);
    std::array<int, 3> slot{};
    for(int i = 0; i < 3; ++i)
      if(variable[std::size_t(v[i])] != Binary_graph_cut::none)
      {
        t.var[t.k] = variable[std::size_t(v[i])];
        slot[t.k] = i;
        ++t.k;
      }
    if(t.k == 0)
      return;
    const std::array<Vector_3d, 3> current{{position(v[0]), position(v[1]), position(v[2])}};
    const Vector_3d current_normal = area_vector(current[0], current[1], current[2]);
    for(int mask = 0; mask < (1 << t.k); ++mask)
    {
      std::array<Vector_3d, 3> p = current;
      for(int j = 0; j < t.k; ++j)
        if((mask >> j) & 1)
          p[slot[j]] = candidate[t.var[j]];
      if(mask == 0)
        t.table[mask] = m_face_term[std::size_t(f)];
      else if(!is_acceptable_triangle(p[0], p[1], p[2], current_normal))
        t.table[mask] = forbidden;
      else if((mask & (mask - 1)) == 0) // one vertex moves: its proposal evaluated this already
        t.table[mask] = m_proposal_face_term[std::size_t(to[slot[mask == 1 ? 0 : (mask == 2 ? 1 : 2)]])];
      else
        t.table[mask] = triangle_energy(f, p[0], p[1], p[2]);
    }
  }

  // The binary energy of the candidates: data terms as unaries, triangle terms over the triangles'
  // moving vertices; the excluded candidates cannot be taken.
  std::vector<char> decide(const std::vector<Vertex>& moving, const std::vector<Vector_3d>& candidate,
                           const std::vector<double>& candidate_data, const std::vector<std::size_t>& variable,
                           const std::vector<char>& excluded) const
  {
    // A configuration that would fold or flatten a triangle costs more than the whole current
    // energy, so the cut, which never does worse than keeping everything, never picks it.
    const double forbidden = 1e3 * (energy() + 1);
    Binary_graph_cut cut(moving.size());
    cut.reserve(m_mesh.number_of_faces() + m_feature_edges.size());
    for(std::size_t i = 0; i < moving.size(); ++i)
      cut.add_unary(i, m_vertex_term[std::size_t(moving[i])], excluded[i] ? forbidden : candidate_data[i]);

    // The tables of the triangles, each on its own, then into the cut in the order of the faces;
    // by blocks, so that the tables of a large mesh are never all in memory.
    const std::size_t block = 1 << 15;
    std::vector<Triangle_table> tables;
    for(std::size_t first = 0; first < m_mesh.num_faces(); first += block)
    {
      tables.assign((std::min)(block, m_mesh.num_faces() - first), Triangle_table());
      for_each_index(tables.size(), [&](std::size_t i) {
        const Face f(static_cast<Face::size_type>(first + i));
        if(!m_mesh.is_removed(f))
          fill_triangle_table(f, candidate, variable, forbidden, tables[i]);
      });
      for(const Triangle_table& t : tables)
      {
        if(t.k == 1)
          cut.add_unary(t.var[0], t.table[0], t.table[1]);
        else if(t.k == 2)
          cut.add_term(t.var[0], t.var[1], Binary_graph_cut::none, t.table);
        else if(t.k == 3)
          cut.add_term(t.var[0], t.var[1], t.var[2], t.table);
      }
    }
    tables = std::vector<Triangle_table>();
    for(std::size_t e = 0; e < m_feature_edges.size(); ++e)
    {
      const Halfedge h = m_mesh.halfedge(m_feature_edges[e]);
      const std::array<Vertex, 2> v{{m_mesh.source(h), m_mesh.target(h)}};
      const std::size_t i = variable[std::size_t(v[0])], j = variable[std::size_t(v[1])];
      const Vector_3d a = position(v[0]), b = position(v[1]);
      const double current = m_edge_term[e];
      if(i != Binary_graph_cut::none && j != Binary_graph_cut::none)
        cut.add_term(i, j, Binary_graph_cut::none,
                     {{current, feature_edge_energy(e, candidate[i], b),
                       feature_edge_energy(e, a, candidate[j]), feature_edge_energy(e, candidate[i], candidate[j]),
                       0, 0, 0, 0}});
      else if(i != Binary_graph_cut::none)
        cut.add_unary(i, current, feature_edge_energy(e, candidate[i], b));
      else if(j != Binary_graph_cut::none)
        cut.add_unary(j, current, feature_edge_energy(e, a, candidate[j]));
    }
    return cut.solve();
  }

  void set_position(Vertex v, const Vector_3d& p) { m_mesh.point(v) = Work_kernel::Point_3(p.x(), p.y(), p.z()); }

  // Pairs of intersecting triangles that did not intersect in the input (exact predicates); with
  // `touched` (by vertex), only pairs with a triangle incident to a touched vertex, which are all
  // the new ones when the mesh had none before those vertices moved.
  std::vector<std::pair<Face, Face> > new_self_intersections(const std::vector<char>* touched = nullptr)
  {
    const std::vector<std::pair<Face, Face> > pairs =
      touched ? m_intersections.pairs_touching(*touched) : m_intersections.all_pairs();
    std::vector<std::pair<Face, Face> > fresh;
    std::set_difference(pairs.begin(), pairs.end(), m_input_intersections.begin(),
                        m_input_intersections.end(), std::back_inserter(fresh));
    return fresh;
  }

  const Reference_surface<Work_mesh>& reference() const { return m_reference; }

  // The first guarantee the working mesh breaks (guarantees.h), or an empty string; also no
  // intersecting pair of triangles the input did not have.
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
    return new_self_intersections().empty() ? std::string() : std::string("two triangles intersect that did not");
  }

  // Section 3 once: local changes then relaxation. Should they make the mesh self-intersect, the
  // pass is undone and tried again with the region around the new intersections left alone, in
  // this pass and the next ones.
  void connectivity_pass(Graphcut_remeshing_statistics& stats)
  {
    std::vector<Box>& keep_out = m_keep_out;
    for(int attempt = 0; attempt < 3; ++attempt)
    {
      const Work_mesh mesh_before = m_mesh;
      const Tracking_state state_before = m_state;
      m_state.frozen = m_intersection_frozen;
      m_state.frozen.resize(m_mesh.num_vertices(), 0);
      for(Vertex v : m_mesh.vertices())
        for(const Box& b : keep_out)
          if(b.contains(position(v)))
            m_state.frozen[std::size_t(v)] = 1;
      Connectivity_optimizer optimizer(m_mesh, m_reference, m_state, m_sizing, &m_polylines,
                                       [this](Vertex v, const Vector_3d& x, double bound) { return local_evidence(v, x, bound); });
      const Connectivity_counts counts = optimizer.run();
      m_intersection_frozen.resize(m_mesh.num_vertices(), 0);
      collect_feature_edges();
      // The mesh had no new intersections before the pass: only triangles it changed or moved
      // can have made some.
      m_intersections.connectivity_changed();
      const std::vector<char> changed = changed_vertices(mesh_before, m_mesh);
      const std::vector<std::pair<Face, Face> > fresh = new_self_intersections(&changed);
#ifdef CGAL_GRAPHCUT_REMESHING_VERBOSE
      std::cerr << "connectivity pass, attempt " << attempt << ": " << counts.flips << " flips, "
                << counts.splits << " splits, " << counts.collapses << " collapses, "
                << counts.vertex_splits << " vertex splits, " << counts.relaxed << " relaxed, "
                << fresh.size() << " new intersecting pairs\n";
#endif
      if(fresh.empty())
      {
        stats.number_of_flips += counts.flips;
        stats.number_of_splits += counts.splits;
        stats.number_of_collapses += counts.collapses;
        stats.number_of_vertex_splits += counts.vertex_splits;
        return;
      }
      for(const auto& pair : fresh)
        for(Face f : {pair.first, pair.second})
        {
          Box b;
          for(Vertex u : face_vertices(f))
            b.add(position(u));
          b.grow(2 * m_sizing.mean_length);
          keep_out.push_back(b);
        }
      m_mesh = mesh_before;
      m_state = state_before;
      m_intersections.invalidate();
      collect_feature_edges(); // the undone pass may have split feature edges
      ++stats.number_of_undone_passes;
    }
  }

private:
  struct Box
  {
    Vector_3d low = Vector_3d::Constant(std::numeric_limits<double>::infinity());
    Vector_3d high = Vector_3d::Constant(-std::numeric_limits<double>::infinity());
    void add(const Vector_3d& p) { low = low.cwiseMin(p); high = high.cwiseMax(p); }
    void grow(double r) { low.array() -= r; high.array() += r; }
    bool contains(const Vector_3d& p) const
    {
      return (p.array() >= low.array()).all() && (p.array() <= high.array()).all();
    }
  };

  std::array<Vertex, 3> face_vertices(Face f) const { return Graphcut_remeshing::face_vertices(m_mesh, f); }


  // The halfedges of f to its vertices, in the order of face_vertices(f).
  std::array<Halfedge, 3> halfedges_to_vertices(Face f) const
  {
    const Halfedge h = m_mesh.halfedge(f);
    return {{m_mesh.prev(h), h, m_mesh.next(h)}};
  }

  // The feature edges of the working mesh and their slots (splits of sharp edges add some).
  void collect_feature_edges()
  {
    m_feature_edges.clear();
    m_feature_edge_slot.assign(m_mesh.num_edges(), Binary_graph_cut::none);
    for(Edge e : m_mesh.edges())
      if(m_state.feature_edge[std::size_t(e)])
      {
        m_feature_edge_slot[std::size_t(e)] = m_feature_edges.size();
        m_feature_edges.push_back(e);
      }
  }

  // F of eq. (4) in the frame at the point of the reference triangles closest to x, searched from
  // the triangle `hint`.
  double squared_distance(const Vector_3d& x, Face hint) const
  {
    return m_reference.approximate_squared_distance(x, hint, m_options.weights.epsilon);
  }

  // lambda_data F(x) for a free vertex; vertices on features lie on the reference polylines by
  // construction and fixed vertices do not move, so they have no data term.
  // The search starts from `hint`, by default the vertex's triangle.
  double data_energy(Vertex v, const Vector_3d& x, Face hint = Work_mesh::null_face()) const
  {
    if(kind_of(v) != Vertex_kind::free_vertex)
      return 0;
    return m_options.weights.lambda_data *
           squared_distance(x, hint != Work_mesh::null_face() ? hint : m_state.vertex_hint[std::size_t(v)]);
  }

  // The terms of eq. (1) that belong to triangle f at positions (a, b, c): its shape, and beyond
  // the paper a data term at its centroid, so that a triangle cutting a chord through a curved
  // part of the reference pays for it even when its vertices lie on the reference.
  double triangle_energy(Face f, const Vector_3d& a, const Vector_3d& b, const Vector_3d& c) const
  {
    return triangle_shape_term(a, b, c) + triangle_data_term(f, a, b, c);
  }

  double triangle_shape_term(const Vector_3d& a, const Vector_3d& b, const Vector_3d& c) const
  {
    return m_options.weights.lambda_shape * shape_energy(a, b, c);
  }

  double triangle_data_term(Face f, const Vector_3d& a, const Vector_3d& b, const Vector_3d& c) const
  {
    return m_options.weights.face_data_weight * m_options.weights.lambda_data *
           squared_distance((a + b + c) / 3, m_state.face_hint[std::size_t(f)]);
  }

  // Beyond the paper: the data term at the midpoint of the i-th feature edge (a, b). Feature
  // vertices lie on the reference polylines, but an edge between two of them is a chord that
  // leaves a curved feature line; this term makes it pay for that.
  double feature_edge_energy(std::size_t i, const Vector_3d& a, const Vector_3d& b) const
  {
    return m_options.weights.feature_data_weight * m_options.weights.lambda_data *
           squared_distance((a + b) / 2, m_state.edge_hint[std::size_t(m_feature_edges[i])]);
  }

  // eq. (7) at the current position of v, from the terms kept: local_evidence(v, position(v)).
  double current_local_evidence(Vertex v) const
  {
    double u = m_vertex_term[std::size_t(v)];
    for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      if(!m_mesh.is_border(h))
        u += m_face_term[std::size_t(m_mesh.face(h))];
    if(kind_of(v) == Vertex_kind::feature_vertex)
      for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      {
        const std::size_t i = m_feature_edge_slot[std::size_t(m_mesh.edge(h))];
        if(i != Binary_graph_cut::none)
          u += m_edge_term[i];
      }
    return u;
  }

  // The terms of eq. (1) at the current positions: all of them (after the mesh changed), or those
  // that depend on a vertex with moved[v] set. The tracking hints only ever move to where the
  // closest-point descent from the previous hint ends, so the terms stay exact when they change.
  void compute_terms()
  {
    m_face_term.assign(m_mesh.num_faces(), 0);
    m_vertex_term.assign(m_mesh.num_vertices(), 0);
    m_edge_term.assign(m_feature_edges.size(), 0);
    for_each_face([&](Face f) { m_face_term[std::size_t(f)] = current_triangle_energy(f); });
    for_each_vertex([&](Vertex v) { m_vertex_term[std::size_t(v)] = data_energy(v, position(v)); });
    for(std::size_t i = 0; i < m_feature_edges.size(); ++i)
      m_edge_term[i] = current_feature_edge_energy(i);
  }

  // After a relocation, the terms that depend on a vertex with moved[v]. A moved vertex's data
  // term (`data`, by vertex) and the terms of the triangles where it alone moved were evaluated
  // at its candidate already, with the same hints; the others are evaluated again.
  void update_terms_after_relocation(const std::vector<char>& moved, const std::vector<double>& data)
  {
    for_each_face([&](Face f) {
      const std::array<Vertex, 3> t = face_vertices(f);
      const int count = moved[std::size_t(t[0])] + moved[std::size_t(t[1])] + moved[std::size_t(t[2])];
      if(count == 1)
        m_face_term[std::size_t(f)] =
          m_proposal_face_term[std::size_t(halfedges_to_vertices(f)[moved[std::size_t(t[0])] ? 0 : (moved[std::size_t(t[1])] ? 1 : 2)])];
      else if(count > 1)
        m_face_term[std::size_t(f)] = current_triangle_energy(f);
    });
    for_each_vertex([&](Vertex v) {
      if(moved[std::size_t(v)])
        m_vertex_term[std::size_t(v)] = data[std::size_t(v)];
    });
    for(std::size_t i = 0; i < m_feature_edges.size(); ++i)
    {
      const Halfedge h = m_mesh.halfedge(m_feature_edges[i]);
      if(moved[std::size_t(m_mesh.source(h))] || moved[std::size_t(m_mesh.target(h))])
        m_edge_term[i] = current_feature_edge_energy(i);
    }
  }

  double current_triangle_energy(Face f) const
  {
    const std::array<Vertex, 3> t = face_vertices(f);
    return triangle_energy(f, position(t[0]), position(t[1]), position(t[2]));
  }

  double current_feature_edge_energy(std::size_t i) const
  {
    const Halfedge h = m_mesh.halfedge(m_feature_edges[i]);
    return feature_edge_energy(i, position(m_mesh.source(h)), position(m_mesh.target(h)));
  }

  // What the local evidence of a vertex v reads of the mesh, gathered once for all the positions
  // of v it is evaluated at: the triangles around v with their corners (v's to be replaced by the
  // position), and for a vertex on a feature its feature edges with their other ends.
  struct Star
  {
    struct Triangle
    {
      Halfedge h;                       // to v
      std::array<Vector_3d, 3> corners; // in the order of the face's vertices
      int slot;                         // which corner is v
    };
    Vertex v;
    boost::container::small_vector<Triangle, 12> triangles;
    boost::container::small_vector<std::pair<std::size_t, Vector_3d>, 4> feature_edges; // slot, other end
  };

  Star star(Vertex v) const
  {
    Star s;
    s.v = v;
    for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
    {
      if(!m_mesh.is_border(h))
      {
        const std::array<Vertex, 3> t = face_vertices(m_mesh.face(h));
        Star::Triangle triangle{h, {}, 0};
        for(int i = 0; i < 3; ++i)
        {
          triangle.corners[i] = position(t[i]);
          if(t[i] == v)
            triangle.slot = i;
        }
        s.triangles.push_back(triangle);
      }
      if(kind_of(v) == Vertex_kind::feature_vertex)
      {
        const std::size_t i = m_feature_edge_slot[std::size_t(m_mesh.edge(h))];
        if(i != Binary_graph_cut::none)
          s.feature_edges.emplace_back(i, position(m_mesh.source(h)));
      }
    }
    return s;
  }

  // eq. (7): the energy terms that depend on the position x of vertex v. The terms are not
  // negative: once their sum reaches `bound` the rest is not evaluated (a candidate that reaches
  // the current local evidence is refused whatever the rest adds). The shape terms come first:
  // they need no search on the reference.
  //
  // With `record`, the terms of each triangle are also written there, at the index of the
  // triangle's halfedge to v. `hint` is where the search for the data term of v starts.
  double local_evidence(const Star& s, const Vector_3d& x, double bound = std::numeric_limits<double>::infinity(),
                        std::vector<double>* record = nullptr, Face hint = Work_mesh::null_face()) const
  {
    boost::container::small_vector<double, 12> shape;
    double u = 0;
    for(const Star::Triangle& t : s.triangles)
    {
      std::array<Vector_3d, 3> p = t.corners;
      p[t.slot] = x;
      shape.push_back(triangle_shape_term(p[0], p[1], p[2]));
      u += shape.back();
      if(!(u < bound))
        return u;
    }
    u += data_energy(s.v, x, hint);
    for(std::size_t k = 0; k < s.triangles.size(); ++k)
    {
      if(!(u < bound))
        return u;
      std::array<Vector_3d, 3> p = s.triangles[k].corners;
      p[s.triangles[k].slot] = x;
      const double data = triangle_data_term(m_mesh.face(s.triangles[k].h), p[0], p[1], p[2]);
      if(record)
        (*record)[std::size_t(s.triangles[k].h)] = shape[k] + data;
      u += data;
    }
    for(const auto& e : s.feature_edges)
      u += feature_edge_energy(e.first, x, e.second);
    return u;
  }

  double local_evidence(Vertex v, const Vector_3d& x, double bound = std::numeric_limits<double>::infinity()) const
  {
    return local_evidence(star(v), x, bound);
  }

  // Section 2.1's tracking: the closest reference vertex y_s0 by local search, and the nearest
  // reference triangles of vertices and centroids (caching where the descent ends does not change
  // any term at the current positions). Both searches end where they start when they start where
  // they last ended: only the vertices moved since, and the elements with one, are searched.
  void update_tracking()
  {
    auto untracked = [&](Vertex v) { return m_untracked[std::size_t(v)] != 0; };
    for_each_vertex([&](Vertex v) {
      if(!untracked(v))
        return;
      if(kind_of(v) == Vertex_kind::feature_vertex)
      {
        // On its polyline: the reference elements come with its place there.
        const Location& l = m_state.location[std::size_t(v)];
        const Halfedge h = m_reference_mesh.is_border(l.h) ? m_reference_mesh.opposite(l.h) : l.h;
        m_state.closest[std::size_t(v)] = m_polylines.nearest_vertex(l);
        m_state.vertex_hint[std::size_t(v)] = m_reference_mesh.face(h);
      }
      if(kind_of(v) != Vertex_kind::free_vertex)
        return;
      const Vector_3d x = position(v);
      m_state.closest[std::size_t(v)] = m_reference.closest_vertex(x, m_state.closest[std::size_t(v)]);
      m_reference.closest_point(x, m_state.vertex_hint[std::size_t(v)]);
    });
    for_each_face([&](Face f) {
      const std::array<Vertex, 3> t = face_vertices(f);
      if(untracked(t[0]) || untracked(t[1]) || untracked(t[2]))
        m_reference.closest_point((position(t[0]) + position(t[1]) + position(t[2])) / 3,
                                  m_state.face_hint[std::size_t(f)]);
    });
    for(std::size_t i = 0; i < m_feature_edges.size(); ++i)
    {
      const Halfedge h = m_mesh.halfedge(m_feature_edges[i]);
      if(untracked(m_mesh.source(h)) || untracked(m_mesh.target(h)))
        m_reference.closest_point((position(m_mesh.source(h)) + position(m_mesh.target(h))) / 2,
                                  m_state.edge_hint[std::size_t(m_feature_edges[i])]);
    }
    std::fill(m_untracked.begin(), m_untracked.end(), 0);
  }

  // function(v) for every vertex, function(f) for every face, as independent items.
  template <typename Function>
  void for_each_vertex(const Function& function) const
  {
    for_each_element<Vertex>(m_mesh.num_vertices(), function);
  }

  template <typename Function>
  void for_each_face(const Function& function) const
  {
    for_each_element<Face>(m_mesh.num_faces(), function);
  }

  // The n index slots of one kind, the removed ones left out.
  template <typename Index, typename Function>
  void for_each_element(std::size_t n, const Function& function) const
  {
    for_each_index(n, [&](std::size_t i) {
      const Index x(static_cast<typename Index::size_type>(i));
      if(!m_mesh.is_removed(x))
        function(x);
    });
  }

  // Section 2.3: the first candidate, in the order of the paper, that lies in the freedom sphere
  // and lowers the local evidence. False when there is none. The terms of the triangles around v
  // with v at the candidate go to `face_term`, by the triangles' halfedges to v; a free vertex's
  // candidate lies on the reference triangle `out_face`.
  bool propose(Vertex v, double temperature, bool greedy, CGAL::Random& rng, Vector_3d& out,
               Location& out_location, Face& out_face, std::vector<double>& face_term) const
  {
    if(kind_of(v) == Vertex_kind::fixed_vertex)
      return false;
    const Vector_3d x = position(v);
    const Star around = star(v);
    // The link from the star: around a triangle's halfedge to v come target(next(h)), then source(h).
    Link link;
    for(const Star::Triangle& t : around.triangles)
      link.emplace_back(t.corners[(t.slot + 1) % 3], t.corners[(t.slot + 2) % 3]);
    boost::container::small_vector<Vector_3d, 12> ring; // border neighbours too
    for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      ring.push_back(position(m_mesh.source(h)));
    const double before = current_local_evidence(v);

    if(kind_of(v) == Vertex_kind::feature_vertex)
      return propose_on_feature(around, x, link, before, temperature, greedy, rng, out, out_location, face_term);

    const Local_frame& frame = m_reference.frame(m_state.closest[std::size_t(v)]);
    const double sigma = freedom_radius(temperature, ring_radius(x, link), frame.min_radius());
    if(!(sigma > 0))
      return false;
    Face face = Work_mesh::null_face(); // where the last candidate was brought onto the reference
    auto accept = [&](const Vector_3d& c) {
      if(!((c - x).norm() <= sigma) || !(local_evidence(around, c, before, &face_term, face) < before))
        return false;
      out = c;
      out_face = face;
      return true;
    };
    // Beyond the paper: a tangent-plane move leaves a curved surface by about k d^2 / 2; bringing
    // the candidate back onto the reference triangles keeps the data term near zero, so the shape
    // term alone decides, as the paper intends its tangent moves to.
    auto on_surface = [&](const Vector_3d& c) {
      face = m_state.vertex_hint[std::size_t(v)];
      return m_reference.closest_point(c, face);
    };

    if(!greedy)
    {
      const double gamma = m_options.smoothing_step;
      if(accept(on_surface(x + gamma * tangential(angle_based_target(x, link) - x, frame.normal))))
        return true;
      if(accept(on_surface(x + gamma * tangential(laplacian_target(x, ring) - x, frame.normal))))
        return true;
      // Guided random: a random direction of the tangent plane, a random length in the sphere.
      for(int attempt = 0; attempt < 3; ++attempt)
      {
        const double angle = rng.get_double(0, 2 * pi);
        const double length = sigma * rng.get_double(0.1, 1.0);
        if(accept(on_surface(x + length * (std::cos(angle) * frame.d1 + std::sin(angle) * frame.d2))))
          return true;
      }
      return false;
    }

    // Greedy phase: along the negative gradient of the local evidence (forward differences from
    // its value here, kept), brought back onto the reference like the other candidates.
    const double step = 1e-3 * sigma;
    Vector_3d gradient;
    for(int a = 0; a < 3; ++a)
      gradient[a] = (local_evidence(around, x + Vector_3d::Unit(a) * step) - before) / step;
    if(!(gradient.norm() > 0) || !std::isfinite(gradient.norm()))
      return false;
    const Vector_3d descent = -gradient.normalized();
    for(int attempt = 0; attempt < 3; ++attempt)
      if(accept(on_surface(x + sigma * rng.get_double(0.05, 1.0) * descent)))
        return true;
    return false;
  }

  // Vertices on a feature slide along their reference polyline: the 1D Laplacian towards the
  // middle of their two feature neighbours, or a random (greedy: downhill) slide.
  bool propose_on_feature(const Star& around, const Vector_3d& x, const Link& link, double before, double temperature,
                          bool greedy, CGAL::Random& rng, Vector_3d& out, Location& out_location,
                          std::vector<double>& face_term) const
  {
    const Vertex v = around.v;
    const Location here = m_state.location[std::size_t(v)];
    // The polyline is followed exactly, so its curvature does not limit the sphere.
    const double sigma = freedom_radius(temperature, ring_radius(x, link), 1.0);
    if(!(sigma > 0))
      return false;
    auto accept = [&](const Vector_3d& displacement) {
      const Location l = m_polylines.move(here, displacement);
      const Vector_3d c = m_polylines.point(l);
      if(!((c - x).norm() <= sigma) || (c - x).norm() == 0 || !(local_evidence(around, c, before, &face_term) < before))
        return false;
      out = c;
      out_location = l;
      return true;
    };
    const Vector_3d tangent = m_polylines.tangent(here);

    if(!greedy)
    {
      Vector_3d middle = Vector_3d::Zero();
      int count = 0;
      for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
        if(m_state.feature_edge[std::size_t(m_mesh.edge(h))])
        {
          middle += position(m_mesh.source(h));
          ++count;
        }
      if(count == 2 && accept(m_options.smoothing_step * (middle / 2 - x)))
        return true;
      for(int attempt = 0; attempt < 3; ++attempt)
      {
        const double sign = rng.get_bool() ? 1. : -1.;
        if(accept(sign * sigma * rng.get_double(0.1, 1.0) * tangent))
          return true;
      }
      return false;
    }

    const double step = 1e-3 * sigma;
    const double forward = local_evidence(around, m_polylines.point(m_polylines.move(here, step * tangent)));
    const double backward = local_evidence(around, m_polylines.point(m_polylines.move(here, -step * tangent)));
    if(!(forward != backward))
      return false;
    const Vector_3d descent = forward < backward ? tangent : Vector_3d(-tangent);
    for(int attempt = 0; attempt < 3; ++attempt)
      if(accept(sigma * rng.get_double(0.05, 1.0) * descent))
        return true;
    return false;
  }

  Work_mesh& m_mesh;
  const Work_mesh m_reference_mesh;
  Reference_surface<Work_mesh> m_reference;
  const std::vector<char> m_reference_feature_edge;   // by reference edge
  const std::vector<Vertex_kind> m_reference_kind;    // by reference vertex
  Polylines m_polylines;
  Remeshing_options m_options;
  std::size_t m_round; // relocations so far: with the vertex, it seeds the vertex's random numbers
  Tracking_state m_state;            // kinds, y_s0 (its frame gives the tangent plane and rho), hints
  Sizing m_sizing;
  std::vector<char> m_intersection_frozen; // by vertex: on a face the input made intersect
  std::vector<char> m_untracked;           // by vertex: moved since the last tracking
  std::vector<Box> m_keep_out;             // regions where connectivity changes made intersections
  std::vector<Edge> m_feature_edges; // the feature edges of the working mesh
  std::vector<std::size_t> m_feature_edge_slot; // by edge index: position in m_feature_edges
  std::vector<double> m_face_term;   // by face: its terms of eq. (1) at the current positions
  std::vector<double> m_vertex_term; // by vertex: its data term at its current position
  std::vector<double> m_edge_term;   // by feature-edge slot: its term at the current positions
  std::vector<double> m_proposal_face_term; // by halfedge h: face(h)'s terms with target(h) at its candidate
  Triangle_intersections m_intersections; // of the working mesh; told when its connectivity changes
  std::vector<std::pair<Face, Face> > m_input_intersections; // sorted
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_REMESHER_H
