// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The allocator of the triangulation's face and vertex arrays: std::allocator for small blocks; a block of
// 4 MiB and more is aligned to 2 MiB and, on Linux, offered to the kernel for transparent huge pages
// (madvise MADV_HUGEPAGE). The face array of a refinement is reserved for the expected output and then
// written face by face: with 4 KiB pages every 16 faces (256 bytes each) took a page fault, about a quarter
// of the CPU time of a refinement of 40k triangles. Where huge pages are not available the advice is
// ignored and nothing else changes.
#ifndef CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_LARGE_BLOCK_ALLOCATOR_H
#define CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_LARGE_BLOCK_ALLOCATOR_H

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace CGAL {
namespace Hyperbolic_surface_mesh_2 {
namespace internal {

template <class T>
struct Large_block_allocator
{
  typedef T value_type;
  static constexpr std::size_t huge_page = std::size_t(1) << 21;
  static constexpr std::size_t threshold = std::size_t(1) << 22;

  Large_block_allocator() noexcept {}
  template <class U> Large_block_allocator(const Large_block_allocator<U>&) noexcept {}

  T* allocate(std::size_t n)
  {
    if(n > std::size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if(bytes < threshold || alignof(T) > huge_page) return std::allocator<T>().allocate(n);
    const std::size_t rounded = (bytes + huge_page - 1) / huge_page * huge_page;
    void* p = std::aligned_alloc(huge_page, rounded);
    if(p == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    (void)::madvise(p, rounded, MADV_HUGEPAGE); // advice only: its failure changes nothing
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) noexcept
  {
    if(n * sizeof(T) < threshold || alignof(T) > huge_page) std::allocator<T>().deallocate(p, n);
    else std::free(p);
  }

  template <class U> bool operator==(const Large_block_allocator<U>&) const noexcept { return true; }
  template <class U> bool operator!=(const Large_block_allocator<U>&) const noexcept { return false; }
};

} // namespace internal
} // namespace Hyperbolic_surface_mesh_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_LARGE_BLOCK_ALLOCATOR_H
