// A game's memory budget for the physics, as the user guide's "Embedding: memory" section sets
// it up: the allocator hook hands the library blocks from the game's own allocator (here a
// counting one with a budget, as a console game might give each system, over the aligned
// operator new: the game's own heap would go there),
// and the capacity hints size the world's stores for the level up front. Prints what the
// library took while the level was built, in its first step and in its settled steps, and that
// everything came back when the world was destroyed.
#include <cstdio>
#include <new>

#include "tamias2d/tamias2d.hpp"

using namespace tamias2d;

namespace {

/// The physics' share of the game's memory: blocks counted against a budget.
struct Budget {
    std::size_t limit = 0;       ///< bytes the physics may hold at once
    std::size_t in_use = 0;      ///< bytes it holds now
    std::size_t peak = 0;        ///< the most it held
    std::size_t allocations = 0; ///< blocks handed out so far
    std::size_t frees = 0;       ///< blocks taken back so far
};

// One world steps on one thread here, so the budget needs no lock (with WorldDef::workers > 1
// the hook may be called from the worker threads: guard it then).
void* allocate(std::size_t size, std::size_t alignment, void* user) {
    Budget& b = *static_cast<Budget*>(user);
    if (b.in_use + size > b.limit)
        return nullptr; // the library throws std::bad_alloc
    void* p = ::operator new(size, std::align_val_t(alignment), std::nothrow);
    if (p == nullptr)
        return nullptr;
    b.in_use += size;
    b.peak = b.in_use > b.peak ? b.in_use : b.peak;
    ++b.allocations;
    return p;
}

void release(void* pointer, std::size_t size, std::size_t alignment, void* user) {
    Budget& b = *static_cast<Budget*>(user);
    b.in_use -= size; // the size the block was allocated with
    ++b.frees;
    ::operator delete(pointer, std::align_val_t(alignment));
}

} // namespace

int main() {
    Budget budget{.limit = std::size_t(64) << 20};
    set_allocator(Allocator{allocate, release, &budget}); // before any world exists
    {
        // A level of 200 crates on a ground: the hints say so, so that building it and its
        // first steps do not grow the stores (every growth is a block and a copy).
        WorldDef def;
        def.capacity = {.bodies = 201, .shapes = 201, .joints = 0, .contacts = 1000};
        World world(def);
        const std::size_t made = budget.allocations;
        BodyDef ground;
        ground.type = BodyType::static_body;
        ground.position = {0.0, -0.5};
        world.create_shape(world.create_body(ground), box_shape(100.0, 1.0));
        for (int k = 0; k < 200; ++k) {
            BodyDef crate;
            crate.position = {-40.0 + 4.0 * (k % 20), 0.5 + 1.0 * (k / 20)}; // 20 stacks of 10
            world.create_shape(world.create_body(crate), box_shape(1.0, 1.0));
        }
        std::printf("building the level: %zu blocks\n", budget.allocations - made);

        const std::size_t before_first = budget.allocations;
        world.step(1.0 / 60.0);
        std::printf("first step: %zu blocks\n", budget.allocations - before_first);
        for (int i = 0; i < 300; ++i)
            world.step(1.0 / 60.0);
        const std::size_t before_steady = budget.allocations;
        for (int i = 0; i < 600; ++i)
            world.step(1.0 / 60.0);
        std::printf("600 settled steps: %zu blocks\n", budget.allocations - before_steady);
        std::printf("peak %zu bytes of a %zu byte budget\n", budget.peak, budget.limit);
    }
    std::printf("after the world: %zu bytes held, %zu blocks not freed\n", budget.in_use,
                budget.allocations - budget.frees);
    reset_allocator(); // nothing is held: the default allocator again
    return budget.in_use == 0 && budget.allocations == budget.frees ? 0 : 1;
}
