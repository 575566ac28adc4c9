// The step's stage clock (internal): World::step and World::Impl::solve mark the end of each
// stage; with profiling off every mark is one test of a flag, and the clock is never read.
#pragma once

#include <chrono>

#include "tamias2d/profile.hpp"

namespace tamias2d {

class StepProfiler {
  public:
    bool enabled = false;
    StepProfile last{}; ///< the last profiled step's times

    /// A step starts: the clock's first reading.
    void begin() {
        if (!enabled)
            return;
        current_ = {};
        start_ = mark_ = clock::now();
    }
    /// The stage `stage` ends now: the time since the last mark is added to it.
    void lap(double StepProfile::*stage) {
        if (!enabled)
            return;
        const clock::time_point t = clock::now();
        current_.*stage += std::chrono::duration<double>(t - mark_).count();
        mark_ = t;
    }
    /// The step ended whole: its times become the last step's.
    void end() {
        if (!enabled)
            return;
        current_.step = std::chrono::duration<double>(clock::now() - start_).count();
        last = current_;
    }

  private:
    using clock = std::chrono::steady_clock;
    StepProfile current_{};
    clock::time_point start_{}, mark_{};
};

} // namespace tamias2d
