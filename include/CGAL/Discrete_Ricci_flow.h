// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Umbrella header of the Discrete_Ricci_flow package: discrete surface Ricci flow (Newton, Ptolemy flips),
// hyperbolic uniformization, hyperbolic embedding (homotopy basis, fundamental domain, deck transformations),
// the flat torus and the spherical uniformization of genus-0 meshes.
#ifndef CGAL_DISCRETE_RICCI_FLOW_H
#define CGAL_DISCRETE_RICCI_FLOW_H

#include <CGAL/Discrete_Ricci_flow/flow_types.h>
#include <CGAL/Discrete_Ricci_flow/compute_metric.h>
#include <CGAL/Discrete_Ricci_flow/hyperbolic_embedding.h>
#include <CGAL/Discrete_Ricci_flow/spherical_uniformization.h>
#include <CGAL/Discrete_Ricci_flow/Bolza_surface_mesh.h>

#endif // CGAL_DISCRETE_RICCI_FLOW_H
