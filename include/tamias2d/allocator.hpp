/// \file
/// The allocator hook: where the library's memory for worlds comes from (Box2D v3's
/// b2SetAllocator, with sizes and alignments on both calls).
///
/// Without a hook the library allocates with the global operator new and delete, and maps its
/// large per-step arrays (1 MiB and more) from the operating system (memory.hpp). With one, every
/// block the core library (tamias2d::tamias2d) takes for a World, a Recorder or a Replayer comes
/// from `allocate` and goes back through `free`, large arrays included: the World's state, its
/// stores, the broad phase, the contacts, the solver's arrays, the events and the scratch of its
/// calls. What stays outside (docs/user-guide.md, "Embedding: memory"):
/// - what is handed to the caller by value: the std::vector of a query, World::bodies(),
///   World::snapshot(), Recorder::bytes() and the like belong to the caller and use
///   std::allocator; the callback and into-a-buffer forms of those calls allocate nothing;
/// - error paths: the exceptions and their messages;
/// - the World's own worker threads (WorldDef::workers > 1 without a TaskSystem): the standard
///   library allocates each std::thread's state with the global operator new, one block per
///   pool thread when the World is made; a game that lends its TaskSystem starts no thread;
/// - a std::function the library copies (BodyDef::load in create_body, the other mixing
///   function in set_friction_mixing / set_restitution_mixing) whose callable std::function
///   keeps on the heap, and a body's name beyond std::string's in-object capacity;
/// - scene files (tamias2d::io), read and written with the standard allocator.
#pragma once

#include <cstddef>

#include "tamias2d/config.hpp"
#include "tamias2d/export.hpp"
#include "tamias2d/result.hpp"

namespace tamias2d {

/// The hook's two functions and the user's pointer handed to both. `allocate` returns a block
/// of `size` bytes (> 0) aligned to `alignment` (a power of two, at least
/// alignof(std::max_align_t)), or nullptr when it has none (the library then throws
/// std::bad_alloc). `free` takes back a block `allocate` returned, with the same size and
/// alignment. Both may be called from the World's worker threads (or the game's task system's)
/// during a step, so they must be thread-safe when WorldDef::workers > 1.
struct Allocator {
    /// A block of `size` bytes aligned to `alignment`, or nullptr.
    void* (*allocate)(std::size_t size, std::size_t alignment, void* user) = nullptr;
    /// Takes back a block of allocate(size, alignment, user).
    void (*free)(void* pointer, std::size_t size, std::size_t alignment, void* user) = nullptr;
    void* user = nullptr; ///< handed to both functions (the game's allocator, say)
};

/// What the library holds now from the current allocator (the hook or the default).
struct AllocatorUse {
    std::size_t blocks = 0; ///< blocks allocated and not yet freed
    std::size_t bytes = 0;  ///< their sizes' sum
};

#if TAMIAS2D_EXCEPTIONS
/// Installs `hook` for the whole process (both functions, not null). Refused with
/// ValidationError ("allocator.allocate" or "allocator.free": must not be null; rule
/// "allocator") and with AllocatorInUse (errors.hpp) while the library holds any block from the
/// current allocator (a World, Recorder or Replayer alive), which gives the count of blocks and
/// bytes. The retained large blocks of past worlds (memory.hpp) are returned to the operating
/// system first. Not to be called while another thread uses the library.
TAMIAS2D_EXPORT void set_allocator(const Allocator& hook);

/// Back to the default allocator (operator new, and mapped large blocks); refused as
/// set_allocator is while the library holds a block.
TAMIAS2D_EXPORT void reset_allocator();

#endif // TAMIAS2D_EXCEPTIONS

// The error-returning forms (result.hpp), declared whatever TAMIAS2D_EXCEPTIONS is.
/// set_allocator, returning its Error (validation, allocator_in_use) instead of throwing it.
TAMIAS2D_EXPORT Result<void> try_set_allocator(const Allocator& hook) noexcept;
/// reset_allocator, returning its Error (allocator_in_use) instead of throwing it.
TAMIAS2D_EXPORT Result<void> try_reset_allocator() noexcept;

/// The hook in use; both functions null when it is the default.
TAMIAS2D_EXPORT Allocator current_allocator() noexcept;

/// The blocks and bytes the library holds now from the current allocator.
TAMIAS2D_EXPORT AllocatorUse allocator_use() noexcept;

} // namespace tamias2d
