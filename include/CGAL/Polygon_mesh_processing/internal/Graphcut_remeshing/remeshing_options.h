// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The parameters of the method and their defaults.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_REMESHING_OPTIONS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_REMESHING_OPTIONS_H

#include <CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/energy.h>

#include <cstddef>
#include <utility>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace Graphcut_remeshing {

// Which operations a connectivity pass makes (CGAL's do_split, which also covers the vertex
// splits that add a vertex, do_collapse and do_flip) and how many relaxation sweeps end it.
struct Connectivity_operations
{
  bool split = true;
  bool collapse = true;
  bool flip = true;
  std::size_t relaxation_steps = 1;
};

// The parameters of the method, with their defaults: the one place they are written. The named
// parameters of graphcut_isotropic_remeshing() fall back to these, and the tools print them.
struct Remeshing_options
{
  Energy_weights weights;
  // The iterations of both phases when the surface is re-sampled at the input's density, where the
  // first connectivity pass already shapes most triangles; `paper_iterations`, the paper's (section
  // 4.1), without re-sampling and at a density asked for (default_iterations()).
  std::size_t number_of_iterations = 75;
  std::size_t number_of_greedy_iterations = 10;
  std::pair<std::size_t, std::size_t> paper_iterations{150, 20};
  double initial_temperature = 10;
  double cooling_factor = 0.95;
  double smoothing_step = 0.06; // gamma of section 2.3
  unsigned int random_seed = 0;
  bool do_connectivity_optimization = true;
  std::size_t connectivity_period = 5;
  // theta_false and theta_true of eq. (8), in degrees, when the surface is re-sampled at the
  // input's density (they measure best there); `paper_sharp_angle_bounds`, the paper's own, with
  // its connectivity and at a density asked for (default_sharp_angle_bounds()).
  // Beyond the paper: reference triangles within theta_false count as one smooth sheet for
  // tracking, and a border that turns by more than theta_true is a corner.
  std::pair<double, double> sharp_angle_bounds{20, 50};
  std::pair<double, double> paper_sharp_angle_bounds{20, 35};
  // The largest distance (unit box) a chord of the target edge length may keep from a curved
  // reference; it shortens the target length where the surface is curved (section 3.1's e_min,
  // e_max depend on the local curvature).
  double sizing_tolerance = 3e-3;
  // Beyond the paper: the connectivity stage re-samples the surface to a curvature-adapted sizing
  // field (sizing.h's curvature_sizing()), collapsing and splitting also where it is curved and
  // along feature lines and borders. Without it, the paper's connectivity stage.
  bool resampling = true;
  // The edge length the re-sampling aims at (unit box), or 0 for the input's mean edge length.
  double target_edge_length = 0;
  // The user gave the sizing tolerance (graphcut_parameters::sizing_tolerance): re-sampling then
  // aims at the lengths whose triangles keep within it, between `edge_length_bounds` (unit box; 0 for
  // a quarter of the target length, and the target length), instead of a field that asks for as
  // many triangles as the target length would (sizing.h).
  bool error_bounded_sizing = false;
  std::pair<double, double> edge_length_bounds{0, 0};
  // The symmetric distance every operation keeps between the mesh and the input (unit box;
  // graphcut_parameters::distance_bound), or 0 for none (distance_bound.h).
  double distance_bound = 0;
  // CGAL's switches of isotropic_remeshing(): which operations the connectivity passes make and
  // how many relaxation sweeps end a pass, and whether the vertices of the user's constrained
  // edges slide along them (else they stay).
  Connectivity_operations operations;
  bool relax_constraints = true;
  static constexpr double shortest_to_target = 0.25;

  // The sharp-angle bounds when the user gives none: `sharp_angle_bounds` when re-sampling at the
  // input's density, the paper's without re-sampling and at a density asked for (where they keep
  // the coarse triangles nearer the input).
  std::pair<double, double> default_sharp_angle_bounds(bool with_resampling, bool density_asked_for) const
  {
    return with_resampling && !density_asked_for ? sharp_angle_bounds : paper_sharp_angle_bounds;
  }

  // The iterations of the two phases when the user gives none. At a density asked for, 75 + 10
  // would leave coarse and fine targets short of the bars that 150 + 20 meets (see the manual).
  std::pair<std::size_t, std::size_t> default_iterations(bool with_resampling, bool density_asked_for) const
  {
    return with_resampling && !density_asked_for ? std::make_pair(number_of_iterations, number_of_greedy_iterations)
                                                 : paper_iterations;
  }
};

} // namespace Graphcut_remeshing
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_GRAPHCUT_REMESHING_REMESHING_OPTIONS_H
