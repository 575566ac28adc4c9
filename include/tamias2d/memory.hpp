/// \file
/// The memory the library holds outside any one world, and how to give it back.
///
/// A world keeps its large per-step arrays (bodies, shapes, contacts, tree nodes, solver packs)
/// in blocks mapped from the operating system. A block of 1 MiB or more that a world releases is
/// kept mapped for the next world, up to 64 MiB in all (as malloc keeps freed heap memory), so
/// that rebuilding a large level does not fault in fresh pages. With an allocator hook set
/// (allocator.hpp) the large blocks come from the hook instead, and none is mapped or kept.
#pragma once

#include <cstddef>

#include "tamias2d/export.hpp"

namespace tamias2d {

/// What the large blocks of every world in the process have done so far.
struct LargeArrayStats {
    std::size_t maps = 0;           ///< large blocks handed out (a growth is not one)
    std::size_t unmaps = 0;         ///< large blocks released
    std::size_t remaps = 0;         ///< large blocks grown in place
    std::size_t mapped_bytes = 0;   ///< bytes in use now
    std::size_t retained_bytes = 0; ///< released, kept mapped for the next blocks (<= 64 MiB)
};

/// The counters of the large blocks; safe to call from any thread.
TAMIAS2D_EXPORT LargeArrayStats large_array_stats() noexcept;

/// Returns every retained block to the operating system (after unloading a large world, say).
/// Safe to call from any thread at any time; worlds alive keep their own blocks.
TAMIAS2D_EXPORT void release_retained_memory() noexcept;

} // namespace tamias2d
