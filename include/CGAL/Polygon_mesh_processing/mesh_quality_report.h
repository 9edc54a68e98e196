// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POLYGON_MESH_PROCESSING_MESH_QUALITY_REPORT_H
#define CGAL_POLYGON_MESH_PROCESSING_MESH_QUALITY_REPORT_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/surface_distance.h>
#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Random.h>
#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>

namespace CGAL {
namespace Polygon_mesh_processing {

/*!
 * \ingroup PkgGraphcutRemeshingRef
 *
 * The shape figures of a triangle mesh, as in the columns of Table 1 of the graph-cut remeshing
 * paper. Angles are in degrees.
 */
struct Mesh_quality_report
{
  /// number of vertices
  std::size_t number_of_vertices = 0;
  /// number of faces
  std::size_t number_of_faces = 0;
  /// percentage of irregular vertices: valence different from 6 for an interior vertex,
  /// from 4 for a border vertex (an isolated vertex is irregular)
  double irregular_vertex_percentage = 0;
  /// mean over the faces of the smallest angle of the face
  double mean_min_angle = 0;
  /// mean over the faces of the largest angle of the face
  double mean_max_angle = 0;
  /// smallest angle of the mesh
  double min_angle = 0;
  /// largest angle of the mesh
  double max_angle = 0;
};

/*!
 * \ingroup PkgGraphcutRemeshingRef
 *
 * Distances between two surfaces, divided by the length of the bounding-box diagonal of the first.
 */
struct Relative_surface_distance
{
  /// symmetric Hausdorff distance: the larger of the two one-sided maxima
  double hausdorff = 0;
  /// the larger of the two one-sided root-mean-square distances
  double rms = 0;
};

/*!
 * \ingroup PkgGraphcutRemeshingRef
 *
 * computes the shape figures of a triangle mesh: vertex and face counts, the percentage of
 * irregular vertices, the mean of the per-face minimum and maximum angles and the extreme angles.
 * For a mesh without faces the angle figures are 0.
 *
 * @tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`
 * @tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * @param tm a triangle mesh
 * @param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{a property map associating points to the vertices of `tm`}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
 *                    as key type and `%Point_3` as value type}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \return the figures of `tm`
 *
 * \pre `CGAL::is_triangle_mesh(tm)`
 */
template <typename TriangleMesh,
          typename NamedParameters = parameters::Default_named_parameters>
Mesh_quality_report mesh_quality_report(const TriangleMesh& tm,
                                        const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace GR = internal::Graphcut_remeshing;

  CGAL_precondition(CGAL::is_triangle_mesh(tm));

  const auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));

  Mesh_quality_report report;
  // Counted over the ranges: num_vertices() and num_faces() of a Surface_mesh also count the
  // elements removed but not yet collected, which isotropic_remeshing() leaves.
  report.number_of_vertices = static_cast<std::size_t>(std::distance(vertices(tm).begin(), vertices(tm).end()));
  report.number_of_faces = static_cast<std::size_t>(std::distance(faces(tm).begin(), faces(tm).end()));

  std::size_t irregular = 0;
  for(auto v : vertices(tm))
  {
    std::size_t valence = 0;
    bool on_border = false;
    const auto h0 = halfedge(v, tm);
    if(h0 != boost::graph_traits<TriangleMesh>::null_halfedge())
    {
      for(auto h : halfedges_around_target(h0, tm))
      {
        ++valence;
        on_border = on_border || is_border_edge(h, tm);
      }
    }
    if(valence != (on_border ? 4u : 6u))
      ++irregular;
  }
  if(report.number_of_vertices > 0)
    report.irregular_vertex_percentage = 100.0 * double(irregular) / double(report.number_of_vertices);

  if(report.number_of_faces == 0)
    return report;

  double sum_min = 0, sum_max = 0;
  double smallest = GR::pi, largest = 0;
  for(auto f : faces(tm))
  {
    const auto h = halfedge(f, tm);
    const auto angles = GR::triangle_angles(GR::to_vector(get(vpm, source(h, tm))),
                                            GR::to_vector(get(vpm, target(h, tm))),
                                            GR::to_vector(get(vpm, target(next(h, tm), tm))));
    const double amin = (std::min)({angles[0], angles[1], angles[2]});
    const double amax = (std::max)({angles[0], angles[1], angles[2]});
    sum_min += amin;
    sum_max += amax;
    smallest = (std::min)(smallest, amin);
    largest = (std::max)(largest, amax);
  }
  const double n = double(report.number_of_faces);
  report.mean_min_angle = GR::to_degrees(sum_min / n);
  report.mean_max_angle = GR::to_degrees(sum_max / n);
  report.min_angle = GR::to_degrees(smallest);
  report.max_angle = GR::to_degrees(largest);
  return report;
}

/*!
 * \ingroup PkgGraphcutRemeshingRef
 *
 * estimates, as the Metro tool does, the symmetric Hausdorff distance and the larger of the two
 * one-sided root-mean-square distances between the surfaces of `tm1` and `tm2`, both divided by
 * the length of the bounding-box diagonal of `tm1`.
 *
 * Each surface is sampled at all its vertices and at `number_of_points_on_faces` points spread over
 * its faces in proportion to their areas; the exact distance from every sample to the other mesh is
 * found with an `AABB_tree`. The Hausdorff distance is the largest distance over all samples of
 * both sides; a one-sided RMS distance is taken over the face samples of that side. The sampling is
 * seeded, so the result is repeatable.
 *
 * @tparam TriangleMesh1 a model of `FaceListGraph` and `VertexListGraph`
 * @tparam TriangleMesh2 a model of `FaceListGraph` and `VertexListGraph`
 * @tparam NamedParameters1 a sequence of \ref bgl_namedparameters "Named Parameters"
 * @tparam NamedParameters2 a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * @param tm1 the reference triangle mesh (its bounding box normalises the distances)
 * @param tm2 the other triangle mesh
 * @param np1 an optional sequence of \ref bgl_namedparameters "Named Parameters" for `tm1` and
 *            the sampling, among the ones listed below
 * @param np2 an optional sequence of \ref bgl_namedparameters "Named Parameters" for `tm2`:
 *            `vertex_point_map` and `geom_traits`, as for `tm1`
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{a property map associating points to the vertices of `tm1`}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh1>::%vertex_descriptor`
 *                    as key type and `%Point_3` as value type}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm1)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{geom_traits}
 *     \cgalParamDescription{an instance of a geometric traits class, used by the `AABB_tree`}
 *     \cgalParamType{a class model of `Kernel`}
 *     \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_points_on_faces}
 *     \cgalParamDescription{the number of samples spread over the faces of each mesh}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{`300000`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{random_seed}
 *     \cgalParamDescription{the seed of the random positions of the face samples}
 *     \cgalParamType{`unsigned int`}
 *     \cgalParamDefault{`0`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \return the two distances, relative to the bounding-box diagonal of `tm1` (0 if a mesh has no
 *         faces)
 *
 * \pre `CGAL::is_triangle_mesh(tm1)` and `CGAL::is_triangle_mesh(tm2)`
 */
template <typename TriangleMesh1, typename TriangleMesh2,
          typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
Relative_surface_distance
relative_surface_distance(const TriangleMesh1& tm1, const TriangleMesh2& tm2,
                          const NamedParameters1& np1 = parameters::default_values(),
                          const NamedParameters2& np2 = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace GR = internal::Graphcut_remeshing;

  CGAL_precondition(CGAL::is_triangle_mesh(tm1));
  CGAL_precondition(CGAL::is_triangle_mesh(tm2));

  const auto vpm1 = choose_parameter(get_parameter(np1, internal_np::vertex_point),
                                     get_const_property_map(CGAL::vertex_point, tm1));
  const auto vpm2 = choose_parameter(get_parameter(np2, internal_np::vertex_point),
                                     get_const_property_map(CGAL::vertex_point, tm2));
  using GT1 = typename GetGeomTraits<TriangleMesh1, NamedParameters1>::type;
  using GT2 = typename GetGeomTraits<TriangleMesh2, NamedParameters2>::type;
  const GT1 gt1 = choose_parameter<GT1>(get_parameter(np1, internal_np::geom_traits));
  const GT2 gt2 = choose_parameter<GT2>(get_parameter(np2, internal_np::geom_traits));

  const std::size_t n = choose_parameter(get_parameter(np1, internal_np::number_of_points_on_faces),
                                         std::size_t(300000));
  const unsigned int seed = choose_parameter(get_parameter(np1, internal_np::random_seed), 0u);

  Relative_surface_distance result;
  if(faces(tm1).begin() == faces(tm1).end() || faces(tm2).begin() == faces(tm2).end())
    return result;

  // One generator for both sides, so that the two sample sets are not correlated.
  CGAL::Random rng(seed);
  const GR::Surface_samples samples1 = GR::sample_surface(tm1, vpm1, n, rng);
  const GR::Surface_samples samples2 = GR::sample_surface(tm2, vpm2, n, rng);
  const GR::One_sided_distance d12 = GR::distance_to_mesh(samples1, tm2, vpm2, gt2);
  const GR::One_sided_distance d21 = GR::distance_to_mesh(samples2, tm1, vpm1, gt1);

  const double diagonal = GR::bounding_box_diagonal(tm1, vpm1);
  if(!(diagonal > 0))
    return result;
  result.hausdorff = (std::max)(d12.max, d21.max) / diagonal;
  result.rms = (std::max)(d12.rms, d21.rms) / diagonal;
  return result;
}

/*!
 * \ingroup PkgGraphcutRemeshingRef
 *
 * computes how far the sharp edges of `tm1` are from those of `tm2`: the largest distance from a
 * point of an edge of `tm1` whose dihedral angle is at least `sharp_angle_1` degrees to the
 * nearest edge of `tm2` whose dihedral angle is at least `sharp_angle_2` degrees, divided by the
 * length of the bounding-box diagonal of `tm1`. With `tm1` the input of a remeshing and `tm2` its
 * output, it says whether the output kept the input's sharp lines: a lower `sharp_angle_2` lets
 * a line that the output kept but made a little blunter count. Border edges have no dihedral
 * angle and are not counted. The edges of `tm1` are sampled every 1e-5 of the diagonal, which is
 * how much the result may be below the true maximum, at most.
 *
 * @tparam TriangleMesh1 a model of `FaceListGraph` and `EdgeListGraph`
 * @tparam TriangleMesh2 a model of `FaceListGraph` and `EdgeListGraph`
 * @tparam NamedParameters1 a sequence of \ref bgl_namedparameters "Named Parameters"
 * @tparam NamedParameters2 a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * @param tm1 the mesh whose sharp edges are measured, and whose diagonal is the unit
 * @param tm2 the mesh whose sharp edges they are measured to
 * @param sharp_angle_1 the smallest dihedral angle of a sharp edge of `tm1`, in degrees
 * @param sharp_angle_2 the smallest dihedral angle of a sharp edge of `tm2`, in degrees
 * @param np1 an optional sequence of \ref bgl_namedparameters "Named Parameters" for `tm1` among the ones listed below
 * @param np2 an optional sequence of \ref bgl_namedparameters "Named Parameters" for `tm2` among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{a property map associating points to the vertices of the mesh}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with the mesh's `%vertex_descriptor`
 *                    as key type and `%Point_3` as value type}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{geom_traits}
 *     \cgalParamDescription{an instance of a geometric traits class}
 *     \cgalParamType{a class model of `Kernel`}
 *     \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \return the relative distance: 0 if `tm1` has no sharp edge, infinity if `tm2` has none and
 *         `tm1` has some
 *
 * \pre `CGAL::is_triangle_mesh(tm1)` and `CGAL::is_triangle_mesh(tm2)`
 */
template <typename TriangleMesh1, typename TriangleMesh2,
          typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
double relative_sharp_edge_distance(const TriangleMesh1& tm1, const TriangleMesh2& tm2,
                                    double sharp_angle_1, double sharp_angle_2,
                                    const NamedParameters1& np1 = parameters::default_values(),
                                    const NamedParameters2& np2 = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace GR = internal::Graphcut_remeshing;

  CGAL_precondition(CGAL::is_triangle_mesh(tm1));
  CGAL_precondition(CGAL::is_triangle_mesh(tm2));

  const auto vpm1 = choose_parameter(get_parameter(np1, internal_np::vertex_point),
                                     get_const_property_map(CGAL::vertex_point, tm1));
  const auto vpm2 = choose_parameter(get_parameter(np2, internal_np::vertex_point),
                                     get_const_property_map(CGAL::vertex_point, tm2));
  using GT1 = typename GetGeomTraits<TriangleMesh1, NamedParameters1>::type;

  const double diagonal = GR::bounding_box_diagonal(tm1, vpm1);
  const auto from = GR::sharp_edge_segments(tm1, vpm1, sharp_angle_1);
  if(from.empty() || !(diagonal > 0))
    return 0;
  const auto to = GR::sharp_edge_segments(tm2, vpm2, sharp_angle_2);
  return GR::max_distance_to_segments<GT1>(from, to, 1e-5 * diagonal) / diagonal;
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_MESH_QUALITY_REPORT_H
