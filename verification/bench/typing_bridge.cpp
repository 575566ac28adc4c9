// The typed instantiation of the typing kernel: every formula goes through tamias2d::bridge.
#include "typing_kernel.hpp"

namespace tamias_bench::typing {

[[gnu::noinline]] TAMIAS_WIDE_KERNEL void run_bridge(KernelData& d, int steps, double dt) {
    Kernel<BridgeOps>::run(d, steps, dt);
}

} // namespace tamias_bench::typing
