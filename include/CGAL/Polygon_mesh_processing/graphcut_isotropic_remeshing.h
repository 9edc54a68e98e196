// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POLYGON_MESH_PROCESSING_GRAPHCUT_ISOTROPIC_REMESHING_H
#define CGAL_POLYGON_MESH_PROCESSING_GRAPHCUT_ISOTROPIC_REMESHING_H

#include <CGAL/Polygon_mesh_processing/graphcut_remeshing_parameters.h>
#include <CGAL/Polygon_mesh_processing/graphcut_remeshing_validation.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/features.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/normalization.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/remesher.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/assertions.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

/// \cond SKIP_IN_MANUAL
namespace internal {
namespace Graphcut_remeshing {

// The visitor used when none is given: never stops.
struct Default_visitor
{
  bool operator()(const Graphcut_remeshing_progress&) const { return true; }
};

} // namespace Graphcut_remeshing
} // namespace internal
/// \endcond

/*!
 * \ingroup PkgGraphcutRemeshingRef
 *
 * remeshes a triangle mesh into nearly equilateral triangles while keeping it close to the input
 * surface, by the global optimisation of Vidal et al.: at each iteration every vertex is offered
 * one candidate position (smoothing or a guided random move within a freedom sphere that lowers
 * its local energy) and one minimum s-t cut chooses, for all vertices at once, which candidates to
 * take so that the energy of eq. (1), shape term plus data term, decreases. A first phase of
 * `number_of_iterations` non-greedy iterations is followed by `number_of_greedy_iterations`
 * iterations along the energy gradient. The input, scaled into the unit box, is kept as the
 * reference surface; sharp edges (by the hysteresis of `sharp_angle_bounds`), border edges and
 * user-constrained edges are features: their vertices slide along the feature polylines of the
 * input, corners (three or more feature edges) and constrained vertices do not move; the end of a
 * feature line slides along its one feature edge.
 *
 * The energy of eq. (1) never increases from one iteration to the next: the cut minimises an
 * upper bound of the energy that is exact at the current positions. No move creates a degenerate
 * triangle or turns a triangle over.
 *
 * Every `connectivity_period` iterations of the first phase, the connectivity is improved as in
 * the paper's section 3: edge flips, splits of long edges, collapses of short edges in flat
 * regions and vertex splits, each kept only when it improves its own criterion and only where the
 * valence can improve, then a tangential relaxation of the vertex positions. Feature edges are
 * never flipped or collapsed, and no edge next to one is collapsed; a long sharp edge may be split
 * at a point of its input polyline (border and constrained edges never are). The number of
 * vertices adapts to the local curvature but stays of the order of the input's. When the connectivity changes,
 * `tmesh` is rebuilt: its elements are replaced, and the constrained maps are updated.
 *
 * @tparam TriangleMesh a model of `MutableFaceGraph`, `FaceListGraph`, `VertexListGraph` and
 *         `EdgeListGraph` (the mesh is rebuilt when its connectivity changes)
 * @tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters", which may
 *         chain \cgal's and the package's with `graphcut_parameters::combine()`
 *
 * @param tmesh a triangle mesh, remeshed in place
 * @param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{a property map associating points to the vertices of `tmesh`}
 *     \cgalParamType{a class model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
 *                    as key type and `%Point_3` as value type}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, tmesh)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{geom_traits}
 *     \cgalParamDescription{an instance of a geometric traits class; its points are built from
 *                           `double` coordinates}
 *     \cgalParamType{a class model of `Kernel`}
 *     \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{edge_is_constrained_map}
 *     \cgalParamDescription{a property map telling which edges are user features: never flipped
 *                           or collapsed; their vertices slide along them. Updated when the
 *                           connectivity changes}
 *     \cgalParamType{a class model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
 *                    as key type and `bool` as value type}
 *     \cgalParamDefault{no edge is constrained}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_is_constrained_map}
 *     \cgalParamDescription{a property map telling which vertices never move; updated
 *                           when the connectivity changes}
 *     \cgalParamType{a class model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
 *                    as key type and `bool` as value type}
 *     \cgalParamDefault{no vertex is constrained}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_iterations}
 *     \cgalParamDescription{the number of iterations of the first, non-greedy phase}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{`150`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{random_seed}
 *     \cgalParamDescription{the seed of the random candidates; the same input and seed give the
 *                           same output}
 *     \cgalParamType{`unsigned int`}
 *     \cgalParamDefault{`0`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{graphcut_parameters::lambda_shape}
 *     \cgalParamDescription{the weight of the shape term (circumradius over shortest edge)}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{`1`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{graphcut_parameters::lambda_data}
 *     \cgalParamDescription{the weight of the data term (approximate squared distance to the
 *                           input surface, in the unit box)}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{`1e7`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{graphcut_parameters::face_data_weight}
 *     \cgalParamDescription{beyond the paper: the weight, relative to `lambda_data`, of a data term
 *                           at each triangle's centroid, which keeps triangles from cutting chords
 *                           through curved parts of the input; `0` gives the paper's energy}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{`0.05`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{graphcut_parameters::number_of_greedy_iterations}
 *     \cgalParamDescription{the number of iterations of the final greedy phase}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{`20`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{graphcut_parameters::sharp_angle_bounds}
 *     \cgalParamDescription{the dihedral angles theta_false and theta_true (degrees) of the
 *                           sharp-edge hysteresis}
 *     \cgalParamType{`std::pair<double, double>`}
 *     \cgalParamDefault{`(20, 35)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{graphcut_parameters::initial_temperature}
 *     \cgalParamDescription{T(1) of the cooling schedule of the freedom sphere}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{`10`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{graphcut_parameters::cooling_factor}
 *     \cgalParamDescription{K of the cooling schedule T(i) = T(1) K^(i-1)}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{`0.95`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{graphcut_parameters::smoothing_step}
 *     \cgalParamDescription{the factor of the smoothing candidates' displacements}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{`0.06`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{graphcut_parameters::visitor}
 *     \cgalParamDescription{called after each iteration with a `Graphcut_remeshing_progress`;
 *                           returning `false` stops the run, leaving a valid mesh}
 *     \cgalParamType{a callable `bool(const Graphcut_remeshing_progress&)`}
 *     \cgalParamDefault{a visitor that never stops}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{graphcut_parameters::do_connectivity_optimization}
 *     \cgalParamDescription{whether to run the connectivity optimisation of section 3; with
 *                           `false` the connectivity of `tmesh` is left as it is}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{graphcut_parameters::connectivity_period}
 *     \cgalParamDescription{the connectivity is optimised after every this many iterations of
 *                           the first phase; 0 never does}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{`5`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \return the energies before and after each iteration, and counts
 *
 * \throws Graphcut_remeshing_input_error when `validate_graphcut_remeshing_input(tmesh, np)`
 *         finds a defect (no faces, a non-triangle face, a non-finite coordinate, an isolated or
 *         non-manifold vertex, a degenerate triangle, an invalid halfedge structure); `tmesh` is
 *         then left untouched
 */
template <typename TriangleMesh,
          typename NamedParameters = parameters::Default_named_parameters>
Graphcut_remeshing_statistics
graphcut_isotropic_remeshing(TriangleMesh& tmesh,
                             const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  namespace GR = internal::Graphcut_remeshing;
  namespace GNP = graphcut_internal_np;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using edge_descriptor = typename boost::graph_traits<TriangleMesh>::edge_descriptor;

  const Graphcut_remeshing_input_validation validation = validate_graphcut_remeshing_input(tmesh, np);
  if(!validation.is_valid())
    throw Graphcut_remeshing_input_error(validation);

  // Named parameters to plain values.
  auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                              get_property_map(CGAL::vertex_point, tmesh));
  using GT = typename GetGeomTraits<TriangleMesh, NamedParameters>::type;
  using Point = typename GT::Point_3;
  auto ecm = choose_parameter(get_parameter(np, internal_np::edge_is_constrained),
                              Static_boolean_property_map<edge_descriptor, false>());
  auto vcm = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                              Static_boolean_property_map<vertex_descriptor, false>());
  GR::Remeshing_options options;
  options.number_of_iterations = choose_parameter(get_parameter(np, internal_np::number_of_iterations), std::size_t(150));
  options.random_seed = choose_parameter(get_parameter(np, internal_np::random_seed), 0u);
  options.weights.lambda_shape = choose_parameter(get_parameter(np, GNP::lambda_shape), 1.0);
  options.weights.lambda_data = choose_parameter(get_parameter(np, GNP::lambda_data), 1e7);
  options.weights.face_data_weight = choose_parameter(get_parameter(np, GNP::face_data_weight), 0.05);
  options.number_of_greedy_iterations =
    choose_parameter(get_parameter(np, GNP::number_of_greedy_iterations), std::size_t(20));
  options.initial_temperature = choose_parameter(get_parameter(np, GNP::initial_temperature), 10.0);
  options.cooling_factor = choose_parameter(get_parameter(np, GNP::cooling_factor), 0.95);
  options.smoothing_step = choose_parameter(get_parameter(np, GNP::smoothing_step), 0.06);
  options.do_connectivity_optimization =
    choose_parameter(get_parameter(np, GNP::do_connectivity_optimization), true);
  options.connectivity_period =
    choose_parameter(get_parameter(np, GNP::connectivity_period), std::size_t(5));
  const std::pair<double, double> sharp_bounds =
    choose_parameter(get_parameter(np, GNP::sharp_angle_bounds), std::make_pair(20.0, 35.0));
  auto visitor = choose_parameter(get_parameter(np, GNP::visitor), GR::Default_visitor());

  // The working copy, scaled into the unit box. Its vertices follow a Hilbert curve and its faces
  // their first vertex: neighbours on the surface are then near in memory, which keeps the cost
  // per vertex of an iteration flat on large meshes.
  std::vector<vertex_descriptor> input_vertices;
  std::vector<GR::Vector_3d> input_points;
  input_vertices.reserve(num_vertices(tmesh));
  input_points.reserve(num_vertices(tmesh));
  for(vertex_descriptor v : vertices(tmesh))
  {
    input_vertices.push_back(v);
    input_points.push_back(GR::to_vector(get(vpm, v)));
  }
  const GR::Unit_box_normalization normalization(input_points);
  GR::Work_mesh work;
  work.reserve(static_cast<typename GR::Work_mesh::size_type>(num_vertices(tmesh)),
               static_cast<typename GR::Work_mesh::size_type>(num_edges(tmesh)),
               static_cast<typename GR::Work_mesh::size_type>(num_faces(tmesh)));
  const auto vertex_index = CGAL::get_initialized_vertex_index_map(tmesh, np);
  std::vector<GR::Work_mesh::Vertex_index> work_vertex(input_vertices.size());
  auto to_work = [&](vertex_descriptor v) { return work_vertex[get(vertex_index, v)]; };
  std::vector<char> constrained_vertex;
  {
    std::vector<GR::Work_kernel::Point_3> unit_points;
    unit_points.reserve(input_points.size());
    for(const GR::Vector_3d& q : input_points)
    {
      const GR::Vector_3d p = normalization.to_unit(q);
      unit_points.emplace_back(p.x(), p.y(), p.z());
    }
    std::vector<std::size_t> order(input_vertices.size());
    for(std::size_t i = 0; i < order.size(); ++i)
      order[i] = i;
    CGAL::hilbert_sort(order.begin(), order.end(),
                       CGAL::Spatial_sort_traits_adapter_3<GR::Work_kernel, decltype(CGAL::make_property_map(unit_points))>(
                         CGAL::make_property_map(unit_points)));
    constrained_vertex.reserve(order.size());
    for(std::size_t i : order)
    {
      work_vertex[get(vertex_index, input_vertices[i])] = work.add_vertex(unit_points[i]);
      constrained_vertex.push_back(get(vcm, input_vertices[i]) ? 1 : 0);
    }
  }
  {
    std::vector<std::pair<std::size_t, std::array<GR::Work_mesh::Vertex_index, 3> > > input_faces;
    input_faces.reserve(num_faces(tmesh));
    for(auto f : faces(tmesh))
    {
      const auto h = halfedge(f, tmesh);
      const std::array<GR::Work_mesh::Vertex_index, 3> t{
        {to_work(source(h, tmesh)), to_work(target(h, tmesh)), to_work(target(next(h, tmesh), tmesh))}};
      input_faces.emplace_back(std::size_t((std::min)({t[0], t[1], t[2]})), t);
    }
    std::stable_sort(input_faces.begin(), input_faces.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for(const auto& f : input_faces)
      work.add_face(f.second[0], f.second[1], f.second[2]);
  }

  // Features: sharp edges of the input, border edges, user-constrained edges.
  std::vector<char> feature_edge = GR::detect_sharp_edges(work, sharp_bounds.first, sharp_bounds.second);
  for(auto e : work.edges())
    if(work.is_border(e))
      feature_edge[std::size_t(e)] = 1;
  std::vector<char> user_edge(feature_edge.size(), 0);
  for(edge_descriptor e : edges(tmesh))
    if(get(ecm, e))
    {
      const auto h = halfedge(e, tmesh);
      const auto wh = work.halfedge(to_work(source(h, tmesh)), to_work(target(h, tmesh)));
      feature_edge[std::size_t(work.edge(wh))] = GR::Tracking_state::constrained_edge;
      user_edge[std::size_t(work.edge(wh))] = 1;
    }
  std::vector<GR::Vertex_kind> kind = GR::classify_vertices(work, feature_edge, constrained_vertex, sharp_bounds.second);

  GR::Graphcut_remesher remesher(work, feature_edge, kind, options);
  Graphcut_remeshing_statistics stats = remesher.run(visitor);
#ifndef CGAL_NO_POSTCONDITIONS
  {
    // Debug builds: what the method promises, after every run, cancelled or not.
    const std::string broken = remesher.broken_guarantee();
    CGAL_postcondition_msg(broken.empty(), broken.c_str());
  }
#endif

  if(stats.number_of_flips + stats.number_of_splits + stats.number_of_collapses +
       stats.number_of_vertex_splits == 0)
  {
    // Same connectivity: back to the input's scale, vertex by vertex. Vertices that never moved
    // keep their exact input coordinates.
    for(std::size_t i = 0; i < input_vertices.size(); ++i)
    {
      const auto w = to_work(input_vertices[i]);
      const GR::Vector_3d unit = GR::to_vector(work.point(w));
      if(unit == normalization.to_unit(input_points[i]))
        continue;
      const GR::Vector_3d p = normalization.from_unit(unit);
      put(vpm, input_vertices[i], Point(p.x(), p.y(), p.z()));
    }
    return stats;
  }

  // New connectivity: `tmesh` is emptied element by element (so that the property maps of its
  // owner stay alive) and receives the working mesh at the input's scale. Feature and fixed
  // vertices are never removed, so a working vertex of an input index still at its input
  // position is that input vertex, and keeps its exact coordinates.
  std::vector<Point> exact(work.num_vertices());
  std::vector<char> is_exact(work.num_vertices(), 0);
  for(std::size_t i = 0; i < input_vertices.size(); ++i)
  {
    const auto w = to_work(input_vertices[i]);
    if(!work.is_removed(w) && GR::to_vector(work.point(w)) == normalization.to_unit(input_points[i]))
    {
      exact[std::size_t(w)] = get(vpm, input_vertices[i]);
      is_exact[std::size_t(w)] = 1;
    }
  }
  for(auto w : work.vertices())
    work.point(w) = [&] {
      const GR::Vector_3d p = normalization.from_unit(GR::to_vector(work.point(w)));
      return GR::Work_kernel::Point_3(p.x(), p.y(), p.z());
    }();
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> old_faces(faces(tmesh).begin(),
                                                                                   faces(tmesh).end());
  for(auto f : old_faces)
    CGAL::Euler::remove_face(halfedge(f, tmesh), tmesh);
  std::vector<std::pair<GR::Work_mesh::Vertex_index, vertex_descriptor> > v2v;
  std::vector<std::pair<GR::Work_mesh::Halfedge_index,
                        typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> > h2h;
  CGAL::copy_face_graph(work, tmesh,
                        parameters::vertex_to_vertex_output_iterator(std::back_inserter(v2v))
                          .halfedge_to_halfedge_output_iterator(std::back_inserter(h2h)),
                        parameters::vertex_point_map(vpm));
  for(const auto& p : v2v)
  {
    if(is_exact[std::size_t(p.first)])
      put(vpm, p.second, exact[std::size_t(p.first)]);
    const std::size_t i = std::size_t(p.first);
    put(vcm, p.second, i < constrained_vertex.size() && constrained_vertex[i] && !work.is_removed(p.first));
  }
  // User-constrained edges are never flipped, split or collapsed: they keep their indices.
  for(const auto& p : h2h)
  {
    const std::size_t i = std::size_t(work.edge(p.first));
    put(ecm, edge(p.second, tmesh), i < user_edge.size() && user_edge[i] != 0);
  }
  return stats;
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_GRAPHCUT_ISOTROPIC_REMESHING_H
