// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The binary decision of section 2.4: minimise a sum of unary, pairwise and triple terms over
// binary variables (0 = keep the current position, 1 = take the candidate) with one s-t minimum cut,
// Boost.Graph's boykov_kolmogorov_max_flow (st_graph.h).
//
// Each term is written as a multilinear polynomial. A cubic coefficient is reduced with one
// auxiliary node (Kolmogorov & Zabih's class F3 construction). Per-variable label mappings
// (which of keep / move is the graph's 0) are chosen greedily, as the paper does, to make as many
// terms representable as possible. The pairwise coefficients that remain supermodular are replaced
// by linear upper bounds that are exact at the current labelling (all keep): the cut minimises an
// upper bound of the energy that is tight at the current labelling, so the labelling it returns
// never has a higher energy than keeping everything, but for the rounding of the graph's
// single-precision capacities (st_graph.h).

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_BINARY_GRAPH_CUT_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_BINARY_GRAPH_CUT_H

#include <CGAL/assertions.h>

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/st_graph.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

class Binary_graph_cut
{
public:
  static constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();

  explicit Binary_graph_cut(std::size_t number_of_variables) : m_unary(number_of_variables, 0.) {}

  std::size_t number_of_variables() const { return m_unary.size(); }

  // Room for this many pairwise and triple terms.
  void reserve(std::size_t number_of_terms) { m_terms.reserve(number_of_terms); }

  // Energy e0 if variable i is 0, e1 if it is 1.
  void add_unary(std::size_t i, double e0, double e1)
  {
    m_constant += e0;
    m_unary[i] += e1 - e0;
  }

  // A term of two or three variables given by its table: e[a + 2b] or e[a + 2b + 4c] for the
  // labels a, b (, c) of i, j (, k). Pass `none` as k for a pairwise term.
  void add_term(std::size_t i, std::size_t j, std::size_t k, const std::array<double, 8>& e)
  {
    Term t;
    t.variables = {{Index(i), Index(j), k == none ? no_index : Index(k)}};
    if(k == none)
    {
      // e(a,b) = e00 + a(e10-e00) + b(e01-e00) + ab(e11-e10-e01+e00)
      m_constant += e[0];
      t.linear = {{e[1] - e[0], e[2] - e[0], 0.}};
      t.quadratic = {{e[3] - e[1] - e[2] + e[0], 0., 0.}}; // pairs (i,j), (i,k), (j,k)
      t.cubic = 0;
    }
    else
    {
      // Moebius inversion of the 8-entry table into the multilinear coefficients.
      m_constant += e[0];
      t.linear = {{e[1] - e[0], e[2] - e[0], e[4] - e[0]}};
      t.quadratic = {{e[3] - e[1] - e[2] + e[0], e[5] - e[1] - e[4] + e[0], e[6] - e[2] - e[4] + e[0]}};
      t.cubic = e[7] - e[3] - e[5] - e[6] + e[1] + e[2] + e[4] - e[0];
    }
    m_terms.push_back(t);
  }

  // Energy of a labelling, straight from the terms (the exact energy, not the graph's bound).
  double energy(const std::vector<char>& labels) const
  {
    double e = m_constant;
    for(std::size_t i = 0; i < m_unary.size(); ++i)
      if(labels[i])
        e += m_unary[i];
    for(const Term& t : m_terms)
      e += t.value(labels);
    return e;
  }

  // Number of terms that were representable (submodular) under the chosen mappings, after `solve`.
  std::size_t number_of_representable_terms() const
  {
    std::size_t representable_terms = 0;
    if(m_mapping.size() != m_unary.size())
      return 0; // not solved yet
    for(const Term& t : m_terms)
      if(representable(t, m_mapping))
        ++representable_terms;
    return representable_terms;
  }

  // Minimises the energy, starting from the all-zero labelling, and returns the labels. The s-t
  // graph is built in `graph`, whose arrays a caller keeps from one cut to the next.
  std::vector<char> solve(St_graph& graph)
  {
    build_graph(graph);
    graph.solve();
    return labels(graph);
  }

  std::vector<char> solve()
  {
    St_graph graph;
    return solve(graph);
  }

  // As solve(graph), but the terms are freed once expanded, before the graph is made: on a large
  // mesh they are a fifth of the cut's memory. energy() and number_of_representable_terms()
  // then see no term.
  std::vector<char> solve_and_free_terms(St_graph& graph)
  {
    build_graph(graph, true);
    graph.solve();
    return labels(graph);
  }

  // The s-t graph of the energy in three stages: the label mappings chosen, the terms expanded
  // over y with the cubic ones reduced and the supermodular pairs bounded, the graph made.
  void build_graph(St_graph& graph, bool free_terms = false)
  {
    choose_mappings();
    // Variables and their graph nodes in 32 bits: the terms and arcs of a large mesh are many.
    CGAL_precondition(m_unary.size() + m_terms.size() < std::size_t(no_index));
    Reduced_energy r = expand_terms();
    if(free_terms)
      m_terms = std::vector<Term>();
    bound_supermodular_pairs(r);
    make_graph(r, graph);
  }

  // The labels of the minimum cut of the graph of build_graph(), once solved.
  std::vector<char> labels(const St_graph& graph) const
  {
    std::vector<char> labels(m_unary.size(), 0);
    for(std::size_t i = 0; i < labels.size(); ++i)
    {
      const bool y = !graph.is_on_source_side(Index(i));
      labels[i] = static_cast<char>(y != (m_mapping[i] != 0)); // x = y xor m
    }
    return labels;
  }

private:
  // Variables and graph nodes in 32 bits: the terms and arcs of a large mesh are many.
  using Index = std::uint32_t;
  static constexpr Index no_index = (std::numeric_limits<Index>::max)();

  // A term without its constant (summed into m_constant).
  struct Term
  {
    std::array<Index, 3> variables; // the third is no_index for a pairwise term
    std::array<double, 3> linear;
    std::array<double, 3> quadratic; // (0,1), (0,2), (1,2)
    double cubic;

    double value(const std::vector<char>& labels) const
    {
      const double a = labels[variables[0]], b = labels[variables[1]];
      const double c = variables[2] == no_index ? 0. : double(labels[variables[2]]);
      return linear[0] * a + linear[1] * b + linear[2] * c + quadratic[0] * a * b + quadratic[1] * a * c +
             quadratic[2] * b * c + cubic * a * b * c;
    }
  };

  static constexpr std::array<std::array<int, 2>, 3> pairs{{{{0, 1}}, {{0, 2}}, {{1, 2}}}};

  // A term is representable under mappings m when each of its pairs, with both projections on the
  // third variable, is submodular once the variables are flipped as m says.
  bool representable(const Term& t, const std::vector<signed char>& m) const
  {
    const int arity = t.variables[2] == no_index ? 2 : 3;
    for(int p = 0; p < (arity == 3 ? 3 : 1); ++p)
    {
      const std::size_t u = t.variables[pairs[p][0]], v = t.variables[pairs[p][1]];
      const bool flipped = (m[u] != m[v]);
      // Both projections of the pair: third variable at 0 gives q, at 1 gives q + cubic.
      const double q0 = t.quadratic[p];
      const double q1 = arity == 3 ? t.quadratic[p] + t.cubic : q0;
      if(!flipped && (q0 > 0 || q1 > 0))
        return false;
      if(flipped && (q0 < 0 || q1 < 0))
        return false;
    }
    return true;
  }

  // The paper's greedy mapping: visit the terms in breadth-first order over shared variables; for
  // each term try every mapping of its not yet mapped variables and keep the one that makes the
  // most of its terms (this one and the already visited neighbours) representable.
  void choose_mappings()
  {
    const std::size_t n = m_unary.size();
    // The terms of each variable, in the order of the terms.
    std::vector<std::size_t> first_term(n + 1, 0);
    for(const Term& t : m_terms)
      for(Index v : t.variables)
        if(v != no_index)
          ++first_term[v + 1];
    for(std::size_t i = 0; i < n; ++i)
      first_term[i + 1] += first_term[i];
    std::vector<Index> adjacent_terms(first_term[n]);
    {
      std::vector<std::size_t> fill(first_term.begin(), first_term.end() - 1);
      for(std::size_t ti = 0; ti < m_terms.size(); ++ti)
        for(Index v : m_terms[ti].variables)
          if(v != no_index)
            adjacent_terms[fill[v]++] = Index(ti);
    }
    m_mapping.assign(n, -1);
    std::vector<char> visited(m_terms.size(), 0);
    // A variable's terms are all queued the first time one of them is dequeued: later visits of
    // the variable would find nothing new.
    std::vector<char> expanded(n, 0);
    // Each term enters the queue once: a flat array read from its front.
    std::vector<Index> queue;
    queue.reserve(m_terms.size());
    for(std::size_t seed = 0; seed < m_terms.size(); ++seed)
    {
      if(visited[seed])
        continue;
      visited[seed] = 1;
      queue.push_back(Index(seed));
      for(std::size_t front = queue.size() - 1; front < queue.size(); ++front)
      {
        const Index ti = queue[front];
        map_term(ti);
        for(Index v : m_terms[ti].variables)
          if(v != no_index && !expanded[v])
          {
            expanded[v] = 1;
            for(std::size_t a = first_term[v]; a < first_term[v + 1]; ++a)
              if(!visited[adjacent_terms[a]])
              {
                visited[adjacent_terms[a]] = 1;
                queue.push_back(adjacent_terms[a]);
              }
          }
      }
    }
    for(std::size_t i = 0; i < n; ++i)
      if(m_mapping[i] < 0)
        m_mapping[i] = 0;
  }

  void map_term(std::size_t ti)
  {
    const Term& t = m_terms[ti];
    std::array<Index, 3> free_vars{};
    int number_free = 0;
    for(Index v : t.variables)
      if(v != no_index && m_mapping[v] < 0)
      {
        bool seen = false;
        for(int f = 0; f < number_free; ++f)
          seen = seen || free_vars[f] == v;
        if(!seen)
          free_vars[number_free++] = v;
      }
    if(number_free == 0)
      return;
    int best = 0, best_score = -1;
    for(int mask = 0; mask < (1 << number_free); ++mask)
    {
      for(int f = 0; f < number_free; ++f)
        m_mapping[free_vars[f]] = static_cast<signed char>((mask >> f) & 1);
      // Unmapped variables of other terms are not yet decided: count only this term. The first
      // mapping that makes it representable is as good as any.
      const int score = representable(t, m_mapping) ? 1 : 0;
      if(score > best_score)
      {
        best_score = score;
        best = mask;
      }
      if(score == 1)
        break;
    }
    for(int f = 0; f < number_free; ++f)
      m_mapping[free_vars[f]] = static_cast<signed char>((best >> f) & 1);
  }

  // The pairs of distinct variables that share a term, by the smaller variable: the larger ones
  // of i are other[start[i]], ..., other[start[i + 1] - 1], increasing. Each pairwise coefficient
  // of the graph is on one of them. Returns the number of terms of three variables.
  std::size_t collect_pairs(std::vector<Index>& start, std::vector<Index>& other) const
  {
    const std::size_t n = m_unary.size();
    std::size_t number_of_triples = 0;
    auto for_each_pair = [&](const auto& function) {
      for(const Term& t : m_terms)
        for(int p = 0; p < (t.variables[2] == no_index ? 1 : 3); ++p)
        {
          const Index u = t.variables[pairs[p][0]], v = t.variables[pairs[p][1]];
          if(u != v)
            function((std::min)(u, v), (std::max)(u, v));
        }
    };
    std::vector<std::size_t> first(n + 1, 0);
    for_each_pair([&](Index i, Index) { ++first[i + 1]; });
    for(std::size_t i = 0; i < n; ++i)
      first[i + 1] += first[i];
    other.resize(first[n]);
    {
      std::vector<std::size_t> fill(first.begin(), first.end() - 1);
      for_each_pair([&](Index i, Index j) { other[fill[i]++] = j; });
    }
    // Each variable's list sorted and without repeats, moved down over the repeats removed.
    start.assign(n + 1, 0);
    std::size_t out = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      const auto b = other.begin() + std::ptrdiff_t(first[i]), e = other.begin() + std::ptrdiff_t(first[i + 1]);
      std::sort(b, e);
      const auto last = std::unique(b, e);
      start[i] = Index(out);
      out = std::size_t(std::copy(b, last, other.begin() + std::ptrdiff_t(out)) - other.begin());
    }
    start[n] = Index(out);
    other.resize(out);
    other.shrink_to_fit();
    for(const Term& t : m_terms)
      if(t.variables[2] != no_index)
        ++number_of_triples;
    return number_of_triples;
  }

  // Graph construction in the mapped variables y = x xor m. A polynomial in x becomes one in y by
  // substituting x = 1 - y for mapped variables; we accumulate unary and pairwise coefficients over
  // y, add auxiliary nodes for cubic terms, bound supermodular pairs, then cut.
  // The energy in y (y_i = x_i, or 1 - x_i where variable i is mapped) as the graph holds it:
  // unaries, the pairwise coefficients of the pairs of collect_pairs() (each the sum of its
  // contributions in the order they come), and the auxiliary nodes of the reduced cubic terms.
  struct Reduced_energy
  {
    // An auxiliary node w of a reduced cubic term: unary cost `unary` when w = 1, and a
    // (submodular, negative) coefficient `pairwise` on w * y for each of the three variables.
    struct Aux
    {
      std::array<Index, 3> variables;
      double unary;
      double pairwise;
    };

    const std::vector<signed char>& mapping;
    std::vector<double> unary; // over y, then by node
    std::vector<Index> pair_start, pair_other;
    std::vector<double> pairwise;
    std::vector<Aux> aux;

    void add_linear(Index i, double c)
    {
      // c * x_i with x_i = m ? 1 - y_i : y_i
      if(mapping[i]) unary[i] -= c; // the constant part is irrelevant to the cut
      else unary[i] += c;
    }

    void add_pair(Index i, Index j, double c)
    {
      const Index a = (std::min)(i, j), b = (std::max)(i, j);
      Index k = pair_start[a];
      while(pair_other[k] != b)
        ++k;
      pairwise[k] += c;
    }

    void add_quadratic(Index i, Index j, double c)
    {
      if(i == j) { add_linear(i, c); return; }
      // c * x_i * x_j; with x = s + sign * y, s in {0,1}, sign in {+1,-1}
      const double si = mapping[i] ? 1. : 0., gi = mapping[i] ? -1. : 1.;
      const double sj = mapping[j] ? 1. : 0., gj = mapping[j] ? -1. : 1.;
      unary[i] += c * gi * sj;
      unary[j] += c * gj * si;
      add_pair(i, j, c * gi * gj);
    }

    void add_cubic(const std::array<Index, 3>& v, double c)
    {
      // In y, after the mapping, c * x0 x1 x2 is again a cubic in y with coefficient
      // c * g0 g1 g2 plus lower-order terms; expand (s + g y) products.
      std::array<double, 3> s, g;
      for(int a = 0; a < 3; ++a)
      {
        s[a] = mapping[v[a]] ? 1. : 0.;
        g[a] = mapping[v[a]] ? -1. : 1.;
      }
      for(int a = 0; a < 3; ++a)
      {
        const int b = (a + 1) % 3, d = (a + 2) % 3;
        unary[v[a]] += c * g[a] * s[b] * s[d];
      }
      for(int p = 0; p < 3; ++p)
      {
        const int a = pairs[p][0], b = pairs[p][1], d = 3 - a - b;
        if(v[a] != v[b])
          add_pair(v[a], v[b], c * g[a] * g[b] * s[d]);
        else
          unary[v[a]] += c * g[a] * g[b] * s[d];
      }
      const double cy = c * g[0] * g[1] * g[2];
      if(cy < 0)
      {
        // cy y0 y1 y2 = min_w cy w (y0 + y1 + y2 - 2)
        aux.push_back({v, -2 * cy, cy});
      }
      else if(cy > 0)
      {
        // cy y0 y1 y2 = cy (y0y1 + y0y2 + y1y2) + min_w [cy w - cy w (y0 + y1 + y2)]
        for(int p = 0; p < 3; ++p)
        {
          const Index a = v[pairs[p][0]], b = v[pairs[p][1]];
          if(a != b)
            add_pair(a, b, cy);
          else
            unary[a] += cy;
        }
        aux.push_back({v, cy, -cy});
      }
    }
  };

  Reduced_energy expand_terms() const
  {
    const std::size_t n = m_unary.size();
    Reduced_energy r{m_mapping, std::vector<double>(n, 0.), {}, {}, {}, {}};
    const std::size_t number_of_triples = collect_pairs(r.pair_start, r.pair_other);
    r.pairwise.assign(r.pair_other.size(), 0.);
    r.aux.reserve(number_of_triples);
    for(std::size_t i = 0; i < n; ++i)
      r.add_linear(Index(i), m_unary[i]);
    for(const Term& t : m_terms)
    {
      const Index i = t.variables[0], j = t.variables[1], k = t.variables[2];
      r.add_linear(i, t.linear[0]);
      r.add_linear(j, t.linear[1]);
      r.add_quadratic(i, j, t.quadratic[0]);
      if(k != no_index)
      {
        r.add_linear(k, t.linear[2]);
        r.add_quadratic(i, k, t.quadratic[1]);
        r.add_quadratic(j, k, t.quadratic[2]);
        if(t.cubic != 0)
          r.add_cubic(t.variables, t.cubic);
      }
    }
    return r;
  }

  // Current labelling in y: x = 0 for all, so y_i = m_i. Supermodular pairs (coefficient a > 0)
  // are bounded by linear terms exact at y0; the submodular ones are kept (a pair whose
  // coefficient is not negative has no arc).
  void bound_supermodular_pairs(Reduced_energy& r) const
  {
    const std::size_t n = m_unary.size();
    for(Index i = 0; i < Index(n); ++i)
      for(Index k = r.pair_start[i]; k < r.pair_start[i + 1]; ++k)
      {
        const Index j = r.pair_other[k];
        const double a = r.pairwise[k];
        if(!(a > 0))
          continue;
        const bool yi = m_mapping[i] != 0, yj = m_mapping[j] != 0;
        if(yi == yj)
        {
          r.unary[i] += a / 2; // a yi yj <= a (yi + yj) / 2, exact at (0,0) and (1,1)
          r.unary[j] += a / 2;
        }
        else if(yi)
          r.unary[j] += a;     // a yi yj <= a yj, exact at yj = 0
        else
          r.unary[i] += a;     // a yi yj <= a yi, exact at yi = 0
      }
  }

  // The s-t graph: node index = variable, then auxiliary nodes. A node on the sink side has label
  // 1. A pairwise a yi yj with a < 0 is a yi + (-a) yi (1 - yj): an arc j -> i of capacity -a. A
  // positive unary is paid when the node is on the sink side (an arc from the source), a negative
  // one when it is on the source side (an arc to the sink). `r` is emptied as the graph is built.
  void make_graph(Reduced_energy& r, St_graph& flow) const
  {
    const std::size_t n = m_unary.size();
    const std::size_t number_of_nodes = n + r.aux.size();
    std::vector<double>& node_unary = r.unary;
    node_unary.resize(number_of_nodes, 0.);
    for(Index i = 0; i < Index(n); ++i)
      for(Index k = r.pair_start[i]; k < r.pair_start[i + 1]; ++k)
        if(r.pairwise[k] < 0)
          node_unary[i] += r.pairwise[k];
    for(std::size_t q = 0; q < r.aux.size(); ++q)
    {
      node_unary[n + q] += r.aux[q].unary;
      for(int a = 0; a < 3; ++a)
        node_unary[n + q] += r.aux[q].pairwise; // w y_v = w - w (1 - y_v)
    }
    flow.reset(number_of_nodes);
    for(std::size_t i = 0; i < number_of_nodes; ++i)
      flow.add_terminal_capacities(Index(i), (std::max)(node_unary[i], 0.), (std::max)(-node_unary[i], 0.));
    node_unary = std::vector<double>();
    auto for_each_arc = [&](const auto& arc) { // arc(tail, head, capacity), capacity > 0
      for(Index i = 0; i < Index(n); ++i)
        for(Index k = r.pair_start[i]; k < r.pair_start[i + 1]; ++k)
          if(r.pairwise[k] < 0)
            arc(r.pair_other[k], i, -r.pairwise[k]);
      for(std::size_t q = 0; q < r.aux.size(); ++q)
        for(Index v : r.aux[q].variables)
          arc(v, Index(n + q), -r.aux[q].pairwise);
    };
    for_each_arc([&](Index u, Index v, double) { flow.count_arc(u, v); });
    for_each_arc([&](Index u, Index v, double c) { flow.add_arc(u, v, c, 0.); });
    r.pair_start = std::vector<Index>();
    r.pair_other = std::vector<Index>();
    r.pairwise = std::vector<double>();
    r.aux = std::vector<Reduced_energy::Aux>();
  }

  double m_constant = 0;
  std::vector<double> m_unary;
  std::vector<Term> m_terms;
  std::vector<signed char> m_mapping;
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_BINARY_GRAPH_CUT_H
