#pragma once
// Descriptors 0, 1 and 2 as the program found them. A tool started with one of them closed
// (`gg-sim ... -o - >&-`) would otherwise hand that number to the next file it opens, and its data
// meant for stdout would go into that file instead. guard_standard_streams() puts /dev/null on
// each closed one, so that no file can take it, and remembers which were closed: writing to a
// stdout that was closed is then an error (H5Output "-"), not a silent loss.
namespace gg {

// Called first by guarded_main (every tool); later calls change nothing.
void guard_standard_streams();

// Whether descriptor `fd` (0, 1 or 2) was closed when guard_standard_streams() first ran.
bool closed_at_start(int fd);

}  // namespace gg
