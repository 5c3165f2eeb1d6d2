// Lees-Edwards uniform shear flow (boundary/sheared.hpp's ShearedBoundary, effects/shear_stress.hpp): the
// engine against a reference written without cells, shells or a calendar, and the conservation laws
// of the sheared frame (docs/PHYSICS.md "Uniform shear flow"):
//  - trajectories: the engine and the reference, from one start under a strong shear, agree to
//    round-off after several collisions per particle (2D and 3D; in a box whose search across the
//    sliding edge looks at the whole row across it, and in a wider one where it looks at part), and
//    so do the unwrapped positions of an engine that counts images;
//  - no pair ever overlaps, under a shear fast enough that the images slide by a box length in a few
//    collision times, over hundreds of collisions per particle (2D and 3D);
//  - the peculiar momentum sum_i (v_i - a (y_i - L/2) x^) is conserved: it changes at -a sum_i v_y,i,
//    which is 0 for a start without net momentum, and a particle crossing the sliding edge keeps it;
//  - the pressure tensor the shear effect reports heats the gas as the energy balance of uniform
//    shear flow says, and its trace over d is the equation of state's pressure;
//  - a granular gas settles at Grad's steady shear flow (a*, the normal stress difference, P_xy).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "engine_harness.hpp"
#include "shear_flow_theory.hpp"

namespace {

using ggsim::Vec;
using ShearFx = ggsim::Effects<ggsim::ShearEffect>;

// A measured value as a test property, to 4 significant digits.
std::string text(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", x);
  return b;
}

template <int D>
ggsim::EngineParameters sheared(double rate, double e, double skin = 0.7) {
  ggsim::EngineParameters par;
  par.skin = skin;
  par.rule.e = e;
  par.rule.effects.set<ggsim::ShearParameters>().rate = rate;
  return par;
}

// A random start of n particles in the cube of edge L with the mean flow u_x = a (y - L/2) added.
template <int D>
ggtest::Start<D> sheared_start(double L, std::size_t n, double a, std::uint64_t seed) {
  ggtest::Start<D> s;
  std::array<double, D> edges;
  edges.fill(L);
  s.box = gg::Box<D>(edges);
  ggsim::Random rng(seed);
  s.r = ggsim::random_positions<D>(s.box, n, rng);
  s.v = ggsim::maxwellian_velocities<D>(n, 1.0, rng);
  for (std::size_t i = 0; i < n; ++i) s.v[i][0] += a * (s.r[i][1] - 0.5 * L);
  return s;
}

// The sliding brick of Lees & Edwards written out for the reference and the checks: the image
// (nx, ny[, nz]) of a particle at (x, y, z) is at (x + nx L + ny s, y + ny L, z + nz L) with
// s = a L t mod L, and moves a L ny faster along x.
template <int D>
struct Brick {
  double L, a;
  double shift(double t) const { return std::fmod(a * L * t, L); }
  // a - image(n) of b at time t.
  Vec<D> apart(const Vec<D>& p, const Vec<D>& q, const std::array<int, D>& n, double t) const {
    Vec<D> d;
    for (int k = 0; k < D; ++k) d[k] = p[k] - q[k] - n[k] * L;
    d[0] -= n[1] * shift(t);
    return d;
  }
  // Every image offset with components in {-1, 0, 1}.
  static std::vector<std::array<int, D>> neighbours() {
    std::vector<std::array<int, D>> all;
    for (int c = 0; c < (D == 2 ? 9 : 27); ++c) {
      std::array<int, D> n;
      for (int k = 0, rest = c; k < D; ++k, rest /= 3) n[k] = rest % 3 - 1;
      all.push_back(n);
    }
    return all;
  }
  // Into the box: across y with the shift and the velocity jump, then x (and z) periodically.
  void fold(Vec<D>& r, Vec<D>& v, double t) const {
    while (r[1] >= L) r[1] -= L, r[0] -= shift(t), v[0] -= a * L;
    while (r[1] < 0) r[1] += L, r[0] += shift(t), v[0] += a * L;
    for (int k = 0; k < D; ++k)
      if (k != 1) r[k] -= L * std::floor(r[k] / L);
  }
  // Smallest distance between two particles at time t over the images around.
  double distance(const Vec<D>& p, const Vec<D>& q, double t) const {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& n : neighbours()) {
      const Vec<D> d = apart(p, q, n, t);
      double s = 0;
      for (int k = 0; k < D; ++k) s += d[k] * d[k];
      best = std::min(best, s);
    }
    return std::sqrt(best);
  }
};

// The reference: every pair at every image around, the earliest contact taken, all particles moved
// to it and folded, the pair collided with the velocity of the image that touches. Beside the
// folded positions it moves each particle in the unbounded sheared space (ru, vu: never folded, vu
// changed by the collisions only), where the images are not bookkept but the particles' own paths.
template <int D>
struct Reference {
  Brick<D> brick;
  double e, t = 0;
  std::vector<Vec<D>> r, v, ru = r, vu = v;

  // Earliest t > 0 with |d + w t| = 1 while approaching.
  static double contact(const Vec<D>& d, const Vec<D>& w) {
    double b = 0, c = -1, a = 0;
    for (int k = 0; k < D; ++k) b += d[k] * w[k], c += d[k] * d[k], a += w[k] * w[k];
    if (b >= 0 || b * b - a * c < 0) return std::numeric_limits<double>::infinity();
    return (-b - std::sqrt(b * b - a * c)) / a;
  }

  void run_to(double t_end) {
    for (;;) {
      double best = std::numeric_limits<double>::infinity();
      std::size_t bi = 0, bj = 0;
      for (std::size_t i = 0; i < r.size(); ++i)
        for (std::size_t j = i + 1; j < r.size(); ++j)
          for (const auto& n : Brick<D>::neighbours()) {
            Vec<D> w = v[i];
            for (int k = 0; k < D; ++k) w[k] -= v[j][k];
            w[0] -= n[1] * brick.a * brick.L;
            const double tc = contact(brick.apart(r[i], r[j], n, t), w);
            if (tc < best) best = tc, bi = i, bj = j;
          }
      const double dt = std::min(best, t_end - t);
      t += dt;
      for (std::size_t i = 0; i < r.size(); ++i) {
        for (int k = 0; k < D; ++k) r[i][k] += v[i][k] * dt, ru[i][k] += vu[i][k] * dt;
        brick.fold(r[i], v[i], t);
      }
      if (t >= t_end) return;
      collide(bi, bj);
    }
  }

  void collide(std::size_t i, std::size_t j) {
    std::array<int, D> touching{};
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& n : Brick<D>::neighbours()) {
      const Vec<D> d = brick.apart(r[i], r[j], n, t);
      double s = 0;
      for (int k = 0; k < D; ++k) s += d[k] * d[k];
      if (s < nearest) nearest = s, touching = n;
    }
    const Vec<D> d = brick.apart(r[i], r[j], touching, t);
    Vec<D> w = v[i];
    for (int k = 0; k < D; ++k) w[k] -= v[j][k];
    w[0] -= touching[1] * brick.a * brick.L;
    double vn = 0;
    for (int k = 0; k < D; ++k) vn += d[k] * w[k];
    vn /= std::sqrt(nearest);
    for (int k = 0; k < D; ++k) {
      const double dv = 0.5 * (1 + e) * vn * d[k] / std::sqrt(nearest);
      v[i][k] -= dv, vu[i][k] -= dv;
      v[j][k] += dv, vu[j][k] += dv;
    }
  }
};

template <int D, class Fx = ShearFx>
void expect_reference_trajectory(double L, std::size_t n, double a, double t_end, int seed) {
  const double e = 0.8;
  const auto s = sheared_start<D>(L, n, a, seed);
  ggsim::Engine<D, Fx> eng(s.box, s.r, s.v, sheared<D>(a, e));
  ggtest::Silent none;
  eng.run(t_end, std::numeric_limits<std::uint64_t>::max(), none);
  Reference<D> ref{Brick<D>{L, a}, e, 0, s.r, s.v};
  ref.run_to(t_end);
  const auto got = ggtest::observed(eng, t_end);
  double worst_r = 0, worst_v = 0;
  for (std::size_t i = 0; i < n; ++i) {
    worst_r = std::max(worst_r, ref.brick.distance(got.r[i], ref.r[i], t_end));
    // Velocities less the mean flow: the same whichever side of the sliding edge a particle is on.
    for (int k = 0; k < D; ++k) {
      const double flow_got = k == 0 ? a * (got.r[i][1] - 0.5 * L) : 0, flow_ref = k == 0 ? a * (ref.r[i][1] - 0.5 * L) : 0;
      worst_v = std::max(worst_v, std::abs((got.v[i][k] - flow_got) - (ref.v[i][k] - flow_ref)));
    }
  }
  ::testing::Test::RecordProperty("collisions", text(eng.collisions()));
  ::testing::Test::RecordProperty("worst_position", text(worst_r));
  ::testing::Test::RecordProperty("worst_velocity", text(worst_v));
  EXPECT_LT(worst_r, 1e-7);
  EXPECT_LT(worst_v, 1e-7);
  if constexpr (ggsim::Engine<D, Fx>::Effects::kCountsFolds) {
    // The unwrapped positions: the engine's folded ones moved by their image counts (boundary/sheared.hpp's
    // unwrapped()) against the reference's own unfolded paths.
    double worst_u = 0, crossed = 0;
    eng.for_each_image(t_end, [&](std::uint32_t i, const ggsim::Image<D>& image) {
      const Vec<D> u = eng.box().unwrapped(got.r[i], image, t_end);
      for (int k = 0; k < D; ++k) worst_u = std::max(worst_u, std::abs(u[k] - ref.ru[i][k]));
      crossed += std::abs(image[1]);
    });
    ::testing::Test::RecordProperty("worst_unwrapped", text(worst_u));
    EXPECT_LT(worst_u, 1e-7);
    EXPECT_GE(crossed, 5);  // particles have crossed the sliding edge (net)
  }
}

// Over 5 time units the images slide by 4 box lengths and each particle collides 4-5 times; the two
// part by 1e-14 at first and by a factor ~10 per time unit after (the gas is chaotic), 5e-9 at the
// end; a missed or false collision would part them by O(1).
TEST(Shear, EngineFollowsTheReference2D) { expect_reference_trajectory<2>(12, 50, 0.8, 5, 3); }
// A wider box, 12 cells along x: a search at the sliding edge looks at part of the row across it.
TEST(Shear, EngineFollowsTheReferenceInAWiderBox) { expect_reference_trajectory<2>(24, 200, 0.8, 3.5, 5); }
TEST(Shear, EngineFollowsTheReference3D) { expect_reference_trajectory<3>(7, 60, 0.8, 5, 4); }
// With image counts (gg-sim --unwrapped): the same, and the unwrapped positions too.
using ShearImagesFx = ggsim::Effects<ggsim::ShearEffect, ggsim::ImagesEffect>;
TEST(Shear, UnwrappedPositionsFollowTheReference2D) { expect_reference_trajectory<2, ShearImagesFx>(12, 50, 0.8, 5, 3); }
TEST(Shear, UnwrappedPositionsFollowTheReference3D) { expect_reference_trajectory<3, ShearImagesFx>(7, 60, 0.8, 5, 4); }

// Observer: at `count` times `every` apart, the smallest pair distance over the images around and
// the peculiar momentum.
template <int D>
struct Watch {
  Brick<D> brick;
  double next, every;
  int left;
  double closest = std::numeric_limits<double>::infinity(), worst_momentum = 0;
  double next_time() const { return left > 0 ? next : ggsim::kNever; }
  template <class E>
  void observe(E& eng, double t) {
    const auto o = ggtest::observed(eng, t);
    for (std::size_t i = 0; i < o.r.size(); ++i)
      for (std::size_t j = i + 1; j < o.r.size(); ++j) closest = std::min(closest, brick.distance(o.r[i], o.r[j], t));
    Vec<D> p{}, scale{};
    for (std::size_t i = 0; i < o.r.size(); ++i)
      for (int k = 0; k < D; ++k) {
        const double V = o.v[i][k] - (k == 0 ? brick.a * (o.r[i][1] - 0.5 * brick.L) : 0);
        p[k] += V, scale[k] += std::abs(V);
      }
    for (int k = 0; k < D; ++k) worst_momentum = std::max(worst_momentum, std::abs(p[k]) / scale[k]);
    next += every, --left;
  }
  template <class E>
  bool poll(const E&) { return false; }
};

template <int D>
void expect_no_overlap_and_momentum_kept(double L, std::size_t n, double a, double e, double t_end) {
  auto s = sheared_start<D>(L, n, a, 11);
  ggsim::Engine<D, ShearFx> eng(s.box, s.r, s.v, sheared<D>(a, e));
  Watch<D> watch{Brick<D>{L, a}, t_end / 40, t_end / 40, 40};
  eng.run(t_end, std::numeric_limits<std::uint64_t>::max(), watch);
  ::testing::Test::RecordProperty("collisions_per_particle", text(eng.collisions() / n));
  ::testing::Test::RecordProperty("closest", text(watch.closest));
  ::testing::Test::RecordProperty("worst_momentum", text(watch.worst_momentum));
  EXPECT_GT(eng.collisions(), 100 * n);
  EXPECT_GT(watch.closest, 1 - 1e-9);
  EXPECT_LT(watch.worst_momentum, 1e-11);
}

// The images slide by a box length in L / (a L) = 1 time unit, about two collision times.
TEST(Shear, NoOverlapAndPeculiarMomentumKept2D) { expect_no_overlap_and_momentum_kept<2>(24, 300, 1.0, 0.9, 60); }
TEST(Shear, NoOverlapAndPeculiarMomentumKept3D) { expect_no_overlap_and_momentum_kept<3>(10, 300, 1.0, 0.9, 40); }

// Observer: the temperature (of the velocities less the mean flow) and the kinetic pressure tensor
// over n, at `left` times `every` apart from `next`; and the particles and the sum of v_x in each of
// kSlabs slabs along y of a box of edge L.
constexpr int kSlabs = 8;
template <int D>
struct Moments {
  double next, every;
  int left;
  double L = 0;
  std::vector<double> t{}, T{};
  std::vector<std::vector<double>> kinetic{};  // sum m c_a c_b / N, row-major
  std::array<double, kSlabs> count{}, flow{};
  double next_time() const { return left > 0 ? next : ggsim::kNever; }
  template <class E>
  void observe(E& eng, double now) {
    std::vector<double> k = eng.velocity_tensor(now);
    for (double& x : k) x /= static_cast<double>(eng.size());
    t.push_back(now);
    T.push_back(2 * eng.kinetic_energy(now) / D);
    kinetic.push_back(std::move(k));
    eng.for_each_particle(now, [&](std::uint32_t, const Vec<D>& r, const Vec<D>& v) {
      const auto slab = std::min(kSlabs - 1, static_cast<int>(r[1] / L * kSlabs));
      count[slab] += 1, flow[slab] += v[0];
    });
    next += every, --left;
  }
  template <class E>
  bool poll(const E&) { return false; }
};

// The ratio of the viscosity an elastic gas's heating gives to Enskog's: sheared at a* = a / nu0 =
// 0.1 from T = 1, n particles at packing fraction phi over 10 / a (T doubles), sqrt(T(t)) fitted by a
// line after the first tenth (P_xy builds up over a few collision times), whose slope is
// eta1 a^2 / (d n) (shear_theory::sheared_elastic_temperature).
template <int D>
double heating_viscosity_ratio(double phi, std::size_t n, std::uint64_t seed) {
  const double rho = phi / shear_theory::packing_fraction(D, 1.0);
  const double L = std::pow(static_cast<double>(n) / rho, 1.0 / D);
  const double a = 0.1 * shear_theory::nu0(D, rho, 1.0);
  const auto s = sheared_start<D>(L, n, a, seed);
  ggsim::Engine<D, ShearFx> eng(s.box, s.r, s.v, sheared<D>(a, 1.0));
  const double t_end = 10 / a;
  Moments<D> m{.next = t_end / 100, .every = t_end / 100, .left = 100, .L = L};
  eng.run(t_end, std::numeric_limits<std::uint64_t>::max(), m);
  double sx = 0, sy = 0, sxx = 0, sxy = 0, c = 0;
  for (std::size_t k = 10; k < m.t.size(); ++k) {
    const double y = std::sqrt(m.T[k]);
    sx += m.t[k], sy += y, sxx += m.t[k] * m.t[k], sxy += m.t[k] * y, ++c;
  }
  const double slope = (c * sxy - sx * sy) / (c * sxx - sx * sx);
  return slope * D * rho / (a * a) / shear_theory::enskog_viscosity(D, rho, 1.0);
}

// Six runs per dimension at packing fraction 0.1; one run scatters by 3-5% (its temperature
// fluctuates). Measured 1.021 (2D) and 1.046 (3D): Enskog's first Sonine approximation is ~1.6% low for
// dilute spheres (docs/PHYSICS.md "Uniform shear flow"), and molecular dynamics finds a few per cent
// more at this density. Held to 7%.
template <int D>
void expect_enskog_heating() {
  double sum = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) sum += heating_viscosity_ratio<D>(0.1, 2000, seed);
  ::testing::Test::RecordProperty("viscosity_over_enskog", text(sum / 6));
  EXPECT_NEAR(sum / 6, 1, 0.07);
}
TEST(ShearPhysics, ElasticGasHeatsAtTheEnskogViscosity2D) { expect_enskog_heating<2>(); }
TEST(ShearPhysics, ElasticGasHeatsAtTheEnskogViscosity3D) { expect_enskog_heating<3>(); }

// Observer: the pressure tensor the shear effect reports (its observables, as gg-sim records them:
// the kinetic part at the sample, the collisional transfer since the one before) and the kinetic
// energy per particle of the velocities less the mean flow, at `left` times `every` apart.
template <int D>
struct StressSamples {
  double next, every;
  int left;
  double volume;
  std::vector<double> t{}, energy{};
  std::map<std::string, std::vector<double>> P{};
  double next_time() const { return left > 0 ? next : ggsim::kNever; }
  template <class E>
  void observe(E& eng, double now) {
    const ggsim::Sample at{.t = now, .kinetic_energy = eng.kinetic_energy(now), .n = static_cast<double>(eng.size()),
                           .volume = volume, .dim = D, .velocity_tensor = [&eng, now] { return eng.velocity_tensor(now); }};
    eng.observables(ggsim::ObservableSink([&](const std::string& name, const std::string&, const std::vector<double>& x) {
                      P[name].push_back(x.at(0));
                    }), at);
    t.push_back(now);
    energy.push_back(at.kinetic_energy);
    next += every, --left;
  }
  template <class E>
  bool poll(const E&) { return false; }
};

// The pressure tensor of an elastic gas sheared at a* = 0.1 (packing fraction 0.1, N = 2000, over 10 / a,
// 400 samples), against two laws its code does not contain:
//  - the energy balance of uniform shear flow, d(N E)/dt = -a V P_xy (the only source of heat, the
//    collisions being elastic): the energy gained over the run against -a V sum P_xy dt, whose
//    collisional part is exact and whose kinetic part is sampled once per interval (a quarter of a
//    collision time). Measured 1.004 (2D), 1.001 (3D); held to 2%.
//  - its trace over d, P = n T Z(phi) near equilibrium (the normal stress differences are of order
//    a*^2): Z = 1 + 2^(d-1) phi chi(phi), the equation of state of Henderson (disks) and Carnahan &
//    Starling (spheres). Measured 0.9994 (2D), 1.002 (3D); held to 1%, where the collisional part
//    is a fifth of P (2D) and a third (3D).
template <int D>
void expect_stress_balance() {
  const double phi = 0.1;
  const std::size_t n = 2000;
  const double rho = phi / shear_theory::packing_fraction(D, 1.0);
  const double L = std::pow(static_cast<double>(n) / rho, 1.0 / D), V = std::pow(L, D);
  const double a = 0.1 * shear_theory::nu0(D, rho, 1.0), t_end = 10 / a;
  const auto s = sheared_start<D>(L, n, a, 5);
  ggsim::Engine<D, ShearFx> eng(s.box, s.r, s.v, sheared<D>(a, 1.0));
  StressSamples<D> m{.next = t_end / 400, .every = t_end / 400, .left = 400, .volume = V};
  eng.run(t_end, std::numeric_limits<std::uint64_t>::max(), m);
  ASSERT_EQ(m.P["pressure_xy"].size(), m.t.size());
  double heat = 0, trace_over_eos = 0;
  const double Z = 1 + std::pow(2.0, D - 1) * phi * shear_theory::contact_value(D, phi);
  for (std::size_t k = 1; k < m.t.size(); ++k) {
    heat += -a * V * m.P["pressure_xy"][k] * (m.t[k] - m.t[k - 1]);
    double trace = m.P["pressure_xx"][k] + m.P["pressure_yy"][k];
    if constexpr (D == 3) trace += m.P["pressure_zz"][k];
    trace_over_eos += trace / D / (rho * 2 * m.energy[k] / D * Z) / static_cast<double>(m.t.size() - 1);
  }
  const double gained = static_cast<double>(n) * (m.energy.back() - m.energy.front());
  ::testing::Test::RecordProperty("heat_over_energy_gained", text(heat / gained));
  ::testing::Test::RecordProperty("trace_over_equation_of_state", text(trace_over_eos));
  EXPECT_NEAR(heat / gained, 1, 0.02);
  EXPECT_NEAR(trace_over_eos, 1, 0.01);
}
TEST(ShearPhysics, StressHeatsTheGasAndItsTraceIsTheEquationOfState2D) { expect_stress_balance<2>(); }
TEST(ShearPhysics, StressHeatsTheGasAndItsTraceIsTheEquationOfState3D) { expect_stress_balance<3>(); }

// What a steady sheared granular gas measures, reduced as the kinetic theory is: a* = a / (chi nu0(T))
// (chi: the collision rate at the run's density), P*_ab = kinetic P_ab / (n T); and its profiles along
// y over 8 slabs: the mean flow u_x and the density.
struct SteadyState {
  double a, P_xx, P_yy, P_zz, P_xy;
  double worst_flow;     // largest |u_x - a (y - L/2)| of a slab, over a L / 2
  double worst_density;  // largest |n_slab / n - 1|
};

// n particles at packing fraction phi (dilute: Boltzmann's theory), restitution alpha, sheared at the
// rate of the theory's steady state at T = 1 from T = 1: 20 / a to settle, then 400 samples over 100 / a.
// The box is a few mean free paths across (the flow is unstable in larger ones).
template <int D>
SteadyState steady_shear(double phi, std::size_t n, double alpha) {
  const double rho = phi / shear_theory::packing_fraction(D, 1.0);
  const double L = std::pow(static_cast<double>(n) / rho, 1.0 / D);
  const double chi = shear_theory::contact_value(D, phi);
  const double a = shear_theory::grad_steady_shear(D, alpha).a * shear_theory::nu0(D, rho, 1.0) * chi;
  const auto s = sheared_start<D>(L, n, a, 23);
  // A dilute gas: a skin of several diameters, so that a particle leaves its shell a few times
  // between collisions rather than dozens.
  ggsim::Engine<D, ShearFx> eng(s.box, s.r, s.v, sheared<D>(a, alpha, 4));
  const double t_relax = 20 / a, t_end = 120 / a;
  Moments<D> m{.next = t_relax, .every = (t_end - t_relax) / 400, .left = 400, .L = L};
  eng.run(t_end, std::numeric_limits<std::uint64_t>::max(), m);
  double T = 0;
  std::array<double, D * D> P{};
  for (std::size_t k = 0; k < m.t.size(); ++k) {
    T += m.T[k];
    for (int e = 0; e < D * D; ++e) P[e] += m.kinetic[k][e];
  }
  T /= static_cast<double>(m.t.size());
  for (double& x : P) x /= static_cast<double>(m.t.size()) * T;
  SteadyState r{a / (chi * shear_theory::nu0(D, rho, T)), P[0], P[D + 1], D == 3 ? P[8] : 0, P[1], 0, 0};
  const double per_slab = static_cast<double>(n) * static_cast<double>(m.t.size()) / kSlabs;
  for (int k = 0; k < kSlabs; ++k) {
    const double y = (k + 0.5) * L / kSlabs;
    r.worst_flow = std::max(r.worst_flow, std::abs(m.flow[k] / m.count[k] - a * (y - 0.5 * L)) / (0.5 * a * L));
    r.worst_density = std::max(r.worst_density, std::abs(m.count[k] / per_slab - 1));
  }
  return r;
}

// Against Grad's solution (shear_theory::grad_steady_shear; docs/PHYSICS.md "Uniform shear flow"),
// which leaves out the non-Gaussian part of the distribution and makes P_yy = P_zz: measured at
// alpha = 0.9 a* and P within 1% of it (P_xy 0.45% in 3D, 1.6% in 2D), at alpha = 0.7 a* 5-6% above
// it and P_yy 3% below, as the simulations of the Boltzmann equation find Grad's a* low at strong
// dissipation. Held to 3% at 0.9; to 8% (a*) and 4% (P) at 0.7. The normal stress difference
// P_xx - P_yy, which carries what P holds beyond its trace (d), measured -1% and +4% (3D, 2D) at 0.9,
// +2.5% and +8% at 0.7: held to 7% and 12%. The flow is linear and the density flat within 3% and 5%
// per slab.
void expect_grad_steady_shear(const SteadyState& got, int d, double alpha) {
  const auto theory = shear_theory::grad_steady_shear(d, alpha);
  const double tol_a = alpha > 0.8 ? 0.03 : 0.08, tol_p = alpha > 0.8 ? 0.03 : 0.04, tol_n = alpha > 0.8 ? 0.07 : 0.12;
  const std::string at = "_alpha" + std::to_string(alpha).substr(0, 3);
  ::testing::Test::RecordProperty("a_star" + at, text(got.a));
  ::testing::Test::RecordProperty("P_xx" + at, text(got.P_xx));
  ::testing::Test::RecordProperty("P_yy" + at, text(got.P_yy));
  if (d == 3) ::testing::Test::RecordProperty("P_zz" + at, text(got.P_zz));
  ::testing::Test::RecordProperty("P_xy" + at, text(got.P_xy));
  ::testing::Test::RecordProperty("worst_flow" + at, text(got.worst_flow));
  ::testing::Test::RecordProperty("worst_density" + at, text(got.worst_density));
  EXPECT_NEAR(got.a / theory.a, 1, tol_a);
  EXPECT_NEAR(got.P_xx / theory.P_xx, 1, tol_p);
  EXPECT_NEAR(got.P_yy / theory.P_yy, 1, tol_p);
  EXPECT_NEAR(got.P_xy / theory.P_xy, 1, tol_p);
  EXPECT_NEAR((got.P_xx - got.P_yy) / (theory.P_xx - theory.P_yy), 1, tol_n);
  EXPECT_LT(got.worst_flow, 0.03);
  EXPECT_LT(got.worst_density, 0.05);
}
TEST(ShearPhysics, SteadyGranularShearFlow3D) {
  expect_grad_steady_shear(steady_shear<3>(0.005, 2000, 0.9), 3, 0.9);
  expect_grad_steady_shear(steady_shear<3>(0.005, 2000, 0.7), 3, 0.7);
}
TEST(ShearPhysics, SteadyGranularShearFlow2D) {
  expect_grad_steady_shear(steady_shear<2>(0.005, 1000, 0.9), 2, 0.9);
  expect_grad_steady_shear(steady_shear<2>(0.005, 1000, 0.7), 2, 0.7);
}

}  // namespace
