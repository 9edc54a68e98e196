// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesh is processed in a unit box (section 2.3: lambda_data and epsilon are meant for it).

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_NORMALIZATION_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_NORMALIZATION_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/triangle_geometry.h>

#include <algorithm>
#include <limits>

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

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_NORMALIZATION_H
