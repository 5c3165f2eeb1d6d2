// Machine code for fetch_codegen_test.sh to read; never run. Each probe calls one of the grid's
// fetching steps, or the effects', for its prefetches alone, as the engine's look-ahead
// does (look_ahead.hpp), a call GCC drops unless the step is inlined first (hot_path.hpp,
// GG_ALWAYS_INLINE). Without it probe_heads holds no prefetch; the lambda of the engine's third
// step is not reproduced here (GCC keeps this one either way).
#include "ggsim/cell_grid.hpp"
#include "ggsim/effects/effect_set.hpp"

using Grid = ggsim::CellGrid<2>;

extern "C" [[gnu::noinline]] void probe_heads(const Grid& g, const Grid::Code& x) { (void)g.prefetch_heads_around(x); }
extern "C" [[gnu::noinline]] void probe_first(const Grid& g, std::int32_t cell) {
  g.prefetch_entries_around<1>(cell, [](Grid::Slot) {});
}
extern "C" [[gnu::noinline]] void probe_second(const Grid& g, std::int32_t cell) {
  g.prefetch_entries_around<2>(cell, [](Grid::Slot) {});
}

// The effects' fetch: one prefetch with the TC model, none without (effects that read no
// per-particle data in a collision must cost the look-ahead nothing).
extern "C" [[gnu::noinline]] void probe_rule_tc(const ggsim::Effects<ggsim::TcEffect>::Set<2>& fx, std::uint32_t i) {
  fx.prefetch(i);
}
extern "C" [[gnu::noinline]] void probe_rule_plain(const ggsim::Effects<ggsim::CutoffEffect, ggsim::VirialEffect>::Set<2>& fx, std::uint32_t i) {
  fx.prefetch(i);
}

int main() { return 0; }
