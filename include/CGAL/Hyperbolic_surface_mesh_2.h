// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Hyperbolic_surface_mesh_2: Delaunay triangulation and Delaunay refinement of closed hyperbolic surfaces,
// and conformal remeshing of closed meshes of genus >= 2. This header includes the whole package.
#ifndef CGAL_HYPERBOLIC_SURFACE_MESH_2_H
#define CGAL_HYPERBOLIC_SURFACE_MESH_2_H

#include <CGAL/Hyperbolic_surface_mesh_2/Fundamental_polygon.h>
#include <CGAL/Hyperbolic_surface_mesh_2/Delaunay_triangulation_on_surface.h>
#include <CGAL/Hyperbolic_surface_mesh_2/refine_surface_mesh.h>

#endif
