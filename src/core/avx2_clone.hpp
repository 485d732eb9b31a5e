// GROWTHUQ_AVX2_CLONE before a function definition compiles it twice, for x86-64's SSE2
// baseline and for AVX2, and picks the clone at load time by the CPU (GCC function
// multiversioning, Linux ifunc). For the sampling core's vectorized loops: AVX2 without FMA does
// the same IEEE operations in the same order as SSE2, 4 doubles at a time instead of 2, so the
// results are identical on every machine. Elsewhere it expands to nothing.
#pragma once

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define GROWTHUQ_AVX2_CLONE __attribute__((target_clones("avx2", "default")))
#else
#define GROWTHUQ_AVX2_CLONE
#endif
