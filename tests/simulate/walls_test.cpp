// Walls and gravity (boundary/walls.hpp, effects/walls.hpp, motion/gravity.hpp's UniformGravity)
// against what mechanics and the statistical mechanics of hard spheres say (docs/PHYSICS.md "Walls and gravity"):
//  - one particle bounces on its parabola, meeting the floor when the free-fall formula says;
//  - an elastic gas between elastic walls under gravity keeps its energy, kinetic plus potential,
//    to round-off, and no particle crosses a wall or overlaps another (2D and 3D);
//  - an elastic gas over a thermal wall comes to equilibrium at the wall's temperature: its
//    temperature is T_w, the walls carry its weight (the momentum they give it grows at N g), and
//    its density profile is the barometric one, n(z) ~ exp(-g z / T_w), when dilute, and the
//    hydrostatic balance dp/dz = -n g with the hard-disk pressure of Henderson's equation of state
//    when dense (where the barometric profile is far off);
//  - a run continued from its saved state halfway is the run without the stop;
//  - in a vibrated inelastic bed the energy the wall puts in is what the collisions take out: the
//    two, each counted during the run, and the change of the energy (kinetic plus potential) balance
//    to round-off, and in the steady state the input equals the loss.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "engine_harness.hpp"

namespace {

using WallsFx = ggsim::Effects<ggsim::WallsEffect>;
using ggsim::Vec;

// N particles between walls at 0 and H (periodic edge L across), at rest in a Maxwellian at T0:
// the box and region of the scene's start (walls_scene.cpp), engine parameters for walls and gravity.
template <int D>
struct WalledStart {
  gg::Box<D> box;
  std::vector<Vec<D>> r, v;
  ggsim::EngineParameters par;
};

template <int D>
WalledStart<D> walled_start(std::size_t n, double L, double H, double g, double wall_T, std::uint64_t seed) {
  WalledStart<D> s;
  std::array<double, D> edges, region;
  edges.fill(L), region.fill(L);
  edges[D - 1] = H + 1, region[D - 1] = H - 1;
  s.box = gg::Box<D>(edges);
  ggsim::Random rng(seed);
  s.r = ggsim::random_positions<D>(gg::Box<D>(region), n, rng);
  for (Vec<D>& x : s.r) x[D - 1] += 0.5;
  s.v = ggsim::maxwellian_velocities<D>(n, 1.0, rng);
  s.par.rule.e = 1;
  s.par.rule.effects.template set<ggsim::WallParameters>() = {.height = H, .temperature = wall_T, .gravity = g, .seed = seed};
  return s;
}

// The walls' observables now, by name.
template <int D>
std::map<std::string, double> wall_observables(ggsim::Engine<D, WallsFx>& eng) {
  std::map<std::string, double> got;
  const ggsim::Sample at{eng.now(), eng.kinetic_energy(), static_cast<double>(eng.size()), 1, D};
  eng.observables(
      ggsim::ObservableSink([&](const std::string& name, const std::string&, const std::vector<double>& x) { got[name] = x.at(0); }), at);
  return got;
}

// Calls f(position, velocity) for every particle at each of `count` times `every` apart.
struct Sampler {
  double next, every;
  int left;
  std::function<void(const Vec<2>&, const Vec<2>&)> f;
  double next_time() const { return left > 0 ? next : ggsim::kNever; }
  template <class E>
  void observe(E& eng, double t) {
    eng.for_each_particle(t, [&](std::uint32_t, const Vec<2>& x, const Vec<2>& v) { f(x, v); });
    next += every, --left;
  }
  template <class E> bool poll(const E&) { return false; }
};

TEST(Walls, OneParticleBouncesOnItsParabola) {
  const double g = 0.3, z0 = 4, vz0 = 1.1, vx = 0.7;
  WalledStart<2> s = walled_start<2>(1, 10, 20, g, 0, 1);
  s.r = {{2.0, z0}};
  s.v = {{vx, vz0}};
  ggsim::Engine<2, WallsFx> eng(s.box, s.r, s.v, s.par);
  // Free fall from z0 - 1/2 above the floor's contact height: the first bounce, then a period of
  // 2 v_impact / g, each bounce reversing the speed it meets the floor with.
  const double v_impact = std::sqrt(vz0 * vz0 + 2 * g * (z0 - 0.5));
  const double t1 = (vz0 + v_impact) / g, period = 2 * v_impact / g;
  ggtest::Silent none;
  for (double t : {0.5 * t1, t1 + 0.3 * period, t1 + 2.7 * period, t1 + 10.5 * period}) {
    eng.run(t, ~0ull, none);
    const double since = t < t1 ? t : std::fmod(t - t1, period);
    const double z = t < t1 ? z0 + vz0 * t - 0.5 * g * t * t : 0.5 + v_impact * since - 0.5 * g * since * since;
    const auto o = ggtest::observed(eng, t);
    EXPECT_NEAR(o.r[0][1], z, 1e-9) << "t = " << t;
    EXPECT_NEAR(o.v[0][1], t < t1 ? vz0 - g * t : v_impact - g * since, 1e-9) << "t = " << t;
    EXPECT_NEAR(o.r[0][0], std::fmod(2.0 + vx * t, 10.0), 1e-9) << "t = " << t;
  }
  EXPECT_EQ(eng.collisions(), 0u);  // meeting a wall is no collision
}

template <int D>
void expect_energy_kept(std::size_t n, double L, double H, double g) {
  WalledStart<D> s = walled_start<D>(n, L, H, g, 0, 3);
  ggsim::Engine<D, WallsFx> eng(s.box, s.r, s.v, s.par);
  const auto energy = [&] {
    double potential = 0, lowest = H, highest = 0;
    for (const Vec<D>& x : ggtest::observed(eng, eng.now()).r) {
      potential += g * x[D - 1];
      lowest = std::min(lowest, x[D - 1]), highest = std::max(highest, x[D - 1]);
    }
    EXPECT_GT(lowest, 0.5 - 1e-9);
    EXPECT_LT(highest, H - 0.5 + 1e-9);
    return eng.kinetic_energy() + potential / static_cast<double>(n);
  };
  const auto mean_vz = [&] {
    double sum = 0;
    for (const Vec<D>& v : ggtest::observed(eng, eng.now()).v) sum += v[D - 1];
    return sum / static_cast<double>(n);
  };
  const double E0 = energy(), vz0 = mean_vz();
  ggtest::Silent none;
  for (int k = 1; k <= 4; ++k) {
    eng.run(ggsim::kNever, k * 50 * n, none);
    EXPECT_NEAR(energy(), E0, 1e-11 * E0) << D << "D, " << k * 50 << " collisions per particle";
    EXPECT_GT(ggtest::min_distance(eng, eng.now()), 1 - 1e-9);
  }
  const auto got = wall_observables(eng);
  EXPECT_EQ(got.at("wall_energy"), 0.0);  // elastic walls neither give nor take
  // Impulse balance (collisions conserve momentum): what the walls gave per particle is what gravity
  // took, g t, plus the change of the mean vertical velocity.
  const double given = got.at("bottom_wall_momentum") + got.at("top_wall_momentum"), pulled = g * eng.now();
  EXPECT_NEAR(given, pulled + mean_vz() - vz0, 1e-9 * pulled) << D << "D";
  EXPECT_GT(got.at("bottom_wall_momentum"), 0.0);
}

// A run over a thermal wall under gravity, continued from its state halfway (as --resume does),
// is the run without the stop: the walls' counts and random numbers are kept with the state.
TEST(Walls, ResumedRunIsTheUninterruptedOne) {
  WalledStart<2> s = walled_start<2>(300, 30, 40, 0.2, 1.0, 9);
  s.par.rule.e = 0.9;
  ggsim::Engine<2, WallsFx> whole(s.box, s.r, s.v, s.par), first(s.box, s.r, s.v, s.par);
  ggtest::Silent none;
  whole.run(60, ~0ull, none);
  first.run(30, ~0ull, none);
  ggsim::Engine<2, WallsFx> resumed(s.box, ggtest::saved_state(first), s.par);
  resumed.run(60, ~0ull, none);
  EXPECT_EQ(resumed.collisions(), whole.collisions());
  EXPECT_EQ(resumed.events(), whole.events());
  const auto a = ggtest::observed(whole, 60), b = ggtest::observed(resumed, 60);
  EXPECT_EQ(a.r, b.r);
  EXPECT_EQ(a.v, b.v);
  const auto got = wall_observables(resumed), want = wall_observables(whole);
  EXPECT_EQ(got, want);
  EXPECT_NE(want.at("wall_energy"), 0.0);  // the thermal wall drew (and counted) velocities
  EXPECT_GT(want.at("collision_loss"), 0.0);
}

// Kinetic plus potential energy per particle (mass 1) now.
template <int D>
double mechanical_energy(const ggsim::Engine<D, WallsFx>& eng, double g) {
  double potential = 0;
  for (const Vec<D>& x : ggtest::observed(eng, eng.now()).r) potential += g * x[D - 1];
  return eng.kinetic_energy() + potential / static_cast<double>(eng.size());
}

TEST(Walls, VibratedBedPutsInWhatCollisionsTakeOut) {
  const double g = 1, e = 0.9;
  WalledStart<2> s = walled_start<2>(200, 40, 200, g, 0, 5);
  s.par.rule.e = e;
  ggsim::WallParameters& walls = s.par.rule.effects.set<ggsim::WallParameters>();
  walls.amplitude = 0.1, walls.frequency = 2;  // Gamma = A w^2 / g = 15.8
  ggsim::Engine<2, WallsFx> eng(s.box, s.r, s.v, s.par);
  ggtest::Silent none;
  eng.run(200, ~0ull, none);  // the steady state
  const auto before = wall_observables(eng);
  const double E1 = mechanical_energy(eng, g);
  eng.run(2000, ~0ull, none);
  const auto after = wall_observables(eng);
  const double put_in = after.at("wall_energy") - before.at("wall_energy");
  const double lost = after.at("collision_loss") - before.at("collision_loss");
  EXPECT_GT(eng.collisions(), 100000u);
  EXPECT_NEAR(put_in - lost, mechanical_energy(eng, g) - E1, 1e-9 * put_in);
  EXPECT_NEAR(put_in / lost, 1.0, 0.03);
}

TEST(Walls, ElasticWallsUnderGravityKeepTheEnergy2D) { expect_energy_kept<2>(600, 30, 40, 0.2); }
TEST(Walls, ElasticWallsUnderGravityKeepTheEnergy3D) { expect_energy_kept<3>(800, 12, 20, 0.2); }

// The hydrostatic profile of hard disks in the local-density approximation: dp/dz = -n g with
// p = n T Z(n), Z = (1 + eta^2 / 8) / (1 - eta)^2 (Henderson, Mol. Phys. 30, 971 (1975)),
// eta = pi n / 4, so dn/dz = -n g / (T d(n Z)/dn); integrated from the floor's contact height
// with the density there chosen so that the column holds N / L disks per unit length. (An ideal
// gas, Z = 1, gives the barometric profile.) Returns n at the heights z_k.
std::vector<double> hydrostatic_profile(double n_per_length, double H, double g, double T, bool ideal,
                                        const std::vector<double>& z) {
  const auto pressure_slope = [ideal](double n) {  // d(n Z)/dn
    if (ideal) return 1.0;
    const double eta = std::numbers::pi * n / 4;
    const double Z = (1 + eta * eta / 8) / ((1 - eta) * (1 - eta));
    const double dZ = (eta / 4) / ((1 - eta) * (1 - eta)) + 2 * (1 + eta * eta / 8) / std::pow(1 - eta, 3);
    return Z + eta * dZ;
  };
  const double h = 1e-3, bottom = 0.5, top = H - 0.5;
  const auto column = [&](double n0, std::vector<double>* at) {
    double n = n0, total = 0, zz = bottom;
    std::size_t k = 0;
    while (zz < top) {
      while (at && k < z.size() && z[k] <= zz + h / 2) (*at)[k++] = n;
      const auto f = [&](double m) { return -m * g / (T * pressure_slope(m)); };
      const double a = f(n), b = f(n + h / 2 * a), c = f(n + h / 2 * b), d = f(n + h * c);
      const double next = n + h / 6 * (a + 2 * b + 2 * c + d);
      total += h / 2 * (n + next);
      n = next, zz += h;
    }
    return total;
  };
  double lo = 0, hi = ideal ? 10 : 4 / std::numbers::pi;  // below close packing
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (column(mid, nullptr) < n_per_length ? lo : hi) = mid;
  }
  std::vector<double> n(z.size(), 0.0);
  column(0.5 * (lo + hi), &n);
  return n;
}

struct Equilibrium {
  double temperature;        // 2 E / d per particle, averaged over the samples
  double weight_carried;     // momentum the walls gave per particle per unit time, over the samples
  std::vector<double> density;  // particles per unit area in bins of unit height from z = 0
};

// An elastic gas of n disks over a thermal wall at T_w = 1 (elastic top wall at H), sampled every
// 5 time units from t = 2000 to 12000; checked to be at equilibrium: at T_w, the walls carrying its weight.
Equilibrium thermal_wall_equilibrium(std::size_t n, double L, double H, double g) {
  WalledStart<2> s = walled_start<2>(n, L, H, g, 1.0, 11);
  ggsim::Engine<2, WallsFx> eng(s.box, s.r, s.v, s.par);
  ggtest::Silent none;
  const double t0 = 2000, t1 = 12000, every = 5;
  eng.run(t0, ~0ull, none);
  const auto before = wall_observables(eng);
  const auto mean_vz = [&] {
    double sum = 0;
    for (const Vec<2>& v : ggtest::observed(eng, eng.now()).v) sum += v[1];
    return sum / static_cast<double>(n);
  };
  const double vz0 = mean_vz();
  Equilibrium eq{0, 0, std::vector<double>(static_cast<std::size_t>(H), 0.0)};
  double v2 = 0, samples = 0;
  Sampler sampler{t0, every, static_cast<int>((t1 - t0) / every), [&](const Vec<2>& x, const Vec<2>& v) {
                    v2 += v[0] * v[0] + v[1] * v[1];
                    eq.density[static_cast<std::size_t>(x[1])] += 1;
                  }};
  eng.run(t1, ~0ull, sampler);
  samples = (t1 - t0) / every;
  const auto after = wall_observables(eng);
  eq.temperature = v2 / (2 * samples * static_cast<double>(n));
  eq.weight_carried = (after.at("bottom_wall_momentum") + after.at("top_wall_momentum") -
                       before.at("bottom_wall_momentum") - before.at("top_wall_momentum")) /
                      (eng.now() - t0);
  for (double& c : eq.density) c /= samples * L;
  EXPECT_NEAR(eq.temperature, 1.0, 0.015);
  // Impulse balance, exact: the walls gave g per unit time plus the change of the mean vertical
  // velocity; at equilibrium that change is noise (~1e-5 g here), so the walls carry the weight.
  EXPECT_NEAR(eq.weight_carried, g + (mean_vz() - vz0) / (eng.now() - t0), 1e-9 * g);
  EXPECT_NEAR(eq.weight_carried, g, 0.003 * g);
  return eq;
}

// The profile's bins against the hydrostatic one at their centres, where the density is above
// `floor` (statistics) and from 3 diameters above the floor (a dense fluid layers against a hard
// wall, which the local-density approximation leaves out): the largest relative deviation.
double worst_deviation(const Equilibrium& eq, const std::vector<double>& theory, double floor) {
  double worst = 0;
  for (std::size_t k = 3; k + 1 < eq.density.size(); ++k)
    if (theory[k] > floor) worst = std::max(worst, std::abs(eq.density[k] / theory[k] - 1));
  return worst;
}

// The equilibrium of n disks over a thermal wall against the hydrostatic profile with Henderson's
// pressure and against the barometric one: each one's worst relative deviation in the bins where it
// exceeds `floor`.
struct Deviations {
  double henderson, barometric;
};
Deviations profile_deviations(std::size_t n, double L, double H, double g, double floor) {
  const Equilibrium eq = thermal_wall_equilibrium(n, L, H, g);
  std::vector<double> z;
  for (int k = 0; k < static_cast<int>(H); ++k) z.push_back(k + 0.5);
  return {worst_deviation(eq, hydrostatic_profile(n / L, H, g, 1, false, z), floor),
          worst_deviation(eq, hydrostatic_profile(n / L, H, g, 1, true, z), floor)};
}

TEST(Walls, ThermalWallGivesTheBarometricProfileWhenDilute) {
  EXPECT_LT(profile_deviations(150, 400, 50, 0.1, 0.01).barometric, 0.06);
}

TEST(Walls, ThermalWallGivesTheEnskogHydrostaticProfileWhenDense) {
  const Deviations d = profile_deviations(300, 60, 60, 0.1, 0.02);
  EXPECT_LT(d.henderson, 0.05);
  EXPECT_GT(d.barometric, 0.2);  // the test tells the two apart
}

}  // namespace
