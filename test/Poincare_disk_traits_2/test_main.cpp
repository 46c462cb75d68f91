// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Test driver of Poincare_disk_traits_2: runs the cases registered by the other translation units
// (an optional argument selects the cases whose name contains it).
#include "cgal_hc_test.h"

int main(int argc, char** argv) { return cgal_hc_test::run_all(argc, argv); }
