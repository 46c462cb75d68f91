// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Package-specific CGAL named parameters. CGAL's own parameters chain as members
// (`CGAL::parameters::number_of_iterations(5).verbose(true)`); the ones a package adds cannot become members
// of `CGAL::Named_function_parameters`, so each is a free function that takes the chain it extends as an
// optional second argument: `seeds(s, CGAL::parameters::verbose(true))`, or any chain built before it.
// They are read back with `CGAL::parameters::get_parameter(np, CGAL::internal_np::TAG_v)` (the tag name with `_v`).
#ifndef CGAL_HYPERBOLIC_GEOMETRY_NAMED_PARAMETERS_H
#define CGAL_HYPERBOLIC_GEOMETRY_NAMED_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

/// Declares the tag `CGAL::internal_np::TAG` (use at global scope).
#define CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(TAG) \
  namespace CGAL { namespace internal_np { enum TAG { TAG##_v }; } }

/// Defines the named-parameter function `NAME(value [, chain])` for the tag `TAG` (use inside the package's
/// `parameters` namespace).
#define CGAL_HYPERBOLIC_NAMED_PARAMETER(NAME, TAG)                                                    \
  template <class T>                                                                                  \
  CGAL::Named_function_parameters<T, CGAL::internal_np::TAG> NAME(const T& v)                         \
  { return CGAL::Named_function_parameters<T, CGAL::internal_np::TAG>(v); }                           \
  template <class T, class T2, class Tag2, class Base2>                                              \
  CGAL::Named_function_parameters<T, CGAL::internal_np::TAG, CGAL::Named_function_parameters<T2, Tag2, Base2> > \
  NAME(const T& v, const CGAL::Named_function_parameters<T2, Tag2, Base2>& base)                      \
  { return CGAL::Named_function_parameters<T, CGAL::internal_np::TAG,                                 \
                                           CGAL::Named_function_parameters<T2, Tag2, Base2> >(v, base); }

#endif // CGAL_HYPERBOLIC_GEOMETRY_NAMED_PARAMETERS_H
