// Elastic hard disks against theory nobody here wrote:
//  - equation of state Z = P/(rho T) from the virial series of Clisby & McCoy, J. Stat. Phys.
//    122, 15 (2006): Z(phi = 0.2906) = 2.0076;
//  - Enskog collision frequency omega = 2 sqrt(pi) rho g sqrt(T) with g = 1.7336 (Henderson
//    with Luding's correction / virial series): 2.2739 at rho = 0.37, T = 1.
#include <gtest/gtest.h>

#include <numbers>
#include <utility>

#include "engine_harness.hpp"

namespace {

using Elastic = ggsim::Effects<ggsim::VirialEffect>;

TEST(HardDiskEquilibrium, PressureAndCollisionFrequencyMatchTheory) {
  const double rho = 0.37, L = std::sqrt(4096 / rho);
  auto s = ggtest::random_start<2>(L, rho, 7);
  ggsim::EngineParameters par;
  ggsim::Engine<2, Elastic> warm(s.box, s.r, s.v, par);
  ggtest::Silent none;
  warm.run(ggsim::kNever, 20 * s.r.size(), none);  // 40 collisions per particle: equilibrated
  auto o = ggtest::observed(warm, warm.now());
  s.r = std::move(o.r), s.v = std::move(o.v);
  ggsim::set_temperature<2>(s.v, 1.0);

  ggsim::Engine<2, Elastic> eng(s.box, s.r, s.v, par);
  eng.run(ggsim::kNever, 400 * s.r.size(), none);  // 800 collisions per particle
  const double n = static_cast<double>(s.r.size()), t = eng.now();
  // With zero total momentum the temperature has d (N - 1) degrees of freedom.
  const double T = 2 * eng.kinetic_energy() * n / (2 * (n - 1));
  const double P = (n / s.box.volume()) * 2 * eng.kinetic_energy() / 2 + eng.effects().template get<ggsim::PressureVirial>().virial() / (2 * s.box.volume() * t);
  const double Z = P / (rho * T);
  RecordProperty("Z", std::to_string(Z));
  EXPECT_NEAR(Z, 2.0076, 0.01 * 2.0076);
  const double omega = 2.0 * static_cast<double>(eng.collisions()) / n / t;
  const double omega_enskog = 2 * std::sqrt(std::numbers::pi) * rho * 1.7336 * std::sqrt(T);
  RecordProperty("omega", std::to_string(omega));
  EXPECT_NEAR(omega, omega_enskog, 0.01 * omega_enskog);
  EXPECT_NEAR(omega_enskog, 2.2739, 1e-3);
  EXPECT_GE(ggtest::min_distance(eng, eng.now()), 1 - ggsim::kOverlapTolerance);
}

TEST(HardDiskEquilibrium, ElasticEnergyAndMomentumAreConservedOverAMillionCollisions) {
  auto s = ggtest::random_start<2>(std::sqrt(2000 / 0.37), 0.37, 3);
  ggsim::Engine<2, ggsim::Effects<>> eng(s.box, s.r, s.v, {});
  const double E0 = eng.kinetic_energy();
  ggtest::Silent none;
  eng.run(ggsim::kNever, 1000000, none);
  ASSERT_EQ(eng.collisions(), 1000000u);
  ggtest::expect_elastic_invariants(eng, E0, 1e-10);
}

}  // namespace
