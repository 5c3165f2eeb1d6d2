#!/usr/bin/env bash
# The look-ahead's prefetches survive compilation: every grid probe in fetch_codegen_probe.cpp
# holds at least one prefetch instruction (none if the compiler dropped the call; several where
# loops are unrolled), the collision rule's probe with the TC model exactly one, and the one
# without it none.
# usage: fetch_codegen_test.sh PROBE_BINARY
set -euo pipefail
prefetches() { objdump -d --no-show-raw-insn --disassemble="$1" "$BINARY" | grep -c prefetch || true; }
BINARY=$1
for probe in probe_heads probe_first probe_second; do
  n=$(prefetches "$probe")
  if [ "$n" -lt 1 ]; then
    echo "$probe: no prefetch instruction in its machine code: the compiler dropped the call to the grid's fetching step (is it still GG_ALWAYS_INLINE?)"
    exit 1
  fi
  echo "$probe: $n prefetch instructions"
done
n=$(prefetches probe_rule_tc)
if [ "$n" -ne 1 ]; then
  echo "probe_rule_tc: $n prefetch instructions, expected 1: the TC model's last collision times are not fetched ahead (CollisionRule::prefetch)"
  exit 1
fi
n=$(prefetches probe_rule_plain)
if [ "$n" -ne 0 ]; then
  echo "probe_rule_plain: $n prefetch instructions, expected none: a rule without the TC model fetches data it never reads"
  exit 1
fi
echo "probe_rule_tc: 1 prefetch instruction; probe_rule_plain: none"
