// Copyright (c) 2026 the Graphcut_remeshing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Must NOT compile: the CTests refuses_<parameter> (test/CMakeLists.txt) build it with
// REFUSED_PARAMETER set to one of CGAL's named parameters of isotropic_remeshing() that
// graphcut_isotropic_remeshing() refuses, and expect the static_assert's message naming it.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/graphcut_isotropic_remeshing.h>
#include <CGAL/Surface_mesh.h>

int main()
{
  CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> mesh;
  CGAL::Polygon_mesh_processing::graphcut_isotropic_remeshing(mesh, CGAL::parameters::REFUSED_PARAMETER(true));
}
