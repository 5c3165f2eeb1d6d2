#!/bin/bash
# plan.sh: what a SCALE of Makefile.study runs and a rough CPU-time estimate (called by `make plan`).
# Cost model: collisions per particle reached by time t (log-log interpolation of the finite-size
# study's runs at rho = 0.37, T0 = 1, equilibrated start, L = 512-2048, which agree within 10% across L;
# 1D: rho = 0.3, e = 0.5, delta = 0.005), times N/2 collisions, at a rate that falls with N as the
# particle data leave the caches: 1.15e6 (N / 4e5)^-0.2 collisions per CPU second in 2D (those runs:
# 1.3-1.45e6 at N = 1e5, 1.1-1.2e6 at 3.9e5, 0.8-0.85e6 at 1.55e6), 3e6 in 1D (gg-sim, one core; see
# `make bench`);
# 3D (Fig. 9): rho = 0.55, T0 = 1, L = 36-60, equilibrated start, at 2.5e5 collisions per CPU second.
# Plus analyses (~0.15 s per snapshot of 1e5 particles for the three tools). Expect +-50%.
set -euo pipefail
awk -v scale="$SCALE" -v L2="$L2" -v nrun="$NRUN" -v fsplan="${FS_PLAN:-}" -v fslong="${FS_LONG_PLAN:-}" \
    -v t05="$TMAX_05" -v t07="$TMAX_07" -v t09="$TMAX_09" \
    -v L2f="$FIG2_L" -v t2f="$FIG2_TLATE" -v L1="$L1" -v nrun1="$NRUN1" -v t1="$TMAX1" -v nproc="$NPROC" \
    -v L3="${L3:-0}" -v nrun3="${NRUN3:-0}" -v t305="${TMAX3_05:-1}" -v t309="${TMAX3_09:-1}" '
function interp(ts, cs, t,   n, T, C, i, a) {
  n = split(ts, T, " "); split(cs, C, " ")
  if (t <= T[1]) return C[1] * t / T[1]
  for (i = 2; i <= n; ++i) if (t <= T[i]) {
    a = log(C[i] / C[i-1]) / log(T[i] / T[i-1]); return C[i-1] * exp(a * log(t / T[i-1])) }
  a = log(C[n] / C[n-1]) / log(T[n] / T[n-1]); return C[n] * exp(a * log(t / T[n]))
}
function cpp(e, t) {
  if (e == "0.5") return interp("1 10 100 1000 3000", "1.7 9 46 1100 5000", t)
  if (e == "0.7") return interp("1 10 100 1000 3000", "1.8 11 32 250 1070", t)
  if (e == "0.8") return interp("1 10 100 1000 3000", "1.85 11 45 160 450", t)
  if (e == "0.9") return interp("1 10 100 1000 3000 10000 31623 100000", "1.9 15 53 125 238 600 1900 8000", t)
  return interp("1 10 100 1000 10000", "0.42 3.4 400 2400 8500", t)   # 1D
}
function cpp3(e, t) {
  if (e == "0.5") return interp("1 10 100 1000 3000", "6.1 21 54 184 313", t)
  return interp("1 10 100 1000 3000 10000", "8.1 43 110 195 253 416", t)
}
function snaps(t) { return 8 * log(t / 0.1) / log(10) + 2 }
function rate2(N) { return 1.15e6 * exp(-0.2 * log(N / 4e5)) }
function cost2(e, L, t,   N) { N = 0.37 * L * L; return N / 2 * (cpp(e, t) + 10) / rate2(N) }
function ana(N, t) { return 0.15 * N / 1e5 * snaps(t) }
BEGIN {
  N2 = int(0.37 * L2 * L2 + 0.5); N1 = int(0.3 * L1 + 0.5)
  printf "SCALE=%s\n", scale
  printf "  %-34s %8s %6s %8s %12s %14s\n", "simulation", "N", "runs", "t_max", "coll/part", "CPU s (total)"
  c = cost2("0.8", L2f, t2f); tot += c
  printf "  %-34s %8d %6d %8g %12.0f %14.0f\n", "fig2: 2D e = 0.8", int(0.37 * L2f * L2f + 0.5), 1, t2f, cpp("0.8", t2f), c
  split("0.5 0.7 0.9", E, " "); T[1] = t05; T[2] = t07; T[3] = t09
  for (i = 1; i <= 3; ++i) {
    c = nrun * (cost2(E[i], L2, T[i]) + ana(N2, T[i])); tot += c
    printf "  %-34s %8d %6d %8g %12.0f %14.0f\n", "fig3-6: 2D e = " E[i] (E[i] == "0.9" ? "" : ", tc = 1e-4"), N2, nrun, T[i], cpp(E[i], T[i]), c
  }
  c = nrun1 * (N1 / 2 * cpp("1d", t1) / 3e6 + ana(N1, t1)); tot += c
  printf "  %-34s %8d %6d %8g %12.0f %14.0f\n", "fig7: 1D e = 0.5, delta = 0.005", N1, nrun1, t1, cpp("1d", t1), c
  if (nrun3 > 0) {
    N3 = int(0.55 * L3 * L3 * L3 + 0.5); split("0.5 0.9", E3, " "); T3[1] = t305; T3[2] = t309
    for (i = 1; i <= 2; ++i) {
      c = nrun3 * (N3 / 2 * (cpp3(E3[i], T3[i]) + 10) / 2.5e5 + ana(N3, T3[i])); tot += c
      printf "  %-34s %8d %6d %8g %12.0f %14.0f\n", "fig9: 3D e = " E3[i] (E3[i] == "0.5" ? ", tc = 1e-4" : ""), N3, nrun3, T3[i], cpp3(E3[i], T3[i]), c
    }
  }
  # Finite-size study (Fig. 8): cells e:L:t_max:runs; a cell equal to a fig3-6 ensemble (same L and
  # t_max) shares its first NRUN runs. Disk: float positions and velocities (16 bytes per
  # particle per snapshot in 2D) while
  # a run is kept, and the per-run result (~30 kB) that fig8 reads.
  # Longer runs beside a cell (FS_LONG, e:L:t_max:runs:id) are cells of their own here.
  nfs = split(fsplan, CELL, " ")
  nlong = split(fslong, LONG, " ")
  for (a = 1; a <= nlong; ++a) CELL[nfs + a] = LONG[a]
  if (nfs > 0) {
    for (i = 1; i <= 3; ++i) TE[E[i]] = T[i]
    printf "  %-34s %8s %6s %8s %12s %14s %10s\n", "finite-size cell (fig8)", "N", "runs", "t_max", "coll/part", "CPU s (total)", "disk GB"
    for (a = 1; a <= nfs + nlong; ++a) {
      split(CELL[a], P, ":"); e = P[1]; L = P[2]; t = P[3]; fsnrun = P[4]; N = int(0.37 * L * L + 0.5)
      extra = (L == L2 && t == TE[e]) ? (fsnrun > nrun ? fsnrun - nrun : 0) : fsnrun
      nres += fsnrun
      c = extra * (cost2(e, L, t) + ana(N, t)); tot += c; fstot += c
      gb = fsnrun * N * 16 * snaps(t) / 1e9; fsgb += gb
      printf "  %-34s %8d %6d %8g %12.0f %14.0f %10.2f%s\n", "L = " L ", e = " e, N, fsnrun, t, cpp(e, t), c, gb,
             (a > nfs ? "  (longer runs beside the cell)" : extra < fsnrun ? "  (shares the fig3-6 runs)" : "")
    }
    printf "  finite-size study: %.0f CPU s = %.2f CPU h, %.1f GB of snapshots (%.1f MB of results)\n",
           fstot, fstot / 3600, fsgb, nres * 0.03
  }
  printf "estimated total: %.0f CPU s = %.2f CPU h; with %d parallel jobs (make -j%d) about %.1f min wall\n",
         tot, tot / 3600, nproc, nproc, tot / nproc / 60
  printf "(plus the build of the tools, ~1.5 min; the largest single run bounds the wall time from below)\n"
}'
