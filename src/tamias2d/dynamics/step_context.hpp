// What every stage of one step reads (internal): the settings, the step's and the substep's
// lengths, whether sleeping is on, the loads evaluated at the step's start and the parallel
// loops. World::step makes one per step and passes it to each stage.
#pragma once

#include <vector>

#include "tamias2d/body_def.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/world_def.hpp"

namespace tamias2d {

class StepTasks;

struct StepContext {
    const WorldDef& def;
    double dt;     ///< s, the step
    double h;      ///< s, the substep: dt / def.substeps
    bool sleeping; ///< def.enable_sleep
    /// The load functions' values per body at the step's start, or empty when no body has one.
    const memory::vector<Load>& loads;
    const StepTasks& tasks; ///< the step's parallel loops
};

} // namespace tamias2d
