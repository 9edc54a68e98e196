// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The s-t graph of the binary graph cut and its minimum cut by Boost.Graph's
// boykov_kolmogorov_max_flow. The graph is a model of Boost.Graph's VertexListGraph,
// EdgeListGraph and IncidenceGraph over flat arrays: the arcs of a node are contiguous (as in a
// compressed sparse row graph), each has its reverse, and the capacities, residuals, parents,
// trees and distances the algorithm reads and writes are vectors indexed by node or arc. The
// capacities are in single precision: they are the largest array of a large mesh's cut, and the
// caller checks what the cut chose in double precision (remesher.h). The arrays of a graph kept
// from one cut to the next only grow.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_ST_GRAPH_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_ST_GRAPH_H

#include <CGAL/assertions.h>

#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#include <boost/graph/graph_traits.hpp>
#include <boost/graph/properties.hpp>
#include <boost/iterator/counting_iterator.hpp>
#include <boost/iterator/iterator_facade.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {
// Its own namespace: the free functions of the graph concepts are found by argument-dependent
// lookup and hide nothing of the package's.
namespace st_graph {

using Index = std::uint32_t; // nodes and arcs: a large mesh has tens of millions of arcs

// An arc (Boost.Graph's edge descriptor): its tail and its place in the arrays.
struct Arc
{
  Index tail = 0;
  Index index = 0;
  bool operator==(const Arc& other) const { return index == other.index && tail == other.tail; }
  bool operator!=(const Arc& other) const { return !(*this == other); }
};

class St_graph;

// The arcs of a node, or with `all`, the arcs of every node, in the order of the arrays.
class Arc_iterator : public boost::iterator_facade<Arc_iterator, Arc, boost::forward_traversal_tag, Arc>
{
public:
  Arc_iterator() = default;
  Arc_iterator(const Index* first, Index tail, Index index, Index last_tail)
    : m_first(first), m_arc{tail, index}, m_last_tail(last_tail)
  {
    skip_empty_nodes();
  }

private:
  friend class boost::iterator_core_access;
  Arc dereference() const { return m_arc; }
  bool equal(const Arc_iterator& other) const { return m_arc.index == other.m_arc.index; }
  void increment()
  {
    ++m_arc.index;
    skip_empty_nodes();
  }
  // Over all arcs: the tail follows the index across nodes (m_last_tail is that of a node's
  // arcs alone).
  void skip_empty_nodes()
  {
    while(m_arc.tail < m_last_tail && m_arc.index == m_first[m_arc.tail + 1])
      ++m_arc.tail;
  }

  const Index* m_first = nullptr;
  Arc m_arc;
  Index m_last_tail = 0;
};

class St_graph
{
public:
  using Index = st_graph::Index;
  using Capacity = float;

  // What boost::graph_traits reads.
  using vertex_descriptor = Index;
  using edge_descriptor = Arc;
  using directed_category = boost::directed_tag;
  using edge_parallel_category = boost::allow_parallel_edge_tag;
  struct traversal_category : boost::incidence_graph_tag, boost::vertex_list_graph_tag, boost::edge_list_graph_tag {};
  using vertex_iterator = boost::counting_iterator<Index>;
  using out_edge_iterator = Arc_iterator;
  using edge_iterator = Arc_iterator;
  using vertices_size_type = Index;
  using edges_size_type = Index;
  using degree_size_type = Index;
  static Index null_vertex() { return (std::numeric_limits<Index>::max)(); }

  // The nodes are 0 .. n - 1, then the terminals: source() = n, sink() = n + 1.
  void reset(std::size_t number_of_nodes)
  {
    CGAL_precondition(number_of_nodes + 2 < std::size_t((std::numeric_limits<Index>::max)()));
    m_nodes = Index(number_of_nodes);
    m_terminal.assign(number_of_nodes, 0.);
    m_first.assign(number_of_nodes + 3, 0);
    m_fill.clear();
    m_laid_out = false;
  }

  Index number_of_nodes() const { return m_nodes; }
  Index source() const { return m_nodes; }
  Index sink() const { return m_nodes + 1; }

  // The capacities of the terminal arcs of node i: only their difference matters to the cut, and
  // a node gets one arc, from the source (a positive difference) or to the sink, or none.
  void add_terminal_capacities(Index i, double from_source, double to_sink)
  {
    m_terminal[i] += from_source - to_sink;
  }

  // The arcs between nodes are given twice: all of them to count_arc() first (after the terminal
  // capacities), then all of them, in any order, to add_arc().
  void count_arc(Index u, Index v)
  {
    ++m_first[u + 1];
    ++m_first[v + 1];
  }

  // The arc u -> v of the given capacity and its reverse v -> u of `reverse_capacity`.
  void add_arc(Index u, Index v, double capacity, double reverse_capacity)
  {
    if(!m_laid_out)
      lay_out();
    link(u, v, capacity, reverse_capacity);
  }

  // The maximum flow, by boykov_kolmogorov_max_flow. Afterwards a node is on the source side of
  // the minimum cut when it ends in the source's search tree, that is when the residual graph
  // still reaches it from the source: that side is the smallest of the minimum cuts.
  double solve()
  {
    if(!m_laid_out)
      lay_out();
    m_fill = std::vector<Index>();
    const std::size_t n = std::size_t(m_nodes) + 2;
    make_room(m_parent, n);
    make_room(m_color, n);
    make_room(m_distance, n);
    const auto node = boost::typed_identity_property_map<Index>();
    // The residual capacities are the capacities, changed in place: the algorithm reads the
    // capacity map only to start the residuals from it, and a large mesh has tens of millions of
    // arcs. So the capacities are gone once the flow is pushed.
    const auto residual = boost::make_iterator_property_map(m_capacity.data(), Arc_index());
    return boost::boykov_kolmogorov_max_flow(
      *this, residual, residual, Reverse_arc{this},
      boost::make_iterator_property_map(m_parent.data(), node), boost::make_iterator_property_map(m_color.data(), node),
      boost::make_iterator_property_map(m_distance.data(), node), node, source(), sink());
  }

  bool is_on_source_side(Index i) const { return m_color[i] == boost::black_color; }

  // What Boost.Graph reads.
  Index number_of_arcs() const { return Index(m_head.size()); }
  Index first_arc(Index u) const { return m_first[u]; }
  Index head(Index a) const { return m_head[a]; }
  Index reverse(Index a) const { return m_reverse[a]; }
  double capacity(Index a) const { return double(m_capacity[a]); } // the residual one after solve()
  const Index* first_arcs() const { return m_first.data(); }

private:
  // The index of an arc in the arrays, for the arc property maps.
  struct Arc_index
  {
    using key_type = Arc;
    using value_type = Index;
    using reference = Index;
    using category = boost::readable_property_map_tag;
    friend Index get(Arc_index, const Arc& a) { return a.index; }
  };

  struct Reverse_arc
  {
    using key_type = Arc;
    using value_type = Arc;
    using reference = Arc;
    using category = boost::readable_property_map_tag;
    const St_graph* graph;
    friend Arc get(const Reverse_arc& r, const Arc& a) { return Arc{r.graph->head(a.index), r.graph->reverse(a.index)}; }
  };

  // Where each node's arcs start, then its terminal arc first: the algorithm's first step looks
  // a node's sink arc up among its arcs.
  void lay_out()
  {
    const Index s = source(), t = sink();
    for(Index i = 0; i < m_nodes; ++i)
      if(m_terminal[i] != 0)
      {
        ++m_first[i + 1];
        ++m_first[(m_terminal[i] > 0 ? s : t) + 1];
      }
    for(std::size_t u = 1; u < m_first.size(); ++u)
      m_first[u] += m_first[u - 1];
    const std::size_t m = m_first.back();
    make_room(m_head, m);
    make_room(m_reverse, m);
    make_room(m_capacity, m);
    m_fill.assign(m_first.begin(), m_first.end() - 1);
    m_laid_out = true;
    for(Index i = 0; i < m_nodes; ++i)
      if(m_terminal[i] > 0)
        link(s, i, m_terminal[i], 0.);
      else if(m_terminal[i] < 0)
        link(i, t, -m_terminal[i], 0.);
    m_terminal = std::vector<double>();
  }

  // n entries, whose values are all written afterwards: when the array has to grow, it does not
  // copy what it held, and (but in a fresh graph) takes room for a sixteenth more, not twice as
  // many, for a caller that keeps the graph from one cut to the next (a large mesh's arrays are
  // tens of megabytes).
  template <typename T>
  static void make_room(std::vector<T>& a, std::size_t n)
  {
    if(a.capacity() < n)
    {
      const bool fresh = a.capacity() == 0;
      a = std::vector<T>();
      a.reserve(fresh ? n : n + n / 16);
    }
    a.resize(n);
  }

  void link(Index u, Index v, double capacity, double reverse_capacity)
  {
    const Index a = m_fill[u]++, b = m_fill[v]++;
    m_head[a] = v;
    m_head[b] = u;
    m_reverse[a] = b;
    m_reverse[b] = a;
    m_capacity[a] = Capacity(capacity);
    m_capacity[b] = Capacity(reverse_capacity);
  }

  Index m_nodes = 0;
  bool m_laid_out = false;
  std::vector<double> m_terminal;    // by node, until laid out: source capacity minus sink capacity
  std::vector<Index> m_first;        // by node, then one past the last: its first arc
  std::vector<Index> m_fill;         // by node, while the arcs are added: its next arc
  std::vector<Index> m_head;         // by arc
  std::vector<Index> m_reverse;      // by arc
  std::vector<Capacity> m_capacity;  // by arc; the residual capacity once solved
  std::vector<Arc> m_parent;         // by node, written by the algorithm
  std::vector<boost::default_color_type> m_color; // by node: its search tree at the end
  std::vector<Index> m_distance;     // by node, written by the algorithm
};

// Boost.Graph's free functions of the concepts, found by argument-dependent lookup.
inline Index num_vertices(const St_graph& g) { return g.number_of_nodes() + 2; }
inline Index num_edges(const St_graph& g) { return g.number_of_arcs(); }
inline std::pair<boost::counting_iterator<Index>, boost::counting_iterator<Index> > vertices(const St_graph& g)
{
  return {boost::counting_iterator<Index>(0), boost::counting_iterator<Index>(num_vertices(g))};
}
inline std::pair<Arc_iterator, Arc_iterator> out_edges(Index u, const St_graph& g)
{
  return {Arc_iterator(g.first_arcs(), u, g.first_arc(u), u), Arc_iterator(g.first_arcs(), u, g.first_arc(u + 1), u)};
}
inline Index out_degree(Index u, const St_graph& g) { return g.first_arc(u + 1) - g.first_arc(u); }
inline std::pair<Arc_iterator, Arc_iterator> edges(const St_graph& g)
{
  const Index last = num_vertices(g);
  return {Arc_iterator(g.first_arcs(), 0, 0, last), Arc_iterator(g.first_arcs(), last, g.number_of_arcs(), last)};
}
inline Index source(const Arc& a, const St_graph&) { return a.tail; }
inline Index target(const Arc& a, const St_graph& g) { return g.head(a.index); }

} // namespace st_graph

using st_graph::St_graph;

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_ST_GRAPH_H
