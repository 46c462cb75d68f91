// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Umbrella header of the Surface_shortest_words package: shortest homotopic paths and loops on closed
// hyperbolic surfaces by transient embedding in the Poincare disk, and words of loops in pi_1(S, p) with
// respect to a canonical system of loops (Y. Li 2012, section 2.3.2, Algorithms 2, 3, 4).
#ifndef CGAL_SURFACE_SHORTEST_WORDS_H
#define CGAL_SURFACE_SHORTEST_WORDS_H

/// \defgroup PkgSurfaceShortestWordsRef Surface Shortest Words Reference

#include <CGAL/Surface_shortest_words/Hyperbolic_surface.h>
#include <CGAL/Surface_shortest_words/shortest_homotopic_path.h>
#include <CGAL/Surface_shortest_words/Shortest_word_solver.h>
#include <CGAL/Surface_shortest_words/geodesic_canonical_system.h>

#endif // CGAL_SURFACE_SHORTEST_WORDS_H
