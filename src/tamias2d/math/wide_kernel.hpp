// TAMIAS_WIDE_KERNEL: one function compiled once per instruction set.
#pragma once

// Functions running loops over packs of lanes (the wide solver's, the pin packs', sincos_batch's)
// are compiled three times, for x86-64-v4 (AVX-512), for AVX2 and for the x86-64 baseline, and
// the processor picks one at load time (GCC function multiversioning). The packs are four doubles
// in each: x86-64-v4 brings no wider pack here but 32 vector registers instead of 16, so the
// iteration's values stay in registers (61 stack accesses in solve_packs' clone against the AVX2
// clone's 161). No clone uses fused multiply-add, so all give the same bits. flatten inlines the
// whole iteration into each clone: it must, because a helper left out of line is compiled for the
// baseline, where a pack travels in memory, while the other clones pass it in a ymm register.
// Unoptimised builds (-O0: the coverage build) do not inline, so they run the baseline loops only.
// Nor does a ThreadSanitizer build: the loader runs the clones' resolver, which TSan instruments,
// before TSan has started.
#ifndef TAMIAS_WIDE_X86_64_V4
#define TAMIAS_WIDE_X86_64_V4 1 // 0: no x86-64-v4 clone (CMake's TAMIAS_WIDE_X86_64_V4)
#endif
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__) && defined(__OPTIMIZE__) &&    \
    !defined(__SANITIZE_THREAD__)
#define TAMIAS_WIDE_CLONES 1
#if TAMIAS_WIDE_X86_64_V4
#define TAMIAS_WIDE_KERNEL                                                                         \
    __attribute__((target_clones("arch=x86-64-v4", "avx2", "default"), flatten))
#else
#define TAMIAS_WIDE_KERNEL __attribute__((target_clones("avx2", "default"), flatten))
#endif
#else
#define TAMIAS_WIDE_CLONES 0
#define TAMIAS_WIDE_KERNEL
#endif
