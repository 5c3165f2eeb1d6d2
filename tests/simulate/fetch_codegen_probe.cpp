// Machine code for fetch_codegen_test.sh to read; never run. The engine's look-ahead calls the
// grid's fetching steps for their prefetches alone (engine.hpp, fetch_ahead): GCC 12 takes a
// function of nothing but loads and prefetches for pure and drops a call to it whose result is
// unused, prefetches and all, unless the function is inlined first (hot_path.hpp,
// GG_ALWAYS_INLINE). Each probe makes such a call; the test checks that its prefetches are there.
#include "ggsim/cell_grid.hpp"

using Grid = ggsim::CellGrid<2>;

extern "C" [[gnu::noinline]] void probe_heads(const Grid& g, const Grid::Code& x) { (void)g.prefetch_heads_around(x); }
extern "C" [[gnu::noinline]] void probe_first(const Grid& g, std::int32_t cell) {
  g.prefetch_first_around(cell, [](Grid::Slot) {});
}

int main() { return 0; }
