// gg-bench-sim: the engine's speed on the paper's system, printed as a table.
//  1. L = 512, rho = 0.37, N = 96993, random start, T0 = 1: collisions per CPU second over the
//     first K collisions and over K collisions deep in the cooling (T/T0 < 1e-3), for e = 0.9
//     and e = 0.5 (with the t_c = 1e-4 it needs), and the cost of each effect as a ratio.
//  2. CPU time per collision for N = 1e4 ... 1e7 at rho = 0.37, e = 0.9, over the first two
//     collisions per particle of fresh starts (as many starts as it takes to time K/4 collisions),
//     so that every N is measured in the same state of the gas.
//  3. Bytes per particle: the resident memory an engine adds (its state, without the start).
//  4. 3D hard spheres at packing fraction eta = 0.30, N ~ 1e5 and 1e6, e = 1 and 0.9: collisions
//     per CPU second over the first K collisions after N untimed ones, and bytes per particle.
//  5. This machine's memory, which sets the cost at large N: a dependent read at random places of
//     arrays of 0.25 MB to 1 GB, and what a prefetched line of 1 GB still costs when it is used.
// CPU time (not wall time) is measured, so other load on the machine matters less; and every
// figure is the median of R runs of the same window (R = 5 unless given), printed with the
// fastest and slowest: on this shared machine one run moves 10-30% from the next.
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "ggsim/engine.hpp"
#include "ggsim/engine_variants.hpp"
#include "ggsim/huge_pages.hpp"
#include "ggsim/initial_state.hpp"

namespace {

using namespace ggsim;

struct Silent {
  double next_time() const { return kNever; }
  template <class E> void observe(E&, double) {}
  template <class E> bool poll(const E&) { return false; }
};

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// Resident memory now, in bytes (Linux /proc/self/statm).
double resident_bytes() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return 0;
  long total = 0, resident = 0;
  const int got = std::fscanf(f, "%ld %ld", &total, &resident);
  std::fclose(f);
  return got == 2 ? static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) : 0;
}

// The most memory resident at any moment since the last reset_peak() (VmHWM), in bytes; 0 if
// the kernel does not say.
double peak_resident_bytes() {
  std::FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return 0;
  char line[256];
  double kb = 0;
  while (std::fgets(line, sizeof line, f))
    if (std::sscanf(line, "VmHWM: %lf kB", &kb) == 1) break;
  std::fclose(f);
  return kb * 1024;
}

// Starts a new peak at the present resident size (Linux >= 4.0: "5" > /proc/self/clear_refs).
bool reset_peak() {
  std::FILE* f = std::fopen("/proc/self/clear_refs", "w");
  if (!f) return false;
  const bool ok = std::fputs("5", f) >= 0;
  return std::fclose(f) == 0 && ok;
}

struct Start {
  gg::Box<2> box;
  std::vector<Vec<2>> r, v;
};

Start random_start(double L, double rho, std::uint64_t seed) {
  Start s;
  s.box = gg::Box<2>({L, L});
  Random rng(seed);
  const auto n = static_cast<std::size_t>(std::llround(rho * L * L));
  s.r = random_positions<2>(s.box, n, rng);
  s.v = maxwellian_velocities<2>(n, 1.0, rng);
  return s;
}

// The next k collisions of `eng`: how many there were and their CPU seconds, and events, shell
// exits and stale events per collision (the same in every run of a window: its trajectory is
// fixed), which tell a window that costs more per event from one that has more events per collision.
struct Window {
  double collisions, cpu, rate, events, exits, stale;
};
template <class E>
Window measure_window(E& eng, std::uint64_t k) {
  Silent none;
  const std::uint64_t c0 = eng.collisions(), e0 = eng.events(), x0 = eng.shell_exits(), s0 = eng.stale_events();
  const double t0 = cpu_seconds();
  eng.run(kNever, c0 + k, none);
  const double cpu = cpu_seconds() - t0, c = static_cast<double>(eng.collisions() - c0);
  const auto per_collision = [c](std::uint64_t n) { return static_cast<double>(n) / c; };
  return {c, cpu, c / cpu, per_collision(eng.events() - e0), per_collision(eng.shell_exits() - x0),
          per_collision(eng.stale_events() - s0)};
}
template <class E>
double rate(E& eng, std::uint64_t k) {
  return measure_window(eng, k).rate;
}

// Runs of one measurement: the median, the least and the most.
struct Spread {
  double median, least, most;
};
Spread spread_of(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  const std::size_t m = x.size() / 2;
  return {x.size() % 2 ? x[m] : 0.5 * (x[m - 1] + x[m]), x.front(), x.back()};
}
template <class Measure>
Spread repeated(int runs, Measure&& measure) {
  std::vector<double> x;
  for (int r = 0; r < runs; ++r) x.push_back(measure());
  return spread_of(std::move(x));
}
// The median, then the range of the runs: "1.62e6 (1.55-1.70)" for rates (in the median's power
// of ten), "467.6 (464.7-470.3)" with `decimals` for smaller numbers.
std::string spread_text(const Spread& s, int decimals = 1) {
  const int exponent = s.median >= 1e4 ? static_cast<int>(std::floor(std::log10(s.median))) : 0;
  const double unit = std::pow(10.0, exponent);
  char buf[96];
  if (exponent == 0) std::snprintf(buf, sizeof buf, "%.*f (%.*f-%.*f)", decimals, s.median, decimals, s.least, decimals, s.most);
  else std::snprintf(buf, sizeof buf, "%.2fe%d (%.2f-%.2f)", s.median / unit, exponent, s.least / unit, s.most / unit);
  return buf;
}

// Engine `eng` run on until T/T0 < 1e-3 (E = T in 2D), in steps of k/4 collisions.
template <class E>
void cool(E& eng, std::uint64_t k) {
  Silent none;
  while (eng.kinetic_energy() >= 1e-3) eng.run(kNever, eng.collisions() + k / 4, none);
}

// Rates early (each run from the start) and late (from the cooled state), and the peak memory
// per particle the engine of the first run added over both windows (with its renumberings and
// calendar rebuilds), which it returns; -1 where the kernel cannot reset the peak. The first
// run is the only engine alive while the peak is measured; the later late runs each start
// from a copy of a second engine cooled the same way (the same trajectory).
template <class Fx>
double early_and_late(const char* label, const Start& s, double e, double tc, std::uint64_t k, int runs) {
  EngineParameters par;
  par.rule.e = e;
  par.rule.effects.set<TcParameters>().tc = tc;
  std::vector<double> early, late;
  malloc_trim(0);  // memory freed by an earlier engine must not be counted as already resident
  const bool peak_known = reset_peak();
  const double before = resident_bytes();
  double peak = -1, t_late = 0, cpp = 0;
  Window first{}, cooled_window{};
  {
    Engine<2, Fx> eng(s.box, s.r, s.v, par);
    first = measure_window(eng, k);
    early.push_back(first.rate);
    cool(eng, k);
    t_late = eng.now(), cpp = 2.0 * static_cast<double>(eng.collisions()) / static_cast<double>(eng.size());
    cooled_window = measure_window(eng, k);
    late.push_back(cooled_window.rate);
    if (peak_known) peak = (peak_resident_bytes() - before) / static_cast<double>(eng.size());
  }
  for (int r = 1; r < runs; ++r) {
    Engine<2, Fx> eng(s.box, s.r, s.v, par);
    early.push_back(rate(eng, k));
  }
  if (runs > 1) {
    Engine<2, Fx> cooled(s.box, s.r, s.v, par);
    Silent none;
    cooled.run(kNever, k, none);  // the first run's early window, then its cooling
    cool(cooled, k);
    for (int r = 1; r < runs; ++r) {
      Engine<2, Fx> eng = cooled;
      late.push_back(rate(eng, k));
    }
  }
  const Spread fresh = spread_of(early), cold = spread_of(late);
  std::printf("%-20s %22s %22s %9.0f   (late window from t = %.0f, %.0f collisions per particle)\n", label,
              spread_text(fresh).c_str(), spread_text(cold).c_str(), peak, t_late, cpp);
  std::printf("%-20s %14.3f (%.3f) %15.3f (%.3f)   events (shell exits) per collision; %.0f and %.0f ns per event\n",
              "", first.events, first.exits, cooled_window.events, cooled_window.exits, 1e9 / (fresh.median * first.events),
              1e9 / (cold.median * cooled_window.events));
  return peak;
}

// Rate over the first k collisions; `mass`: a mixture's masses (radii 1/2, so the start stays valid);
// `viscoelastic`: K of the viscoelastic law (0: none).
template <class Fx>
double first_rate(const Start& s, double e, double tc, std::uint64_t k, double beta = -1,
                  const std::vector<double>& mass = {}, double viscoelastic = 0) {
  EngineParameters par;
  par.rule.e = e;
  par.rule.effects.set<TcParameters>().tc = tc;
  par.rule.effects.set<RoughParameters>().beta = beta;
  par.rule.effects.set<ViscoelasticParameters>().k = viscoelastic;
  EffectRecords sizes;
  if (!mass.empty()) ParticleSizes::add_start({.radius = std::vector<double>(mass.size(), 0.5), .mass = mass}, sizes);
  Engine<2, Fx> eng(s.box, s.r, s.v, par, std::move(sizes));
  return rate(eng, k);
}

// Walls in use: the paper's system between elastic walls at 0 and H = L - 1 across y (the particles
// of its start that lie between them, about all), under gravity g; each relative to the plain engine
// on the same particles in the same (periodic) box, over the first k collisions.
double walls_cost(const Start& paper, double g, std::uint64_t k) {
  const double H = paper.box.L[1] - 1;
  Start s{paper.box, {}, {}};
  for (std::size_t i = 0; i < paper.r.size(); ++i)
    if (paper.r[i][1] > 0.5 && paper.r[i][1] < H - 0.5) s.r.push_back(paper.r[i]), s.v.push_back(paper.v[i]);
  EngineParameters par;
  par.rule.e = 0.9;
  const double plain = first_rate<Effects<>>(s, 0.9, 0, k);
  par.rule.effects.set<WallParameters>() = {.height = H, .gravity = g, .seed = 1};
  Engine<2, Effects<WallsEffect>> walled(s.box, s.r, s.v, par);
  return plain / rate(walled, k);
}

// A shear in use: the paper's start with the mean flow u_x = a (y - L/2) added, sheared at the rate a
// (Lees-Edwards images); relative to the plain engine on the same start without the flow, over the
// first k collisions.
double shear_cost(const Start& paper, double a, std::uint64_t k) {
  Start s = paper;
  for (std::size_t i = 0; i < s.r.size(); ++i) s.v[i][0] += a * (s.r[i][1] - 0.5 * s.box.L[1]);
  EngineParameters par;
  par.rule.e = 0.9;
  par.rule.effects.set<ShearParameters>().rate = a;
  Engine<2, Effects<ShearEffect>> sheared(s.box, s.r, s.v, par);
  return first_rate<Effects<>>(paper, 0.9, 0, k) / rate(sheared, k);
}

// The drive in use on the paper's system at e = 0.9 (strength for a steady T = T0 = 1, the default
// 20 kicks per particle per collision): CPU time per collision and per event (a kick or a collision)
// over k collisions, each relative to the plain engine's over the same first k collisions.
struct DriveCost {
  double per_collision, per_event;
};
DriveCost drive_cost(const Start& s, std::uint64_t k) {
  EngineParameters par;
  par.rule.e = 0.9;
  Engine<2, Effects<>> plain(s.box, s.r, s.v, par);
  const Window p = measure_window(plain, k);
  const double rho = static_cast<double>(s.r.size()) / (s.box.L[0] * s.box.L[1]);
  const double omega1 = enskog_frequency_at_unit_temperature(2, rho), xi = std::sqrt((1 - 0.81) * omega1 / 4);
  par.rule.effects.set<DriveParameters>() = {"white-noise", xi, default_drive_rate(2, rho, 0.9, xi, 1.0), 1};
  Engine<2, Effects<DrivenEffect>> driven(s.box, s.r, s.v, par);
  const Window d = measure_window(driven, k);
  return {p.rate / d.rate, (p.rate * p.events) / (d.rate * d.events)};
}

// Nanoseconds of CPU time per collision over the first two collisions per particle of fresh
// random starts of n particles (seeds 2, 3, ...) until at least k collisions are timed; *bytes
// gets the peak memory per particle that the first engine added (-1 where the kernel cannot
// reset the peak), *events the events per collision (the same in every run).
double ns_per_collision(double n, std::uint64_t k, double* bytes, double* events) {
  const double L = std::sqrt(n / 0.37);
  double cpu = 0;
  std::uint64_t done = 0, events_done = 0;
  for (std::uint64_t seed = 2; done < k; ++seed) {
    const Start s = random_start(L, 0.37, seed);
    EngineParameters par;
    par.rule.e = 0.9;
    malloc_trim(0);
    const bool peak_known = reset_peak();
    const double before = resident_bytes();
    Engine<2, Effects<>> eng(s.box, s.r, s.v, par);
    Silent none;
    const double t0 = cpu_seconds();
    eng.run(kNever, s.r.size(), none);  // N collisions: two per particle
    cpu += cpu_seconds() - t0;
    if (seed == 2) *bytes = peak_known ? (peak_resident_bytes() - before) / static_cast<double>(s.r.size()) : -1;
    done += eng.collisions();
    events_done += eng.events();
  }
  *events = static_cast<double>(events_done) / static_cast<double>(done);
  return 1e9 * cpu / static_cast<double>(done);
}

// `gg-bench-sim --single N K [SKIN [WARM [DIM]]]`: one fresh start of N particles (2D: rho = 0.37;
// 3D: spheres at packing fraction 0.30; e = 0.9) run for K collisions (timed) after WARM collisions
// (not timed: WARM = 1e7 at N = 96993 reaches the clustered state), with the events per collision;
// small enough to run under valgrind (cachegrind / callgrind count instructions and cache misses per
// collision repeatably).
template <int D>
int single(double n, double k, double skin, double warm) {
  const double rho = D == 2 ? 0.37 : 6 * 0.30 / std::acos(-1.0), L = D == 2 ? std::sqrt(n / rho) : std::cbrt(n / rho);
  std::array<double, D> edges;
  edges.fill(L);
  const gg::Box<D> box(edges);
  Random rng(2);
  double expected = rho;  // rho L^d in the order random_start multiplies (the same N in 2D)
  for (int d = 0; d < D; ++d) expected *= L;
  const auto count = static_cast<std::size_t>(std::llround(expected));
  const std::vector<Vec<D>> r = random_positions<D>(box, count, rng);
  const std::vector<Vec<D>> v = maxwellian_velocities<D>(count, 1.0, rng);
  EngineParameters par;
  par.rule.e = 0.9;
  par.skin = skin;
  Engine<D, Effects<>> eng(box, r, v, par);
  Silent none;
  eng.run(kNever, static_cast<std::uint64_t>(warm), none);
  const Window w = measure_window(eng, static_cast<std::uint64_t>(k));
  std::printf("N = %zu, skin = %g: %.0f collisions in %.3f CPU s (%.0f ns each, %.3g /s); per collision: %.3f events, "
              "%.3f shell exits, %.3f stale events; t = %.4g, E = %.4g\n",
              eng.size(), skin, w.collisions, w.cpu, 1e9 / w.rate, w.rate, w.events, w.exits, w.stale, eng.now(),
              eng.kinetic_energy());
  return 0;
}

// 3D spheres at packing fraction 0.30 (rho = 6 eta / pi) in a cubic box holding about n: the median
// rate over k collisions after n untimed ones (the random start relaxed), and the peak memory per
// particle the first engine added (-1 where the kernel cannot reset the peak).
void spheres_3d(double n, double e, std::uint64_t k, int runs) {
  const double rho = 6 * 0.30 / std::acos(-1.0), L = std::cbrt(n / rho);
  gg::Box<3> box({L, L, L});
  Random rng(1);
  const auto count = static_cast<std::size_t>(std::llround(rho * L * L * L));
  const std::vector<Vec<3>> r = random_positions<3>(box, count, rng), v = maxwellian_velocities<3>(count, 1.0, rng);
  EngineParameters par;
  par.rule.e = e;
  std::vector<double> rates;
  double bytes = -1;
  for (int run = 0; run < runs; ++run) {
    malloc_trim(0);
    const bool peak_known = run == 0 && reset_peak();
    const double before = resident_bytes();
    Engine<3, Effects<>> eng(box, r, v, par);
    Silent none;
    eng.run(kNever, count, none);
    rates.push_back(rate(eng, k));
    if (peak_known) bytes = (peak_resident_bytes() - before) / static_cast<double>(count);
  }
  std::printf("%12zu %8.1f %22s %18.0f\n", count, e, spread_text(spread_of(rates)).c_str(), bytes);
}

// The 3D table: N ~ 1e5 and 1e6 (up to max_n), e = 1 and 0.9.
void spheres_3d_table(std::uint64_t k, double max_n, int runs) {
  std::printf("\n3D hard spheres, eta = 0.30, random start relaxed by N collisions (collisions per CPU second over K):\n");
  std::printf("%12s %8s %22s %18s\n", "N", "e", "collisions/s", "peak bytes/part.");
  for (const double n : {1e5, 1e6})
    if (n <= max_n * 1.0001)
      for (const double e : {1.0, 0.9}) spheres_3d(n, e, k, runs);
}

// Nanoseconds per read when each read's address depends on the one before (a walk over a random
// cycle through `bytes` of 64-byte lines, in memory as the engine's arrays are): what an event
// waits for each time it touches a particle nobody touched lately. Sets the scale for the cost
// per collision at large N.
double dependent_read_ns(std::size_t bytes) {
  struct alignas(64) Line {
    std::uint32_t next;
  };
  const std::size_t n = bytes / sizeof(Line);
  std::vector<std::uint32_t> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = static_cast<std::uint32_t>(k);
  Random rng(7);
  for (std::size_t k = n - 1; k > 0; --k) std::swap(order[k], order[static_cast<std::size_t>(rng.uniform() * (k + 1))]);
  ParticleArray<Line> line(n);
  for (std::size_t k = 0; k < n; ++k) line[order[k]].next = order[(k + 1) % n];
  const std::uint64_t reads = 5000000;
  std::uint32_t at = 0;
  const double t0 = cpu_seconds();
  for (std::uint64_t k = 0; k < reads; ++k) at = line[at].next;
  const double ns = 1e9 * (cpu_seconds() - t0) / static_cast<double>(reads);
  return at < n ? ns : -1;  // `at` is used, so the walk is not optimised away
}

// What a line at a random place of a 1 GB array still costs when it is used although it was
// prefetched microseconds before, over the same steps on a 4 MB array (in cache): each step reads
// one line, prefetches the line kAhead steps on, and works ~0.4 us on what it read (300
// multiply-adds in one chain, which no other step's read can overlap). A layout takes the lines
// `group` to a random region of `region_bytes` (group 1, region 64: every line at random). The
// arrays are filled once; every round times each layout on both, so that the machine's load
// weighs on all alike; medians of the rounds. An event of the engine at N = 1e7 reads its
// particles' lines thus (its look-ahead prefetches them), so this is what each costs it at the least.
struct LineLayout {
  int group;
  std::size_t region_bytes;
};
template <std::size_t L>
std::array<double, L> prefetched_line_ns(const std::array<LineLayout, L>& layouts) {
  struct alignas(64) Line {
    std::uint64_t value;
  };
  constexpr int kAhead = 8, kRounds = 5, kWork = 300;
  constexpr std::size_t kSteps = 100000;
  Random rng(11);
  std::array<ParticleArray<Line>, 2> array;  // 4 MB, 1 GB
  std::array<std::array<std::vector<std::uint32_t>, 2>, L> line_at;  // per layout and array
  for (int a = 0; a < 2; ++a) {
    array[a].resize(((a == 0 ? std::size_t{4} : std::size_t{1024}) << 20) / sizeof(Line));
    for (std::size_t k = 0; k < array[a].size(); ++k) array[a][k].value = k;
    for (std::size_t l = 0; l < L; ++l) {
      const std::size_t lines_per_region = layouts[l].region_bytes / sizeof(Line);
      const std::size_t group = static_cast<std::size_t>(layouts[l].group), per_place = lines_per_region / group;
      const std::size_t regions = array[a].size() / lines_per_region;
      std::size_t region = 0;
      for (std::size_t k = 0; k < kSteps + kAhead; ++k) {
        if (k % group == 0) region = static_cast<std::size_t>(rng.uniform() * regions);
        // the group's lines at distinct random places within the region
        const std::size_t place = (k % group) * per_place + static_cast<std::size_t>(rng.uniform() * per_place);
        line_at[l][a].push_back(static_cast<std::uint32_t>(region * lines_per_region + place));
      }
    }
  }
  std::array<std::vector<double>, L> extra;
  for (int r = 0; r < kRounds; ++r)
    for (std::size_t l = 0; l < L; ++l) {
      double ns[2];
      for (int a = 0; a < 2; ++a) {
        const Line* line = array[a].data();
        const std::uint32_t* at = line_at[l][a].data();
        std::uint64_t acc = 1;
        const double t0 = cpu_seconds();
        for (std::size_t k = 0; k < kSteps; ++k) {
          __builtin_prefetch(&line[at[k + kAhead]]);
          std::uint64_t v = line[at[k]].value + acc;
          for (int w = 0; w < kWork; ++w) v = v * 2862933555777941757ull + 3037000493ull;
          acc = v;
        }
        ns[a] = 1e9 * (cpu_seconds() - t0) / kSteps;
        const volatile std::uint64_t keep = acc;  // the chain's result is used: it is not optimised away
        (void)keep;
      }
      extra[l].push_back(ns[1] - ns[0]);
    }
  std::array<double, L> median;
  for (std::size_t l = 0; l < L; ++l) median[l] = spread_of(extra[l]).median;
  return median;
}

}  // namespace

// The cost of each effect on the paper's system, and of all of them compiled in but unused.
void effect_costs(const Start& paper, std::uint64_t k, int runs) {
  // The effects in turn within each run, so that a slow moment weighs on all of them alike.
  std::printf("\nCost of each effect (first K/4 collisions, e = 0.9; time per collision relative to the plain engine):\n");
  std::vector<double> plain, cut, tcm, vir, rough, mix, visco, walls, gravity, shear, unused;
  // A binary mixture used: masses 1 and 4 by turns (its radii, read at every prediction, are 1/2).
  std::vector<double> mixture_mass(paper.r.size());
  for (std::size_t i = 0; i < mixture_mass.size(); ++i) mixture_mass[i] = i % 2 ? 4.0 : 1.0;
  for (int r = 0; r < runs; ++r) {
    plain.push_back(first_rate<Effects<>>(paper, 0.9, 0, k / 4));
    cut.push_back(plain.back() / first_rate<Effects<CutoffEffect>>(paper, 0.9, 0, k / 4));
    tcm.push_back(plain.back() / first_rate<Effects<TcEffect>>(paper, 0.9, 1e-4, k / 4));
    vir.push_back(plain.back() / first_rate<Effects<VirialEffect>>(paper, 0.9, 0, k / 4));
    rough.push_back(plain.back() / first_rate<Effects<RoughEffect>>(paper, 0.9, 0, k / 4, 0.0));
    mix.push_back(plain.back() / first_rate<Effects<MixtureEffect>>(paper, 0.9, 0, k / 4, -1, mixture_mass));
    // K = 0.085: e ~ 0.9 at the start's typical impact speed (g ~ 1.5), a pow() and a table per collision.
    visco.push_back(plain.back() / first_rate<Effects<ViscoelasticEffect>>(paper, 0.9, 0, k / 4, -1, {}, 0.085));
    walls.push_back(walls_cost(paper, 0, k / 4));
    // g = 1 / L: a drop of T0 over the box's height, a mild stratification; shells centred, not ahead.
    gravity.push_back(walls_cost(paper, 1 / paper.box.L[1], k / 4));
    // a = 0.01: a reduced shear rate a / nu ~ 0.005 at T0 = 1; the images slide by a L ~ 5 sigma per
    // unit time (L = 512).
    shear.push_back(shear_cost(paper, 0.01, k / 4));
    // The variant a scene without an exact one runs (engine_variants.hpp): every effect but
    // aggregation compiled in, none used.
    unused.push_back(plain.back() / first_rate<Effects<ViscoelasticEffect, CutoffEffect, TcEffect, VirialEffect, ImagesEffect, DrivenEffect, RoughEffect, MixtureEffect>>(paper, 0.9, 0, k / 4));
  }
  const auto of = [](const std::vector<double>& x) { return spread_text(spread_of(x), 3); };
  std::printf("  plain %s /s; delta x%s; tc x%s; pressure x%s; rough (beta = 0) x%s; mixture (masses 1, 4) x%s;\n"
              "  viscoelastic (K = 0.085) x%s; walls x%s; walls and gravity (g = 1/L) x%s; shear (a = 0.01) x%s;\n"
              "  viscoelastic, delta, tc, pressure, images, drive, rough and mixture compiled in, none used x%s\n",
              of(plain).c_str(), of(cut).c_str(), of(tcm).c_str(), of(vir).c_str(), of(rough).c_str(), of(mix).c_str(),
              of(visco).c_str(), of(walls).c_str(), of(gravity).c_str(), of(shear).c_str(), of(unused).c_str());
  std::vector<double> drive_collision, drive_event;
  for (int r = 0; r < runs; ++r) {
    const DriveCost c = drive_cost(paper, k / 40);
    drive_collision.push_back(c.per_collision), drive_event.push_back(c.per_event);
  }
  std::printf("  drive in use (20 kicks per particle per collision, first K/40 collisions): x%s per collision, "
              "x%s per event (a kick or a collision)\n",
              of(drive_collision).c_str(), of(drive_event).c_str());
}

int main(int argc, char** argv) {
  if (argc > 1 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    std::printf("usage: gg-bench-sim [K [MAX_N [RUNS]]]  |  gg-bench-sim --single N K [SKIN [WARM [DIM]]]\n"
                "  K      collisions per measured window (default 1e7)\n"
                "  MAX_N  largest N of the cost-per-collision table (default 1e7)\n"
                "  RUNS   runs of every measurement, of which the median is printed (default 5)\n"
                "  --single N K [SKIN [WARM [DIM]]]  one fresh start of N particles run for K collisions after\n"
                "                              WARM untimed ones (default 0; DIM 2 or 3; for valgrind, A/B runs)\n"
                "  --spheres K [MAX_N [RUNS]]  the 3D table alone\n"
                "  --effects K [RUNS]          the cost of each effect alone (K collisions per window)\n");
    return 0;
  }
  // A wrong argument: what is wrong, in one line.
  const auto refuse = [](const std::string& what) {
    std::fprintf(stderr, "gg-bench-sim: error: %s; see gg-bench-sim --help\n", what.c_str());
    return 2;
  };
  // The whole of `text` as a number (else NaN).
  const auto number = [](const char* text) {
    char* end = nullptr;
    const double x = std::strtod(text, &end);
    return end != text && *end == '\0' ? x : std::nan("");
  };
  const auto count = [&](int i, double fallback) { return argc > i ? number(argv[i]) : fallback; };
  if (argc > 1 && std::string(argv[1]) == "--single") {
    if (argc < 4 || argc > 7) return refuse("--single takes N K [SKIN [WARM [DIM]]]");
    const double n = number(argv[2]), k = number(argv[3]), dim = count(6, 2);
    if (!(n >= 2)) return refuse("--single: N = '" + std::string(argv[2]) + "' is not a number >= 2");
    if (!(k >= 1)) return refuse("--single: K = '" + std::string(argv[3]) + "' is not a number >= 1");
    if (dim != 2 && dim != 3) return refuse("--single: DIM must be 2 or 3");
    const double skin = count(4, default_skin(static_cast<int>(dim))), warm = count(5, 0);
    if (!(skin > 0) || !(warm >= 0)) return refuse("--single: SKIN must be > 0 and WARM >= 0");
    return dim == 3 ? single<3>(n, k, skin, warm) : single<2>(n, k, skin, warm);
  }
  const bool spheres_only = argc > 1 && std::string(argv[1]) == "--spheres";
  const bool effects_only = argc > 1 && std::string(argv[1]) == "--effects";
  if (spheres_only || effects_only) --argc, ++argv;
  if (argc > 1 && argv[1][0] == '-') return refuse("unknown option " + std::string(argv[1]));
  if (argc > (effects_only ? 3 : 4)) return refuse("too many arguments");
  const double k_given = count(1, 1e7);
  if (!(k_given >= 100) || k_given != std::floor(k_given)) return refuse("K must be a whole number >= 100");
  const auto k = static_cast<std::uint64_t>(k_given);
  const double runs_given = count(effects_only ? 2 : 3, 5);
  if (!(runs_given >= 1 && runs_given <= 99) || runs_given != std::floor(runs_given))
    return refuse("RUNS must be a whole number from 1 to 99");
  if (effects_only) {
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    effect_costs(random_start(512, 0.37, 1), k, static_cast<int>(runs_given));
    return 0;
  }
  const double max_n = count(2, 1e7);
  if (!(max_n >= 1e4)) return refuse("MAX_N must be a number >= 1e4");
  const int runs = static_cast<int>(runs_given);
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // each line as soon as it is measured
  if (spheres_only) {
    spheres_3d_table(k, max_n, runs);
    return 0;
  }

  std::printf("gg-bench-sim: collisions per CPU second (one core), K = %.3g collisions per window; median of %d "
              "runs (fastest-slowest)\n\n",
              static_cast<double>(k), runs);
  const Start paper = random_start(512, 0.37, 1);
  std::printf("%-20s %22s %22s %9s\n", "L = 512, N = 96993", "first K", "T/T0 < 1e-3", "peak B/p");
  const double bytes = early_and_late<Effects<>>("e = 0.9", paper, 0.9, 0, k, runs);
  early_and_late<Effects<TcEffect>>("e = 0.5, tc = 1e-4", paper, 0.5, 1e-4, k, runs);

  effect_costs(paper, k, runs);

  std::printf("\nCost per collision vs N (rho = 0.37, e = 0.9, first 2 collisions per particle, >= %.3g in all):\n",
              static_cast<double>(k / 4));
  std::printf("%12s %24s %10s %18s %14s %10s\n", "N", "ns/collision", "vs 1e4", "peak bytes/part.", "events/coll.",
              "ns/event");
  double base = 0;
  for (double n = 1e4; n <= max_n * 1.0001; n *= 10) {
    double bytes = 0, events = 0;
    const Spread ns = repeated(runs, [&] { return ns_per_collision(n, k / 4, &bytes, &events); });
    if (base == 0) base = ns.median;
    std::printf("%12.0f %24s %10.2f %18.0f %14.3f %10.1f\n", n, spread_text(ns).c_str(), ns.median / base, bytes, events,
                ns.median / events);
    std::fflush(stdout);
  }

  spheres_3d_table(k, max_n, runs);

  std::printf("\nThis machine: ns per dependent read at random places of an array of this size (in huge pages\n"
              "where granted, as the engine's; the engine at N = 96993 holds %.1f MB):\n",
              bytes * static_cast<double>(paper.r.size()) / (1 << 20));
  for (const double mb : {0.25, 1.0, 4.0, 16.0, 64.0, 256.0, 1024.0})
    std::printf("  %7.2f MB %8.1f\n", mb, dependent_read_ns(static_cast<std::size_t>(mb * (1 << 20))));
  std::printf("ns a line of a 1 GB array costs when used (over a 4 MB one) although prefetched microseconds before:\n");
  const auto line_ns = prefetched_line_ns<3>({{{1, 64}, {4, 4096}, {4, std::size_t{2} << 20}}});
  std::printf("  lines at random %.0f; four to each random 4 KB page %.0f each; four to each random 2 MB page %.0f each\n",
              line_ns[0], line_ns[1], line_ns[2]);
  return 0;
}
