#pragma once
// Shared helpers of the engine tests: building a state, observers that record or check.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "ggsim/engine.hpp"
#include "ggsim/initial_state.hpp"

namespace ggtest {

using ggsim::Vec;

template <int D>
struct Start {
  gg::Box<D> box;
  std::vector<Vec<D>> r, v;
};

// Random homogeneous start at density rho in a cubic box of edge L, T = T0.
template <int D>
Start<D> random_start(double L, double rho, std::uint64_t seed, double T0 = 1) {
  Start<D> s;
  std::array<double, D> edges;
  edges.fill(L);
  s.box = gg::Box<D>(edges);
  ggsim::Random rng(seed);
  const auto n = static_cast<std::size_t>(std::llround(rho * std::pow(L, D)));
  s.r = ggsim::random_positions<D>(s.box, n, rng);
  s.v = ggsim::maxwellian_velocities<D>(n, T0, rng);
  return s;
}

// Observer that records nothing.
struct Silent {
  double next_time() const { return ggsim::kNever; }
  template <class E> void observe(E&, double) {}
  template <class E> bool poll(const E&) { return false; }
};

// Observer that samples the kinetic energy at given times.
struct EnergyAt {
  std::vector<double> times, energy;
  std::size_t k = 0;
  double next_time() const { return k < times.size() ? times[k] : ggsim::kNever; }
  template <class E> void observe(E& eng, double) { energy.push_back(eng.kinetic_energy()), ++k; }
  template <class E> bool poll(const E&) { return false; }
};

// The engine's state as a checkpoint keeps it (checkpoint.cpp writes the same arrays from view()),
// for an engine that continues from it.
template <int D, class Fx>
ggsim::EngineState<D> saved_state(const ggsim::Engine<D, Fx>& eng) {
  const ggsim::EngineView<D> view = eng.view();
  ggsim::EngineState<D> st;
  st.particles.assign(view.particles.begin(), view.particles.end());
  for (std::uint32_t i = 0; i < view.particles.size(); ++i) {
    st.id.push_back(view.grid.label(i));
    st.centres.push_back(view.grid.centre(i));
    st.event_time.push_back(view.calendar.time(i));
  }
  st.cell_head = view.grid.heads(), st.cell_next = view.grid.links();
  st.now = view.now;
  st.collisions = view.collisions, st.events = view.events, st.shell_exits = view.shell_exits;
  st.stale_events = view.stale_events, st.renumber_at = view.renumber_at;
  view.save_effects({[&](const std::string& name, const std::vector<double>& a) { st.effects.real[name] = a; },
                     [&](const std::string& name, const std::vector<std::int64_t>& a) { st.effects.integer[name] = a; }});
  return st;
}

// Positions at time t (wrapped into the box) and velocities, by the numbers of the start.
template <int D>
struct Observed {
  std::vector<Vec<D>> r, v;
};

template <int D, class Fx>
Observed<D> observed(const ggsim::Engine<D, Fx>& eng, double t) {
  Observed<D> o{std::vector<Vec<D>>(eng.size()), std::vector<Vec<D>>(eng.size())};
  eng.for_each_particle(t, [&](std::uint32_t i, const Vec<D>& r, const Vec<D>& v) { o.r[i] = r, o.v[i] = v; });
  return o;
}

// The plain engine and one with the effects Fx, from the random start of seed 7 at e = 0.5 (an
// inelastic gas, clusters forming), `par` the same for both (what the plain engine does not read
// is for Fx), run 20 collisions per particle: the same clock, collisions, positions and velocities.
// `given_sizes`: Fx's particles are given radius 1/2 and mass 1 each (as a mixture's start gives them).
template <int D, class Fx>
void expect_plain_trajectory(double L, double rho, ggsim::EngineParameters par, bool given_sizes = false) {
  const auto s = random_start<D>(L, rho, 7);
  par.rule.e = 0.5;
  ggsim::EffectRecords sizes;
  const std::size_t n = s.r.size();
  if (given_sizes) ggsim::ParticleSizes::add_start({.radius = std::vector(n, 0.5), .mass = std::vector(n, 1.0)}, sizes);
  ggsim::Engine<D, ggsim::Effects<>> a(s.box, s.r, s.v, par);
  ggsim::Engine<D, Fx> b(s.box, s.r, s.v, par, std::move(sizes));
  Silent none;
  const auto budget = static_cast<std::uint64_t>(20 * s.r.size());
  a.run(ggsim::kNever, budget, none);
  b.run(ggsim::kNever, budget, none);
  EXPECT_EQ(a.kinetic_energy(), b.kinetic_energy());
  ASSERT_EQ(a.collisions(), b.collisions());
  ASSERT_EQ(a.now(), b.now());
  const auto x = observed(a, a.now()), y = observed(b, b.now());
  for (std::size_t i = 0; i < x.r.size(); ++i)
    for (int k = 0; k < D; ++k) {
      ASSERT_EQ(x.r[i][k], y.r[i][k]) << "particle " << i;
      ASSERT_EQ(x.v[i][k], y.v[i][k]) << "particle " << i;
    }
}

// Smallest pair distance at time t (pairs closer than 1.5 found through unit cells; 1.5 if none).
template <int D, class Fx>
double min_distance(const ggsim::Engine<D, Fx>& eng, double t) {
  const std::vector<Vec<D>> x = observed(eng, t).r;
  ggsim::CellGrid<D> cells(eng.box(), 1.5, x.size());
  double best2 = 1.5 * 1.5;
  for (std::size_t i = 0; i < x.size(); ++i) {
    cells.for_each_near(cells.encode(x[i]), [&](std::uint32_t j, const auto&) {
      double d2 = 0;
      for (int k = 0; k < D; ++k) {
        const double d = eng.box().min_image(x[i][k] - x[j][k], k);
        d2 += d * d;
      }
      best2 = std::min(best2, d2);
    });
    cells.insert(static_cast<std::uint32_t>(i), x[i]);
  }
  return std::sqrt(best2);
}

template <int D, class Fx>
std::vector<double> total_momentum(const ggsim::Engine<D, Fx>& eng, double* abs_sum) {
  std::vector<double> p(D, 0.0);
  *abs_sum = 0;
  for (const Vec<D>& v : observed(eng, eng.now()).v)
    for (int k = 0; k < D; ++k) p[k] += v[k], *abs_sum += std::abs(v[k]);
  return p;
}

// Elastic equilibrium at density rho in a cubic box of edge L: a random start after 20
// collisions per particle, rescaled to T = 1.
template <int D>
Start<D> equilibrium(double L, double rho, std::uint64_t seed) {
  auto s = random_start<D>(L, rho, seed);
  ggsim::Engine<D, ggsim::Effects<>> warm(s.box, s.r, s.v, {});
  Silent none;
  warm.run(ggsim::kNever, 10 * s.r.size(), none);
  auto o = observed(warm, warm.now());
  s.r = std::move(o.r), s.v = std::move(o.v);
  ggsim::set_temperature<D>(s.v, 1.0);
  return s;
}

// What an elastic run must keep: the energy E0 (to `energy_tolerance`, relative), zero total
// momentum (to 1e-12 of the sum of |p|), and no pair closer than sigma (beyond ggsim::kOverlapTolerance).
template <int D, class Fx>
void expect_elastic_invariants(const ggsim::Engine<D, Fx>& eng, double E0, double energy_tolerance) {
  EXPECT_NEAR(eng.kinetic_energy() / E0 - 1, 0, energy_tolerance);
  double abs_sum = 0;
  for (double p : total_momentum(eng, &abs_sum)) EXPECT_LT(std::abs(p), 1e-12 * abs_sum);
  EXPECT_GE(min_distance(eng, eng.now()), 1 - ggsim::kOverlapTolerance);
}

}  // namespace ggtest
