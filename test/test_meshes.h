// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Meshes the tests build themselves, and access to CGAL's sample meshes extracted by CMake.

#ifndef CGAL_GRAPHCUT_REMESHING_TEST_MESHES_H
#define CGAL_GRAPHCUT_REMESHING_TEST_MESHES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Random.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/version.h>

// CGAL 6.0 renamed AABB_traits (deprecated) to AABB_traits_3; CGAL 6.2 moved
// extract_boundary_cycles out of Polygon_mesh_processing.
#if CGAL_VERSION_NR >= 1060000000
#include <CGAL/AABB_traits_3.h>
#else
#include <CGAL/AABB_traits.h>
#endif
#if CGAL_VERSION_NR >= 1060200000
#include <CGAL/boost/graph/border.h>
#else
#include <CGAL/Polygon_mesh_processing/border.h>
#endif

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace graphcut_remeshing_test {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
#if CGAL_VERSION_NR >= 1060000000
template <typename GeomTraits, typename Primitive>
using Tree_traits = CGAL::AABB_traits_3<GeomTraits, Primitive>;
#else
template <typename GeomTraits, typename Primitive>
using Tree_traits = CGAL::AABB_traits<GeomTraits, Primitive>;
#endif

// One halfedge of each border cycle of m.
template <typename PolygonMesh, typename OutputIterator>
OutputIterator boundary_cycles(const PolygonMesh& m, OutputIterator out)
{
#if CGAL_VERSION_NR >= 1060200000
  return CGAL::extract_boundary_cycles(m, out);
#else
  return CGAL::Polygon_mesh_processing::extract_boundary_cycles(m, out);
#endif
}

// The type of the remesher's working mesh (GR::Work_mesh), for tests of its parts.
using Work_point = CGAL::Simple_cartesian<double>::Point_3;
using Work_mesh = CGAL::Surface_mesh<Work_point>;
using Work_vertex = Work_mesh::Vertex_index;

inline const double pi = std::acos(-1.0);

// The mean length of the edges of m (num_edges() would also count the removed ones).
inline double mean_edge_length(const Mesh& m)
{
  double sum = 0;
  for(Mesh::Edge_index e : edges(m))
    sum += std::sqrt(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1))));
  return sum / double(m.number_of_edges());
}

// Constrains, with ecm[e] = true, the edges between the faces of m with a vertex below the plane
// z = 0 and the others: a closed loop of edges round a closed surface. Returns their number.
template <typename EdgeConstrainedMap>
std::size_t constrain_equator(const Mesh& m, EdgeConstrainedMap& ecm)
{
  auto below = [&](Mesh::Face_index f) {
    for(auto u : vertices_around_face(halfedge(f, m), m))
      if(m.point(u).z() < 0)
        return true;
    return false;
  };
  std::size_t count = 0;
  for(auto e : edges(m))
  {
    const auto h = halfedge(e, m);
    if(below(face(h, m)) != below(face(opposite(h, m), m)))
    {
      ecm[e] = true;
      ++count;
    }
  }
  return count;
}

// `input` as a working mesh, index for index when `input` holds no removed element (a remeshed
// mesh may: then its vertices are numbered in order).
inline Work_mesh to_work_mesh(const Mesh& input)
{
  Work_mesh w;
  std::vector<Work_vertex> to_work(input.num_vertices());
  for(auto v : vertices(input))
    to_work[std::size_t(v)] = w.add_vertex(Work_point(input.point(v).x(), input.point(v).y(), input.point(v).z()));
  for(auto f : faces(input))
  {
    const auto h = halfedge(f, input);
    w.add_face(to_work[std::size_t(source(h, input))], to_work[std::size_t(target(h, input))],
               to_work[std::size_t(target(next(h, input), input))]);
  }
  return w;
}

inline Mesh mesh_from_soup(const std::vector<Point>& points,
                           const std::vector<std::array<std::size_t, 3> >& triangles)
{
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  return mesh;
}

inline Mesh make_triangle(const Point& a, const Point& b, const Point& c)
{
  return mesh_from_soup({a, b, c}, {{{0, 1, 2}}});
}

// An n x m grid of vertices (n, m >= 2) placed by `place(i, j)`; every quad is split by the same
// diagonal, so interior vertices have valence 6 and border vertices other than corners valence 4.
inline Mesh make_grid(std::size_t n, std::size_t m, const std::function<Point(std::size_t, std::size_t)>& place)
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  for(std::size_t j = 0; j < m; ++j)
    for(std::size_t i = 0; i < n; ++i)
      points.push_back(place(i, j));
  auto id = [n](std::size_t i, std::size_t j) { return j * n + i; };
  for(std::size_t j = 0; j + 1 < m; ++j)
    for(std::size_t i = 0; i + 1 < n; ++i)
    {
      triangles.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
      triangles.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
    }
  return mesh_from_soup(points, triangles);
}

// A patch of the regular triangular lattice: n x n vertices, all triangles equilateral with side `h`.
inline Mesh make_equilateral_patch(std::size_t n, double h)
{
  return make_grid(n, n, [h](std::size_t i, std::size_t j) {
    return Point(h * (double(i) - 0.5 * double(j)), h * std::sqrt(3.0) / 2 * double(j), 0);
  });
}

// A torus (R, r) whose n x m grid wraps in both directions: every vertex has valence 6.
inline Mesh make_torus(std::size_t n, std::size_t m, double R, double r)
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  for(std::size_t j = 0; j < m; ++j)
    for(std::size_t i = 0; i < n; ++i)
    {
      const double u = 2 * pi * double(i) / double(n), v = 2 * pi * double(j) / double(m);
      points.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                          r * std::sin(v));
    }
  auto id = [n, m](std::size_t i, std::size_t j) { return (j % m) * n + (i % n); };
  for(std::size_t j = 0; j < m; ++j)
    for(std::size_t i = 0; i < n; ++i)
    {
      triangles.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
      triangles.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
    }
  return mesh_from_soup(points, triangles);
}

// A sphere: an icosahedron whose triangles are split in four `levels` times, vertices pushed onto
// the sphere.
inline Mesh make_sphere(unsigned levels, double radius = 1.0, const Point& center = CGAL::ORIGIN)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2;
  std::vector<std::array<double, 3> > p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                           {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                           {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<std::size_t, 3> > f = {
    {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
    {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
    {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for(unsigned l = 0; l < levels; ++l)
  {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> midpoint;
    auto middle = [&](std::size_t a, std::size_t b) {
      const auto key = std::make_pair((std::min)(a, b), (std::max)(a, b));
      auto it = midpoint.find(key);
      if(it != midpoint.end())
        return it->second;
      p.push_back({{(p[a][0] + p[b][0]) / 2, (p[a][1] + p[b][1]) / 2, (p[a][2] + p[b][2]) / 2}});
      midpoint.emplace(key, p.size() - 1);
      return p.size() - 1;
    };
    std::vector<std::array<std::size_t, 3> > g;
    for(const auto& tri : f)
    {
      const std::size_t ab = middle(tri[0], tri[1]), bc = middle(tri[1], tri[2]),
                        ca = middle(tri[2], tri[0]);
      g.push_back({{tri[0], ab, ca}});
      g.push_back({{tri[1], bc, ab}});
      g.push_back({{tri[2], ca, bc}});
      g.push_back({{ab, bc, ca}});
    }
    f.swap(g);
  }
  std::vector<Point> points;
  for(const auto& q : p)
  {
    const double s = radius / std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    points.emplace_back(center.x() + s * q[0], center.y() + s * q[1], center.z() + s * q[2]);
  }
  return mesh_from_soup(points, f);
}

// An icosphere whose vertices are pushed at random along and across the surface.
inline Mesh noisy_sphere(unsigned levels, double tangential, double normal, unsigned seed)
{
  Mesh m = make_sphere(levels);
  CGAL::Random rng(seed);
  for(auto v : vertices(m))
  {
    const Vector n = m.point(v) - CGAL::ORIGIN;
    const Vector t = CGAL::cross_product(n, Vector(rng.get_double(-1, 1), rng.get_double(-1, 1), rng.get_double(-1, 1)));
    m.point(v) = m.point(v) + tangential * t + normal * rng.get_double(-1, 1) * n;
  }
  return m;
}

// A closed box [0, a] x [0, b] x [0, c] whose faces are n x n grids, each slightly jittered
// inside its face plane so that the triangles are uneven; each cell is cut into two triangles,
// or with `centred_cells` into four around its centre.
inline Mesh jittered_box(double a, double b, double c, std::size_t n, unsigned seed, bool centred_cells = false)
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  CGAL::Random rng(seed);
  std::map<std::array<long, 3>, std::size_t> index;
  auto vertex = [&](long i, long j, long k) {
    const std::array<long, 3> key{{i, j, k}};
    auto it = index.find(key);
    if(it != index.end())
      return it->second;
    // Jitter along the coordinates that are not on the box's boundary in that direction.
    double p[3] = {double(i), double(j), double(k)};
    const long ijk[3] = {i, j, k};
    for(int d = 0; d < 3; ++d)
      if(ijk[d] != 0 && ijk[d] != long(n))
        p[d] += rng.get_double(-0.3, 0.3);
    points.emplace_back(a * p[0] / double(n), b * p[1] / double(n), c * p[2] / double(n));
    index.emplace(key, points.size() - 1);
    return points.size() - 1;
  };
  // Each face: a grid over two free coordinates, the third fixed at 0 or n, oriented outwards.
  for(int axis = 0; axis < 3; ++axis)
    for(long side : {0l, long(n)})
      for(long u = 0; u < long(n); ++u)
        for(long w = 0; w < long(n); ++w)
        {
          auto at = [&](long s, long t) {
            long ijk[3];
            ijk[axis] = side;
            ijk[(axis + 1) % 3] = s;
            ijk[(axis + 2) % 3] = t;
            return vertex(ijk[0], ijk[1], ijk[2]);
          };
          const std::size_t p00 = at(u, w), p10 = at(u + 1, w), p11 = at(u + 1, w + 1), p01 = at(u, w + 1);
          if(centred_cells)
          {
            // A fan of four triangles around the cell's centre, in the order of the outward normal.
            points.push_back(CGAL::centroid(points[p00], points[p10], points[p11], points[p01]));
            const std::size_t centre = points.size() - 1;
            const std::array<std::size_t, 4> cell = side == 0 ? std::array<std::size_t, 4>{{p00, p01, p11, p10}}
                                                              : std::array<std::size_t, 4>{{p00, p10, p11, p01}};
            for(std::size_t k = 0; k < 4; ++k)
              triangles.push_back({{cell[k], cell[(k + 1) % 4], centre}});
          }
          else if(side == 0)
          {
            triangles.push_back({{p00, p11, p10}});
            triangles.push_back({{p00, p01, p11}});
          }
          else
          {
            triangles.push_back({{p00, p10, p11}});
            triangles.push_back({{p00, p11, p01}});
          }
        }
  return mesh_from_soup(points, triangles);
}

// One of CGAL's sample meshes, extracted into the build tree by CMake.
inline Mesh load_sample_mesh(const std::string& name)
{
  Mesh mesh;
  const std::string path = std::string(GRAPHCUT_REMESHING_DATA_DIR) + "/" + name + ".off";
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || num_faces(mesh) == 0)
    ADD_FAILURE() << "cannot read " << path;
  return mesh;
}

} // namespace graphcut_remeshing_test

#endif // CGAL_GRAPHCUT_REMESHING_TEST_MESHES_H
