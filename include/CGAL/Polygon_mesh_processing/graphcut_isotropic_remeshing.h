// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POLYGON_MESH_PROCESSING_GRAPHCUT_ISOTROPIC_REMESHING_H
#define CGAL_POLYGON_MESH_PROCESSING_GRAPHCUT_ISOTROPIC_REMESHING_H

#include <CGAL/Polygon_mesh_processing/graphcut_remeshing_parameters.h>
#include <CGAL/Polygon_mesh_processing/graphcut_remeshing_validation.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/remesher.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/working_copy.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/assertions.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
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

// CGAL's callback when none is given: never stops.
struct Default_callback
{
  bool operator()(double) const { return true; }
};

// Progress and cancellation, told to the package's `visitor`, to CGAL's `visitor` (the same
// callable) and to CGAL's `callback` (the fraction of the iterations done, in [0, 1]); any of them
// returning false ends the run.
template <typename Visitor, typename CgalVisitor, typename Callback>
struct Progress_listeners
{
  Visitor visitor;
  CgalVisitor cgal_visitor;
  Callback callback;
  std::size_t first_phase, total;

  bool operator()(const Graphcut_remeshing_progress& p)
  {
    const std::size_t done = p.iteration + (p.phase == Graphcut_remeshing_progress::GREEDY_FITTING ? first_phase : 0);
    const bool go_on = visitor(p);
    const bool cgal_go_on = cgal_visitor(p);
    const bool callback_go_on = callback(total == 0 ? 1. : double(done) / double(total));
    return go_on && cgal_go_on && callback_go_on;
  }
};

// CGAL's named parameters of isotropic_remeshing() that have no meaning here are refused at
// compile time, so that none is silently ignored.
template <typename NamedParameters>
void refuse_meaningless_parameters()
{
  static_assert(parameters::is_default_parameter<NamedParameters, internal_np::protect_constraints_t>::value,
                "graphcut_isotropic_remeshing: protect_constraints is not a choice here: the edges of "
                "edge_is_constrained_map are always protected (never flipped, split or collapsed); leave an edge "
                "out of the map to let the remesher re-sample it as a sharp edge");
  static_assert(parameters::is_default_parameter<NamedParameters, internal_np::collapse_constraints_t>::value,
                "graphcut_isotropic_remeshing: collapse_constraints is not a choice here: the edges of "
                "edge_is_constrained_map are never collapsed; leave an edge out of the map to let the remesher "
                "re-sample it as a sharp edge");
  static_assert(parameters::is_default_parameter<NamedParameters, internal_np::do_project_t>::value,
                "graphcut_isotropic_remeshing: do_project has no meaning here: the data term of eq. (1) and the "
                "tracking of the closest input point keep every vertex on the input; there is no projection "
                "step to switch off");
}

// Named parameters to plain values; a parameter not given keeps the default of
// Remeshing_options, where the defaults are written. `resample`: re-sampling whatever `np` says
// (a density asked for).
template <typename NamedParameters>
Remeshing_options remeshing_options(const NamedParameters& np, bool resample = false)
{
  namespace GNP = graphcut_internal_np;
  Remeshing_options options; // the defaults
  // A parameter given in `np` replaces the default in `field`.
  auto read = [&np](auto& field, auto tag) {
    field = parameters::choose_parameter(parameters::get_parameter(np, tag), field);
  };
  read(options.resampling, GNP::resampling);
  options.resampling = options.resampling || resample;
  std::tie(options.number_of_iterations, options.number_of_greedy_iterations) =
    options.default_iterations(options.resampling, resample);
  read(options.number_of_iterations, internal_np::number_of_iterations);
  read(options.random_seed, internal_np::random_seed);
  read(options.weights.lambda_shape, GNP::lambda_shape);
  read(options.weights.lambda_data, GNP::lambda_data);
  read(options.weights.face_data_weight, GNP::face_data_weight);
  read(options.number_of_greedy_iterations, GNP::number_of_greedy_iterations);
  read(options.initial_temperature, GNP::initial_temperature);
  read(options.cooling_factor, GNP::cooling_factor);
  read(options.smoothing_step, GNP::smoothing_step);
  read(options.do_connectivity_optimization, GNP::do_connectivity_optimization);
  read(options.connectivity_period, GNP::connectivity_period);
  options.sharp_angle_bounds = options.default_sharp_angle_bounds(options.resampling, resample);
  read(options.sharp_angle_bounds, GNP::sharp_angle_bounds);
  read(options.operations.split, internal_np::do_split);
  read(options.operations.collapse, internal_np::do_collapse);
  read(options.operations.flip, internal_np::do_flip);
  read(options.operations.relaxation_steps, internal_np::number_of_relaxation_steps);
  read(options.relax_constraints, internal_np::relax_constraints);
  return options;
}

template <typename NamedParameters>
auto make_progress_listeners(const NamedParameters& np, const Remeshing_options& options)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  auto visitor = choose_parameter(get_parameter(np, graphcut_internal_np::visitor), Default_visitor());
  auto cgal_visitor = choose_parameter(get_parameter(np, internal_np::visitor), Default_visitor());
  auto callback = choose_parameter(get_parameter(np, internal_np::callback), Default_callback());
  return Progress_listeners<decltype(visitor), decltype(cgal_visitor), decltype(callback)>{
    visitor, cgal_visitor, callback, options.number_of_iterations,
    options.number_of_iterations + options.number_of_greedy_iterations};
}

// The sizing tolerance and edge length bounds the user gave (the mesh's units; a tolerance of 0 is
// none, bounds of (0, 0) the defaults), checked before anything is copied.
struct Sizing_request
{
  double tolerance = 0;
  std::pair<double, double> bounds{0, 0};
  double distance_bound = 0;
};

template <typename NamedParameters>
Sizing_request sizing_request(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace GNP = graphcut_internal_np;
  Sizing_request r;
  r.tolerance = choose_parameter(get_parameter(np, GNP::sizing_tolerance), r.tolerance);
  r.bounds = choose_parameter(get_parameter(np, GNP::edge_length_bounds), r.bounds);
  if(!parameters::is_default_parameter<NamedParameters, GNP::sizing_tolerance_t>::value &&
     (!(r.tolerance > 0) || !std::isfinite(r.tolerance)))
    throw std::invalid_argument("graphcut_isotropic_remeshing: the sizing tolerance must be positive and finite");
  if(r.bounds != std::make_pair(0., 0.) &&
     (!(r.bounds.first > 0) || !(r.bounds.first <= r.bounds.second) || !std::isfinite(r.bounds.second)))
    throw std::invalid_argument("graphcut_isotropic_remeshing: the edge length bounds must be 0 < shortest <= longest");
  r.distance_bound = choose_parameter(get_parameter(np, GNP::distance_bound), r.distance_bound);
  if(!(r.distance_bound >= 0) || !std::isfinite(r.distance_bound))
    throw std::invalid_argument("graphcut_isotropic_remeshing: the distance bound must be finite, and positive or 0 for none");
  return r;
}

// Both calls: remeshes the faces `region` of `tmesh` (`in_region(f)` tells them), to
// `target_edge_length` (the mesh's units) when it is positive, else as the options say.

template <typename TriangleMesh, typename InRegion, typename NamedParameters>
Graphcut_remeshing_statistics
remesh_faces(TriangleMesh& tmesh, std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> region,
             const InRegion& in_region, double target_edge_length, const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using edge_descriptor = typename boost::graph_traits<TriangleMesh>::edge_descriptor;

  const Graphcut_remeshing_input_validation validation = validate_graphcut_remeshing_input(tmesh, np);
  if(!validation.is_valid())
    throw Graphcut_remeshing_input_error(validation);

  refuse_meaningless_parameters<NamedParameters>();
  Remeshing_options options = remeshing_options(np, target_edge_length > 0);
  const Sizing_request sizing = sizing_request(np);
  auto listeners = make_progress_listeners(np, options);
  auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point), get_property_map(CGAL::vertex_point, tmesh));
  auto ecm = choose_parameter(get_parameter(np, internal_np::edge_is_constrained),
                              Static_boolean_property_map<edge_descriptor, false>());
  auto vcm = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                              Static_boolean_property_map<vertex_descriptor, false>());
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Face = Work_mesh::Face_index;
  constexpr bool has_patches = !parameters::is_default_parameter<NamedParameters, internal_np::face_patch_t>::value;
  auto face_patch =
    choose_parameter(get_parameter(np, internal_np::face_patch), Constant_property_map<face_descriptor, int>(0));
  using GT = typename GetGeomTraits<TriangleMesh, NamedParameters>::type;
  const GT gt = choose_parameter<GT>(get_parameter(np, internal_np::geom_traits));
  const auto vertex_index = CGAL::get_initialized_vertex_index_map(tmesh, np);

  Working_copy<TriangleMesh, decltype(vpm), decltype(vertex_index), typename GT::Construct_point_3> copy(
    tmesh, vpm, vertex_index, gt.construct_point_3_object());
  Work_mesh work;
  copy.make(work, vcm, std::move(region), in_region);
  if(sizing.tolerance > 0)
  {
    options.error_bounded_sizing = true;
    options.sizing_tolerance = copy.to_unit_length(sizing.tolerance);
  }
  options.edge_length_bounds = {copy.to_unit_length(sizing.bounds.first), copy.to_unit_length(sizing.bounds.second)};
  if(sizing.distance_bound > 0)
  {
    // A millionth below the bound: the unit box and the way back to the input's units round.
    options.distance_bound = (1 - 1e-6) * copy.to_unit_length(sizing.distance_bound);
    // The chords the sizing field asks for reach the bound where the surface is curved: a smaller
    // tolerance costs many vertices for little angle (manual, "A Distance Bound").
    if(!(sizing.tolerance > 0))
    {
      options.error_bounded_sizing = true;
      options.sizing_tolerance = options.distance_bound;
    }
  }
  if(target_edge_length > 0)
    options.target_edge_length = copy.to_unit_length(target_edge_length);
  // Re-sampling bounds how far a shortened feature line leaves the removed vertex and keeps a turn
  // beyond the upper sharp bound, and follows fading creases; without it, a strong crease keeps
  // every turn of its own.
  const double crease_turn_angle = options.resampling ? options.sharp_angle_bounds.second : strong_crease_turn_angle;
  // Coarsening: the lines of the input's sampling that are short at the target's scale go.
  const double input_mean_length = mean_edge_length(work);
  const double shortest_sharp_line =
    options.target_edge_length > input_mean_length ? short_sharp_line_to_target * options.target_edge_length : 0;
  auto features = copy.features(work, ecm, face_patch, options.sharp_angle_bounds, crease_turn_angle,
                                options.resampling, options.relax_constraints, shortest_sharp_line);
  Graphcut_remesher remesher(work, input_mean_length, std::move(features.first), std::move(features.second), options,
                             copy.output_points());
  Graphcut_remeshing_statistics stats = remesher.run(listeners);
  if(options.distance_bound > 0)
    stats.hausdorff_distance = remesher.measured_distance() / copy.to_unit_length(1);
#ifndef CGAL_NO_POSTCONDITIONS
  {
    // Debug builds: what the method promises, after every run, cancelled or not.
    const std::string broken = remesher.broken_guarantee();
    CGAL_postcondition_msg(broken.empty(), broken.c_str());
  }
#endif
  if(stats.number_of_flips + stats.number_of_splits + stats.number_of_collapses + stats.number_of_vertex_splits == 0)
    copy.copy_positions_back(work);
  else
    copy.copy_mesh_back(work, ecm, vcm, face_patch, has_patches ? remesher.reference_faces_below() : std::vector<Face>());
  return stats;
}

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
 * Every `connectivity_period` iterations of the first phase, the connectivity changes. By
 * default (`resampling`) the surface is re-sampled to a curvature-adapted sizing field around the
 * input's mean edge length, as `isotropic_remeshing()` does: edges longer than 4/3 of their target
 * are split and shorter than 4/5 collapsed, also along sharp lines and borders, as long as the new
 * triangles stay near the input; flips follow, and a tangential relaxation of the vertex
 * positions. With `resampling(false)`, the paper's section 3: edge flips, splits of long edges,
 * collapses of short edges in flat regions and vertex splits, each kept only when it improves its
 * own criterion and only where the valence can improve, then the relaxation; the number of
 * vertices then stays of the order of the input's. The edges of `edge_is_constrained_map` are
 * never flipped, split or collapsed. When the connectivity changes, `tmesh` is rebuilt: its
 * elements are replaced, and the constrained maps are updated.
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
 *   \cgalParamNBegin{vertex_index_map}
 *     \cgalParamDescription{a property map associating to each vertex of `tmesh` a unique index between
 *                           `0` and `num_vertices(tmesh) - 1`}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
 *                    as key type and `std::size_t` as value type}
 *     \cgalParamDefault{an automatically indexed internal map}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{geom_traits}
 *     \cgalParamDescription{an instance of a geometric traits class; its `Construct_point_3` makes
 *                           the points written back into `tmesh` from `double` coordinates}
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
 *   \cgalParamNBegin{face_patch_map}
 *     \cgalParamDescription{a property map with the patch of each face; the edges between two
 *                           patches are sharp edges (feature lines), whatever their angle. The new
 *                           faces take the patch of the input face below their centroid}
 *     \cgalParamType{a class model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
 *                    as key type and the patch id (comparable with `!=`) as value type}
 *     \cgalParamDefault{one patch: no edge is a feature for this reason}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{relax_constraints}
 *     \cgalParamDescription{whether the vertices of the edges of `edge_is_constrained_map` slide
 *                           along them; with `false` they never move}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{do_split}
 *     \cgalParamDescription{whether the connectivity passes split edges (and split vertices, which
 *                           also adds a vertex); with `false`, the vertex count never grows}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{do_collapse}
 *     \cgalParamDescription{whether the connectivity passes collapse edges}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{do_flip}
 *     \cgalParamDescription{whether the connectivity passes flip edges}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_relaxation_steps}
 *     \cgalParamDescription{the number of tangential relaxation sweeps that end each connectivity
 *                           pass}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{`1`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{visitor}
 *     \cgalParamDescription{\cgal's own `visitor` parameter, honoured as `graphcut_parameters::visitor`
 *                           (both may be given; either returning `false` ends the run)}
 *     \cgalParamType{a callable `bool(const Graphcut_remeshing_progress&)`}
 *     \cgalParamDefault{a visitor that never ends the run}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{callback}
 *     \cgalParamDescription{called after each iteration with the fraction of the iterations done,
 *                           in [0, 1], as \cgal's algorithms with a `callback` do; returning
 *                           `false` ends the run, leaving a valid mesh}
 *     \cgalParamType{a callable `bool(double)`}
 *     \cgalParamDefault{a callback that never ends the run}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_iterations}
 *     \cgalParamDescription{the number of iterations of the first, non-greedy phase; when it is
 *                           smaller than `connectivity_period`, one connectivity pass ends the
 *                           phase (before the greedy phase when it is 0), so that the density is
 *                           reached whatever the count}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{`75`; the paper's `150` without re-sampling and in the call with a
 *                       target length}
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
 *                           input surface, in the unit box); with `resampling`, scaled down where
 *                           the sizing tolerance exceeds 9e-4 of the unit box (see
 *                           \ref GraphcutRemeshingResampling)}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{`1e7`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{graphcut_parameters::face_data_weight}
 *     \cgalParamDescription{beyond the paper: the weight, relative to `lambda_data`, of a data term
 *                           at each triangle's centroid, which keeps triangles from cutting chords
 *                           through curved parts of the input; `0` gives the paper's energy.
 *                           When the call re-samples at the input's density, only the distance
 *                           beyond half the sizing field's tolerance counts (see the manual)}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{`0.05`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{graphcut_parameters::number_of_greedy_iterations}
 *     \cgalParamDescription{the number of iterations of the final greedy phase}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{`10`; the paper's `20` without re-sampling and in the call with a
 *                       target length}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{graphcut_parameters::sharp_angle_bounds}
 *     \cgalParamDescription{the dihedral angles theta_false and theta_true (degrees) of the
 *                           sharp-edge hysteresis of eq. (8); the input's triangles within
 *                           theta_false of each other also count as one smooth sheet when a
 *                           vertex is tracked to its closest input point, and a border that
 *                           turns by more than theta_true at a vertex makes it a corner}
 *     \cgalParamType{`std::pair<double, double>`}
 *     \cgalParamDefault{`(20, 50)`; the paper's `(20, 35)` without re-sampling and in the call with a
 *                       target edge length}
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
 *   \cgalParamNBegin{graphcut_parameters::resampling}
 *     \cgalParamDescription{whether the connectivity passes re-sample the surface to a
 *                           curvature-adapted sizing field (splits and collapses also where the
 *                           surface is curved and along feature lines and borders); `false` gives
 *                           the paper's own connectivity stage (flips, splits and collapses in flat
 *                           regions, vertex splits), whose results the paper's Table 1 lists}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{graphcut_parameters::sizing_tolerance}
 *     \cgalParamDescription{how far, in the units of `tmesh`'s points, the triangles may leave the
 *                           input surface. With `resampling` (or a target length), the target
 *                           length at each point becomes the edge length whose equilateral
 *                           triangles keep within it at their centroids, sqrt(6 tolerance rho) for a
 *                           smallest radius of curvature rho (as CGAL's `Adaptive_sizing_field`),
 *                           between the bounds of `edge_length_bounds`, graded; no collapse and no
 *                           relaxation step makes a triangle whose centroid leaves the input by
 *                           more (and where edges of the shortest bound would, they stay shorter);
 *                           without it, the field asks for as many triangles as the target length
 *                           would everywhere. Without `resampling`, it shortens the edges the
 *                           connectivity stage aims at where the surface is curved}
 *     \cgalParamType{`double`, positive}
 *     \cgalParamDefault{none: with `resampling`, a field for the target length's count; without,
 *                       3e-3 of the mesh's unit box}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{graphcut_parameters::edge_length_bounds}
 *     \cgalParamDescription{the shortest and longest target lengths, in the units of `tmesh`'s
 *                           points, of the field `sizing_tolerance` makes (without
 *                           `sizing_tolerance` they are not used)}
 *     \cgalParamType{`std::pair<double, double>`, 0 < shortest <= longest, or (0, 0)}
 *     \cgalParamDefault{`(0, 0)`, which stands for a quarter of the target length and the target
 *                       length (the input's mean edge length without one)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{graphcut_parameters::distance_bound}
 *     \cgalParamDescription{the largest symmetric Hausdorff distance, in the units of `tmesh`'s
 *                           points, between the output and the input: every operation that moves
 *                           the surface is checked against the input's triangles, both ways,
 *                           before it is taken, and refused if it would break the bound; the
 *                           sizing field is that of a `sizing_tolerance` equal to the bound unless
 *                           one is given; the distance achieved is measured at the end
 *                           (`Graphcut_remeshing_statistics::hausdorff_distance`)}
 *     \cgalParamType{`double`, positive, or 0 for none}
 *     \cgalParamDefault{0: no bound}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \cgal's `protect_constraints`, `collapse_constraints` and `do_project` are refused at compile
 * time (a `static_assert` says why): the edges of `edge_is_constrained_map` are always protected,
 * and the data term, not a projection step, keeps the vertices on the input.
 *
 * \return the energies before and after each iteration, and counts
 *
 * \throws std::invalid_argument when `sizing_tolerance` is not positive and finite,
 *         `edge_length_bounds` neither (0, 0) nor 0 < shortest <= longest, or `distance_bound`
 *         negative or not finite; `tmesh` is then left untouched
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
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> all(faces(tmesh).begin(), faces(tmesh).end());
  return internal::Graphcut_remeshing::remesh_faces(tmesh, std::move(all), [](const auto&) { return true; }, 0., np);
}

/*!
 * \ingroup PkgGraphcutRemeshingRef
 *
 * remeshes the faces `face_range` of `tmesh` as `graphcut_isotropic_remeshing(tmesh, np)` does,
 * at the density `target_edge_length` asks for: the call is shaped as CGAL's
 * `isotropic_remeshing(faces, target_edge_length, pmesh, np)`. The connectivity passes re-sample the
 * surface (`graphcut_parameters::resampling` is on) to a sizing field around `target_edge_length`:
 * shorter where the surface is curved, longer where it is flat, graded, and asking for as many
 * triangles as `target_edge_length` would everywhere (with `graphcut_parameters::sizing_tolerance`,
 * the lengths whose triangles keep within that tolerance, between `edge_length_bounds`: by default
 * at most `target_edge_length`); feature lines and borders are re-sampled too, and a vertex next to
 * a feature line may go into it.
 *
 * Where the faces of `face_range` meet the rest of `tmesh`, the seam, its vertices and edges stay
 * as they are (as if constrained); no vertex, edge or face outside the range changes. The seam's
 * edges keep their `edge_is_constrained_map` values. When the connectivity changes, the range's
 * faces are replaced, and so are its vertices off the seam (the constrained maps are updated). The
 * range is scaled into its own unit box: `lambda_data` and the tolerances are relative to its size.
 * No self-intersection is made within the range away from the range's own (those within the box of
 * an intersecting pair of its triangles, grown by its mean edge length); the triangles outside are
 * not looked at.
 * A `resampling(false)` in `np` is overridden: only re-sampling reaches a density.
 *
 * @tparam FaceRange a range of `boost::graph_traits<TriangleMesh>::%face_descriptor`
 * @tparam TriangleMesh as for `graphcut_isotropic_remeshing(tmesh, np)`
 * @tparam NamedParameters as for `graphcut_isotropic_remeshing(tmesh, np)`
 *
 * @param face_range the faces to remesh (each once)
 * @param target_edge_length the edge length aimed at, in the units of `tmesh`'s points; positive
 *        and finite
 * @param tmesh a triangle mesh, remeshed in place
 * @param np the named parameters of `graphcut_isotropic_remeshing(tmesh, np)`, and
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{face_index_map}
 *     \cgalParamDescription{a property map associating to each face of `tmesh` a unique index between
 *                           `0` and `num_faces(tmesh) - 1`}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
 *                    as key type and `std::size_t` as value type}
 *     \cgalParamDefault{an automatically indexed internal map}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \return the energies before and after each iteration, and counts
 *
 * \throws Graphcut_remeshing_input_error as `graphcut_isotropic_remeshing(tmesh, np)` (the whole of
 *         `tmesh` is validated); `tmesh` is then left untouched
 * \throws std::invalid_argument when `target_edge_length` is not positive and finite
 * \throws std::runtime_error when the remeshed range would meet the rest of the mesh along an edge
 *         the rest already has (so that it could not be sewn in); `tmesh` is then left untouched
 */
template <typename FaceRange, typename TriangleMesh,
          typename NamedParameters = parameters::Default_named_parameters>
Graphcut_remeshing_statistics
graphcut_isotropic_remeshing(const FaceRange& face_range, const double target_edge_length, TriangleMesh& tmesh,
                             const NamedParameters& np = parameters::default_values())
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  if(!(target_edge_length > 0) || !std::isfinite(target_edge_length))
    throw std::invalid_argument("graphcut_isotropic_remeshing: the target edge length must be positive and finite");
  const auto face_index = CGAL::get_initialized_face_index_map(tmesh, np);
  std::vector<char> in_range(num_faces(tmesh), 0);
  for(face_descriptor f : face_range)
    in_range[get(face_index, f)] = 1;
  std::vector<face_descriptor> region;
  for(face_descriptor f : faces(tmesh))
    if(in_range[get(face_index, f)])
      region.push_back(f);
  if(region.empty())
    return Graphcut_remeshing_statistics();
  return internal::Graphcut_remeshing::remesh_faces(
    tmesh, std::move(region), [&](face_descriptor f) { return in_range[get(face_index, f)] != 0; },
    target_edge_length, np);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_GRAPHCUT_ISOTROPIC_REMESHING_H
