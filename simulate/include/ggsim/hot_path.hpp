#pragma once
// Inlining and unrolling hints for the engine's hot path (engine.hpp, cell_grid.hpp). The
// sanitizer build (tests at -O1 with AddressSanitizer) leaves them out: they multiply the
// instrumented code (run.cpp took 193 s and 2.3 GB to compile with them, 52 s without), and
// speed is not what that build is for. GG_OFF_HOT_PATH keeps rare work (a renumbering every 16
// events per particle) out of the event loop, so that its size does not change what GCC inlines
// there.
#define GG_OFF_HOT_PATH [[gnu::noinline, gnu::cold]]
#if defined(__SANITIZE_ADDRESS__)
#define GG_FLATTEN
#define GG_UNROLL_CELLS
#else
#define GG_FLATTEN [[gnu::flatten]]
#define GG_UNROLL_CELLS _Pragma("GCC unroll 27")
#endif
