// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The s-t minimum cut of the binary graph cut: Boykov and Kolmogorov's augmenting-path algorithm
// (two search trees, one from each terminal, grown until they touch, then repaired after each
// augmentation by adopting orphans; "An experimental comparison of min-cut/max-flow algorithms",
// PAMI 2004). The terminals are not nodes: each node keeps its residual capacity to them, so that
// no node carries the thousands of terminal arcs of a graph where nearly every node has one.
// The arcs are laid out by tail in flat arrays, each with its reverse.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_MAX_FLOW_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_MAX_FLOW_H

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

class Max_flow
{
public:
  using Index = std::uint32_t; // nodes and arcs

  explicit Max_flow(std::size_t number_of_nodes)
    : m_first(number_of_nodes + 1, 0), m_terminal(number_of_nodes, 0.)
  {
    CGAL_precondition(number_of_nodes < std::size_t(orphan));
  }

  // Capacities of the arcs source -> i and i -> sink; only their difference matters to the cut.
  void add_terminal_capacities(Index i, double from_source, double to_sink) { m_terminal[i] += from_source - to_sink; }

  // The arcs between nodes are given twice: all of them to count_arc() first, then all of them,
  // in any order, to add_arc().
  void count_arc(Index u, Index v)
  {
    ++m_first[u + 1];
    ++m_first[v + 1];
  }

  // The arc u -> v of the given capacity and its reverse v -> u of `reverse_capacity`.
  void add_arc(Index u, Index v, double capacity, double reverse_capacity)
  {
    if(m_fill.empty())
      lay_out();
    const Index a = m_fill[u]++, b = m_fill[v]++;
    m_head[a] = v;
    m_head[b] = u;
    m_sister[a] = b;
    m_sister[b] = a;
    m_residual[a] = capacity;
    m_residual[b] = reverse_capacity;
  }

  // Pushes a maximum flow. Afterwards a node is on the source side of the minimum cut when the
  // residual graph still reaches it from the source: that side is the smallest of the minimum cuts.
  void solve()
  {
    if(m_fill.empty())
      lay_out();
    const std::size_t n = m_terminal.size();
    m_parent.assign(n, no_arc);
    m_sink_tree.assign(n, 0);
    m_stamp.assign(n, 0);
    m_distance.assign(n, 0);
    m_active.assign(n, 0);
    m_queue.clear();
    m_front = 0;
    m_time = 0;
    for(std::size_t i = 0; i < n; ++i)
      if(m_terminal[i] != 0)
      {
        m_parent[i] = terminal;
        m_sink_tree[i] = m_terminal[i] < 0;
        m_distance[i] = 1;
        activate(Index(i));
      }

    Index current = no_node;
    for(;;)
    {
      Index i = no_node;
      if(current != no_node)
      {
        m_active[current] = 0;
        if(m_parent[current] != no_arc)
          i = current;
      }
      if(i == no_node)
        i = next_active();
      if(i == no_node)
        break;

      // Grow the tree of i by its free neighbours; stop at the first arc to the other tree.
      Index middle = no_arc; // from the source tree to the sink tree
      for(Index a = m_first[i]; a < m_first[i + 1]; ++a)
      {
        const Index j = m_head[a];
        if(!m_sink_tree[i] ? !(m_residual[a] > 0) : !(m_residual[m_sister[a]] > 0))
          continue;
        if(m_parent[j] == no_arc)
        {
          m_sink_tree[j] = m_sink_tree[i];
          m_parent[j] = m_sister[a];
          m_stamp[j] = m_stamp[i];
          m_distance[j] = m_distance[i] + 1;
          activate(j);
        }
        else if(m_sink_tree[j] != m_sink_tree[i])
        {
          middle = m_sink_tree[i] ? m_sister[a] : a;
          break;
        }
        else if(m_stamp[j] <= m_stamp[i] && m_distance[j] > m_distance[i])
        {
          // A shorter way to the terminal, as of a time no older.
          m_parent[j] = m_sister[a];
          m_stamp[j] = m_stamp[i];
          m_distance[j] = m_distance[i] + 1;
        }
      }
      ++m_time;
      if(middle == no_arc)
      {
        current = no_node;
        continue;
      }
      // i stays the node grown next, unless the repair frees it.
      m_active[i] = 1;
      current = i;
      augment(middle);
      for(std::size_t k = 0; k < m_orphans.size(); ++k)
        adopt(m_orphans[k]);
      m_orphans.clear();
    }
  }

  bool is_on_source_side(Index i) const { return m_parent[i] != no_arc && !m_sink_tree[i]; }

private:
  static constexpr Index no_arc = (std::numeric_limits<Index>::max)(); // a free node's parent
  static constexpr Index terminal = no_arc - 1;                        // a child of its terminal
  static constexpr Index orphan = no_arc - 2;                          // lost its parent arc
  static constexpr Index no_node = no_arc;
  static constexpr Index infinite_distance = (std::numeric_limits<Index>::max)();

  void lay_out()
  {
    const std::size_t n = m_terminal.size();
    for(std::size_t i = 0; i < n; ++i)
      m_first[i + 1] += m_first[i];
    CGAL_precondition(m_first[n] < orphan);
    m_fill.assign(m_first.begin(), m_first.end() - 1);
    m_fill.push_back(m_first[n]); // never empty once laid out
    m_head.resize(m_first[n]);
    m_sister.resize(m_first[n]);
    m_residual.resize(m_first[n]);
  }

  void activate(Index i)
  {
    if(m_active[i])
      return;
    m_active[i] = 1;
    m_queue.push_back(i);
  }

  // The first queued node still in a tree; the queue is compacted when half of it was read.
  Index next_active()
  {
    while(m_front < m_queue.size())
    {
      const Index i = m_queue[m_front++];
      m_active[i] = 0;
      if(m_parent[i] != no_arc)
      {
        if(2 * m_front > m_queue.size() && m_front > 1024)
        {
          m_queue.erase(m_queue.begin(), m_queue.begin() + std::ptrdiff_t(m_front));
          m_front = 0;
        }
        return i;
      }
    }
    m_queue.clear();
    m_front = 0;
    return no_node;
  }

  // Pushes the bottleneck along source ... -> tail(middle) -> head(middle) -> ... sink; the nodes
  // whose parent arc (or terminal arc) it saturates become orphans.
  void augment(Index middle)
  {
    double bottleneck = m_residual[middle];
    for(Index k = m_head[m_sister[middle]];;)
    {
      const Index p = m_parent[k];
      if(p == terminal)
      {
        bottleneck = (std::min)(bottleneck, m_terminal[k]);
        break;
      }
      bottleneck = (std::min)(bottleneck, m_residual[m_sister[p]]);
      k = m_head[p];
    }
    for(Index k = m_head[middle];;)
    {
      const Index p = m_parent[k];
      if(p == terminal)
      {
        bottleneck = (std::min)(bottleneck, -m_terminal[k]);
        break;
      }
      bottleneck = (std::min)(bottleneck, m_residual[p]);
      k = m_head[p];
    }

    m_residual[m_sister[middle]] += bottleneck;
    m_residual[middle] -= bottleneck;
    for(Index k = m_head[m_sister[middle]];;)
    {
      const Index p = m_parent[k];
      if(p == terminal)
      {
        m_terminal[k] -= bottleneck;
        if(!(m_terminal[k] > 0))
          make_orphan(k);
        break;
      }
      m_residual[p] += bottleneck;
      m_residual[m_sister[p]] -= bottleneck;
      if(!(m_residual[m_sister[p]] > 0))
        make_orphan(k);
      k = m_head[p];
    }
    for(Index k = m_head[middle];;)
    {
      const Index p = m_parent[k];
      if(p == terminal)
      {
        m_terminal[k] += bottleneck;
        if(!(m_terminal[k] < 0))
          make_orphan(k);
        break;
      }
      m_residual[m_sister[p]] += bottleneck;
      m_residual[p] -= bottleneck;
      if(!(m_residual[p] > 0))
        make_orphan(k);
      k = m_head[p];
    }
  }

  void make_orphan(Index k)
  {
    m_parent[k] = orphan;
    m_orphans.push_back(k);
  }

  // Whether the arc a from orphan k to a node of its tree can be k's parent arc.
  bool can_be_parent(Index k, Index a) const
  {
    return !m_sink_tree[k] ? m_residual[m_sister[a]] > 0 : m_residual[a] > 0;
  }

  // A new parent for orphan k in its tree: the neighbour nearest its terminal among those whose
  // way there is not broken. Without one, k leaves the tree: its neighbours that could grow into
  // it become active, its children orphans.
  void adopt(Index k)
  {
    Index best = no_arc;
    Index best_distance = infinite_distance;
    for(Index a = m_first[k]; a < m_first[k + 1]; ++a)
    {
      const Index j = m_head[a];
      if(m_parent[j] == no_arc || m_sink_tree[j] != m_sink_tree[k] || !can_be_parent(k, a))
        continue;
      // The distance of j to its terminal, if it has a way there; the nodes on it are stamped.
      Index d = 0;
      for(Index m = j;;)
      {
        if(m_stamp[m] == m_time)
        {
          d += m_distance[m];
          break;
        }
        const Index p = m_parent[m];
        ++d;
        if(p == terminal)
        {
          m_stamp[m] = m_time;
          m_distance[m] = 1;
          break;
        }
        if(p == orphan)
        {
          d = infinite_distance;
          break;
        }
        m = m_head[p];
      }
      if(d == infinite_distance)
        continue;
      if(d < best_distance)
      {
        best = a;
        best_distance = d;
      }
      for(Index m = j; m_stamp[m] != m_time; m = m_head[m_parent[m]])
      {
        m_stamp[m] = m_time;
        m_distance[m] = d--;
      }
    }
    if(best != no_arc)
    {
      m_parent[k] = best;
      m_stamp[k] = m_time;
      m_distance[k] = best_distance + 1;
      return;
    }
    m_parent[k] = no_arc;
    for(Index a = m_first[k]; a < m_first[k + 1]; ++a)
    {
      const Index j = m_head[a];
      const Index p = m_parent[j];
      if(p == no_arc || m_sink_tree[j] != m_sink_tree[k])
        continue;
      if(can_be_parent(k, a))
        activate(j);
      if(p != terminal && p != orphan && m_head[p] == k)
        make_orphan(j);
    }
  }

  std::vector<Index> m_first;     // by node: its first arc; the arcs of i are [first[i], first[i + 1])
  std::vector<Index> m_fill;      // by node: where its next arc goes, while arcs are added
  std::vector<Index> m_head;      // by arc
  std::vector<Index> m_sister;    // by arc: its reverse
  std::vector<double> m_residual; // by arc
  std::vector<double> m_terminal; // by node: residual from the source if positive, to the sink if negative
  std::vector<Index> m_parent;    // by node: the arc to its parent, or terminal, orphan, no_arc
  std::vector<char> m_sink_tree;  // by node: in the sink's tree (when in a tree)
  std::vector<Index> m_stamp;     // by node: the time its distance was known to be right
  std::vector<Index> m_distance;  // by node: to its terminal, along parent arcs
  std::vector<char> m_active;     // by node: queued, or the node being grown
  std::vector<Index> m_queue;
  std::size_t m_front = 0;
  std::vector<Index> m_orphans;
  Index m_time = 0;
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_MAX_FLOW_H
