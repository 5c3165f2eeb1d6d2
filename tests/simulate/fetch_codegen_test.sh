#!/usr/bin/env bash
# The look-ahead's prefetches survive compilation: every probe in fetch_codegen_probe.cpp holds
# at least one prefetch instruction (none if the compiler dropped the call; several where loops
# are unrolled).
# usage: fetch_codegen_test.sh PROBE_BINARY
set -euo pipefail
for probe in probe_heads probe_first probe_second; do
  n=$(objdump -d --no-show-raw-insn --disassemble="$probe" "$1" | grep -c prefetch || true)
  if [ "$n" -lt 1 ]; then
    echo "$probe: no prefetch instruction in its machine code: the compiler dropped the call to the grid's fetching step (is it still GG_ALWAYS_INLINE?)"
    exit 1
  fi
  echo "$probe: $n prefetch instructions"
done
