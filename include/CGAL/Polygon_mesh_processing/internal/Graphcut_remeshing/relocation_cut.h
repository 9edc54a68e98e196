// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The decision of section 2.4 for each relocation: the binary energy of the candidates (keep the
// current position or take the candidate), a table per triangle and per feature edge over its
// moving vertices, handed to the binary graph cut.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_RELOCATION_CUT_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_RELOCATION_CUT_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/binary_graph_cut.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/energy.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/parallel.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/work_mesh.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

class Relocation_cut
{
  using Vertex = Work_mesh::Vertex_index;
  using Halfedge = Work_mesh::Halfedge_index;
  using Face = Work_mesh::Face_index;

public:
  static constexpr std::size_t none = Binary_graph_cut::none;

  Relocation_cut(const Work_mesh& mesh, const Mesh_energy& energy) : m_mesh(mesh), m_energy(energy) {}

  // Frees the tables' arrays: a connectivity pass changes the mesh, and needs the memory more.
  void release() { m_tables = std::vector<Triangle_table>(); }

  // The labels (1: take the candidate) that minimise the binary energy of the candidates: data
  // terms as unaries, triangle terms over the triangles' moving vertices. `moving[i]` is the
  // vertex of variable i (variable[v] is none for the others), at its candidate the data term
  // candidate_data[i]; the excluded candidates cannot be taken.
  std::vector<char> decide(const std::vector<Vertex>& moving, const std::vector<Vector_3d>& candidate,
                           const std::vector<double>& candidate_data, const std::vector<std::size_t>& variable,
                           const std::vector<char>& excluded)
  {
    // A configuration that would fold or flatten a triangle costs more than the whole current
    // energy, so the cut, which never does worse than keeping everything, never picks it.
    const double forbidden = 1e3 * (m_energy.energy() + 1);
    Binary_graph_cut cut(moving.size());
    cut.reserve(m_mesh.number_of_faces() + m_energy.feature_edges().size());
    for(std::size_t i = 0; i < moving.size(); ++i)
      cut.add_unary(i, m_energy.vertex_term(moving[i]), excluded[i] ? forbidden : candidate_data[i]);
    add_triangle_terms(candidate, variable, forbidden, cut);
    add_feature_edge_terms(candidate, variable, cut);
    // The graph lives for this cut only: the largest part of the memory of a large mesh's cut, it
    // would otherwise be held while the next cut's terms are made.
    St_graph graph;
    return cut.solve_and_free_terms(graph);
  }

private:
  // The variables of the moving vertices of a triangle and its energy for each choice of theirs:
  // bit j of the index of `table` says whether the j-th moving vertex takes its candidate.
  struct Triangle_table
  {
    int k = 0; // number of moving vertices
    std::array<std::size_t, 3> var{};
    std::array<double, 8> table{};
  };

  Vector_3d position(Vertex v) const { return to_vector(m_mesh.point(v)); }

  // The tables of the triangles, each on its own, then into the cut in the order of the faces; by
  // blocks, so that the tables of a large mesh are never all in memory. The blocks' array is kept
  // from one cut to the next: each table is written whole.
  void add_triangle_terms(const std::vector<Vector_3d>& candidate, const std::vector<std::size_t>& variable,
                          double forbidden, Binary_graph_cut& cut)
  {
    const std::size_t block = 1 << 15;
    for(std::size_t first = 0; first < m_mesh.num_faces(); first += block)
    {
      m_tables.resize((std::min)(block, m_mesh.num_faces() - first));
      for_each_index(m_tables.size(), [&](std::size_t i) {
        const Face f(static_cast<Face::size_type>(first + i));
        m_tables[i].k = 0;
        if(!m_mesh.is_removed(f))
          fill_triangle_table(f, candidate, variable, forbidden, m_tables[i]);
      });
      for(const Triangle_table& t : m_tables)
      {
        if(t.k == 1)
          cut.add_unary(t.var[0], t.table[0], t.table[1]);
        else if(t.k == 2)
          cut.add_term(t.var[0], t.var[1], none, t.table);
        else if(t.k == 3)
          cut.add_term(t.var[0], t.var[1], t.var[2], t.table);
      }
    }
  }

  void fill_triangle_table(Face f, const std::vector<Vector_3d>& candidate, const std::vector<std::size_t>& variable,
                           double forbidden, Triangle_table& t) const
  {
    const std::array<Vertex, 3> v = face_vertices(m_mesh, f);
    const std::array<Halfedge, 3> to = m_energy.halfedges_to_vertices(f);
    std::array<int, 3> slot{};
    for(int i = 0; i < 3; ++i)
      if(variable[std::size_t(v[i])] != none)
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
        t.table[mask] = m_energy.face_term(f);
      else if(!is_acceptable_triangle(p[0], p[1], p[2], current_normal))
        t.table[mask] = forbidden;
      else if((mask & (mask - 1)) == 0) // one vertex moves: its proposal evaluated this already
        t.table[mask] = m_energy.proposal_face_term(to[slot[mask == 1 ? 0 : (mask == 2 ? 1 : 2)]]);
      else
        t.table[mask] = m_energy.triangle_energy(f, p[0], p[1], p[2]);
    }
  }

  void add_feature_edge_terms(const std::vector<Vector_3d>& candidate, const std::vector<std::size_t>& variable,
                              Binary_graph_cut& cut) const
  {
    for(std::size_t e = 0; e < m_energy.feature_edges().size(); ++e)
    {
      const Halfedge h = m_mesh.halfedge(m_energy.feature_edges()[e]);
      const std::array<Vertex, 2> v{{m_mesh.source(h), m_mesh.target(h)}};
      const std::size_t i = variable[std::size_t(v[0])], j = variable[std::size_t(v[1])];
      const Vector_3d a = position(v[0]), b = position(v[1]);
      const double current = m_energy.edge_term(e);
      if(i != none && j != none)
        cut.add_term(i, j, none,
                     {{current, m_energy.feature_edge_energy(e, candidate[i], b),
                       m_energy.feature_edge_energy(e, a, candidate[j]),
                       m_energy.feature_edge_energy(e, candidate[i], candidate[j]), 0, 0, 0, 0}});
      else if(i != none)
        cut.add_unary(i, current, m_energy.feature_edge_energy(e, candidate[i], b));
      else if(j != none)
        cut.add_unary(j, current, m_energy.feature_edge_energy(e, a, candidate[j]));
    }
  }

  const Work_mesh& m_mesh;
  const Mesh_energy& m_energy;
  std::vector<Triangle_table> m_tables;
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_RELOCATION_CUT_H
