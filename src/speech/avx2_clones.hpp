// A function whose loops run lane by lane, compiled twice where the platform chooses between
// clones as the library loads (GCC's target_clones, an ELF ifunc): once for the baseline x86-64 the
// library is built for (SSE2: four floats or two doubles a register) and once for AVX2 (twice as
// many). Only for sums and maxima taken lane by lane, with no reduction across lanes: AVX2 alone
// enables no fused multiply-add, so each lane's operations and roundings are the same and both
// clones give the same numbers to the bit (bench/README.md, Session 28).
#ifndef TALKFACE_SPEECH_AVX2_CLONES_HPP
#define TALKFACE_SPEECH_AVX2_CLONES_HPP

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define TALKFACE_HAS_AVX2_CLONES 1
#define TALKFACE_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define TALKFACE_HAS_AVX2_CLONES 0
#define TALKFACE_AVX2_CLONES
#endif

#endif  // TALKFACE_SPEECH_AVX2_CLONES_HPP
