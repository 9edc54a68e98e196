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
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/energy.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/features.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/reference_surface.h>

#include <CGAL/Random.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

using Work_kernel = CGAL::Simple_cartesian<double>;
using Work_mesh = CGAL::Surface_mesh<Work_kernel::Point_3>;

struct Remeshing_options
{
  Energy_weights weights;
  std::size_t number_of_iterations = 150;
  std::size_t number_of_greedy_iterations = 20;
  double initial_temperature = 10;
  double cooling_factor = 0.95;
  double smoothing_step = 0.06; // gamma of section 2.3
  unsigned int random_seed = 0;
};

class Graphcut_remesher
{
  using Vertex = Work_mesh::Vertex_index;
  using Halfedge = Work_mesh::Halfedge_index;
  using Face = Work_mesh::Face_index;
  using Polylines = Feature_polylines<Work_mesh>;
  using Location = Polylines::Location;

public:
  // `mesh` is the working mesh, already in the unit box; `feature_edge` (by edge index) holds
  // the sharp, border and user-constrained edges, `kind` (by vertex index) what each vertex may do.
  Graphcut_remesher(Work_mesh& mesh, std::vector<char> feature_edge, std::vector<Vertex_kind> kind,
                    const Remeshing_options& options)
    : m_mesh(mesh), m_reference_mesh(mesh), m_reference(m_reference_mesh),
      m_feature_edge(std::move(feature_edge)), m_kind(std::move(kind)),
      m_polylines(m_reference_mesh, m_feature_edge, m_kind), m_options(options),
      m_rng(options.random_seed)
  {
    const std::size_t n = m_mesh.number_of_vertices();
    m_closest.resize(n);
    m_location.resize(n);
    for(Vertex v : m_mesh.vertices())
    {
      m_closest[std::size_t(v)] = v; // the working mesh starts as the reference
      if(kind_of(v) == Vertex_kind::feature_vertex)
        m_location[std::size_t(v)] = m_polylines.at_vertex(v);
    }
  }

  Vertex_kind kind_of(Vertex v) const { return m_kind[std::size_t(v)]; }

  Vector_3d position(Vertex v) const { return to_vector(m_mesh.point(v)); }

  // eq. (1)
  double energy() const
  {
    double u = 0;
    for(Face f : m_mesh.faces())
    {
      const Halfedge h = m_mesh.halfedge(f);
      u += m_options.weights.lambda_shape *
           shape_energy(position(m_mesh.target(h)), position(m_mesh.target(m_mesh.next(h))),
                        position(m_mesh.source(h)));
    }
    for(Vertex v : m_mesh.vertices())
      u += data_energy(v, position(v));
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
    update_closest_reference_vertices();

    // Candidates.
    const std::size_t n = m_mesh.number_of_vertices();
    std::vector<std::size_t> variable(n, Binary_graph_cut::none);
    std::vector<Vertex> moving;
    std::vector<Vector_3d> candidate;
    std::vector<Location> candidate_location;
    for(Vertex v : m_mesh.vertices())
    {
      Vector_3d c;
      Location l;
      if(propose(v, temperature, greedy, c, l))
      {
        variable[std::size_t(v)] = moving.size();
        moving.push_back(v);
        candidate.push_back(c);
        candidate_location.push_back(l);
      }
    }
    if(moving.empty())
      return 0;

    // The binary energy: data terms as unaries, shape terms as terms of up to three variables.
    Binary_graph_cut cut(moving.size());
    for(std::size_t i = 0; i < moving.size(); ++i)
      cut.add_unary(i, data_energy(moving[i], position(moving[i])), data_energy(moving[i], candidate[i]));

    // A configuration that would fold or flatten a triangle costs more than the whole current
    // energy, so the cut, which never does worse than keeping everything, never picks it.
    const double forbidden = 1e3 * (energy() + 1);
    for(Face f : m_mesh.faces())
    {
      const Halfedge h = m_mesh.halfedge(f);
      const std::array<Vertex, 3> v{{m_mesh.target(h), m_mesh.target(m_mesh.next(h)), m_mesh.source(h)}};
      std::array<std::size_t, 3> var{}, slot{};
      int k = 0;
      for(int i = 0; i < 3; ++i)
        if(variable[std::size_t(v[i])] != Binary_graph_cut::none)
        {
          var[k] = variable[std::size_t(v[i])];
          slot[k] = i;
          ++k;
        }
      if(k == 0)
        continue;
      const std::array<Vector_3d, 3> current{{position(v[0]), position(v[1]), position(v[2])}};
      const Vector_3d current_normal = area_vector(current[0], current[1], current[2]);
      std::array<double, 8> table{};
      for(int mask = 0; mask < (1 << k); ++mask)
      {
        std::array<Vector_3d, 3> p = current;
        for(int j = 0; j < k; ++j)
          if((mask >> j) & 1)
            p[slot[j]] = candidate[var[j]];
        if(mask != 0 && !is_acceptable_triangle(p[0], p[1], p[2], current_normal))
          table[mask] = forbidden;
        else
          table[mask] = m_options.weights.lambda_shape * shape_energy(p[0], p[1], p[2]);
      }
      if(k == 1)
        cut.add_unary(var[0], table[0], table[1]);
      else if(k == 2)
        cut.add_term(var[0], var[1], Binary_graph_cut::none, table);
      else
        cut.add_term(var[0], var[1], var[2], table);
    }

    const std::vector<char> labels = cut.solve();
    std::size_t moved = 0;
    for(std::size_t i = 0; i < moving.size(); ++i)
      if(labels[i])
      {
        const Vector_3d& c = candidate[i];
        m_mesh.point(moving[i]) = Work_kernel::Point_3(c.x(), c.y(), c.z());
        if(kind_of(moving[i]) == Vertex_kind::feature_vertex)
          m_location[std::size_t(moving[i])] = candidate_location[i];
        ++moved;
      }
    return moved;
  }

  const Reference_surface<Work_mesh>& reference() const { return m_reference; }

private:
  // lambda_data F(x) for a free vertex; vertices on features lie on the reference polylines by
  // construction and fixed vertices do not move, so they have no data term.
  double data_energy(Vertex v, const Vector_3d& x) const
  {
    if(kind_of(v) != Vertex_kind::free_vertex)
      return 0;
    return m_options.weights.lambda_data * squared_distance(x, m_closest[std::size_t(v)]);
  }

  // F of eq. (4) in the frame at the closest point of the reference triangles around `near`.
  double squared_distance(const Vector_3d& x, Vertex near) const
  {
    return squared_distance_approximation(x, m_reference.frame_at_closest_point(x, near),
                                          m_options.weights.epsilon);
  }

  // eq. (7): the energy terms that depend on the position x of vertex v.
  double local_evidence(Vertex v, const Vector_3d& x) const
  {
    double u = data_energy(v, x);
    for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
      if(!m_mesh.is_border(h))
        u += m_options.weights.lambda_shape *
             shape_energy(x, position(m_mesh.target(m_mesh.next(h))), position(m_mesh.source(h)));
    return u;
  }

  // Section 2.1's tracking: move each free vertex's reference to a closer reference vertex, when
  // that does not raise its data term (so the energy stays monotone from one iteration to the next).
  void update_closest_reference_vertices()
  {
    for(Vertex v : m_mesh.vertices())
    {
      if(kind_of(v) != Vertex_kind::free_vertex)
        continue;
      const Vector_3d x = position(v);
      const Vertex old_ref = m_closest[std::size_t(v)];
      const Vertex new_ref = m_reference.closest_vertex(x, old_ref);
      if(new_ref == old_ref)
        continue;
      if(squared_distance(x, new_ref) <= squared_distance(x, old_ref))
        m_closest[std::size_t(v)] = new_ref;
    }
  }

  // Section 2.3: the first candidate, in the order of the paper, that lies in the freedom sphere
  // and lowers the local evidence. False when there is none.
  bool propose(Vertex v, double temperature, bool greedy, Vector_3d& out, Location& out_location)
  {
    if(kind_of(v) == Vertex_kind::fixed_vertex)
      return false;
    const Vector_3d x = position(v);
    Link link;
    std::vector<Vector_3d> ring;
    for(Halfedge h : halfedges_around_target(m_mesh.halfedge(v), m_mesh))
    {
      ring.push_back(position(m_mesh.source(h)));
      if(!m_mesh.is_border(h))
        link.emplace_back(position(m_mesh.target(m_mesh.next(h))), position(m_mesh.source(h)));
    }
    const double before = local_evidence(v, x);

    if(kind_of(v) == Vertex_kind::feature_vertex)
      return propose_on_feature(v, x, link, before, temperature, greedy, out, out_location);

    const Local_frame& frame = m_reference.frame(m_closest[std::size_t(v)]);
    const double sigma = freedom_radius(temperature, ring_radius(x, link), frame.min_radius());
    if(!(sigma > 0))
      return false;
    auto accept = [&](const Vector_3d& c) {
      if(!((c - x).norm() <= sigma) || !(local_evidence(v, c) < before))
        return false;
      out = c;
      return true;
    };

    if(!greedy)
    {
      const double gamma = m_options.smoothing_step;
      if(accept(x + gamma * tangential(angle_based_target(x, link) - x, frame.normal)))
        return true;
      if(accept(x + gamma * tangential(laplacian_target(x, ring) - x, frame.normal)))
        return true;
      // Guided random: a random direction of the tangent plane, a random length in the sphere.
      for(int attempt = 0; attempt < 3; ++attempt)
      {
        const double angle = m_rng.get_double(0, 2 * pi);
        const double length = sigma * m_rng.get_double(0.1, 1.0);
        if(accept(x + length * (std::cos(angle) * frame.d1 + std::sin(angle) * frame.d2)))
          return true;
      }
      return false;
    }

    // Greedy phase: along the negative gradient of the local evidence (central differences).
    const double step = 1e-3 * sigma;
    Vector_3d gradient;
    for(int a = 0; a < 3; ++a)
    {
      const Vector_3d e = Vector_3d::Unit(a) * step;
      gradient[a] = (local_evidence(v, x + e) - local_evidence(v, x - e)) / (2 * step);
    }
    if(!(gradient.norm() > 0) || !std::isfinite(gradient.norm()))
      return false;
    const Vector_3d descent = -gradient.normalized();
    for(int attempt = 0; attempt < 3; ++attempt)
      if(accept(x + sigma * m_rng.get_double(0.05, 1.0) * descent))
        return true;
    return false;
  }

  // Vertices on a feature slide along their reference polyline: the 1D Laplacian towards the
  // middle of their two feature neighbours, or a random (greedy: downhill) slide.
  bool propose_on_feature(Vertex v, const Vector_3d& x, const Link& link, double before,
                          double temperature, bool greedy, Vector_3d& out, Location& out_location)
  {
    const Location here = m_location[std::size_t(v)];
    // The polyline is followed exactly, so its curvature does not limit the sphere.
    const double sigma = freedom_radius(temperature, ring_radius(x, link), 1.0);
    if(!(sigma > 0))
      return false;
    auto accept = [&](const Vector_3d& displacement) {
      const Location l = m_polylines.move(here, displacement);
      const Vector_3d c = m_polylines.point(l);
      if(!((c - x).norm() <= sigma) || (c - x).norm() == 0 || !(local_evidence(v, c) < before))
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
        if(m_feature_edge[std::size_t(m_mesh.edge(h))])
        {
          middle += position(m_mesh.source(h));
          ++count;
        }
      if(count == 2 && accept(m_options.smoothing_step * (middle / 2 - x)))
        return true;
      for(int attempt = 0; attempt < 3; ++attempt)
      {
        const double sign = m_rng.get_bool() ? 1. : -1.;
        if(accept(sign * sigma * m_rng.get_double(0.1, 1.0) * tangent))
          return true;
      }
      return false;
    }

    const double step = 1e-3 * sigma;
    const double forward = local_evidence(v, m_polylines.point(m_polylines.move(here, step * tangent)));
    const double backward = local_evidence(v, m_polylines.point(m_polylines.move(here, -step * tangent)));
    if(!(forward != backward))
      return false;
    const Vector_3d descent = forward < backward ? tangent : Vector_3d(-tangent);
    for(int attempt = 0; attempt < 3; ++attempt)
      if(accept(sigma * m_rng.get_double(0.05, 1.0) * descent))
        return true;
    return false;
  }

  Work_mesh& m_mesh;
  const Work_mesh m_reference_mesh;
  Reference_surface<Work_mesh> m_reference;
  std::vector<char> m_feature_edge;
  std::vector<Vertex_kind> m_kind;
  Polylines m_polylines;
  Remeshing_options m_options;
  CGAL::Random m_rng;
  std::vector<Vertex> m_closest;     // y_s0 of each vertex
  std::vector<Location> m_location;  // place on the reference polyline of each feature vertex
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_REMESHER_H
