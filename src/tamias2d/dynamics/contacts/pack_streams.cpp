#include "tamias2d/dynamics/contacts/pack_streams.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace tamias2d {

namespace {

void relax() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#endif
}

// At most this many packs between two reports of progress; a run also ends right after a pack
// another stream waits for, so that the report reaches it without delay.
constexpr std::uint32_t run_length = 8;
// How long a thread spins on a wait another thread is about to meet before it lets its stream go.
constexpr int patience = 256;

} // namespace

void PackStreams::reset() {
    for (Stream& s : streams_) {
        s.done.store(0, std::memory_order_relaxed);
        s.held.store(0, std::memory_order_relaxed);
    }
}

void PackStreams::run(const ConstraintGraph& graph, std::uint32_t preferred, RunPacks run_packs,
                      void* context) {
    const std::uint32_t count = graph.streams();
    // The stream pack i still waits for, or count if none.
    const auto blocker = [&](std::size_t i) {
        for (const StreamWait& w : graph.waits(i)) {
            if (streams_[w.stream].done.load(std::memory_order_acquire) < w.packs)
                return w.stream;
        }
        return count;
    };
    for (;;) {
        bool finished = true, progressed = false;
        for (std::uint32_t k = 0; k < count; ++k) {
            const std::uint32_t s = (preferred + k) % count;
            Stream& stream = streams_[s];
            const std::uint32_t begin = graph.stream_begin(s);
            const std::uint32_t size = graph.stream_begin(s + 1) - begin;
            if (stream.done.load(std::memory_order_acquire) == size)
                continue;
            finished = false;
            std::uint32_t free = 0;
            if (stream.held.load(std::memory_order_relaxed) != 0 ||
                !stream.held.compare_exchange_strong(free, 1, std::memory_order_acquire,
                                                     std::memory_order_relaxed))
                continue;
            // Held: done is this thread's to advance (the last holder's stores are visible).
            std::uint32_t done = stream.done.load(std::memory_order_relaxed);
            int idle = 0;
            while (done < size) {
                const std::uint32_t waits_for = blocker(begin + done);
                if (waits_for != count) {
                    // A free stream is nobody's to advance: go and run it.
                    if (streams_[waits_for].held.load(std::memory_order_relaxed) == 0 ||
                        ++idle > patience)
                        break;
                    relax();
                    continue;
                }
                idle = 0;
                std::uint32_t end = done + 1;
                while (end < size && end - done < run_length && !graph.awaited(begin + end - 1) &&
                       blocker(begin + end) == count)
                    ++end;
                run_packs(context, begin + done, end - done, s);
                done = end;
                stream.done.store(done, std::memory_order_release);
                progressed = true;
            }
            stream.held.store(0, std::memory_order_release);
        }
        if (finished)
            return;
        if (!progressed)
            relax();
    }
}

} // namespace tamias2d
