// Kernels that GCC vectorises are built twice on x86-64 Linux (an ifunc chooses at load time):
// for AVX2, 4 doubles a register, where the CPU has it, and for the baseline's SSE2. AVX2
// without FMA rounds every operation as the scalar code does, so both give the same bits, as
// long as the source file is compiled with -ffp-contract=off (CMakeLists.txt). Elsewhere the
// kernel is built once.
#pragma once

#if defined(__GNUC__) && defined(__x86_64__) && defined(__ELF__)
#define YDRY_AVX2_CLONE __attribute__((target_clones("avx2", "default")))
#else
#define YDRY_AVX2_CLONE
#endif
