// Timing of the structural analyses (each tool's analysis of one N = 96993, L = 512 snapshot
// must take under 50 ms). Builds two configurations in memory (no file I/O):
//   homogeneous: uniform random positions at rho = 0.37 (the start of every run);
//   clustered:   the same N with 80% of the particles packed into 300 random discs (a late, coarsened
//                state: big clusters, long union-find chains, few interfaces).
// Each tool's time = coarse-graining (DensityGrid::assign) + its analysis; the median of --repeat runs
// is printed as a table on stdout. Then (unless --no-tools) the homogeneous snapshot is written as an
// H5MD file and each whole tool run (gg-cluster FILE -o OUT, reading and writing included) is timed:
// median of 5 wall-clock runs (under 0.3 s).
// A second table times what only some runs ask for, on the same two configurations with Maxwellian
// velocities (T = 1): gg-velocity's analysis (the Sonine coefficients, f(c) and the flow field with its
// correlations) and gg-correlate's opt-in g(r) (--pairs, up to r = 5) and S_rho (--density); the whole
// tool runs then include gg-velocity and gg-correlate --pairs --density on the snapshot with velocities.
// Usage: gg-bench-structure [--repeat 21] [--L 512] [--rho 0.37] [--no-tools]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "cluster.hpp"
#include "correlation.hpp"
#include "domains.hpp"
#include "gg/density_grid.hpp"
#include "pair_correlation.hpp"
#include "velocity.hpp"
#include "gg/h5file.hpp"
#include "gg/trajectory.hpp"

#include <filesystem>
#include <unistd.h>

namespace {

std::vector<double> homogeneous(std::size_t n, double L, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, L);
  std::vector<double> x(2 * n);
  for (auto& v : x) v = u(rng);
  return x;
}

std::vector<double> clustered(std::size_t n, double L, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int blobs = 300;
  std::vector<double> cx(blobs), cy(blobs);
  for (int b = 0; b < blobs; ++b) {
    cx[b] = u(rng) * L;
    cy[b] = u(rng) * L;
  }
  const double radius = std::sqrt(0.8 * n / blobs / (0.8 * M_PI));  // discs at density ~0.8
  std::vector<double> x(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    if (u(rng) < 0.8) {
      const int b = static_cast<int>(u(rng) * blobs);
      const double r = radius * std::sqrt(u(rng)), a = 2 * M_PI * u(rng);
      x[2 * i] = std::fmod(cx[b] + r * std::cos(a) + L, L);
      x[2 * i + 1] = std::fmod(cy[b] + r * std::sin(a) + L, L);
    } else {
      x[2 * i] = u(rng) * L;
      x[2 * i + 1] = u(rng) * L;
    }
  }
  return x;
}

double median_ms(int repeat, const std::function<void()>& f) {
  std::vector<double> t;
  f();  // warm-up (page faults, caches)
  for (int r = 0; r < repeat; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    const auto t1 = std::chrono::steady_clock::now();
    t.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
  }
  std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
  return t[t.size() / 2];
}

std::vector<double> maxwellian(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<double> v(2 * n);
  for (auto& x : v) x = g(rng);
  return v;
}

volatile double sink = 0;  // keeps results alive

// Whole tool runs on the homogeneous snapshot written as an H5MD file (float64 positions).
int time_tools(std::size_t n, double L) {
  char tmpl[] = "/tmp/gg-bench-structure-XXXXXX";
  if (!mkdtemp(tmpl)) {
    std::perror("gg-bench-structure: mkdtemp");
    return 1;
  }
  const std::string dir = tmpl;
  {
    gg::Snapshots s;
    s.dim = 2;
    s.edges = {L, L};
    s.n_particles = n;
    s.time = {0.0};
    s.step = {0};
    s.position = homogeneous(n, L, 12345);
    s.velocity = maxwellian(n, 54321);
    gg::H5Output out(dir + "/snapshot.h5");
    gg::write_snapshots(out, s, "gg-bench-structure");
    out.commit();
  }
  std::printf("# whole tool runs (read + analyse + write), one snapshot, median of 5 wall-clock runs\n");
  int status = 0;
  const std::vector<std::pair<const char*, const char*>> runs = {{GG_CLUSTER_EXE, ""},
                                                                 {GG_CORRELATE_EXE, ""},
                                                                 {GG_DOMAINS_EXE, ""},
                                                                 {GG_VELOCITY_EXE, ""},
                                                                 {GG_CORRELATE_EXE, " --pairs --density"}};
  for (const auto& [exe, extra] : runs) {
    const std::string cmd = std::string(exe) + " " + dir + "/snapshot.h5 -o " + dir + "/out.h5 --quiet" + extra;
    int rc = 0;
    const double ms = median_ms(5, [&] { rc |= std::system(cmd.c_str()); });
    const std::string name = std::filesystem::path(exe).filename().string() + extra;
    std::printf("%-34s %8.1f ms%s\n", name.c_str(), ms, rc ? "  (FAILED)" : "");
    status |= rc != 0;
  }
  std::filesystem::remove_all(dir);
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 21;
  double L = 512, rho = 0.37;
  bool tools = true;
  for (int i = 1; i < argc; i += 2) {
    if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
      std::printf("usage: gg-bench-structure [--repeat 21] [--L 512] [--rho 0.37] [--no-tools]\n"
                  "  times each analysis of one snapshot of N = rho L^2 disks, homogeneous and clustered (median of\n"
                  "  --repeat runs, ms), then each whole tool run on it unless --no-tools\n");
      return 0;
    }
    if (!std::strcmp(argv[i], "--no-tools")) {
      tools = false;
      --i;
    } else if (i + 1 >= argc) {
      std::fprintf(stderr, "gg-bench-structure: error: %s needs a value\n", argv[i]);
      return 2;
    } else if (!std::strcmp(argv[i], "--repeat")) repeat = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--L")) L = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--rho")) rho = std::atof(argv[i + 1]);
    else {
      std::fprintf(stderr, "gg-bench-structure: error: unknown option %s (use --repeat, --L, --rho, --no-tools)\n", argv[i]);
      return 2;
    }
  }
  // The largest box whose snapshot and grids fit a machine of a few GB (N = 1e8 at rho = 0.37).
  if (repeat < 1 || !(L >= 1 && L <= 16384) || !(rho > 0 && rho < 1)) {
    std::fprintf(stderr, "gg-bench-structure: error: need --repeat >= 1, 1 <= --L <= 16384, 0 < --rho < 1\n");
    return 2;
  }
  const auto n = static_cast<std::size_t>(std::lround(rho * L * L));
  std::printf("# gg-bench-structure: N = %zu, L = %g, grid 1, coarse 1, rho_c 0.5; median of %d runs, ms\n", n, L,
              repeat);
  std::printf("%-12s %10s %10s %10s %10s %10s %10s %10s\n", "config", "grid", "cluster", "correlate", "domains",
              "gg-cluster", "gg-correl.", "gg-domains");

  const gg::CoarseGrain params{};
  for (const char* name : {"homogeneous", "clustered"}) {
    const auto x = std::strcmp(name, "homogeneous") == 0 ? homogeneous(n, L, 12345) : clustered(n, L, 12345);
    gg::DensityGrid grid({L, L}, params);
    gg::Correlator correlator(grid);  // plans: once per file, not per frame
    grid.assign(x.data(), n);

    const double t_grid = median_ms(repeat, [&] { grid.assign(x.data(), n); });
    const double t_cluster = median_ms(repeat, [&] {
      const auto c = gg::find_clusters(grid, gg::Connectivity::face);
      sink = sink + gg::summarize(c.clusters, 1).mean_mass;
    });
    const double t_corr = median_ms(repeat, [&] { sink = sink + correlator.compute(grid, 0.5).length; });
    const double t_dom = median_ms(repeat, [&] { sink = sink + gg::measure_domains(grid, gg::Phase::both).length; });
    std::printf("%-12s %10.2f %10.2f %10.2f %10.2f %10.2f %10.2f %10.2f\n", name, t_grid, t_cluster, t_corr, t_dom,
                t_grid + t_cluster, t_grid + t_corr, t_grid + t_dom);

    const auto c = gg::find_clusters(grid, gg::Connectivity::face);
    const auto s = gg::summarize(c.clusters, 1);
    const auto corr = correlator.compute(grid, 0.5);
    const auto dom = gg::measure_domains(grid, gg::Phase::both);
    std::printf("# %s: m = %.3f, m_w = %.3f, count = %lld, largest = %lld, l_C = %.3f, l_d = %.3f\n", name,
                s.mean_mass, s.weight_mass, static_cast<long long>(s.count), static_cast<long long>(s.largest),
                corr.length, dom.length);
  }
  std::printf("\n# what only some runs ask for, ms (velocity = gg-velocity's analysis: the Sonine coefficients, f(c) "
              "with its tail fit, the flow field; g(r) = gg-correlate --pairs, r <= 5 in bins of 0.02; S_rho = "
              "gg-correlate --density); each + grid = the tool's time per frame\n");
  std::printf("%-12s %10s %10s %10s %10s %10s %10s %10s\n", "config", "grid", "velocity", "sonine", "f(c)", "flow",
              "g(r)", "S_rho");
  const auto v = maxwellian(n, 54321);
  const std::vector<double> speed_edges = gg::speed_bin_edges(0.1, 3, 20, 12);
  for (const char* name : {"homogeneous", "clustered"}) {
    const auto x = std::strcmp(name, "homogeneous") == 0 ? homogeneous(n, L, 12345) : clustered(n, L, 12345);
    gg::DensityGrid grid({L, L}, params);
    gg::Correlator correlator(grid);
    gg::FlowAnalyzer flow(grid);
    grid.assign(x.data(), n);
    const double t_grid = median_ms(repeat, [&] { grid.assign(x.data(), n); });
    const double t_sonine = median_ms(repeat, [&] { sink = sink + gg::sonine_coefficients(v.data(), nullptr, n, 2).a2; });
    const double t_distribution = median_ms(repeat, [&] {
      sink = sink + gg::speed_distribution(v.data(), nullptr, n, 2, speed_edges, 1.5).tail_A;
    });
    const double t_flow = median_ms(repeat, [&] { sink = sink + flow.compute(grid, x.data(), v.data(), nullptr, n, 0.5).length_L; });
    const double t_pairs = median_ms(repeat, [&] {
      const auto g = gg::radial_distribution(x.data(), n, {L, L}, 5, 0.02);
      sink = sink + gg::contact_value(g, 1.0, 0.1);
    });
    const double t_srho = median_ms(repeat, [&] { sink = sink + correlator.density_structure_factor(grid)[1]; });
    std::printf("%-12s %10.2f %10.2f %10.2f %10.2f %10.2f %10.2f %10.2f\n", name, t_grid, t_sonine + t_distribution + t_flow,
                t_sonine, t_distribution, t_flow, t_pairs, t_srho);
  }
  std::printf("\n");
  if (tools) return time_tools(n, L);
  return 0;
}
