// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Words in the surface group: written once in the shared surface layer.
#ifndef CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_WORDS_H
#define CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_WORDS_H

#include <CGAL/Hyperbolic_surface_2/internal/surface_group_words.h>

namespace CGAL {
namespace Surface_shortest_words {
namespace internal {
using namespace CGAL::Hyperbolic_surface_2::internal;
} // namespace internal
} // namespace Surface_shortest_words
} // namespace CGAL

#endif // CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_WORDS_H
