// LAPLACIAN_EDITING_SIMD_CLONES: a function built twice, for AVX2 with FMA (x86-64-v3) and
// for the baseline, the loader picking the one the processor runs (GCC's target_clones on
// x86-64 Linux; elsewhere one build). For the hot loops of a drag step and a solve, which
// Debian's baseline x86-64 build (SSE2) would run at a quarter of the vector width.
#ifndef LaplacianEditing_SimdClones_h
#define LaplacianEditing_SimdClones_h

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define LAPLACIAN_EDITING_SIMD_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define LAPLACIAN_EDITING_SIMD_CLONES
#endif

#endif
