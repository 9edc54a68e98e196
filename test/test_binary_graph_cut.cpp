// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The binary decision against brute force over all 2^n labellings, and its minimum cut against
// Boost's Boykov-Kolmogorov max-flow.

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/binary_graph_cut.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/max_flow.h>

#include <CGAL/Random.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>

#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <vector>

using CGAL::Polygon_mesh_processing::internal::Graphcut_remeshing::Binary_graph_cut;
using CGAL::Polygon_mesh_processing::internal::Graphcut_remeshing::Max_flow;

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

// Boost's maximum flow value and the nodes its source tree ends with, on the same graph with the
// terminals as nodes n (source) and n + 1 (sink).
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

} // namespace

TEST(MaxFlow, SameCutAsBoostOnRandomGraphs)
{
  // Integer capacities, so that every flow is exact and the source side of the smallest minimum
  // cut is one set, whichever order the paths were found in. Sparse random graphs and grids
  // (the neighbourhoods of the binary decision), from a few nodes to a few thousand.
  CGAL::Random rng(17);
  std::size_t nontrivial = 0;
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

    Max_flow flow(n);
    for(std::size_t i = 0; i < n; ++i)
      flow.add_terminal_capacities(Max_flow::Index(i), source[i], sink[i]);
    for(const Arc& a : arcs)
      flow.count_arc(Max_flow::Index(a.u), Max_flow::Index(a.v));
    for(const Arc& a : arcs)
      flow.add_arc(Max_flow::Index(a.u), Max_flow::Index(a.v), a.capacity, a.reverse_capacity);
    flow.solve();
    std::vector<char> ours(n);
    for(std::size_t i = 0; i < n; ++i)
      ours[i] = flow.is_on_source_side(Max_flow::Index(i));

    // The capacity of our cut is the maximum flow.
    double cut = 0;
    for(std::size_t i = 0; i < n; ++i)
      cut += ours[i] ? sink[i] : source[i];
    for(const Arc& a : arcs)
      cut += ours[a.u] && !ours[a.v] ? a.capacity : (!ours[a.u] && ours[a.v] ? a.reverse_capacity : 0);
    std::vector<char> theirs;
    const double maximum = boost_max_flow(n, source, sink, arcs, theirs);
    EXPECT_EQ(cut, maximum);
    EXPECT_EQ(ours, theirs);
    std::size_t on_source_side = 0;
    for(char c : ours)
      on_source_side += c;
    nontrivial += on_source_side > 0 && on_source_side < n ? 1 : 0;
  }
  EXPECT_GT(nontrivial, 50u);
}
