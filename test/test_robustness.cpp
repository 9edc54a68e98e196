// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bad input is refused before anything changes; unusual meshes (a single triangle, a
// tetrahedron, borders, several components, handles) keep their topology and the guarantees of
// graphcut_isotropic_remeshing; the result does not depend on the scale or the place of the input.

#include "test_meshes.h"

#include <CGAL/Polygon_mesh_processing/graphcut_isotropic_remeshing.h>
#include <CGAL/Polygon_mesh_processing/graphcut_remeshing_validation.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_report.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Aff_transformation_3.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace GP = PMP::graphcut_parameters;
using namespace graphcut_remeshing_test;
using Defect = PMP::Graphcut_remeshing_input_defect;

namespace {

std::string as_text(const Mesh& m)
{
  std::ostringstream out;
  out.precision(17);
  out << m;
  return out.str();
}

Mesh tetrahedron()
{
  return mesh_from_soup({Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)},
                        {{{0, 2, 1}}, {{0, 1, 3}}, {{1, 2, 3}}, {{0, 3, 2}}});
}

// What remeshing must keep: the counts of the topology.
struct Topology
{
  long euler = 0;
  std::size_t components = 0;
  std::size_t border_cycles = 0;
};

Topology topology(const Mesh& m)
{
  Topology t;
  t.euler = long(num_vertices(m)) - long(num_edges(m)) + long(num_faces(m));
  std::vector<std::size_t> ids(num_faces(m));
  t.components = PMP::connected_components(m, CGAL::make_property_map(ids));
  std::vector<Mesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(m, std::back_inserter(cycles));
  t.border_cycles = cycles.size();
  return t;
}

// The guarantees of graphcut_isotropic_remeshing, checked on `output` against `input`: a valid
// triangle mesh without degenerate triangles or non-manifold vertices, the same topology, no
// triangle turned over with respect to the input triangle nearest its centroid, and no more
// intersecting pairs than the input had.
void expect_guarantees(const Mesh& input, const Mesh& output, const std::string& name)
{
  const PMP::Graphcut_remeshing_input_validation validation = PMP::validate_graphcut_remeshing_input(output);
  EXPECT_TRUE(validation.is_valid()) << name << ": " << validation.reason;
  const Topology a = topology(input), b = topology(output);
  EXPECT_EQ(b.euler, a.euler) << name;
  EXPECT_EQ(b.components, a.components) << name;
  EXPECT_EQ(b.border_cycles, a.border_cycles) << name;

  using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive> >;
  const Tree tree(faces(input).first, faces(input).second, input);
  std::size_t turned = 0;
  for(Mesh::Face_index f : faces(output))
  {
    const Point c = CGAL::centroid(output.point(output.target(output.halfedge(f))),
                                   output.point(output.target(output.next(output.halfedge(f)))),
                                   output.point(output.source(output.halfedge(f))));
    const Mesh::Face_index g = tree.closest_point_and_primitive(c).second;
    if(PMP::compute_face_normal(f, output) * PMP::compute_face_normal(g, input) < 0)
      ++turned;
  }
  EXPECT_EQ(turned, 0u) << name << ": triangles turned over";

  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index> > before, after;
  PMP::self_intersections(input, std::back_inserter(before));
  PMP::self_intersections(output, std::back_inserter(after));
  EXPECT_LE(after.size(), before.size()) << name << ": new self-intersections";
}

} // namespace

TEST(GraphcutRemeshingInput, EachDefectIsRefusedAndTheMeshLeftUntouched)
{
  struct Case
  {
    std::string name;
    Mesh mesh;
    Defect defect;
  };
  std::vector<Case> cases;
  cases.push_back({"empty", Mesh(), Defect::NO_FACES});
  {
    Mesh m;
    const auto a = m.add_vertex(Point(0, 0, 0)), b = m.add_vertex(Point(1, 0, 0)), c = m.add_vertex(Point(1, 1, 0)),
               d = m.add_vertex(Point(0, 1, 0));
    m.add_face(a, b, c, d);
    cases.push_back({"quad", m, Defect::NON_TRIANGLE_FACE});
  }
  {
    Mesh m = tetrahedron();
    m.point(*std::next(m.vertices().begin(), 2)) = Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
    cases.push_back({"NaN", m, Defect::NON_FINITE_COORDINATE});
    m = tetrahedron();
    m.point(*m.vertices().begin()) = Point(0, std::numeric_limits<double>::infinity(), 0);
    cases.push_back({"infinity", m, Defect::NON_FINITE_COORDINATE});
  }
  {
    Mesh m = tetrahedron();
    m.add_vertex(Point(2, 2, 2));
    cases.push_back({"isolated vertex", m, Defect::ISOLATED_VERTEX});
  }
  {
    // Two triangles with one common vertex: a bow tie.
    Mesh m;
    const auto o = m.add_vertex(Point(0, 0, 0));
    const auto a = m.add_vertex(Point(1, 0, 0)), b = m.add_vertex(Point(0, 1, 0));
    const auto c = m.add_vertex(Point(-1, 0, 0)), d = m.add_vertex(Point(0, -1, 0));
    m.add_face(o, a, b);
    m.add_face(o, c, d);
    cases.push_back({"bow tie", m, Defect::NON_MANIFOLD_VERTEX});
  }
  cases.push_back({"collinear triangle",
                   mesh_from_soup({Point(0, 0, 0), Point(1, 0, 0), Point(2, 0, 0), Point(0, 1, 0)},
                                  {{{0, 1, 3}}, {{1, 2, 3}}, {{0, 2, 1}}}),
                   Defect::DEGENERATE_FACE});
  {
    Mesh m = tetrahedron();
    const Mesh::Halfedge_index h = m.halfedge(*m.faces().begin());
    m.set_next(h, h);
    cases.push_back({"broken halfedges", m, Defect::INVALID_HALFEDGE_STRUCTURE});
  }

  for(Case& c : cases)
  {
    const PMP::Graphcut_remeshing_input_validation v = PMP::validate_graphcut_remeshing_input(c.mesh);
    EXPECT_EQ(v.defect, c.defect) << c.name << ": " << v.reason;
    EXPECT_FALSE(v.is_valid()) << c.name;
    EXPECT_FALSE(v.reason.empty()) << c.name;
    EXPECT_EQ(v.reason.find('\n'), std::string::npos) << c.name << ": the reason is one line";
    const bool printable = c.defect != Defect::INVALID_HALFEDGE_STRUCTURE;
    const std::string before = printable ? as_text(c.mesh) : std::string();
    const std::size_t nv = c.mesh.number_of_vertices(), nf = c.mesh.number_of_faces();
    try
    {
      PMP::graphcut_isotropic_remeshing(c.mesh, CGAL::parameters::number_of_iterations(2));
      ADD_FAILURE() << c.name << ": not refused";
    }
    catch(const PMP::Graphcut_remeshing_input_error& e)
    {
      EXPECT_EQ(e.defect(), c.defect) << c.name;
      EXPECT_EQ(std::string(e.what()), v.reason) << c.name;
    }
    EXPECT_EQ(c.mesh.number_of_vertices(), nv) << c.name;
    EXPECT_EQ(c.mesh.number_of_faces(), nf) << c.name;
    if(printable)
    {
      EXPECT_EQ(as_text(c.mesh), before) << c.name << ": the mesh changed";
    }
  }

  // What it accepts: borders, several components, handles, self-intersections.
  Mesh two = make_sphere(2);
  const Mesh other = make_sphere(2, 0.8, Point(0.5, 0, 0));
  CGAL::copy_face_graph(other, two);
  for(const Mesh& m : {tetrahedron(), make_equilateral_patch(5, 1), make_torus(12, 8, 2, 0.5), two})
    EXPECT_TRUE(PMP::validate_graphcut_remeshing_input(m).is_valid());
}

TEST(GraphcutRemeshingRobustness, UnusualMeshesKeepTheirTopologyAndGuarantees)
{
  struct Case
  {
    std::string name;
    Mesh mesh;
  };
  std::vector<Case> cases;
  cases.push_back({"single triangle", make_triangle(Point(0, 0, 0), Point(1, 0, 0), Point(0.2, 0.9, 0))});
  cases.push_back({"tetrahedron", tetrahedron()});
  cases.push_back({"jittered square with a border",
                   make_grid(12, 12, [](std::size_t i, std::size_t j) {
                     const double x = double(i) + 0.3 * std::sin(7.0 * double(i * 13 + j)),
                                  y = double(j) + 0.3 * std::cos(5.0 * double(j * 11 + i));
                     return Point(i == 0 || i == 11 ? double(i) : x, j == 0 || j == 11 ? double(j) : y, 0);
                   })});
  {
    Mesh holed = make_sphere(3);
    CGAL::Euler::remove_face(holed.halfedge(*holed.faces().begin()), holed);
    CGAL::Euler::remove_face(holed.halfedge(*std::next(holed.faces().begin(), 100)), holed);
    holed.collect_garbage();
    cases.push_back({"sphere with two holes", holed});
  }
  {
    Mesh two = make_sphere(2);
    CGAL::copy_face_graph(make_sphere(2, 0.5, Point(3, 0, 0)), two);
    cases.push_back({"two spheres", two});
  }
  cases.push_back({"torus", make_torus(24, 12, 2, 0.6)});
  cases.push_back({"uneven sphere", noisy_sphere(3, 0.04, 0.0, 7)});

  for(const Case& c : cases)
  {
    Mesh m = c.mesh;
    PMP::graphcut_isotropic_remeshing(m, GP::combine(CGAL::parameters::number_of_iterations(30),
                                                     GP::number_of_greedy_iterations(5)));
    expect_guarantees(c.mesh, m, c.name);
  }

  // A single triangle has three corners: nothing may move.
  Mesh t = cases[0].mesh;
  PMP::graphcut_isotropic_remeshing(t);
  EXPECT_EQ(as_text(t), as_text(cases[0].mesh));
}

// Scaled by 1e-8 or 1e8, or moved by 1e6, fandisk remeshes as it does in place: the method works
// in the unit box.
TEST(GraphcutRemeshingRobustness, FandiskAtAnyScaleAndPlace)
{
  const Mesh input = load_sample_mesh("fandisk");
  const auto np = GP::combine(CGAL::parameters::number_of_iterations(60), GP::number_of_greedy_iterations(10));
  Mesh reference = input;
  PMP::graphcut_isotropic_remeshing(reference, np);
  const double angle = PMP::mesh_quality_report(reference).mean_min_angle;
  const double hausdorff = PMP::relative_surface_distance(input, reference).hausdorff;

  using Transformation = CGAL::Aff_transformation_3<Kernel>;
  const std::vector<std::pair<std::string, Transformation> > moves = {
    {"scaled by 1e-8", Transformation(CGAL::SCALING, 1e-8)},
    {"scaled by 1e8", Transformation(CGAL::SCALING, 1e8)},
    {"moved by 1e6", Transformation(CGAL::TRANSLATION, Kernel::Vector_3(1e6, -1e6, 1e6))}};
  for(const auto& move : moves)
  {
    Mesh moved = input;
    PMP::transform(move.second, moved);
    const Mesh moved_input = moved;
    PMP::graphcut_isotropic_remeshing(moved, np);
    const double a = PMP::mesh_quality_report(moved).mean_min_angle;
    const double h = PMP::relative_surface_distance(moved_input, moved).hausdorff;
    std::cout << move.first << ": mean min angle " << a << " (in place " << angle << "), Hausdorff " << h
              << " (in place " << hausdorff << ")\n";
    EXPECT_NEAR(a, angle, 0.5) << move.first;
    EXPECT_NEAR(h, hausdorff, 0.25 * hausdorff) << move.first;
    expect_guarantees(moved_input, moved, move.first);
  }
}
