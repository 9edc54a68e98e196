// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The binary decision against brute force over all 2^n labellings, and its s-t graph solved by
// a direct call of Boost's Boykov-Kolmogorov max-flow on a graph of Boost's own.

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/binary_graph_cut.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/st_graph.h>

#include <CGAL/Random.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>

#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <vector>

using CGAL::Polygon_mesh_processing::internal::Graphcut_remeshing::Binary_graph_cut;
using CGAL::Polygon_mesh_processing::internal::Graphcut_remeshing::St_graph;

namespace {

struct Triple { std::size_t i, j, k; std::array<double, 8> table; };

// Random distinct triples over n variables, like the triangles of a small mesh.
std::vector<std::array<std::size_t, 3> > random_triples(std::size_t n, std::size_t count, CGAL::Random& rng)
{
  std::vector<std::array<std::size_t, 3> > t;
  while(t.size() < count)
  {
    const std::size_t a = rng.get_int(0, int(n)), b = rng.get_int(0, int(n)), c = rng.get_int(0, int(n));
    if(a != b && b != c && a != c)
      t.push_back({{a, b, c}});
  }
  return t;
}

// A table that is representable once the variables are flipped as `hidden` says: built in the
// flipped labels as unary + strictly submodular pairwise + a cubic term that keeps every
// projection submodular, then written back in the original labels.
std::array<double, 8> representable_table(const std::array<std::size_t, 3>& v, const std::vector<int>& hidden,
                                          CGAL::Random& rng)
{
  const double u0 = rng.get_double(-1, 1), u1 = rng.get_double(-1, 1), u2 = rng.get_double(-1, 1);
  const double p01 = -rng.get_double(0.1, 1), p02 = -rng.get_double(0.1, 1), p12 = -rng.get_double(0.1, 1);
  // Projections stay submodular when p + c <= 0 for every pair.
  const double c = rng.get_double(-1, -(std::max)({p01, p02, p12}));
  std::array<double, 8> e{};
  for(int a = 0; a < 2; ++a)
    for(int b = 0; b < 2; ++b)
      for(int d = 0; d < 2; ++d)
      {
        const int y0 = a ^ hidden[v[0]], y1 = b ^ hidden[v[1]], y2 = d ^ hidden[v[2]];
        e[a + 2 * b + 4 * d] = u0 * y0 + u1 * y1 + u2 * y2 + p01 * y0 * y1 + p02 * y0 * y2 +
                               p12 * y1 * y2 + c * y0 * y1 * y2 + 3;
      }
  return e;
}

double brute_force_minimum(const Binary_graph_cut& gc)
{
  const std::size_t n = gc.number_of_variables();
  double best = std::numeric_limits<double>::infinity();
  std::vector<char> labels(n);
  for(unsigned long mask = 0; mask < (1ul << n); ++mask)
  {
    for(std::size_t i = 0; i < n; ++i)
      labels[i] = static_cast<char>((mask >> i) & 1);
    best = (std::min)(best, gc.energy(labels));
  }
  return best;
}

} // namespace

TEST(BinaryGraphCut, UnaryOnlyPicksEachCheaperLabel)
{
  Binary_graph_cut gc(3);
  gc.add_unary(0, 1, 2);
  gc.add_unary(1, 2, 1);
  gc.add_unary(2, -1, -3);
  const std::vector<char> labels = gc.solve();
  EXPECT_EQ(labels, (std::vector<char>{0, 1, 1}));
}

TEST(BinaryGraphCut, EqualsBruteForceWhenAllTermsAreRepresentable)
{
  CGAL::Random rng(1);
  for(int trial = 0; trial < 300; ++trial)
  {
    const std::size_t n = 3 + trial % 10;
    std::vector<int> hidden(n);
    for(int& h : hidden)
      h = rng.get_int(0, 2);
    Binary_graph_cut gc(n);
    for(std::size_t i = 0; i < n; ++i)
      gc.add_unary(i, rng.get_double(0, 2), rng.get_double(0, 2));
    const auto triples = random_triples(n, n, rng);
    for(const auto& t : triples)
      gc.add_term(t[0], t[1], t[2], representable_table(t, hidden, rng));
    const std::vector<char> labels = gc.solve();
    EXPECT_EQ(gc.number_of_representable_terms(), triples.size()) << "trial " << trial;
    EXPECT_NEAR(gc.energy(labels), brute_force_minimum(gc), 1e-9) << "trial " << trial;
  }
}

TEST(BinaryGraphCut, PairwiseTermsAreExactWhenRepresentable)
{
  CGAL::Random rng(2);
  for(int trial = 0; trial < 200; ++trial)
  {
    const std::size_t n = 2 + trial % 12;
    std::vector<int> hidden(n);
    for(int& h : hidden)
      h = rng.get_int(0, 2);
    Binary_graph_cut gc(n);
    // A chain: always consistently mappable.
    for(std::size_t i = 0; i + 1 < n; ++i)
    {
      const double p = -rng.get_double(0.1, 2), u = rng.get_double(-1, 1), w = rng.get_double(-1, 1);
      std::array<double, 8> e{};
      for(int a = 0; a < 2; ++a)
        for(int b = 0; b < 2; ++b)
        {
          const int y0 = a ^ hidden[i], y1 = b ^ hidden[i + 1];
          e[a + 2 * b] = u * y0 + w * y1 + p * y0 * y1;
        }
      gc.add_term(i, i + 1, Binary_graph_cut::none, e);
    }
    const std::vector<char> labels = gc.solve();
    EXPECT_NEAR(gc.energy(labels), brute_force_minimum(gc), 1e-9) << "trial " << trial;
  }
}

TEST(BinaryGraphCut, NeverWorseThanKeepingOnArbitraryEnergies)
{
  CGAL::Random rng(3);
  int strictly_better = 0;
  for(int trial = 0; trial < 500; ++trial)
  {
    const std::size_t n = 3 + trial % 12;
    Binary_graph_cut gc(n);
    for(std::size_t i = 0; i < n; ++i)
      gc.add_unary(i, rng.get_double(0, 1), rng.get_double(0, 1));
    for(const auto& t : random_triples(n, 2 * n, rng))
    {
      std::array<double, 8> e;
      for(double& x : e)
        x = rng.get_double(0, 1);
      gc.add_term(t[0], t[1], t[2], e);
    }
    const std::vector<char> labels = gc.solve();
    const double keep = gc.energy(std::vector<char>(n, 0));
    const double got = gc.energy(labels);
    const double best = brute_force_minimum(gc);
    EXPECT_LE(got, keep + 1e-12) << "trial " << trial;
    EXPECT_GE(got, best - 1e-12);
    if(got < keep - 1e-9)
      ++strictly_better;
  }
  // The bound must not freeze everything: most random energies can be improved.
  EXPECT_GT(strictly_better, 250);
}

namespace {

struct Arc { std::size_t u, v; double capacity, reverse_capacity; };

// Boost's maximum flow value and the nodes its source tree ends with, by a direct call on an
// adjacency_list of the same arcs, with the terminals as nodes n (source) and n + 1 (sink).
double boost_max_flow(std::size_t n, const std::vector<double>& source, const std::vector<double>& sink,
                      const std::vector<Arc>& arcs, std::vector<char>& source_side)
{
  using Traits = boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS>;
  using Graph = boost::adjacency_list<
    boost::vecS, boost::vecS, boost::directedS,
    boost::property<boost::vertex_index_t, long,
      boost::property<boost::vertex_color_t, boost::default_color_type,
        boost::property<boost::vertex_distance_t, long,
          boost::property<boost::vertex_predecessor_t, Traits::edge_descriptor> > > >,
    boost::property<boost::edge_capacity_t, double,
      boost::property<boost::edge_residual_capacity_t, double,
        boost::property<boost::edge_reverse_t, Traits::edge_descriptor> > > >;
  Graph g(n + 2);
  auto capacity = get(boost::edge_capacity, g);
  auto reverse = get(boost::edge_reverse, g);
  auto add = [&](std::size_t u, std::size_t v, double c, double rc) {
    const auto a = add_edge(u, v, g).first, b = add_edge(v, u, g).first;
    capacity[a] = c;
    capacity[b] = rc;
    reverse[a] = b;
    reverse[b] = a;
  };
  for(std::size_t i = 0; i < n; ++i)
  {
    if(source[i] > 0)
      add(n, i, source[i], 0);
    if(sink[i] > 0)
      add(i, n + 1, sink[i], 0);
  }
  for(const Arc& a : arcs)
    add(a.u, a.v, a.capacity, a.reverse_capacity);
  const double flow = boost::boykov_kolmogorov_max_flow(g, n, n + 1);
  auto color = get(boost::vertex_color, g);
  source_side.assign(n, 0);
  for(std::size_t i = 0; i < n; ++i)
    source_side[i] = color[i] == boost::black_color;
  return flow;
}

// The arcs of an St_graph between its nodes, and its terminal capacities, as lists (before it is
// solved: solving changes the capacities into residual ones).
void read_graph(const St_graph& g, std::vector<double>& source, std::vector<double>& sink, std::vector<Arc>& arcs)
{
  const std::size_t n = g.number_of_nodes();
  source.assign(n, 0);
  sink.assign(n, 0);
  arcs.clear();
  for(St_graph::Index u = 0; u < n + 2; ++u)
    for(St_graph::Index a = g.first_arc(u); a < g.first_arc(u + 1); ++a)
    {
      const St_graph::Index v = g.head(a);
      if(u == g.source())
        source[v] += g.capacity(a);
      else if(v == g.sink())
        sink[u] += g.capacity(a);
      else if(u < n && v < n && u < v) // each pair of arcs once, from its lower end
        arcs.push_back({u, v, g.capacity(a), g.capacity(g.reverse(a))});
    }
}

} // namespace

TEST(StGraph, SameCutAsBoostOnAnAdjacencyListOnRandomGraphs)
{
  // Integer capacities, so that every flow is exact and the source side of the smallest minimum
  // cut is one set, whichever order the paths were found in. Sparse random graphs and grids
  // (the neighbourhoods of the binary decision), from a few nodes to a few thousand; one graph's
  // arrays serve every trial, as they do from one relocation to the next.
  CGAL::Random rng(17);
  std::size_t nontrivial = 0;
  St_graph graph;
  for(int trial = 0; trial < 60; ++trial)
  {
    SCOPED_TRACE(trial);
    const bool grid = trial % 2 == 1;
    const std::size_t side = std::size_t(2 + trial), n = grid ? side * side : std::size_t(3 + 40 * trial);
    std::vector<double> source(n, 0), sink(n, 0);
    for(std::size_t i = 0; i < n; ++i)
    {
      const int t = rng.get_int(-12, 13);
      (t > 0 ? source[i] : sink[i]) = std::abs(t);
      if(rng.get_double() < 0.1) // both terminals: only the difference counts
      {
        source[i] += 5;
        sink[i] += 5;
      }
    }
    std::vector<Arc> arcs;
    if(grid)
    {
      for(std::size_t r = 0; r < side; ++r)
        for(std::size_t c = 0; c < side; ++c)
        {
          if(c + 1 < side)
            arcs.push_back({r * side + c, r * side + c + 1, double(rng.get_int(0, 9)), double(rng.get_int(0, 9))});
          if(r + 1 < side)
            arcs.push_back({r * side + c, (r + 1) * side + c, double(rng.get_int(0, 9)), double(rng.get_int(0, 9))});
        }
    }
    else
      for(std::size_t k = 0; k < 3 * n; ++k)
      {
        const std::size_t u = rng.get_int(0, int(n)), v = rng.get_int(0, int(n));
        if(u != v)
          arcs.push_back({u, v, double(rng.get_int(0, 9)), double(rng.get_int(0, 3))});
      }

    graph.reset(n);
    for(std::size_t i = 0; i < n; ++i)
      graph.add_terminal_capacities(St_graph::Index(i), source[i], sink[i]);
    for(const Arc& a : arcs)
      graph.count_arc(St_graph::Index(a.u), St_graph::Index(a.v));
    for(const Arc& a : arcs)
      graph.add_arc(St_graph::Index(a.u), St_graph::Index(a.v), a.capacity, a.reverse_capacity);
    const double flow = graph.solve();
    std::vector<char> ours(n);
    for(std::size_t i = 0; i < n; ++i)
      ours[i] = graph.is_on_source_side(St_graph::Index(i));

    // The capacity of the cut is the maximum flow.
    double cut = 0;
    for(std::size_t i = 0; i < n; ++i)
      cut += ours[i] ? sink[i] : source[i];
    for(const Arc& a : arcs)
      cut += ours[a.u] && !ours[a.v] ? a.capacity : (!ours[a.u] && ours[a.v] ? a.reverse_capacity : 0);
    std::vector<char> theirs;
    const double maximum = boost_max_flow(n, source, sink, arcs, theirs);
    double net_terminals = 0; // the graph keeps the difference of a node's two terminal arcs
    for(std::size_t i = 0; i < n; ++i)
      net_terminals += (std::min)(source[i], sink[i]);
    EXPECT_EQ(cut, maximum);
    EXPECT_EQ(flow + net_terminals, maximum);
    EXPECT_EQ(ours, theirs);
    std::size_t on_source_side = 0;
    for(char c : ours)
      on_source_side += c;
    nontrivial += on_source_side > 0 && on_source_side < n ? 1 : 0;
  }
  EXPECT_GT(nontrivial, 50u);
}

// Every cut of the binary decision is Boost's: the graph the decision builds, solved again by a
// direct call of boykov_kolmogorov_max_flow on an adjacency_list of its arcs, has the same
// source side, and the labels the decision returns follow from it.
TEST(BinaryGraphCut, ItsGraphSolvedDirectlyByBoostGivesTheSameCut)
{
  CGAL::Random rng(5);
  St_graph graph;
  std::size_t nontrivial = 0;
  for(int trial = 0; trial < 200; ++trial)
  {
    SCOPED_TRACE(trial);
    const std::size_t n = 3 + trial;
    Binary_graph_cut gc(n);
    // Integer energies: the flows are exact, so both solvers' sides are the one smallest side.
    for(std::size_t i = 0; i < n; ++i)
      gc.add_unary(i, rng.get_int(0, 20), rng.get_int(0, 20));
    for(const auto& t : random_triples(n, 2 * n, rng))
    {
      std::array<double, 8> e;
      for(double& x : e)
        x = rng.get_int(0, 20);
      gc.add_term(t[0], t[1], t[2], e);
    }
    // What solve(graph) does, with the graph read before it is solved.
    gc.build_graph(graph);
    std::vector<double> source, sink;
    std::vector<Arc> arcs;
    read_graph(graph, source, sink, arcs);
    graph.solve();
    const std::vector<char> labels = gc.labels(graph);
    std::vector<char> theirs;
    boost_max_flow(graph.number_of_nodes(), source, sink, arcs, theirs);
    std::size_t on_source_side = 0;
    for(std::size_t i = 0; i < graph.number_of_nodes(); ++i)
    {
      EXPECT_EQ(graph.is_on_source_side(St_graph::Index(i)), theirs[i] != 0) << "node " << i;
      on_source_side += theirs[i];
    }
    nontrivial += on_source_side > 0 && on_source_side < graph.number_of_nodes() ? 1 : 0;
    EXPECT_LE(gc.energy(labels), gc.energy(std::vector<char>(n, 0)));
    EXPECT_EQ(labels, gc.solve()) << "solve() on a graph of its own";
    EXPECT_EQ(labels, gc.solve_and_free_terms(graph)) << "the terms freed before the graph is made";
    EXPECT_EQ(gc.number_of_representable_terms(), 0u) << "no term left";
  }
  EXPECT_GT(nontrivial, 150u);
}
