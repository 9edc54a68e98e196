// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POLYGON_MESH_PROCESSING_GRAPHCUT_REMESHING_VALIDATION_H
#define CGAL_POLYGON_MESH_PROCESSING_GRAPHCUT_REMESHING_VALIDATION_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <cstddef>
#include <iterator>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

/*!
 * \ingroup PkgGraphcutRemeshingRef
 *
 * What makes a mesh unfit for `graphcut_isotropic_remeshing()`: the first defect
 * `validate_graphcut_remeshing_input()` finds, in the order of this list.
 */
enum class Graphcut_remeshing_input_defect
{
  NONE,                       ///< the mesh can be remeshed
  NO_FACES,                   ///< the mesh has no face
  ISOLATED_VERTEX,            ///< a vertex is on no face
  INVALID_HALFEDGE_STRUCTURE, ///< `CGAL::is_valid_polygon_mesh()` fails
  NON_TRIANGLE_FACE,          ///< a face has more than three sides
  NON_FINITE_COORDINATE,      ///< a vertex has an infinite or NaN coordinate
  NON_MANIFOLD_VERTEX,        ///< the faces around a vertex form more than one fan
  DEGENERATE_FACE             ///< the three vertices of a face are collinear
};

/*!
 * \ingroup PkgGraphcutRemeshingRef
 *
 * The answer of `validate_graphcut_remeshing_input()`.
 */
struct Graphcut_remeshing_input_validation
{
  /// the first defect found, `NONE` when there is none
  Graphcut_remeshing_input_defect defect = Graphcut_remeshing_input_defect::NONE;
  /// one line that says what is wrong and where (elements are numbered in the order of the
  /// mesh's ranges, from 0); empty when there is no defect
  std::string reason;
  /// tells whether the mesh can be remeshed
  /// \return `true` when no defect was found
  bool is_valid() const { return defect == Graphcut_remeshing_input_defect::NONE; }
};

/*!
 * \ingroup PkgGraphcutRemeshingRef
 *
 * The exception `graphcut_isotropic_remeshing()` throws, before changing anything, when
 * `validate_graphcut_remeshing_input()` finds a defect; `what()` is the reason.
 */
class Graphcut_remeshing_input_error : public std::invalid_argument
{
public:
  /// makes the exception of a validation that found a defect
  /// \param validation the answer of `validate_graphcut_remeshing_input()`, whose reason becomes `what()`
  explicit Graphcut_remeshing_input_error(const Graphcut_remeshing_input_validation& validation)
    : std::invalid_argument(validation.reason), m_defect(validation.defect)
  {}
  /// tells which defect was found
  /// \return the defect found
  Graphcut_remeshing_input_defect defect() const { return m_defect; }

private:
  Graphcut_remeshing_input_defect m_defect;
};

/*!
 * \ingroup PkgGraphcutRemeshingRef
 *
 * checks that `tmesh` can be given to `graphcut_isotropic_remeshing()`, which calls it first:
 * a valid halfedge structure with faces, only triangles, finite coordinates, no isolated vertex,
 * no non-manifold vertex and no degenerate triangle. Meshes with borders, several connected
 * components, any genus and self-intersections are accepted. The mesh is not changed.
 *
 * Non-manifold edges cannot be represented in a halfedge data structure; a reader that builds
 * the mesh from a polygon soup refuses them (see `CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh()`).
 *
 * @tparam TriangleMesh a model of `FaceListGraph`, `VertexListGraph` and `HalfedgeListGraph`
 * @tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * @param tmesh the triangle mesh to check
 * @param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{a property map associating points to the vertices of `tmesh`}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
 *                    as key type and `%Point_3` as value type}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, tmesh)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{geom_traits}
 *     \cgalParamDescription{an instance of a geometric traits class, whose `Collinear_3` decides
 *                           degenerate triangles}
 *     \cgalParamType{a class model of `Kernel`}
 *     \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \return the first defect found and its reason
 */
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Graphcut_remeshing_input_validation
validate_graphcut_remeshing_input(const TriangleMesh& tmesh, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Defect = Graphcut_remeshing_input_defect;
  Graphcut_remeshing_input_validation result;
  auto refuse = [&](Defect defect, const std::string& reason) {
    result.defect = defect;
    result.reason = reason;
    return result;
  };

  if(faces(tmesh).empty())
    return refuse(Defect::NO_FACES, "the mesh has no faces");
  // Before the halfedge structure, which an isolated vertex makes invalid.
  std::size_t i = 0;
  for(auto v : vertices(tmesh))
  {
    if(halfedge(v, tmesh) == boost::graph_traits<TriangleMesh>::null_halfedge())
      return refuse(Defect::ISOLATED_VERTEX, "vertex " + std::to_string(i) + " is on no face");
    ++i;
  }
  if(!CGAL::is_valid_polygon_mesh(tmesh))
    return refuse(Defect::INVALID_HALFEDGE_STRUCTURE, "the halfedge structure of the mesh is not valid");
  i = 0;
  for(auto f : faces(tmesh))
  {
    const std::size_t sides = CGAL::halfedges_around_face(halfedge(f, tmesh), tmesh).size();
    if(sides != 3)
      return refuse(Defect::NON_TRIANGLE_FACE, "face " + std::to_string(i) + " has " + std::to_string(sides) +
                                                 " sides; the remeshing needs triangles");
    ++i;
  }
  const auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tmesh));
  i = 0;
  for(auto v : vertices(tmesh))
  {
    const auto& p = get(vpm, v);
    if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
       !std::isfinite(CGAL::to_double(p.z())))
      return refuse(Defect::NON_FINITE_COORDINATE, "vertex " + std::to_string(i) + " has a non-finite coordinate");
    ++i;
  }
  // One sweep over the halfedges (is_non_manifold_vertex() sweeps them all for each vertex).
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  std::vector<halfedge_descriptor> pinched;
  non_manifold_vertices(tmesh, std::back_inserter(pinched));
  if(!pinched.empty())
  {
    std::set<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> non_manifold;
    for(halfedge_descriptor h : pinched)
      non_manifold.insert(target(h, tmesh));
    i = 0;
    for(auto v : vertices(tmesh))
    {
      if(non_manifold.count(v))
        return refuse(Defect::NON_MANIFOLD_VERTEX,
                      "vertex " + std::to_string(i) + " is non-manifold (its faces form more than one fan)");
      ++i;
    }
  }
  i = 0;
  for(auto f : faces(tmesh))
  {
    if(is_degenerate_triangle_face(f, tmesh, np))
      return refuse(Defect::DEGENERATE_FACE, "face " + std::to_string(i) + " is degenerate (its vertices are collinear)");
    ++i;
  }
  return result;
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_GRAPHCUT_REMESHING_VALIDATION_H
