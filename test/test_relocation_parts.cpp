// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The parts of vertex relocation, each against an independent computation: the unit box, the
// energy terms (eq. 2 and eq. 4), the reference surface, the candidates (eq. 5), the sharp
// features (eq. 8) and the named parameters.

#include "test_meshes.h"

#include <CGAL/Polygon_mesh_processing/graphcut_remeshing_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/candidates.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/distance_bound.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/energy.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/features.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/normalization.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/reference_surface.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>

#include <CGAL/Random.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <type_traits>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace GP = PMP::graphcut_parameters;
namespace GR = PMP::internal::Graphcut_remeshing;
using namespace graphcut_remeshing_test;

using GR::Vector_3d;

namespace {

const double eps = std::numeric_limits<double>::epsilon();
// The sharp-edge hysteresis bounds of eq. (8) these tests use (the library's defaults).
const double theta_false = 20, theta_true = 35;

Vector_3d vec(const Work_point& p) { return Vector_3d(p.x(), p.y(), p.z()); }

Vector_3d random_vector(CGAL::Random& rng, double lo = -1, double hi = 1)
{
  return Vector_3d(rng.get_double(lo, hi), rng.get_double(lo, hi), rng.get_double(lo, hi));
}

Vector_3d random_unit(CGAL::Random& rng)
{
  for(;;)
  {
    const Vector_3d v = random_vector(rng);
    if(v.norm() > 0.1 && v.norm() < 1)
      return v.normalized();
  }
}

Eigen::Matrix3d random_rotation(CGAL::Random& rng)
{
  return Eigen::AngleAxisd(rng.get_double(0, 2 * pi), random_unit(rng)).toRotationMatrix();
}

Vector_3d closest_on_segment(const Vector_3d& p, const Vector_3d& s, const Vector_3d& t)
{
  const double l2 = (t - s).squaredNorm();
  const double x = l2 > 0 ? std::clamp((p - s).dot(t - s) / l2, 0.0, 1.0) : 0.0;
  return s + x * (t - s);
}

// Closest point of a triangle, computed differently from the header: the projection on the plane
// when it falls inside (signed sub-areas), otherwise the best clamped projection on the three sides.
Vector_3d reference_closest_point(const Vector_3d& p, const Vector_3d& a, const Vector_3d& b, const Vector_3d& c)
{
  const Vector_3d n = (b - a).cross(c - a);
  const double n2 = n.squaredNorm();
  if(n2 > 0)
  {
    const Vector_3d q = p - ((p - a).dot(n) / n2) * n;
    const double u = (c - b).cross(q - b).dot(n) / n2, v = (a - c).cross(q - c).dot(n) / n2;
    if(u >= 0 && v >= 0 && 1 - u - v >= 0)
      return q;
  }
  Vector_3d best = closest_on_segment(p, a, b);
  for(const Vector_3d& q : {closest_on_segment(p, b, c), closest_on_segment(p, c, a)})
    if((q - p).squaredNorm() < (best - p).squaredNorm())
      best = q;
  return best;
}

// A cube [0,1]^3 whose faces are n x n grids of split squares, outward oriented, vertices shared
// along the cube edges. Cube-edge vertices are the ones with two extreme lattice coordinates.
Work_mesh make_lattice_cube(int n)
{
  Work_mesh m;
  std::map<std::array<int, 3>, Work_vertex> index;
  auto vertex = [&](std::array<int, 3> p) {
    auto it = index.find(p);
    if(it != index.end())
      return it->second;
    const Work_vertex v = m.add_vertex(Work_point(double(p[0]) / n, double(p[1]) / n, double(p[2]) / n));
    index.emplace(p, v);
    return v;
  };
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side <= n; side += n)
    {
      // (u, v) with e_u x e_v = +e_axis; swapped on the low side so that normals point outward.
      int u = (axis + 1) % 3, v = (axis + 2) % 3;
      if(side == 0)
        std::swap(u, v);
      auto at = [&](int i, int j) {
        std::array<int, 3> p{};
        p[axis] = side;
        p[u] = i;
        p[v] = j;
        return vertex(p);
      };
      for(int i = 0; i < n; ++i)
        for(int j = 0; j < n; ++j)
        {
          m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
          m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
        }
    }
  return m;
}

int extreme_coordinates(const Work_point& p)
{
  int count = 0;
  for(int i = 0; i < 3; ++i)
    count += (p[i] == 0 || p[i] == 1) ? 1 : 0;
  return count;
}

bool on_cube_edge(const Work_mesh& m, Work_mesh::Edge_index e)
{
  const Work_point p = m.point(m.vertex(e, 0)), q = m.point(m.vertex(e, 1));
  return extreme_coordinates(CGAL::midpoint(p, q)) >= 2;
}

// A roof strip along the x axis: crease vertices C_i = (i, 0, 0), and for the crease segment i one
// triangle on each side whose apex is raised so that the two make the dihedral angle theta[i]; the
// triangles between consecutive apexes close the strip. Returns the mesh and the crease edges.
std::pair<Work_mesh, std::vector<Work_mesh::Edge_index> > make_roof(const std::vector<double>& theta)
{
  Work_mesh m;
  const std::size_t n = theta.size();
  std::vector<Work_vertex> c, l, r;
  for(std::size_t i = 0; i <= n; ++i)
    c.push_back(m.add_vertex(Work_point(double(i), 0, 0)));
  for(std::size_t i = 0; i < n; ++i)
  {
    const double half = theta[i] / 2 * pi / 180;
    l.push_back(m.add_vertex(Work_point(i + 0.5, -std::cos(half), std::sin(half))));
    r.push_back(m.add_vertex(Work_point(i + 0.5, std::cos(half), std::sin(half))));
  }
  for(std::size_t i = 0; i < n; ++i)
  {
    m.add_face(c[i + 1], c[i], l[i]);
    m.add_face(c[i], c[i + 1], r[i]);
    if(i + 1 < n)
    {
      m.add_face(c[i + 1], l[i], l[i + 1]);
      m.add_face(c[i + 1], r[i + 1], r[i]);
    }
  }
  std::vector<Work_mesh::Edge_index> crease;
  for(std::size_t i = 0; i < n; ++i)
    crease.push_back(m.edge(m.halfedge(c[i], c[i + 1])));
  return {m, crease};
}

} // namespace

// ------------------------------------------------------------------------------------------------

TEST(Unit_box_normalization, MapsTheBoundingBoxToACentredUnitBox)
{
  CGAL::Random rng(1);
  const std::array<Vector_3d, 3> shapes = {{Vector_3d(1, 0.3, 0.6), Vector_3d(0.2, 1, 0.7), Vector_3d(0.5, 0.4, 1)}};
  for(double scale : {1e-8, 1.0, 1e8})
    for(double offset : {0.0, 1.0, -1e3, 1e6}) // in units of the extent
      for(const Vector_3d& shape : shapes)
      {
        const Vector_3d shift = offset * scale * Vector_3d(1, -0.5, 0.25);
        std::vector<Vector_3d> points;
        for(int i = 0; i < 200; ++i)
          points.push_back(shift + scale * Vector_3d(rng.get_double(0, shape.x()), rng.get_double(0, shape.y()),
                                                     rng.get_double(0, shape.z())));
        Vector_3d lo = points[0], hi = points[0];
        for(const Vector_3d& p : points)
        {
          lo = lo.cwiseMin(p);
          hi = hi.cwiseMax(p);
        }
        const double extent = (hi - lo).maxCoeff();
        const GR::Unit_box_normalization normalization(points);
        EXPECT_NEAR(normalization.scale() * extent, 1.0, 1e-15);

        // The centre can be no more accurate than the coordinates it is computed from.
        const double tolerance = 1e-12 + 4 * eps * std::abs(offset);
        Vector_3d ulo = normalization.to_unit(points[0]), uhi = ulo;
        for(const Vector_3d& p : points)
        {
          const Vector_3d q = normalization.to_unit(p);
          ulo = ulo.cwiseMin(q);
          uhi = uhi.cwiseMax(q);
          const double back = (normalization.from_unit(q) - p).cwiseAbs().maxCoeff();
          EXPECT_LE(back, 1e-12 * extent + 4 * eps * p.cwiseAbs().maxCoeff())
            << "scale " << scale << " offset " << offset;
        }
        EXPECT_NEAR((uhi - ulo).maxCoeff(), 1.0, 1e-12) << "scale " << scale << " offset " << offset;
        for(int k = 0; k < 3; ++k)
        {
          EXPECT_NEAR(ulo[k] + uhi[k], 0.0, 2 * tolerance) << "axis " << k << " scale " << scale << " offset " << offset;
          EXPECT_LE(uhi[k] - ulo[k], 1.0 + 1e-12);
        }
      }
}

TEST(Unit_box_normalization, SinglePointAndEmptySet)
{
  const std::vector<Vector_3d> one(1, Vector_3d(3, -2, 7));
  const GR::Unit_box_normalization single(one);
  EXPECT_EQ(single.scale(), 1.0); // no extent: no scaling, and no division by zero
  EXPECT_EQ(single.to_unit(one[0]), Vector_3d::Zero());
  EXPECT_EQ(single.from_unit(Vector_3d::Zero()), one[0]);
  const GR::Unit_box_normalization empty(std::vector<Vector_3d>{});
  EXPECT_EQ(empty.to_unit(one[0]), one[0]);
}

// ------------------------------------------------------------------------------------------------

TEST(Energy, ShapeEnergyOfKnownTriangles)
{
  CGAL::Random rng(2);
  const Vector_3d a(0, 0, 0), b(1, 0, 0), c(0.5, std::sqrt(3.0) / 2, 0), d(0, 1, 0);
  for(double scale : {1e-6, 1e-3, 1.0, 1e3, 1e6})
    for(int trial = 0; trial < 10; ++trial)
    {
      const Eigen::Matrix3d rotation = random_rotation(rng);
      const Vector_3d t = scale * random_vector(rng);
      auto place = [&](const Vector_3d& p) { return Vector_3d(rotation * (scale * p) + t); };
      EXPECT_NEAR(GR::shape_energy(place(a), place(b), place(c)) * std::sqrt(3.0), 1.0, 1e-12) << "scale " << scale;
      // Right isosceles with legs 1: R = sqrt(2)/2 (half the hypotenuse), shortest edge 1.
      EXPECT_NEAR(GR::shape_energy(place(a), place(b), place(d)), std::sqrt(2.0) / 2, 1e-12) << "scale " << scale;
    }
}

TEST(Energy, ShapeEnergyAgainstTheCircumcentre)
{
  CGAL::Random rng(3);
  int checked = 0;
  while(checked < 500)
  {
    const Vector_3d a = random_vector(rng), b = random_vector(rng), c = random_vector(rng);
    const auto angles = GR::triangle_angles(a, b, c);
    if(*std::min_element(angles.begin(), angles.end()) < 5 * pi / 180)
      continue;
    ++checked;
    // Circumcentre from the standard cross-product formula.
    const Vector_3d ab = b - a, ac = c - a, n = ab.cross(ac);
    const Vector_3d centre = a + (ac.squaredNorm() * n.cross(ab) + ab.squaredNorm() * ac.cross(n)) / (2 * n.squaredNorm());
    const double radius = (centre - a).norm();
    ASSERT_NEAR((centre - b).norm() / radius, 1.0, 1e-9);
    const double shortest = (std::min)({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const double expected = radius / shortest;
    EXPECT_NEAR(GR::shape_energy(a, b, c) / expected, 1.0, 1e-10);
    // Scale invariance (eq. 2 is a ratio of lengths).
    for(double s : {1e-6, 1e6})
      EXPECT_NEAR(GR::shape_energy(s * a, s * b, s * c) / expected, 1.0, 1e-10) << "scale " << s;
  }
}

TEST(Energy, DegenerateTrianglesHaveInfiniteShapeEnergy)
{
  const Vector_3d a(0, 0, 0), b(1, 2, 3), p(-1.5, 0.25, 4);
  const std::vector<std::array<Vector_3d, 3> > degenerate = {
    {{a, b, Vector_3d(2, 4, 6)}},       // collinear, c beyond b
    {{a, b, Vector_3d(0.5, 1, 1.5)}},   // collinear, c between a and b
    {{a, a, b}},                        // repeated point
    {{p, b, p}},
    {{p, p, p}}};
  for(const auto& t : degenerate)
  {
    const double e = GR::shape_energy(t[0], t[1], t[2]);
    EXPECT_TRUE(std::isinf(e) && e > 0) << "got " << e;
  }
  // Nearly degenerate: finite and huge (R / lmin ~ 0.25 / height).
  const double e = GR::shape_energy(Vector_3d(0, 0, 0), Vector_3d(1, 0, 0), Vector_3d(0.5, 1e-9, 0));
  EXPECT_TRUE(std::isfinite(e));
  EXPECT_NEAR(e / 2.5e8, 1.0, 1e-6);
}

TEST(Energy, AcceptableTriangles)
{
  CGAL::Random rng(4);
  for(double scale : {1e-6, 1.0, 1e6})
    for(int trial = 0; trial < 20; ++trial)
    {
      const Eigen::Matrix3d rotation = random_rotation(rng);
      auto place = [&](double x, double y) { return Vector_3d(scale * (rotation * Vector_3d(x, y, 0))); };
      const Vector_3d a = place(0, 0), b = place(1, 0), c = place(0.4, 0.8);
      const Vector_3d current = GR::area_vector(a, b, c);
      EXPECT_TRUE(GR::is_acceptable_triangle(a, b, c, current)) << "scale " << scale;
      // A small move keeps the triangle valid, whatever the scale.
      EXPECT_TRUE(GR::is_acceptable_triangle(a, b, c + 0.01 * scale * random_unit(rng), current)) << "scale " << scale;
      // A thin but honest triangle (height 1e-6 of its length) is not refused.
      EXPECT_TRUE(GR::is_acceptable_triangle(a, b, place(0.4, 1e-6), current)) << "scale " << scale;
      // Turned over: orientation reversed, or the apex moved across the opposite edge.
      EXPECT_FALSE(GR::is_acceptable_triangle(a, c, b, current)) << "scale " << scale;
      EXPECT_FALSE(GR::is_acceptable_triangle(a, b, place(0.4, -0.3), current)) << "scale " << scale;
      // Degenerate: apex on the base (exactly at its midpoint), or on a vertex.
      EXPECT_FALSE(GR::is_acceptable_triangle(a, b, 0.5 * (a + b), current)) << "scale " << scale;
      EXPECT_FALSE(GR::is_acceptable_triangle(a, b, a, current)) << "scale " << scale;
      // Relative area 1e-14: a shape energy near 1e13, below the documented 1e-12 threshold.
      EXPECT_FALSE(GR::is_acceptable_triangle(a, b, place(0.4, 1e-14), current)) << "scale " << scale;
    }
}

// ------------------------------------------------------------------------------------------------

// The data term of eq. (4) against the exact squared distance to a sphere or a cylinder of radius
// R, for x = origin + h (a d1 + b d2 + c n), r2 = a^2 + b^2 on the sphere, a^2 on the cylinder
// (r2 <= 2). With d = h |c|, series in h give
//   F - exact^2 = (|c| - c) r2 h^3 / R - r2^2 h^4 / (4 R^2) + O(h^5 / R^3).
// Outside (c > 0) the cubic terms cancel: error <= h^4 / R^2 (bound used: 2 h^4 / R^2). Inside,
// the |rho| of eq. (4) leaves 2 |c| r2 h^3 / R <= 4 h^3 / R (bound used: 5 h^3 / R).
namespace {

void check_data_term(bool cylinder, double R, CGAL::Random& rng)
{
  for(double h : {1e-2, 1e-3, 1e-4})
  {
    double worst_inside = 0, worst_outside = 0;
    for(int trial = 0; trial < 200; ++trial)
    {
      const Vector_3d centre = random_vector(rng, -0.5, 0.5);
      const Eigen::Matrix3d rotation = random_rotation(rng);
      const Vector_3d axis = rotation.col(2);
      // A random point of the surface; d1 along the circles for the cylinder, any tangent pair on
      // the sphere.
      GR::Local_frame frame;
      if(cylinder)
      {
        frame.normal = rotation.col(0);
        frame.d1 = axis.cross(frame.normal);
        frame.d2 = axis;
        frame.origin = centre + rng.get_double(-1, 1) * axis + R * frame.normal;
        frame.k1 = 1 / R;
        frame.k2 = 0;
      }
      else
      {
        frame.normal = rotation.col(0);
        frame.d1 = rotation.col(1);
        frame.d2 = rotation.col(2);
        frame.origin = centre + R * frame.normal;
        frame.k1 = frame.k2 = 1 / R;
      }
      const double a = rng.get_double(-1, 1), b = rng.get_double(-1, 1), c = rng.get_double(-1, 1);
      const Vector_3d x = frame.origin + h * (a * frame.d1 + b * frame.d2 + c * frame.normal);
      double exact;
      if(cylinder)
      {
        const Vector_3d v = x - centre;
        exact = (v - v.dot(axis) * axis).norm() - R;
      }
      else
        exact = (x - centre).norm() - R;
      const double error = std::abs(GR::squared_distance_approximation(x, frame, 0.01) - exact * exact);
      if(c > 0)
      {
        EXPECT_LE(error, 2 * std::pow(h, 4) / (R * R))
          << (cylinder ? "cylinder" : "sphere") << " R " << R << " h " << h << " (a, b, c) = " << a << " " << b << " " << c;
        worst_outside = (std::max)(worst_outside, error);
      }
      else
        worst_inside = (std::max)(worst_inside, error);
      EXPECT_LE(error, 5 * std::pow(h, 3) / R)
        << (cylinder ? "cylinder" : "sphere") << " R " << R << " h " << h << " (a, b, c) = " << a << " " << b << " " << c;
    }
    // Not vacuous: inside, the cubic error term is really there (|rho| of eq. 4).
    EXPECT_GT(worst_inside, 0.1 * std::pow(h, 3) / R);
    EXPECT_LT(worst_outside, 0.1 * std::pow(h, 3) / R);
  }
}

} // namespace

TEST(Data_term, SecondOrderAgreementWithTheSphere)
{
  CGAL::Random rng(5);
  for(double R : {1.0, 0.2})
    check_data_term(false, R, rng);
}

TEST(Data_term, SecondOrderAgreementWithTheCylinder)
{
  CGAL::Random rng(6);
  for(double R : {1.0, 0.2})
    check_data_term(true, R, rng);
}

TEST(Data_term, FlatFrameGivesTheSquaredNormalOffset)
{
  CGAL::Random rng(7);
  for(double scale : {1e-4, 1.0, 1e4})
    for(int trial = 0; trial < 100; ++trial)
    {
      const Eigen::Matrix3d rotation = random_rotation(rng);
      GR::Local_frame frame;
      frame.origin = scale * random_vector(rng);
      frame.normal = rotation.col(0);
      frame.d1 = rotation.col(1);
      frame.d2 = rotation.col(2);
      EXPECT_EQ(frame.min_radius(), std::numeric_limits<double>::infinity());
      const Vector_3d x = frame.origin + scale * random_vector(rng, -3, 3);
      const double offset = (x - frame.origin).dot(frame.normal);
      EXPECT_EQ(GR::squared_distance_approximation(x, frame, 0.01), offset * offset);
    }
}

// ------------------------------------------------------------------------------------------------

namespace {

// The vertices at exactly k edges from v.
std::vector<Work_vertex> ring_at(const Work_mesh& m, Work_vertex v, int k)
{
  std::vector<int> depth(m.number_of_vertices(), -1);
  std::vector<Work_vertex> frontier(1, v), next;
  depth[std::size_t(v)] = 0;
  for(int d = 0; d < k; ++d)
  {
    next.clear();
    for(Work_vertex u : frontier)
      for(auto h : halfedges_around_target(m.halfedge(u), m))
        if(depth[std::size_t(m.source(h))] < 0)
        {
          depth[std::size_t(m.source(h))] = d + 1;
          next.push_back(m.source(h));
        }
    frontier.swap(next);
  }
  return frontier;
}

} // namespace

TEST(Reference_surface, JetFramesOnAnIcosphere)
{
  for(double R : {0.5, 1.0, 2.0})
  {
    const Vector_3d centre(0.1, -0.2, 0.3);
    const Work_mesh m = to_work_mesh(make_sphere(4, R, Point(centre.x(), centre.y(), centre.z())));
    const GR::Reference_surface<Work_mesh> reference(m, theta_false);
    double worst = 0;
    for(Work_vertex v : m.vertices())
    {
      const GR::Local_frame& f = reference.frame(v);
      const Vector_3d radial = (vec(m.point(v)) - centre).normalized();
      EXPECT_GT(f.normal.dot(radial), 0.99) << "R " << R << " vertex " << std::size_t(v);
      EXPECT_NEAR(f.normal.norm(), 1.0, 1e-12);
      EXPECT_NEAR(f.d1.norm(), 1.0, 1e-12);
      EXPECT_NEAR(f.d2.norm(), 1.0, 1e-12);
      EXPECT_NEAR(f.d1.dot(f.d2), 0.0, 1e-9);
      EXPECT_NEAR(f.d1.dot(f.normal), 0.0, 1e-9);
      EXPECT_NEAR(f.d2.dot(f.normal), 0.0, 1e-9);
      EXPECT_EQ(f.origin, vec(m.point(v)));
      worst = (std::max)({worst, std::abs(std::abs(f.k1) * R - 1), std::abs(std::abs(f.k2) * R - 1)});
      EXPECT_GE(std::abs(f.k1), std::abs(f.k2)); // d1 carries the larger curvature
    }
    EXPECT_LE(worst, 0.05) << "R " << R;
  }
}

namespace {

struct Sphere_fixture
{
  Vector_3d centre;
  double R;
  Work_mesh m;
  GR::Reference_surface<Work_mesh> reference;

  explicit Sphere_fixture(double radius)
    : centre(0.1, -0.2, 0.3), R(radius),
      m(to_work_mesh(make_sphere(4, radius, Point(centre.x(), centre.y(), centre.z())))), reference(m, theta_false)
  {}

  Vector_3d point(Work_vertex v) const { return vec(m.point(v)); }

  // A point at relative height in [lo, hi] above the sphere.
  Vector_3d random_point(CGAL::Random& rng, double lo, double hi) const
  {
    return centre + R * (1 + rng.get_double(lo, hi)) * random_unit(rng);
  }

  Work_vertex nearest_vertex(const Vector_3d& x) const
  {
    Work_vertex nearest = *m.vertices().begin();
    for(Work_vertex v : m.vertices())
      if((point(v) - x).squaredNorm() < (point(nearest) - x).squaredNorm())
        nearest = v;
    return nearest;
  }

  Vector_3d closest_point_of_face(const Vector_3d& x, Work_mesh::Face_index f, std::array<double, 3>& w) const
  {
    const auto t = reference.face_vertices(f);
    return GR::closest_point_on_triangle(x, point(t[0]), point(t[1]), point(t[2]), w);
  }

  double distance_to_mesh(const Vector_3d& x) const
  {
    double d = std::numeric_limits<double>::infinity();
    std::array<double, 3> w;
    for(auto f : m.faces())
      d = (std::min)(d, (closest_point_of_face(x, f, w) - x).norm());
    return d;
  }

  // A vertex three rings away from the one nearest to x: where a search starts.
  Work_vertex start_for(const Vector_3d& x, CGAL::Random& rng) const
  {
    const std::vector<Work_vertex> far = ring_at(m, nearest_vertex(x), 3);
    return far[std::size_t(rng.get_int(0, int(far.size())))];
  }
};

// frame_at_closest_point from three rings away, for points at relative heights in [lo, hi].
void check_closest_point(double lo, double hi, CGAL::Random& rng)
{
  for(double R : {0.5, 1.0, 2.0})
  {
    const Sphere_fixture s(R);
    int interior = 0;
    for(int trial = 0; trial < 100; ++trial)
    {
      const Vector_3d x = s.random_point(rng, lo, hi);
      const double distance = s.distance_to_mesh(x);
      auto hint = s.reference.incident_face(s.start_for(x, rng));
      const GR::Local_frame frame = s.reference.frame_at_closest_point(x, hint);
      EXPECT_NEAR((frame.origin - x).norm(), distance, 1e-12)
        << "R " << R << " trial " << trial << ", |x - centre| / R = " << (x - s.centre).norm() / R;
      // The hint now holds the triangle of the closest point.
      std::array<double, 3> w;
      EXPECT_LE((s.closest_point_of_face(x, hint, w) - frame.origin).norm(), 1e-12) << "R " << R << " trial " << trial;
      EXPECT_NEAR(frame.normal.norm(), 1.0, 1e-12);
      EXPECT_NEAR(frame.d1.dot(frame.normal), 0.0, 1e-12);
      // Inside a triangle x - origin is along the normal: eq. (4) is then the exact squared distance.
      if(*std::min_element(w.begin(), w.end()) > 1e-3)
      {
        ++interior;
        EXPECT_NEAR(GR::squared_distance_approximation(x, frame, 0.01), distance * distance,
                    1e-12 * R * R + 1e-9 * distance * distance) << "R " << R << " trial " << trial;
      }
    }
    EXPECT_GT(interior, 50); // most points project inside a triangle
  }
}

} // namespace

TEST(Reference_surface, ClosestVertexByLocalSearch)
{
  CGAL::Random rng(8);
  for(double R : {0.5, 1.0, 2.0})
  {
    const Sphere_fixture s(R);
    for(int trial = 0; trial < 200; ++trial)
    {
      const Vector_3d x = s.random_point(rng, -0.05, 0.05);
      const Work_vertex found = s.reference.closest_vertex(x, s.start_for(x, rng));
      // Compared by distance: ties between vertices are allowed.
      EXPECT_EQ((s.point(found) - x).squaredNorm(), (s.point(s.nearest_vertex(x)) - x).squaredNorm())
        << "R " << R << " trial " << trial;
    }
  }
}

TEST(Reference_surface, ClosestPointFromOutside)
{
  CGAL::Random rng(14);
  check_closest_point(0.001, 0.05, rng);
}

// On the concave side several triangles' normal prisms overlap, so a triangle that x projects
// into need not be the closest one.
TEST(Reference_surface, ClosestPointFromInside)
{
  CGAL::Random rng(15);
  check_closest_point(-0.05, -0.001, rng);
}

// ------------------------------------------------------------------------------------------------

TEST(Closest_point_on_triangle, AgainstAClampedProjection)
{
  CGAL::Random rng(9);
  for(double scale : {1e-3, 1.0, 1e3})
    for(int trial = 0; trial < 200; ++trial)
    {
      const Vector_3d shift = scale * random_vector(rng);
      const Vector_3d a = shift + scale * random_vector(rng), b = shift + scale * random_vector(rng),
                      c = shift + scale * random_vector(rng);
      for(int k = 0; k < 10; ++k)
      {
        const Vector_3d p = shift + scale * random_vector(rng, -2, 2);
        std::array<double, 3> w;
        const Vector_3d q = GR::closest_point_on_triangle(p, a, b, c, w);
        EXPECT_LE((q - reference_closest_point(p, a, b, c)).norm(), 1e-12 * scale) << "scale " << scale;
        EXPECT_NEAR(w[0] + w[1] + w[2], 1.0, 1e-12);
        for(double wi : w)
          EXPECT_TRUE(wi >= 0 && wi <= 1) << wi;
        EXPECT_LE((w[0] * a + w[1] * b + w[2] * c - q).norm(), 1e-12 * scale);
      }
    }
}

TEST(Closest_point_on_triangle, EveryVoronoiRegion)
{
  CGAL::Random rng(10);
  for(int trial = 0; trial < 300; ++trial)
  {
    const std::array<Vector_3d, 3> v = {{random_vector(rng), random_vector(rng), random_vector(rng)}};
    const Vector_3d n = GR::area_vector(v[0], v[1], v[2]);
    if(n.norm() < 0.05)
      continue;
    const Vector_3d unit_n = n.normalized();
    auto check = [&](const Vector_3d& p, const Vector_3d& expected, const std::array<double, 3>& expected_w,
                     const char* region) {
      std::array<double, 3> w;
      const Vector_3d q = GR::closest_point_on_triangle(p, v[0], v[1], v[2], w);
      EXPECT_LE((q - expected).norm(), 1e-12) << region;
      for(int i = 0; i < 3; ++i)
        EXPECT_NEAR(w[i], expected_w[i], 1e-12) << region << " weight " << i;
      EXPECT_LE((w[0] * v[0] + w[1] * v[1] + w[2] * v[2] - q).norm(), 1e-12) << region;
    };
    const double z = rng.get_double(-1, 1);
    for(int i = 0; i < 3; ++i)
    {
      const Vector_3d& a = v[i];
      const Vector_3d& b = v[(i + 1) % 3];
      const Vector_3d& c = v[(i + 2) % 3];
      // Vertex region of a: (p - a).(b - a) <= 0 and (p - a).(c - a) <= 0.
      for(;;)
      {
        const Vector_3d d = GR::tangential(random_vector(rng), unit_n);
        if(d.dot(b - a) < 0 && d.dot(c - a) < 0)
        {
          std::array<double, 3> w{};
          w[i] = 1;
          check(a + d + z * unit_n, a, w, "vertex");
          break;
        }
      }
      // Region of edge ab: outside the edge, between the perpendiculars at a and b.
      const double t = rng.get_double(0.01, 0.99);
      Vector_3d out = (b - a).cross(unit_n).normalized();
      if(out.dot(c - a) > 0)
        out = -out;
      std::array<double, 3> w{};
      w[i] = 1 - t;
      w[(i + 1) % 3] = t;
      check(a + t * (b - a) + rng.get_double(0.01, 2) * out + z * unit_n, a + t * (b - a), w, "edge");
    }
    // The interior.
    const double u = rng.get_double(0.01, 1), s = rng.get_double(0.01, 1), r = rng.get_double(0.01, 1);
    const std::array<double, 3> w = {{u / (u + s + r), s / (u + s + r), r / (u + s + r)}};
    const Vector_3d inside = w[0] * v[0] + w[1] * v[1] + w[2] * v[2];
    check(inside + z * unit_n, inside, w, "face");
  }
}

TEST(Closest_point_on_triangle, NoSampleOfTheTriangleIsCloser)
{
  CGAL::Random rng(11);
  const int n = 60;
  for(int trial = 0; trial < 100; ++trial)
  {
    const Vector_3d a = random_vector(rng), b = random_vector(rng), c = random_vector(rng);
    const Vector_3d p = random_vector(rng, -2, 2);
    std::array<double, 3> w;
    const double d = (GR::closest_point_on_triangle(p, a, b, c, w) - p).norm();
    double sampled = std::numeric_limits<double>::infinity();
    for(int i = 0; i <= n; ++i)
      for(int j = 0; i + j <= n; ++j)
        sampled = (std::min)(sampled, (p - (double(n - i - j) * a + double(i) * b + double(j) * c) / n).norm());
    EXPECT_LE(d, sampled + 1e-12);
    // The samples are within half a sampling step of the closest point.
    EXPECT_LE(sampled, d + 2.0 * 2 * std::sqrt(3.0) / n);
  }
}

TEST(Closest_point_on_triangle, DegenerateTriangles)
{
  CGAL::Random rng(12);
  for(int trial = 0; trial < 200; ++trial)
  {
    // Three points collinear up to rounding (a sliver of area ~1e-17): its closest point is within
    // rounding of the closest point of its sides.
    const Vector_3d o = random_vector(rng), d = random_vector(rng);
    const Vector_3d a = o, b = o + d, c = o + rng.get_double(-1, 2) * d;
    const Vector_3d p = random_vector(rng, -2, 2);
    std::array<double, 3> w;
    const Vector_3d q = GR::closest_point_on_triangle(p, a, b, c, w);
    Vector_3d expected = closest_on_segment(p, a, b);
    for(const Vector_3d& r : {closest_on_segment(p, b, c), closest_on_segment(p, c, a)})
      if((r - p).squaredNorm() < (expected - p).squaredNorm())
        expected = r;
    EXPECT_LE((q - expected).norm(), 1e-9) << "trial " << trial << ": a = " << a.transpose() << ", b = "
      << b.transpose() << ", c = " << c.transpose() << ", p = " << p.transpose() << ", area "
      << GR::area_vector(a, b, c).norm() / 2;
    EXPECT_NEAR(w[0] + w[1] + w[2], 1.0, 1e-12);
  }
}

// ------------------------------------------------------------------------------------------------

namespace {

// The largest distance from a dense grid of samples of t to the triangles (a lower bound of the
// true largest distance, below it by at most the grid's spacing).
double sampled_distance(const GR::Triangle_3d& t, const std::vector<GR::Triangle_3d>& to, int n = 40)
{
  double largest = 0;
  for(int i = 0; i <= n; ++i)
    for(int j = 0; i + j <= n; ++j)
    {
      const double u = double(i) / n, v = double(j) / n;
      largest = (std::max)(largest, GR::distance_to_triangles((1 - u - v) * t[0] + u * t[1] + v * t[2], to));
    }
  return largest;
}

std::vector<GR::Triangle_3d> mesh_triangles(const Work_mesh& m)
{
  std::vector<GR::Triangle_3d> triangles;
  for(auto f : m.faces())
  {
    const auto v = GR::face_vertices(m, f);
    triangles.push_back(GR::Triangle_3d{{vec(m.point(v[0])), vec(m.point(v[1])), vec(m.point(v[2]))}});
  }
  return triangles;
}

// The triangles around v with v at x.
std::vector<GR::Triangle_3d> star(const Work_mesh& m, Work_mesh::Vertex_index v, const Vector_3d& x)
{
  std::vector<GR::Triangle_3d> triangles;
  for(auto h : CGAL::halfedges_around_target(m.halfedge(v), m))
    if(!m.is_border(h))
      triangles.push_back(GR::Triangle_3d{{x, vec(m.point(m.target(m.next(h)))), vec(m.point(m.source(h)))}});
  return triangles;
}

} // namespace

TEST(Distance_bound, TrianglesOverASquare)
{
  for(double scale : {1e-3, 1.0, 1e3})
  {
    const Work_mesh square = to_work_mesh(make_grid(9, 9, [scale](std::size_t i, std::size_t j) {
      return Point(scale * double(i) / 8, scale * double(j) / 8, 0);
    }));
    const double bound = 0.01 * scale;
    const GR::Distance_bound check(square, bound);
    auto above = [&](double height, double out) {
      const GR::Triangle_3d t{{Vector_3d(0.3 * scale, 0.2 * scale, height), Vector_3d(1 * scale + out, 0.4 * scale, height),
                               Vector_3d(0.45 * scale, 0.9 * scale, height)}};
      return check.near_input({t});
    };
    for(double h : {0.0, 0.5, 0.99})
      EXPECT_TRUE(above(h * bound, 0)) << "height " << h << " scale " << scale;
    for(double h : {1.01, 2.0})
      EXPECT_FALSE(above(h * bound, 0)) << "height " << h << " scale " << scale;
    // Beyond the square's border, in its plane: the distance is the overhang.
    EXPECT_TRUE(above(0, 0.9 * bound));
    EXPECT_TRUE(above(0.6 * bound, 0.7 * bound)); // sqrt(0.36 + 0.49) < 1
    EXPECT_FALSE(above(0, 1.1 * bound));
    EXPECT_FALSE(above(0.8 * bound, 0.7 * bound));
  }
}

// The answer yes is never wrong: the triangles said to be within the bound are, by a dense
// sampling; and the answer is tight: triangles within 0.8 times the bound are nearly all accepted.
TEST(Distance_bound, NearTheInputOnlyWhenWithinTheBound)
{
  CGAL::Random rng(31);
  const Work_mesh sphere = to_work_mesh(make_sphere(2));
  const std::vector<GR::Triangle_3d> input = mesh_triangles(sphere);
  const double bound = 0.02;
  const GR::Distance_bound check(sphere, bound);
  int yes = 0, refused_well_within = 0, well_within = 0;
  for(int trial = 0; trial < 300; ++trial)
  {
    const Vector_3d n = random_unit(rng);
    const Vector_3d u = n.unitOrthogonal(), w = n.cross(u);
    const double size = rng.get_double(0.05, 0.3), offset = rng.get_double(-1.5 * bound, 1.2 * bound);
    GR::Triangle_3d t;
    for(int k = 0; k < 3; ++k)
    {
      const double angle = 2 * GR::pi * k / 3 + rng.get_double(-0.5, 0.5);
      t[k] = (1 + offset) * n + size * (std::cos(angle) * u + std::sin(angle) * w);
    }
    const double sampled = sampled_distance(t, input);
    const bool answer = check.near_input({t});
    yes += answer;
    if(answer)
    {
      EXPECT_LE(sampled, bound) << "trial " << trial;
    }
    if(sampled <= 0.8 * bound)
    {
      ++well_within;
      refused_well_within += !answer;
    }
  }
  std::cout << yes << " accepted, " << refused_well_within << " of " << well_within << " within 0.8 times refused\n";
  EXPECT_GT(yes, 30);
  EXPECT_GT(well_within, 30);
  EXPECT_LE(refused_well_within, well_within / 20);
}

// A vertex of a flat grid lifted off it: the input below it stays covered while the star's
// triangles pass within the bound of it.
TEST(Distance_bound, InputCoveredByTheTrianglesThatReplaceAStar)
{
  for(double scale : {1e-2, 1.0, 1e2})
  {
    const Work_mesh grid = to_work_mesh(make_grid(7, 7, [scale](std::size_t i, std::size_t j) {
      return Point(scale * double(i) / 6, scale * double(j) / 6, 0);
    }));
    const Work_mesh::Vertex_index centre(24);
    ASSERT_EQ(vec(grid.point(centre)), Vector_3d(scale / 2, scale / 2, 0));
    const double bound = 0.01 * scale;
    const GR::Distance_bound check(grid, bound);
    const std::vector<GR::Triangle_3d> before = star(grid, centre, vec(grid.point(centre)));
    std::vector<GR::Triangle_3d> around;
    for(auto f : grid.faces())
    {
      const auto v = GR::face_vertices(grid, f);
      if(std::find(v.begin(), v.end(), centre) == v.end())
        around.push_back(GR::Triangle_3d{{vec(grid.point(v[0])), vec(grid.point(v[1])), vec(grid.point(v[2]))}});
    }
    auto covered = [&](const Vector_3d& moved) { return check.input_covered(before, star(grid, centre, moved), around); };
    // Lifted by h, the cone's nearest point to the centre below is about h away (the star's
    // edges are 1/6 and sqrt(2)/6 long, so it is h cos of a small angle).
    for(double h : {0.5, 0.98})
      EXPECT_TRUE(covered(vec(grid.point(centre)) + Vector_3d(0, 0, h * bound))) << h << " scale " << scale;
    for(double h : {1.05, 3.0})
      EXPECT_FALSE(covered(vec(grid.point(centre)) + Vector_3d(0, 0, h * bound))) << h << " scale " << scale;
    // Slid within the plane, the star still covers all of it.
    EXPECT_TRUE(covered(vec(grid.point(centre)) + Vector_3d(0.05 * scale, -0.03 * scale, 0)));
    // Output triangles that were there are kept by the other direction's check.
    EXPECT_TRUE(check.near_input(star(grid, centre, vec(grid.point(centre)) + Vector_3d(0, 0, 0.9 * bound))));
    EXPECT_FALSE(check.near_input(star(grid, centre, vec(grid.point(centre)) + Vector_3d(0, 0, 1.1 * bound))));
  }
}

// The input goes on 1.5 bounds beyond the mesh's border: its points there, about the bound from the
// border, are as near to the border's sides after a move that keeps them as before (the cells at
// the bound cannot be told apart by distances alone).
TEST(Distance_bound, InputBeyondABorderSideThatStays)
{
  for(double scale : {1e-2, 1.0, 1e2})
  {
    const double bound = 0.01 * scale;
    const Work_mesh grid = to_work_mesh(make_grid(7, 7, [scale](std::size_t i, std::size_t j) {
      return Point(scale * double(i) / 6, scale * double(j) / 6, 0);
    }));
    const Work_mesh input = to_work_mesh(make_grid(8, 7, [scale, bound](std::size_t i, std::size_t j) {
      return Point(i < 7 ? scale * double(i) / 6 : scale + 1.5 * bound, scale * double(j) / 6, 0);
    }));
    const GR::Distance_bound check(input, bound);
    const Work_mesh::Vertex_index next_to_border(3 * 7 + 5);
    ASSERT_EQ(vec(grid.point(next_to_border)), Vector_3d(scale * 5 / 6, scale / 2, 0));
    const std::vector<GR::Triangle_3d> before = star(grid, next_to_border, vec(grid.point(next_to_border)));
    std::vector<GR::Triangle_3d> around;
    for(auto f : grid.faces())
    {
      const auto v = GR::face_vertices(grid, f);
      if(std::find(v.begin(), v.end(), next_to_border) == v.end())
        around.push_back(GR::Triangle_3d{{vec(grid.point(v[0])), vec(grid.point(v[1])), vec(grid.point(v[2]))}});
    }
    auto covered = [&](const Vector_3d& step) {
      return check.input_covered(before, star(grid, next_to_border, vec(grid.point(next_to_border)) + step), around);
    };
    EXPECT_TRUE(covered(Vector_3d(-0.02 * scale, 0.01 * scale, 0))) << "scale " << scale;
    EXPECT_TRUE(covered(Vector_3d(0, 0, 0.5 * bound))) << "scale " << scale;
    EXPECT_FALSE(covered(Vector_3d(0, 0, 1.05 * bound))) << "scale " << scale;
  }
}

// The answer yes is never wrong: after a random move of a vertex of the input itself, every sampled
// input point within the bound of the star before is within it of the star after or of the rest.
TEST(Distance_bound, InputCoveredOnlyWhenItIs)
{
  CGAL::Random rng(7);
  const Work_mesh sphere = to_work_mesh(make_sphere(2));
  const std::vector<GR::Triangle_3d> input = mesh_triangles(sphere);
  const double bound = 0.02;
  const GR::Distance_bound check(sphere, bound);
  int yes = 0;
  for(int trial = 0; trial < 200; ++trial)
  {
    const Work_mesh::Vertex_index v(rng.get_int(0, int(sphere.number_of_vertices())));
    const Vector_3d moved = vec(sphere.point(v)) + rng.get_double(0, 3 * bound) * random_unit(rng);
    const std::vector<GR::Triangle_3d> before = star(sphere, v, vec(sphere.point(v)));
    std::vector<GR::Triangle_3d> cover = star(sphere, v, moved);
    for(auto f : sphere.faces())
    {
      const auto u = GR::face_vertices(sphere, f);
      if(std::find(u.begin(), u.end(), v) == u.end())
        cover.push_back(GR::Triangle_3d{{vec(sphere.point(u[0])), vec(sphere.point(u[1])), vec(sphere.point(u[2]))}});
    }
    if(!check.input_covered(before, std::vector<GR::Triangle_3d>(cover.begin(), cover.begin() + before.size()),
                            std::vector<GR::Triangle_3d>(cover.begin() + before.size(), cover.end())))
      continue;
    ++yes;
    double worst = 0;
    for(const GR::Triangle_3d& t : GR::triangles_in(input, GR::triangles_box(before, bound)))
      for(int i = 0, n = 24; i <= n; ++i)
        for(int j = 0; i + j <= n; ++j)
        {
          const Vector_3d x = (1 - double(i + j) / n) * t[0] + double(i) / n * t[1] + double(j) / n * t[2];
          if(GR::distance_to_triangles(x, before) <= bound)
            worst = (std::max)(worst, GR::distance_to_triangles(x, cover));
        }
    EXPECT_LE(worst, bound) << "trial " << trial;
  }
  std::cout << yes << " of 200 moves accepted\n";
  EXPECT_GT(yes, 40);
  EXPECT_LT(yes, 190);
}

// ------------------------------------------------------------------------------------------------

TEST(Candidates, FreedomRadiusAndCoolingSchedule)
{
  for(double T : {-5.0, 0.0, 0.5, 3.0, 60.0})
    for(double r : {1e-3, 1.0, 7.0})
      for(double rho : {1e-2, 0.5, 1.0, 4.0, std::numeric_limits<double>::infinity()})
      {
        const double expected = 0.5 / (1 + std::exp(-T)) * r * (rho < 1 ? rho : 1.0);
        EXPECT_NEAR(GR::freedom_radius(T, r, rho) / expected, 1.0, 1e-15) << T << " " << r << " " << rho;
      }
  // Hot: half the ring radius; T = 0: a quarter; curvature radius below 1 shrinks it.
  EXPECT_NEAR(GR::freedom_radius(60, 2, 10), 1.0, 1e-15);
  EXPECT_NEAR(GR::freedom_radius(0, 2, 10), 0.5, 1e-15);
  EXPECT_NEAR(GR::freedom_radius(60, 2, 0.25), 0.25, 1e-15);

  for(double T1 : {10.0, 0.5})
    for(double K : {0.95, 0.5, 1.0})
    {
      EXPECT_EQ(GR::temperature(T1, K, 1), T1);
      double expected = T1;
      for(std::size_t i = 2; i <= 150; ++i)
      {
        expected *= K;
        EXPECT_NEAR(GR::temperature(T1, K, i) / expected, 1.0, 1e-12) << "iteration " << i;
      }
    }
}

TEST(Candidates, SmoothingTargetsOnARegularHexagon)
{
  CGAL::Random rng(13);
  for(double r : {1e-2, 1.0, 1e2})
    for(int trial = 0; trial < 10; ++trial)
    {
      const Eigen::Matrix3d rotation = random_rotation(rng);
      const Vector_3d centre = r * random_vector(rng), e1 = rotation.col(0), e2 = rotation.col(1);
      std::vector<Vector_3d> ring;
      for(int k = 0; k < 6; ++k)
        ring.push_back(centre + r * (std::cos(k * pi / 3) * e1 + std::sin(k * pi / 3) * e2));
      GR::Link link;
      for(int k = 0; k < 6; ++k)
        link.emplace_back(ring[k], ring[(k + 1) % 6]);

      EXPECT_NEAR(GR::ring_radius(centre, link) / r, std::sqrt(3.0) / 2, 1e-14);
      EXPECT_LE((GR::angle_based_target(centre, link) - centre).norm(), 1e-12 * r) << "r " << r;
      EXPECT_LE((GR::laplacian_target(centre, ring) - centre).norm(), 1e-12 * r) << "r " << r;

      for(double phi : {0.0, 0.7, 2.0, 4.5})
      {
        const Vector_3d x = centre + 0.3 * r * (std::cos(phi) * e1 + std::sin(phi) * e2);
        const double before = (x - centre).norm();
        const Vector_3d angle_based = GR::angle_based_target(x, link), laplacian = GR::laplacian_target(x, ring);
        EXPECT_LT((angle_based - centre).norm(), before) << "r " << r << " phi " << phi;
        EXPECT_LT((laplacian - centre).norm(), before) << "r " << r << " phi " << phi;
        // Both stay in the plane of the ring.
        EXPECT_LE(std::abs((angle_based - centre).dot(rotation.col(2))), 1e-12 * r);
        EXPECT_LE(std::abs((laplacian - centre).dot(rotation.col(2))), 1e-12 * r);
      }
      // Zhou-Shimada keeps |x - p| and turns x onto the bisector at each ring vertex p: for a small
      // offset delta, p + |x - p| u_p = centre + (delta . u_p) u_p + O(delta^2), and the six u_p
      // u_p^T sum to 3 I in the plane, so the target is halfway back to the centre.
      for(double phi : {0.3, 1.9})
      {
        const Vector_3d delta = 0.01 * r * (std::cos(phi) * e1 + std::sin(phi) * e2);
        const Vector_3d moved = GR::angle_based_target(centre + delta, link) - centre;
        EXPECT_LE((moved - 0.5 * delta).norm(), 1e-3 * delta.norm()) << "r " << r << " phi " << phi;
      }
    }
}

// ------------------------------------------------------------------------------------------------

TEST(Features, DihedralAngleOfAFold)
{
  for(double fold : {0.0, 10.0, 45.0, 90.0, 135.0, 170.0})
  {
    // Two triangles on the edge (0,0,0)-(1,0,0); the second turned by `fold` degrees about it.
    const double t = fold * pi / 180;
    Work_mesh m;
    const Work_vertex a = m.add_vertex(Work_point(0, 0, 0)), b = m.add_vertex(Work_point(1, 0, 0));
    const Work_vertex c = m.add_vertex(Work_point(0.5, -1, 0));
    const Work_vertex d = m.add_vertex(Work_point(0.5, std::cos(t), std::sin(t)));
    m.add_face(b, a, c);
    m.add_face(a, b, d);
    EXPECT_NEAR(GR::dihedral_angle(m, m.edge(m.halfedge(a, b))), fold, 1e-10) << "fold " << fold;
    EXPECT_EQ(GR::dihedral_angle(m, m.edge(m.halfedge(a, c))), 0.0); // border edge
  }
}

TEST(Features, SharpEdgesOfACube)
{
  for(int n : {1, 2, 3, 4})
  {
    const Work_mesh m = make_lattice_cube(n);
    ASSERT_TRUE(CGAL::is_closed(m));
    ASSERT_EQ(m.number_of_vertices(), std::size_t(6 * n * n + 2));
    const std::vector<char> sharp = GR::detect_sharp_edges(m, 20, 35);
    std::size_t count = 0;
    for(auto e : m.edges())
    {
      const bool expected = on_cube_edge(m, e);
      EXPECT_EQ(sharp[std::size_t(e)] != 0, expected) << "n " << n << " edge " << std::size_t(e);
      EXPECT_NEAR(GR::dihedral_angle(m, e), expected ? 90.0 : 0.0, 1e-10);
      count += sharp[std::size_t(e)] ? 1 : 0;
    }
    EXPECT_EQ(count, std::size_t(12 * n));
  }
}

TEST(Features, HysteresisAlongACrease)
{
  struct Case { std::vector<double> theta; std::vector<bool> sharp; const char* what; };
  const std::vector<Case> cases = {
    {{40, 40, 30, 40, 40}, {true, true, true, true, true}, "30 degrees continuing a 40-degree crease"},
    {{40, 40, 30, 10, 10}, {true, true, false, false, false}, "30 degrees with a strong neighbour on one side only"},
    {{10, 10, 30, 10, 10}, {false, false, false, false, false}, "isolated 30 degrees"},
    {{40, 30, 30, 30, 40}, {true, false, false, false, true}, "30 degrees between 30-degree edges"},
    {{36, 19, 36, 36, 19}, {true, false, true, true, false}, "below theta_false, never sharp"}};
  for(const Case& k : cases)
  {
    const auto roof = make_roof(k.theta);
    const Work_mesh& m = roof.first;
    const std::vector<char> sharp = GR::detect_sharp_edges(m, 20, 35);
    for(std::size_t i = 0; i < k.theta.size(); ++i)
    {
      const auto e = roof.second[i];
      ASSERT_NEAR(GR::dihedral_angle(m, e), k.theta[i], 1e-9) << k.what;
      EXPECT_EQ(sharp[std::size_t(e)] != 0, k.sharp[i]) << k.what << ", crease edge " << i;
    }
    // The edges off the crease are only slightly bent, and not sharp.
    for(auto e : m.edges())
      if(std::find(roof.second.begin(), roof.second.end(), e) == roof.second.end())
      {
        ASSERT_LT(GR::dihedral_angle(m, e), 20.0) << k.what;
        EXPECT_EQ(sharp[std::size_t(e)], 0) << k.what;
      }
  }
}

// eq. (8) on the paper's models, against an evaluation of each edge from its dihedral angles: an
// edge between 20 and 35 degrees is sharp exactly when edges above 35 degrees meet it at both ends.
// Where two strong edges meet it at one end only it is not sharp (and that end not made a corner);
// the organic models have many such edges.
TEST(Features, HysteresisOnThePaperModels)
{
  for(const std::string name : {"fandisk", "cow", "triceratops"})
  {
    const Work_mesh m = to_work_mesh(load_sample_mesh(name));
    const std::vector<char> sharp = GR::detect_sharp_edges(m, 20, 35);
    std::size_t in_between = 0, one_sided = 0;
    for(auto e : m.edges())
    {
      const double theta = GR::dihedral_angle(m, e);
      if(theta > 35 || theta < 20)
      {
        EXPECT_EQ(sharp[std::size_t(e)] != 0, theta > 35) << name;
        continue;
      }
      ++in_between;
      std::array<int, 2> strong{{0, 0}};
      for(int end = 0; end < 2; ++end)
      {
        const auto h = end == 0 ? m.halfedge(e) : m.opposite(m.halfedge(e));
        for(auto g : halfedges_around_target(h, m))
          strong[end] += m.edge(g) != e && GR::dihedral_angle(m, m.edge(g)) > 35 ? 1 : 0;
      }
      EXPECT_EQ(sharp[std::size_t(e)] != 0, strong[0] > 0 && strong[1] > 0) << name;
      one_sided += (strong[0] >= 2 && strong[1] == 0) || (strong[1] >= 2 && strong[0] == 0) ? 1 : 0;
    }
    EXPECT_GT(in_between, 0u) << name;
    if(name != "fandisk")
    {
      EXPECT_GT(one_sided, 10u) << name;
    }
  }
}

TEST(Features, VertexKindsOnACube)
{
  const int n = 3;
  const Work_mesh m = make_lattice_cube(n);
  const std::vector<char> sharp = GR::detect_sharp_edges(m, 20, 35);
  std::vector<char> constrained(m.number_of_vertices(), 0);
  auto check = [&](const std::vector<GR::Vertex_kind>& kind) {
    for(Work_vertex v : m.vertices())
    {
      const int extremes = extreme_coordinates(m.point(v));
      const GR::Vertex_kind expected = constrained[std::size_t(v)] || extremes == 3 ? GR::Vertex_kind::fixed_vertex
                                       : extremes == 2 ? GR::Vertex_kind::feature_vertex
                                                       : GR::Vertex_kind::free_vertex;
      EXPECT_EQ(int(kind[std::size_t(v)]), int(expected)) << "vertex " << m.point(v);
    }
  };
  const std::vector<GR::Vertex_kind> kind = GR::classify_vertices(m, sharp, constrained, theta_true);
  check(kind);
  EXPECT_EQ(std::count(kind.begin(), kind.end(), GR::Vertex_kind::fixed_vertex), 8);
  EXPECT_EQ(std::count(kind.begin(), kind.end(), GR::Vertex_kind::feature_vertex), 12 * (n - 1));
  EXPECT_EQ(std::count(kind.begin(), kind.end(), GR::Vertex_kind::free_vertex), 6 * (n - 1) * (n - 1));

  // A user constraint fixes a free vertex and a feature vertex alike.
  for(Work_vertex v : m.vertices())
    if((extreme_coordinates(m.point(v)) == 1 && std::count(constrained.begin(), constrained.end(), 1) == 0) ||
       (extreme_coordinates(m.point(v)) == 2 && std::count(constrained.begin(), constrained.end(), 1) == 1))
      constrained[std::size_t(v)] = 1;
  ASSERT_EQ(std::count(constrained.begin(), constrained.end(), 1), 2);
  const std::vector<GR::Vertex_kind> constrained_kind = GR::classify_vertices(m, sharp, constrained, theta_true);
  check(constrained_kind);
  EXPECT_EQ(std::count(constrained_kind.begin(), constrained_kind.end(), GR::Vertex_kind::fixed_vertex), 10);
}

// A sheet folded along the grid line j = 3, sheared so that the crease turns by atan(0.2) (11.3
// degrees) at i = 3 and runs straight elsewhere. The fold's dihedral angle is about
// 2 atan(slope).
TEST(Features, StrongCreasesKeepTheirTurns)
{
  for(double slope : {1.0, 0.45}) // about 90 degrees: a strong crease; about 48: a weak one
  {
    const Work_mesh m = to_work_mesh(make_grid(8, 7, [slope](std::size_t i, std::size_t j) {
      const double x = double(i), bend = x > 3 ? 0.2 * (x - 3) : 0;
      return Point(x, double(j) + bend, slope * std::abs(double(j) - 3));
    }));
    std::vector<char> sharp = GR::detect_sharp_edges(m, 20, 35);
    for(auto e : m.edges())
      if(m.is_border(e))
        sharp[std::size_t(e)] = 1;
    // With re-sampling, only a turn beyond the upper bound (theta_true) is kept.
    for(double crease_turn : {GR::strong_crease_turn_angle, theta_true})
    {
      const std::vector<GR::Vertex_kind> kind =
        GR::classify_vertices(m, sharp, std::vector<char>(m.number_of_vertices(), 0), theta_true, crease_turn);
      for(Work_vertex v : m.vertices())
      {
        const Work_point& p = m.point(v);
        const bool on_crease = std::abs(p.z()) < 1e-12, inside = p.x() > 0.5 && p.x() < 6.5;
        if(!on_crease || !inside)
          continue;
        const bool corner = std::abs(p.x() - 3) < 1e-12 && slope == 1.0 && crease_turn < 11.3;
        EXPECT_EQ(int(kind[std::size_t(v)]), int(corner ? GR::Vertex_kind::fixed_vertex : GR::Vertex_kind::feature_vertex))
          << "slope " << slope << ", turn limit " << crease_turn << ", vertex " << p;
      }
    }
  }
}

// The sheared fold of StrongCreasesKeepTheirTurns, classified as with re-sampling (its turn at
// x = 3 is no corner): how far the crease between two places leaves the chord between them.
TEST(Features, ChordDeviationAlongACrease)
{
  const Work_mesh m = to_work_mesh(make_grid(8, 7, [](std::size_t i, std::size_t j) {
    const double x = double(i), bend = x > 3 ? 0.2 * (x - 3) : 0;
    return Point(x, double(j) + bend, std::abs(double(j) - 3));
  }));
  std::vector<char> sharp = GR::detect_sharp_edges(m, 20, 35);
  for(auto e : m.edges())
    if(m.is_border(e))
      sharp[std::size_t(e)] = 1;
  const std::vector<GR::Vertex_kind> kind =
    GR::classify_vertices(m, sharp, std::vector<char>(m.number_of_vertices(), 0), theta_true, theta_true);
  const GR::Feature_polylines<Work_mesh> polylines(m, sharp, kind);
  auto crease = [&](double x) {
    for(Work_vertex v : m.vertices())
      if(m.point(v).z() == 0 && m.point(v).x() == x)
        return polylines.at_vertex(v);
    return polylines.at_vertex(*m.vertices().begin());
  };
  // From x = 1 to x = 5, the vertex at the turn is farthest: 0.8 / |(4, 0.4)| from the chord.
  const double turn = 0.8 / std::sqrt(16.16);
  EXPECT_NEAR(polylines.chord_deviation(crease(1), crease(5), 5), turn, 1e-12);
  EXPECT_NEAR(polylines.chord_deviation(crease(5), crease(1), 5), turn, 1e-12);
  // Where the crease runs straight, from the middle of a segment or within one, it is the chord.
  const auto middle = polylines.move(crease(1), Vector_3d(0.5, 0, 0));
  ASSERT_LE((polylines.point(middle) - Vector_3d(1.5, 3, 0)).norm(), 1e-12);
  EXPECT_LE(polylines.chord_deviation(middle, crease(3), 5), 1e-15);
  EXPECT_LE(polylines.chord_deviation(middle, crease(2), 5), 1e-15);
  EXPECT_NEAR(polylines.chord_deviation(middle, crease(5), 5), 0.6 / std::sqrt(12.41), 1e-12);
  // Not reached: farther along the crease than the limit, or on another line (the border, past
  // the crease's end at a corner).
  EXPECT_EQ(polylines.chord_deviation(crease(1), crease(5), 2.5), std::numeric_limits<double>::infinity());
  Work_vertex on_border;
  for(Work_vertex v : m.vertices())
    if(m.point(v) == Work_point(0, 1, 2))
      on_border = v;
  EXPECT_EQ(polylines.chord_deviation(crease(1), polylines.at_vertex(on_border), 100),
            std::numeric_limits<double>::infinity());
  // The fold is at about 90 degrees, a strong crease: re-sampling holds its slides to the line
  // tolerance; a border's too when asked.
  EXPECT_TRUE(polylines.holds_turns(crease(1)));
  EXPECT_TRUE(polylines.holds_turns(middle));
  EXPECT_FALSE(polylines.holds_turns(polylines.at_vertex(on_border)));
  GR::Feature_polylines<Work_mesh> with_borders = polylines;
  with_borders.set_line_tolerance(0.1, true);
  EXPECT_TRUE(with_borders.holds_turns(polylines.at_vertex(on_border)));
  EXPECT_TRUE(with_borders.holds_turns(crease(1)));
}

// A fold along y = 3 whose dihedral fades from about 70 to 30 degrees along x. With bounds (20,
// 50), eq. (8) ends the crease where it falls below 50 degrees; followed, it runs on while at 35
// degrees or more, and no other edge becomes sharp; with no turn allowed, nothing is followed.
TEST(Features, FadingCreasesAreFollowed)
{
  const Work_mesh m = to_work_mesh(make_grid(12, 7, [](std::size_t i, std::size_t j) {
    const double slope = 0.7 - 0.05 * double(i);
    return Point(double(i), double(j), slope * std::abs(double(j) - 3));
  }));
  auto on_crease = [&](Work_mesh::Edge_index e) {
    const auto h = m.halfedge(e);
    return m.point(m.source(h)).y() == 3 && m.point(m.target(h)).y() == 3;
  };
  const std::vector<char> plain = GR::detect_sharp_edges(m, 20, 50);
  const std::vector<char> followed = GR::detect_sharp_edges(m, 20, 50, true);
  std::size_t fading = 0, weak = 0;
  for(Work_mesh::Edge_index e : m.edges())
  {
    const double theta = GR::dihedral_angle(m, e);
    if(!on_crease(e))
    {
      EXPECT_FALSE(followed[std::size_t(e)]) << theta;
      continue;
    }
    EXPECT_EQ(plain[std::size_t(e)] != 0, theta > 50) << theta;
    EXPECT_EQ(followed[std::size_t(e)] != 0, theta >= 35) << theta;
    fading += theta >= 35 && theta <= 50 ? 1 : 0;
    weak += theta < 35 ? 1 : 0;
  }
  EXPECT_GE(fading, 3u);
  EXPECT_GE(weak, 2u);
  // The line tolerance holds the crease's turns where it is strong (60 degrees or more) only.
  const GR::Feature_polylines<Work_mesh> polylines(
    m, followed, GR::classify_vertices(m, followed, std::vector<char>(m.number_of_vertices(), 0), 50));
  std::size_t held = 0;
  for(Work_mesh::Edge_index e : m.edges())
    if(followed[std::size_t(e)])
    {
      const bool strong = GR::dihedral_angle(m, e) >= 60;
      EXPECT_EQ(polylines.holds_turns({m.halfedge(e), 0.}), strong);
      held += strong ? 1 : 0;
    }
  EXPECT_GE(held, 1u);
  // The crease runs straight: with no turn allowed, nothing is followed.
  std::vector<double> theta(m.number_of_edges());
  for(Work_mesh::Edge_index e : m.edges())
    theta[std::size_t(e)] = GR::dihedral_angle(m, e);
  std::vector<char> stiff = plain;
  GR::follow_fading_creases(m, theta, 35, 0, stiff);
  EXPECT_EQ(stiff, plain);
}

TEST(Features, SlidingAlongACubeEdge)
{
  const int n = 4; // the edge from (0,0,0) to (1,0,0) has four segments of length 0.25
  const Work_mesh m = make_lattice_cube(n);
  const std::vector<char> sharp = GR::detect_sharp_edges(m, 20, 35);
  const std::vector<GR::Vertex_kind> kind = GR::classify_vertices(m, sharp, std::vector<char>(m.number_of_vertices(), 0), theta_true);
  const GR::Feature_polylines<Work_mesh> polylines(m, sharp, kind);
  Work_vertex start;
  for(Work_vertex v : m.vertices())
    if(m.point(v) == Work_point(0.25, 0, 0))
      start = v;
  ASSERT_EQ(int(kind[std::size_t(start)]), int(GR::Vertex_kind::feature_vertex));
  const auto at_start = polylines.at_vertex(start);
  ASSERT_LE((polylines.point(at_start) - Vector_3d(0.25, 0, 0)).norm(), 1e-15);

  // Only the component along the edge counts; the others are dropped.
  const Vector_3d across(0, 0.07, -0.04);
  struct Move { double along, expected; };
  const std::vector<Move> moves = {
    {0.1, 0.35}, {0.3, 0.55}, {0.6, 0.85}, {0.75, 1.0}, {5.0, 1.0},   // through 0.5 and 0.75, stop at the corner
    {-0.1, 0.15}, {-0.25, 0.0}, {-5.0, 0.0}};                          // the other way
  for(const Move& move : moves)
  {
    const auto l = polylines.move(at_start, move.along * Vector_3d(1, 0, 0) + across);
    EXPECT_LE((polylines.point(l) - Vector_3d(move.expected, 0, 0)).norm(), 1e-12)
      << "move by " << move.along << ": got " << polylines.point(l).transpose();
  }
  // From the middle of a segment, back through two feature vertices.
  const auto middle = polylines.move(at_start, Vector_3d(0.4, 0, 0));
  ASSERT_LE((polylines.point(middle) - Vector_3d(0.65, 0, 0)).norm(), 1e-12);
  EXPECT_LE((polylines.point(polylines.move(middle, Vector_3d(-0.5, 0.1, 0.1))) - Vector_3d(0.15, 0, 0)).norm(), 1e-12);
  // Stopped at the corner, which is fixed: a further push along the edge's line does nothing.
  const auto corner = polylines.move(at_start, Vector_3d(2, 0, 0));
  EXPECT_EQ(int(kind[std::size_t(polylines.nearest_vertex(corner))]), int(GR::Vertex_kind::fixed_vertex));
  EXPECT_LE((polylines.point(polylines.move(corner, Vector_3d(1, 0, 0))) - Vector_3d(1, 0, 0)).norm(), 1e-15);
  // A push perpendicular to the edge does not move along it.
  EXPECT_LE((polylines.point(polylines.move(middle, across)) - Vector_3d(0.65, 0, 0)).norm(), 1e-15);
}

// ------------------------------------------------------------------------------------------------

TEST(Named_parameters, CombineCgalAndPackageParameters)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace GNP = PMP::graphcut_internal_np;
  const auto np = GP::combine(CGAL::parameters::number_of_iterations(7).random_seed(3), GP::lambda_data(5.0),
                              GP::sharp_angle_bounds(std::make_pair(10.0, 50.0)));
  EXPECT_EQ(get_parameter(np, CGAL::internal_np::number_of_iterations), 7);
  EXPECT_EQ(get_parameter(np, CGAL::internal_np::random_seed), 3);
  EXPECT_EQ(get_parameter(np, GNP::lambda_data), 5.0);
  EXPECT_EQ(get_parameter(np, GNP::sharp_angle_bounds), std::make_pair(10.0, 50.0));
  EXPECT_EQ(choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 150), 7);
  // As the driver reads it: an unsigned seed.
  EXPECT_EQ(unsigned(choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u)), 3u);
  EXPECT_EQ(choose_parameter(get_parameter(np, GNP::lambda_data), 1e7), 5.0);
  EXPECT_EQ(choose_parameter(get_parameter(np, GNP::sharp_angle_bounds), std::make_pair(20.0, 35.0)),
            std::make_pair(10.0, 50.0));
  // Absent ones, of CGAL and of the package: not found, so the default.
  static_assert(std::is_same<std::decay_t<decltype(get_parameter(np, GNP::lambda_shape))>,
                             CGAL::internal_np::Param_not_found>::value, "lambda_shape was not given");
  static_assert(std::is_same<std::decay_t<decltype(get_parameter(np, CGAL::internal_np::geom_traits))>,
                             CGAL::internal_np::Param_not_found>::value, "geom_traits was not given");
  EXPECT_EQ(choose_parameter(get_parameter(np, GNP::lambda_shape), 1.0), 1.0);
  EXPECT_EQ(choose_parameter(get_parameter(np, GNP::cooling_factor), 0.95), 0.95);
  EXPECT_EQ(choose_parameter(get_parameter(np, CGAL::internal_np::number_of_relaxation_steps), 4), 4);
}

TEST(Named_parameters, CombineWithOnePackAndWithDefaults)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace GNP = PMP::graphcut_internal_np;
  const auto single = GP::combine(GP::lambda_data(2.0));
  EXPECT_EQ(get_parameter(single, GNP::lambda_data), 2.0);
  EXPECT_EQ(choose_parameter(get_parameter(single, CGAL::internal_np::random_seed), 0u), 0u);

  const auto cgal_only = GP::combine(CGAL::parameters::number_of_iterations(9));
  EXPECT_EQ(get_parameter(cgal_only, CGAL::internal_np::number_of_iterations), 9);
  EXPECT_EQ(choose_parameter(get_parameter(cgal_only, GNP::lambda_data), 1e7), 1e7);

  const auto defaults = GP::combine(CGAL::parameters::default_values());
  EXPECT_EQ(choose_parameter(get_parameter(defaults, GNP::lambda_data), 1e7), 1e7);
  EXPECT_EQ(choose_parameter(get_parameter(defaults, CGAL::internal_np::number_of_iterations), 150), 150);

  // default_values() first, last or in the middle is neutral.
  const auto first = GP::combine(CGAL::parameters::default_values(), GP::lambda_data(2.0));
  const auto last = GP::combine(GP::lambda_data(2.0), CGAL::parameters::default_values());
  const auto middle = GP::combine(CGAL::parameters::number_of_iterations(9), CGAL::parameters::default_values(),
                                  GP::lambda_data(2.0));
  EXPECT_EQ(get_parameter(first, GNP::lambda_data), 2.0);
  EXPECT_EQ(get_parameter(last, GNP::lambda_data), 2.0);
  EXPECT_EQ(get_parameter(middle, GNP::lambda_data), 2.0);
  EXPECT_EQ(get_parameter(middle, CGAL::internal_np::number_of_iterations), 9);
  EXPECT_EQ(choose_parameter(get_parameter(first, CGAL::internal_np::random_seed), 0u), 0u);
  EXPECT_EQ(choose_parameter(get_parameter(last, CGAL::internal_np::random_seed), 0u), 0u);
  EXPECT_EQ(choose_parameter(get_parameter(last, GNP::lambda_shape), 1.0), 1.0);
  EXPECT_EQ(choose_parameter(get_parameter(middle, GNP::sharp_angle_bounds), std::make_pair(20.0, 35.0)),
            std::make_pair(20.0, 35.0));
}
