#pragma once
// Inlining and unrolling hints for the engine's hot path (engine.hpp, cell_grid.hpp). The
// sanitizer build (tests at -O1 with AddressSanitizer) leaves them out: they multiply the
// instrumented code (run.cpp took 193 s and 2.3 GB to compile with them, 52 s without), and
// speed is not what that build is for. GG_OFF_HOT_PATH keeps rare work (a renumbering every 16
// events per particle) out of the event loop, so that its size does not change what GCC inlines
// there.
#define GG_OFF_HOT_PATH [[gnu::noinline, gnu::cold]]
// GG_ALWAYS_INLINE (functions) and GG_ALWAYS_INLINE_LAMBDA (after a lambda's parameter list)
// for code called only for its prefetches: GCC 12 takes a function of nothing but loads and
// prefetches for pure and drops a call to it whose result is unused, prefetches and all, before it
// would inline it. Inlined, the prefetches stay (fetch_codegen_test.sh checks).
#define GG_ALWAYS_INLINE [[gnu::always_inline]] inline
#define GG_ALWAYS_INLINE_LAMBDA __attribute__((always_inline))
#if defined(__SANITIZE_ADDRESS__)
#define GG_FLATTEN
#define GG_UNROLL_CELLS
#else
#define GG_FLATTEN [[gnu::flatten]]
#define GG_UNROLL_CELLS _Pragma("GCC unroll 27")
#endif
