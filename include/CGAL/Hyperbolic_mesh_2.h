// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Umbrella header of the Hyperbolic_mesh_2 package: Delaunay refinement (generalized Chew and Ruppert) of planar
// geodesic graphs in the Poincare disk, criteria, quality bounds, checked PSLG insertion and SVG output.
#ifndef CGAL_HYPERBOLIC_MESH_2_H
#define CGAL_HYPERBOLIC_MESH_2_H

#include <CGAL/Poincare_disk_traits_2.h>
#include <CGAL/Hyperbolic_mesh_2/quality_bounds.h>
#include <CGAL/Hyperbolic_mesh_2/mesh_types.h>
#include <CGAL/Hyperbolic_mesh_2/insert_geodesic_pslg.h>
#include <CGAL/Hyperbolic_mesh_criteria_2.h>
#include <CGAL/refine_hyperbolic_mesh_2.h>
#include <CGAL/Hyperbolic_mesh_2/IO/write_hyperbolic_mesh_svg.h>

#endif // CGAL_HYPERBOLIC_MESH_2_H
