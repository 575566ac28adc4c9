// A counting allocator hook (tamias2d::Allocator) and a counting replacement of the global
// operator new and delete, both for the embedding tests (one executable: the replacement is
// global to it).
//
// The hook takes its blocks from std::aligned_alloc and notes each live block's size and
// alignment in a fixed table (it allocates nothing else), so that every free can be matched
// with its allocation. The global operator new counts only inside a window (open_window,
// close_window), and only on the threads that allocate while it is open.
#pragma once

#include <cstddef>

#include "tamias2d/allocator.hpp"

namespace tamias2d::test {

/// What the counting hook has seen since reset_hook_counts().
struct HookCounts {
    std::size_t allocations = 0; ///< calls of allocate
    std::size_t frees = 0;       ///< calls of free
    std::size_t live = 0;        ///< blocks allocated, not yet freed
    std::size_t bytes = 0;       ///< sum of the sizes asked for
    std::size_t mismatched = 0;  ///< frees whose size or alignment differs from the block's
    std::size_t unknown = 0;     ///< frees of a pointer the hook did not hand out (or twice)
    std::size_t misaligned = 0;  ///< blocks not aligned as asked, or alignments not powers of 2
    std::size_t table_full = 0;  ///< blocks the table had no room to note (a test defect)
};

/// The counting hook (allocate, free, user = nullptr).
Allocator counting_hook();
HookCounts hook_counts();
void reset_hook_counts();

/// Global operator new calls (any form) since the window opened; counted only while open.
void open_window();
void close_window();
std::size_t window_news();
/// The bytes those calls asked for.
std::size_t window_new_bytes();
/// With TAMIAS_EMBEDDING_TRAP=1 in the environment, an operator new inside the window aborts;
/// each calls tamias_embedding_window_new() first, and each of the hook's allocations
/// tamias_embedding_hook_allocate(): places for a debugger's breakpoints.

} // namespace tamias2d::test
