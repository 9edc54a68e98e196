// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesh is processed in a unit box (section 2.3: lambda_data and epsilon are meant for it), and
// written back at the input's scale.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_NORMALIZATION_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_NORMALIZATION_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// Maps the bounding box of a point set to a box centred at the origin whose largest side is 1.
class Unit_box_normalization
{
public:
  Unit_box_normalization() = default;

  template <typename PointRange>
  explicit Unit_box_normalization(const PointRange& points)
  {
    Vector_3d lo = Vector_3d::Constant(std::numeric_limits<double>::infinity());
    Vector_3d hi = -lo;
    bool any = false;
    for(const Vector_3d& p : points)
    {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
      any = true;
    }
    if(!any)
      return;
    m_center = 0.5 * (lo + hi);
    const double extent = (hi - lo).maxCoeff();
    m_scale = extent > 0 ? 1.0 / extent : 1.0;
  }

  Vector_3d to_unit(const Vector_3d& p) const { return (p - m_center) * m_scale; }
  Vector_3d from_unit(const Vector_3d& p) const { return p / m_scale + m_center; }
  double scale() const { return m_scale; }

private:
  Vector_3d m_center = Vector_3d::Zero();
  double m_scale = 1;
};

// Where the vertices of the working mesh are written at the input's scale: a vertex still at the
// unit point of its input point keeps the input's exact coordinates, any other unit point is
// mapped back. Mapping back rounds: a vertex a fraction of an ulp above another sheet of the
// surface in the unit box can be written through it. The exact tests of the intersections'
// search decide on these points, so that what they find is what the output has. Without a
// normalization, a vertex is written as it is.
class Output_points
{
public:
  Output_points() = default;

  // `input` by working vertex index: the input's point of that vertex (the vertices the working
  // copy made from the input's come first); it must outlive this.
  Output_points(const Unit_box_normalization& normalization, const std::vector<Vector_3d>& input)
    : m_normalization(normalization), m_input(&input)
  {}

  // Whether working vertex v (by index) at unit point p is still at its input point.
  bool at_input_point(std::size_t v, const Vector_3d& p) const
  {
    return m_input != nullptr && v < m_input->size() && m_normalization.to_unit((*m_input)[v]) == p;
  }

  // The point written for working vertex v (by index) at unit point p.
  Vector_3d operator()(std::size_t v, const Vector_3d& p) const
  {
    if(m_input == nullptr)
      return p;
    return at_input_point(v, p) ? (*m_input)[v] : m_normalization.from_unit(p);
  }

private:
  Unit_box_normalization m_normalization;
  const std::vector<Vector_3d>* m_input = nullptr;
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_NORMALIZATION_H
