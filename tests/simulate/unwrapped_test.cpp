// Unwrapped positions (position + image x L, gg-sim --unwrapped) against motion no one here
// computed: free flight across many boundaries, and the mean-square displacement of an elastic
// dilute hard-disk gas, ballistic (d T t^2) before its first collisions and diffusive (2 d D t) after
// many, with the Chapman-Enskog self-diffusion coefficient of hard disks (docs/PHYSICS.md "Hard disks
// at equilibrium").
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine_harness.hpp"

namespace {

using ggsim::Vec;
using WithImages = ggsim::Effects<ggsim::ImagesEffect>;

// Unwrapped positions at the given times, by the numbers of the start.
template <int D>
struct Unwrapped {
  std::vector<double> times;
  std::vector<std::vector<Vec<D>>> frames;
  std::size_t k = 0;
  double next_time() const { return k < times.size() ? times[k] : ggsim::kNever; }
  template <class E>
  void observe(E& eng, double t) {
    std::vector<Vec<D>> x(eng.size());
    eng.for_each_particle(t, [&](std::uint32_t i, const Vec<D>& r, const Vec<D>&) { x[i] = r; });
    eng.for_each_image(t, [&](std::uint32_t i, const ggsim::Image<D>& a) {
      for (int c = 0; c < D; ++c) x[i][c] += a[c] * eng.box().L[c];
    });
    frames.push_back(std::move(x));
    ++k;
  }
  template <class E> bool poll(const E&) { return false; }
};

// Particles on a lattice, all with one velocity, never touch: each moves as x0 + v t, here through
// ~100 box edges along every axis while the engine renumbers them every event per particle.
template <int D>
void expect_free_flight() {
  const double L = 12;
  std::array<double, D> edges;
  edges.fill(L);
  const gg::Box<D> box(edges);
  std::vector<Vec<D>> r = ggsim::lattice_positions<D>(box, D == 1 ? 4 : 16);
  const Vec<D> u = [] {
    Vec<D> w;
    for (int c = 0; c < D; ++c) w[c] = (c % 2 ? -1 : 1) * (3.1 + 0.7 * c);  // up and down the axes
    return w;
  }();
  const std::vector<Vec<D>> v(r.size(), u);
  ggsim::EngineParameters par;
  par.renumber_every = 1;
  ggsim::Engine<D, WithImages> eng(box, r, v, par);
  Unwrapped<D> obs;
  for (int k = 1; k <= 40; ++k) obs.times.push_back(10.0 * k + 0.123);
  eng.run(obs.times.back(), ~0ull, obs);
  ASSERT_EQ(eng.collisions(), 0u);
  ASSERT_EQ(obs.frames.size(), obs.times.size());
  for (std::size_t k = 0; k < obs.times.size(); ++k)
    for (std::size_t i = 0; i < r.size(); ++i)
      for (int c = 0; c < D; ++c) {
        const double want = r[i][c] + u[c] * obs.times[k];
        // Round-off of one advance per event (~1e-15 L), over a few thousand events.
        ASSERT_NEAR(obs.frames[k][i][c], want, 1e-9 * L) << D << "D particle " << i << " axis " << c << " t = " << obs.times[k];
      }
}

TEST(Unwrapped, FreeFlightIsStraightAcrossEveryBoundaryIn1D) { expect_free_flight<1>(); }
TEST(Unwrapped, FreeFlightIsStraightAcrossEveryBoundaryIn2D) { expect_free_flight<2>(); }
TEST(Unwrapped, FreeFlightIsStraightAcrossEveryBoundaryIn3D) { expect_free_flight<3>(); }

// An engine without image counts reports image 0 everywhere (and never counts).
TEST(Unwrapped, WithoutImageCountsEveryImageIsZero) {
  const gg::Box<1> box({10.0});
  ggsim::Engine<1, ggsim::Effects<>> eng(box, {{1.0}}, {{7.0}}, {});
  ggtest::Silent none;
  eng.run(100.0, ~0ull, none);
  eng.for_each_image(eng.now(), [](std::uint32_t, const ggsim::Image<1>& a) { EXPECT_EQ(a[0], 0); });
}

// Mean of |x(t0 + lag) - x(t0)|^2 over particles and over every origin t0 on the frame grid.
double msd(const std::vector<std::vector<Vec<2>>>& frames, std::size_t lag) {
  double s = 0;
  std::size_t count = 0;
  for (std::size_t k = 0; k + lag < frames.size(); ++k)
    for (std::size_t i = 0; i < frames[k].size(); ++i, ++count)
      for (int c = 0; c < 2; ++c) {
        const double d = frames[k + lag][i][c] - frames[k][i][c];
        s += d * d;
      }
  return s / static_cast<double>(count);
}

// An elastic gas of hard disks at rho = 0.05 (phi = 0.039), in equilibrium at T = 1, in a box of
// L = 280 (3920 disks): Henderson's g = (1 - 7 phi/16) / (1 - phi)^2, the Enskog collision frequency
// omega = 2 sqrt(pi) rho g sqrt(T) (docs/PHYSICS.md) and the Chapman-Enskog self-diffusion
// coefficient of hard disks D = sqrt(T / pi) / (2 rho g) (first Sonine approximation: Gass, J. Chem.
// Phys. 54, 1898 (1971)), D = T / omega: the velocity relaxes at the collision frequency, so
// MSD(t) = 2 d D [t - (1 - exp(-omega t)) / omega], d T t^2 for omega t << 1 and 2 d D t for omega t >> 1.
TEST(Unwrapped, DiluteGasDisplacementIsBallisticThenDiffusive) {
  const double rho = 0.05, L = 280, T = 1;
  const double phi = M_PI * rho / 4, g = (1 - 7 * phi / 16) / ((1 - phi) * (1 - phi));
  const double omega = 2 * std::sqrt(M_PI) * rho * g * std::sqrt(T), D = std::sqrt(T / M_PI) / (2 * rho * g);
  ASSERT_NEAR(D * omega, T, 1e-12);
  const auto s = ggtest::equilibrium<2>(L, rho, 11);
  ggsim::Engine<2, WithImages> eng(s.box, s.r, s.v, {});
  Unwrapped<2> early, late;
  // Ballistic: frames 0.002 / omega apart, from t = 0.
  for (int k = 0; k <= 10; ++k) early.times.push_back(0.002 * k / omega);
  eng.run(early.times.back(), ~0ull, early);
  // Diffusive: frames 2 / omega apart up to 600 / omega (~ 1.2e6 collisions; rms displacement ~ L).
  for (int k = 0; k <= 300; ++k) late.times.push_back(early.times.back() + 2.0 * k / omega);
  eng.run(late.times.back(), ~0ull, late);

  // Before collisions matter the displacement is v t: MSD = <v^2> t^2 = d T t^2, less a fraction of
  // order omega t (here <= 0.02) for the particles that have collided.
  for (std::size_t k = 1; k < early.frames.size(); ++k) {
    const double t = early.times[k];
    double s2 = 0;
    for (std::size_t i = 0; i < s.r.size(); ++i)
      for (int c = 0; c < 2; ++c) {
        const double d = early.frames[k][i][c] - early.frames[0][i][c];
        s2 += d * d;
      }
    const double ratio = s2 / static_cast<double>(s.r.size()) / (2 * T * t * t);
    EXPECT_NEAR(ratio, 1, omega * t) << "t = " << t;
  }
  // Long after: the slope of MSD between lags of 40 and 80 mean free times is 2 d D (the exponential
  // tail is e^-40). Higher Sonine approximations and the 2D long-time tail of the velocity
  // autocorrelation (D grows as ln t: Alder, Gass & Wainwright, J. Chem. Phys. 53, 3813 (1970)) put
  // the measured D a few per cent above this first approximation; the statistical error over 3920
  // disks and ~ 15 independent origins is about 2%.
  const double lag_time = 2.0 / omega;
  const double slope = (msd(late.frames, 80) - msd(late.frames, 40)) / (40 * lag_time);
  EXPECT_GT(slope / (4 * D), 0.97) << "D measured " << slope / 4 << ", Chapman-Enskog " << D;
  EXPECT_LT(slope / (4 * D), 1.08) << "D measured " << slope / 4 << ", Chapman-Enskog " << D;
  // And at the shortest lag, two mean free times, the crossover itself: the exponential relaxation
  // of the velocity is the same first approximation, good to a few per cent at low density.
  const double predicted = 4 * D * (lag_time - (1 - std::exp(-omega * lag_time)) / omega);
  EXPECT_NEAR(msd(late.frames, 1) / predicted, 1, 0.1) << "MSD " << msd(late.frames, 1) << ", predicted " << predicted;
}

}  // namespace
