// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POLYGON_MESH_PROCESSING_GRAPHCUT_REMESHING_PARAMETERS_H
#define CGAL_POLYGON_MESH_PROCESSING_GRAPHCUT_REMESHING_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

/// \cond SKIP_IN_MANUAL
// The tags of the package's own named parameters (CGAL 5.5 offers no way to add to
// `CGAL::parameters`, whose lookup works with any tag type).
namespace graphcut_internal_np {
enum lambda_shape_t { lambda_shape };
enum lambda_data_t { lambda_data };
enum face_data_weight_t { face_data_weight };
enum number_of_greedy_iterations_t { number_of_greedy_iterations };
enum connectivity_period_t { connectivity_period };
enum sharp_angle_bounds_t { sharp_angle_bounds };
enum initial_temperature_t { initial_temperature };
enum cooling_factor_t { cooling_factor };
enum smoothing_step_t { smoothing_step };
enum visitor_t { visitor };
enum do_connectivity_optimization_t { do_connectivity_optimization };
enum resampling_t { resampling };
enum sizing_tolerance_t { sizing_tolerance };
enum edge_length_bounds_t { edge_length_bounds };
enum distance_bound_t { distance_bound };
} // namespace graphcut_internal_np
/// \endcond

/*!
 * \ingroup PkgGraphcutRemeshingRef
 *
 * What a visitor of `graphcut_isotropic_remeshing()` is told after each iteration.
 */
struct Graphcut_remeshing_progress
{
  /// the two calls of the paper's Algorithm 1
  enum Phase
  {
    RELOCATION,    ///< the non-greedy phase
    GREEDY_FITTING ///< the final greedy phase
  };
  /// the current phase
  Phase phase = RELOCATION;
  /// the iteration just done in this phase, from 1
  std::size_t iteration = 0;
  /// the number of iterations of this phase
  std::size_t number_of_iterations = 0;
  /// the energy of eq. (1) after the iteration, in the unit-box scale the method works in
  double energy = 0;
};

/*!
 * \ingroup PkgGraphcutRemeshingRef
 *
 * What `graphcut_isotropic_remeshing()` returns.
 */
struct Graphcut_remeshing_statistics
{
  /// the energy of eq. (1) before the first iteration, then after each iteration
  std::vector<double> energies;
  /// the number of iterations done, both phases together
  std::size_t number_of_iterations = 0;
  /// the number of vertex moves taken by the graph cuts, all iterations together
  std::size_t number_of_moves = 0;
  /// the iterations (counted from 1 over both phases) after which a connectivity pass ran; the
  /// energy never rises from one iteration to the next except across these, where the number
  /// of triangles changes
  std::vector<std::size_t> connectivity_passes;
  /// the edge flips of the connectivity passes, all passes together
  std::size_t number_of_flips = 0;
  /// the edge splits of the connectivity passes
  std::size_t number_of_splits = 0;
  /// the edge collapses of the connectivity passes
  std::size_t number_of_collapses = 0;
  /// the vertex splits of the connectivity passes
  std::size_t number_of_vertex_splits = 0;
  /// the connectivity passes undone because they would have made the mesh self-intersect
  std::size_t number_of_undone_passes = 0;
  /// with `graphcut_parameters::distance_bound`, the symmetric Hausdorff distance between the
  /// output and the input measured at the end (in the mesh's units; the vertices and 100,000
  /// random points of each surface, to the other); negative without a bound
  double hausdorff_distance = -1;
  /// `true` if the visitor stopped the run
  bool cancelled = false;
};

/*!
 * \ingroup PkgGraphcutRemeshingRef
 *
 * The named parameters of the package. They are built like \cgal's own (each function returns a
 * one-element pack) and chained with \cgal's by `combine()`. Their defaults are listed with
 * `graphcut_isotropic_remeshing()`:
 *
 * \code
 * namespace PMP = CGAL::Polygon_mesh_processing;
 * namespace GP = PMP::graphcut_parameters;
 * PMP::graphcut_isotropic_remeshing(mesh,
 *     GP::combine(CGAL::parameters::number_of_iterations(100).random_seed(3),
 *                 GP::lambda_data(1e6), GP::number_of_greedy_iterations(10)));
 * \endcode
 */
namespace graphcut_parameters {

/// \cond SKIP_IN_MANUAL
#define CGAL_GRAPHCUT_REMESHING_PARAMETER(NAME)                                                      \
  template <typename T>                                                                              \
  Named_function_parameters<T, graphcut_internal_np::NAME##_t> NAME(const T& value)                  \
  {                                                                                                  \
    return Named_function_parameters<T, graphcut_internal_np::NAME##_t>(value);                      \
  }
/// \endcond

/*!
 * sets `lambda_shape`, the weight of the shape term of eq. (1) (circumradius over shortest
 * edge of each triangle).
 *
 * \tparam T a number type convertible to `double`
 * \param value the weight
 * \return a pack of named parameters holding `value`, to be chained with others by `combine()`
 */
CGAL_GRAPHCUT_REMESHING_PARAMETER(lambda_shape)
/*!
 * sets `lambda_data`, the weight of the data term of eq. (1) (approximate squared distance of
 * each vertex to the input surface), for the mesh scaled into the unit box the method works in.
 *
 * \tparam T a number type convertible to `double`
 * \param value the weight
 * \return a pack of named parameters holding `value`, to be chained with others by `combine()`
 */
CGAL_GRAPHCUT_REMESHING_PARAMETER(lambda_data)
/*!
 * sets `face_data_weight`, beyond the paper: the weight, relative to `lambda_data`, of a data
 * term at each triangle's centroid, which keeps triangles from cutting chords through curved parts
 * of the input. `0` gives the paper's energy.
 *
 * \tparam T a number type convertible to `double`
 * \param value the relative weight
 * \return a pack of named parameters holding `value`, to be chained with others by `combine()`
 */
CGAL_GRAPHCUT_REMESHING_PARAMETER(face_data_weight)
/*!
 * sets `number_of_greedy_iterations`, the number of iterations of the final greedy phase, whose
 * candidates follow the energy gradient.
 *
 * \tparam T an integral type convertible to `std::size_t`
 * \param value the number of iterations
 * \return a pack of named parameters holding `value`, to be chained with others by `combine()`
 */
CGAL_GRAPHCUT_REMESHING_PARAMETER(number_of_greedy_iterations)
/*!
 * sets `connectivity_period`: the connectivity is optimised after every this many iterations of
 * the first, non-greedy phase; `0` never does.
 *
 * \tparam T an integral type convertible to `std::size_t`
 * \param value the period, in iterations
 * \return a pack of named parameters holding `value`, to be chained with others by `combine()`
 */
CGAL_GRAPHCUT_REMESHING_PARAMETER(connectivity_period)
/*!
 * sets `sharp_angle_bounds`, the dihedral angles theta_false and theta_true (degrees) of the
 * sharp-edge hysteresis of eq. (8), which also bound the smooth sheets of closest-point tracking
 * and the turn of a border corner.
 *
 * \tparam T `std::pair<double, double>`
 * \param value the lower and upper angle
 * \return a pack of named parameters holding `value`, to be chained with others by `combine()`
 */
CGAL_GRAPHCUT_REMESHING_PARAMETER(sharp_angle_bounds)
/*!
 * sets `initial_temperature`, T(1) of the cooling schedule of the freedom sphere of eq. (5).
 *
 * \tparam T a number type convertible to `double`
 * \param value the temperature
 * \return a pack of named parameters holding `value`, to be chained with others by `combine()`
 */
CGAL_GRAPHCUT_REMESHING_PARAMETER(initial_temperature)
/*!
 * sets `cooling_factor`, K of the cooling schedule T(i) = T(1) K^(i-1).
 *
 * \tparam T a number type convertible to `double`
 * \param value the factor, in (0, 1]
 * \return a pack of named parameters holding `value`, to be chained with others by `combine()`
 */
CGAL_GRAPHCUT_REMESHING_PARAMETER(cooling_factor)
/*!
 * sets `smoothing_step`, the factor gamma of the displacements of the smoothing candidates.
 *
 *
 * \tparam T a number type convertible to `double`
 * \param value the factor
 * \return a pack of named parameters holding `value`, to be chained with others by `combine()`
 */
CGAL_GRAPHCUT_REMESHING_PARAMETER(smoothing_step)
/*!
 * sets `visitor`, called after each iteration with a `Graphcut_remeshing_progress`; returning
 * `false` stops the run and leaves a valid mesh.
 *
 * \tparam T a callable `bool(const Graphcut_remeshing_progress&)`
 * \param value the visitor, copied
 * \return a pack of named parameters holding `value`, to be chained with others by `combine()`
 */
CGAL_GRAPHCUT_REMESHING_PARAMETER(visitor)
/*!
 * sets `do_connectivity_optimization`: whether to run the connectivity optimisation of section 3
 * of the paper; with `false` the connectivity of the mesh is kept.
 *
 * \tparam T `bool`
 * \param value whether to change the connectivity
 * \return a pack of named parameters holding `value`, to be chained with others by `combine()`
 */
CGAL_GRAPHCUT_REMESHING_PARAMETER(do_connectivity_optimization)
/*!
 * sets `resampling`, beyond the paper: whether the connectivity passes re-sample the surface to a
 * sizing field, as `isotropic_remeshing()` does: edges longer than 4/3 of their target length are
 * split and shorter than 4/5 collapsed, also where the surface is curved and along feature lines
 * and borders, as long as the new triangles stay near the input. The target lengths follow the
 * input's curvature, between half and twice its mean edge length (half and 5/4 of a target length
 * asked for), for about as many triangles as the mean length would make. On by default; `false`
 * gives the paper's own connectivity stage, whose results the paper's Table 1 lists.
 *
 * \tparam T `bool`
 * \param value whether to re-sample
 * \return a pack of named parameters holding `value`, to be chained with others by `combine()`
 */
CGAL_GRAPHCUT_REMESHING_PARAMETER(resampling)
/*!
 * sets `sizing_tolerance`, beyond the paper: how far (in the mesh's units) the triangles may leave
 * the input surface, as the tolerance of CGAL's `Adaptive_sizing_field`. When the surface is
 * re-sampled, the target length at each point is the edge length whose equilateral triangles keep
 * within it at their centroids (sqrt(6 tolerance rho), rho the smallest radius of curvature there),
 * between the bounds of `edge_length_bounds`, and no collapse or relaxation step makes a triangle
 * whose centroid leaves the input by more.
 *
 * \tparam T a number type convertible to `double`
 * \param value the tolerance, positive
 * \return a pack of named parameters holding `value`, to be chained with others by `combine()`
 */
CGAL_GRAPHCUT_REMESHING_PARAMETER(sizing_tolerance)
/*!
 * sets `edge_length_bounds`, the shortest and longest target lengths (in the mesh's units) of the
 * sizing field `sizing_tolerance` builds; `(0, 0)` stands for a quarter of the target length and
 * the target length.
 *
 * \tparam T `std::pair<double, double>`
 * \param value the shortest and the longest length
 * \return a pack of named parameters holding `value`, to be chained with others by `combine()`
 */
CGAL_GRAPHCUT_REMESHING_PARAMETER(edge_length_bounds)
/*!
 * sets `distance_bound`, beyond the paper: the largest symmetric Hausdorff distance (in the mesh's
 * units) between the output and the input. Every operation that moves the surface (the
 * relocation's candidates, splits, collapses, flips, vertex splits, relaxation, coverings, the
 * smallest-angle repair) is checked against the input's triangles, both ways, before it is taken,
 * and refused if it would break the bound. The check is exact up to rounding: a triangle is cut
 * into convex cells, each measured at its corners to one triangle of the other surface (the
 * distance to a triangle is convex). Unless `sizing_tolerance` is given, the sizing field is that
 * of a tolerance equal to the bound.
 *
 * \tparam T a number type convertible to `double`
 * \param value the bound, positive; 0 sets none
 * \return a pack of named parameters holding `value`, to be chained with others by `combine()`
 */
CGAL_GRAPHCUT_REMESHING_PARAMETER(distance_bound)

#undef CGAL_GRAPHCUT_REMESHING_PARAMETER

/// \cond SKIP_IN_MANUAL
namespace internal {

template <typename NP2>
const NP2& chain(const Named_function_parameters<bool, CGAL::internal_np::all_default_t>&, const NP2& rest)
{
  return rest;
}

template <typename T, typename Tag, typename NP2>
Named_function_parameters<T, Tag, NP2>
chain(const Named_function_parameters<T, Tag, CGAL::internal_np::No_property>& first, const NP2& rest)
{
  return Named_function_parameters<T, Tag, NP2>(first.v, rest);
}

template <typename T, typename Tag, typename Base, typename NP2>
auto chain(const Named_function_parameters<T, Tag, Base>& first, const NP2& rest)
{
  auto tail = chain(static_cast<const Base&>(first), rest);
  return Named_function_parameters<T, Tag, decltype(tail)>(first.v, tail);
}

} // namespace internal
/// \endcond

/// \cond SKIP_IN_MANUAL
template <typename NP>
const NP& combine(const NP& np)
{
  return np;
}
/// \endcond

/*!
 * chains packs of named parameters, \cgal's and the package's, into one pack holding all of
 * their parameters.
 * \param np1 a pack of named parameters
 * \param np2 a second pack
 * \param nps more packs
 * \return one pack with the parameters of all
 */
template <typename NP1, typename NP2, typename... NPs>
auto combine(const NP1& np1, const NP2& np2, const NPs&... nps)
{
  return internal::chain(np1, combine(np2, nps...));
}

} // namespace graphcut_parameters

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_GRAPHCUT_REMESHING_PARAMETERS_H
