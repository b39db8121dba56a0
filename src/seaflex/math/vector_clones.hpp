// SEAFLEX_VECTOR_CLONES: a function marked with it is compiled twice, for the portable x86-64
// baseline (SSE2) and for x86-64-v3 (AVX2 and FMA: Intel Haswell, AMD Zen and later), and the
// processor's version is picked when the program loads (GCC's target_clones, as glibc picks
// its own memset). For the few loops where the storm spends its time on long vectors
// (math/row_sums.cpp, post/envelope.cpp): the portable build gets the wider vectors where the
// machine has them, the rest of the program stays portable (the SEAFLEX_NATIVE option
// compiles all of it for the build machine). The two versions may differ at round-off (FMA):
// results are identical on one machine for any thread count, and within round-off between
// machines. One version only where the build already targets AVX2 (SEAFLEX_NATIVE on such a
// machine: its own instructions are used, AVX-512 included), with clang (the fuzz build),
// under the sanitizers, with GCC before 11 (no x86-64-v3), and off x86-64 Linux with glibc
// (the indirect function needs glibc's loader).
#pragma once

#include <cstddef>  // the C++ library's configuration: __GLIBC__ where it is glibc

#if defined(__x86_64__) && defined(__linux__) && defined(__GLIBC__) && defined(__GNUC__) && \
    !defined(__clang__) && __GNUC__ >= 11 && !defined(__AVX2__) &&                          \
    !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#define SEAFLEX_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define SEAFLEX_VECTOR_CLONES
#endif
