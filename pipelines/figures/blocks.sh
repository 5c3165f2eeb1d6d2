#!/bin/bash
# blocks.sh LABEL1 CMD1 LABEL2 CMD2 ...: run each command (a gg-fit table ...) and print its output as one
# gnuplot data block headed "# LABEL", blocks separated by two blank lines (gnuplot 'index').
set -euo pipefail
first=1
while [ $# -ge 2 ]; do
  [ $first = 1 ] || printf '\n\n'
  first=0
  printf '# %s\n' "$1"
  eval "$2"
  shift 2
done
