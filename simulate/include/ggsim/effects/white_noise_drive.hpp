#pragma once
// The white-noise drive (gg-sim --drive white-noise): the random-force thermostat of Williams &
// MacKintosh, Phys. Rev. E 54, R9 (1996), in the momentum-conserving form of van Noije, Ernst,
// Trizac & Pagonabarraga, Phys. Rev. E 59, 4326 (1999). At Poisson times, at total rate F N / 2,
// a random pair (i, j) of distinct particles gets opposite kicks dv_i = -dv_j = w, each component
// of w Gaussian with variance 2 XI^2 / F: every particle is kicked at rate F and gains on average
// F d 2 XI^2 / F, so d<v^2>/dt = 2 d XI^2 per particle (dT/dt = 2 XI^2, dE/dt = d XI^2), and total
// momentum is kept exactly (docs/PHYSICS.md "Driven gas").
//
// The drive is a timed effect (effect_set.hpp): it kicks a pair of particles at its own times
// between the engine's events. It owns its random numbers (split_mix.hpp), so that a run is the
// same for a scene and seed, and a checkpoint holds all of it (DriveState, saved as "drive" and "drive_random").
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <utility>

#include "gg/trajectory.hpp"
#include "ggsim/effects/effect_parameters.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/effects/hooks.hpp"
#include "ggsim/effects/registry_entry.hpp"
#include "ggsim/prediction.hpp"
#include "ggsim/split_mix.hpp"

namespace ggsim {

// What a scene asks of the drive (src/scene/drive_scene.cpp). strength 0: no drive, and an engine
// compiled with one never kicks.
struct DriveParameters {
  std::string kind{};     // "white-noise", or empty for none
  double strength = 0;    // XI: d<v^2>/dt = 2 d XI^2 per particle
  double rate = 0;        // F: kicks per particle per unit time (the scene's 0: the default, set at the start)
  std::uint64_t seed = 0; // the scene's (set at the start)
};

// Everything of the drive that changes in a run (what a checkpoint keeps).
struct DriveState {
  SplitMix64 random;         // the generator
  double next = kNever;      // time of the next kick
  double injected = 0;       // energy put in so far, summed over the particles (mass 1)
  double rate = 0;           // F of the run (a resumed run keeps the one it started with)
};

template <int D>
class WhiteNoiseDrive {
 public:
  static constexpr Hooks kHooks = hook::timed | hook::observables | hook::save;

  // The engine's drive: the saved state of a checkpoint if the start has one, else a fresh one.
  template <class Parameters>
  WhiteNoiseDrive(const Parameters& par, const EffectStart& s)
      : WhiteNoiseDrive(effect_parameters<DriveParameters>(par), s.n, s.t0) {
    if (!s.records) return;
    const std::vector<double> saved = s.records->take_real("drive", 3);
    const std::vector<std::int64_t> random = s.records->take_integer("drive_random", 1);
    if (saved.empty() != random.empty()) throw gg::RuntimeError("the drive's saved state is incomplete; the checkpoint is damaged");
    if (!saved.empty())
      *this = WhiteNoiseDrive(effect_parameters<DriveParameters>(par), s.n, DriveState{{std::bit_cast<std::uint64_t>(random[0])}, saved[0], saved[1], saved[2]});
  }
  // A fresh run at time t0; the stream differs from the start's (ggsim::Random) for the same seed.
  WhiteNoiseDrive(const DriveParameters& p, std::size_t n, double t0)
      : WhiteNoiseDrive(p, n, DriveState{{p.seed ^ kStream}, kNever, 0, p.rate}) {
    if (p.strength > 0) state_.next = t0 + wait();
  }
  // Continues from a saved state (its rate, not p's).
  WhiteNoiseDrive(const DriveParameters& p, std::size_t n, const DriveState& s)
      : n_(n), pair_rate_(0.5 * s.rate * static_cast<double>(n)),
        kick_sd_(s.rate > 0 ? std::sqrt(2 / s.rate) * p.strength : 0), state_(s) {}

  double next_time() const { return state_.next; }
  const DriveState& state() const { return state_; }
  // The energy put in per particle so far (mass 1), with which the energy balance closes.
  void observables(const ObservableSink& out) const {
    if (kick_sd_ > 0) out("injected_energy", gg::kUnitEnergy, state_.injected / static_cast<double>(n_));
  }
  void save(const EffectSink& out) const {
    out.real("drive", {state_.next, state_.injected, state_.rate});
    out.integer("drive_random", {std::bit_cast<std::int64_t>(state_.random.state)});
  }

  // The pair kicked next: two distinct particles of the n, uniformly.
  std::pair<std::uint32_t, std::uint32_t> pair() {
    const auto i = below(n_);
    auto j = below(n_ - 1);
    j += j >= i;
    return {i, j};
  }
  // Kicks the pair: va += w, vb -= w; then draws the time of the next kick.
  void kick(Vec<D>& va, Vec<D>& vb) {
    Vec<D> w;
    for (int k = 0; k < D; k += 2) {
      // Box-Muller, two normals a time (the second dropped for the last component of odd D).
      const double rad = kick_sd_ * std::sqrt(-2 * std::log(1 - uniform()));
      const double ang = 2 * std::numbers::pi * uniform();
      w[k] = rad * std::cos(ang);
      if (k + 1 < D) w[k + 1] = rad * std::sin(ang);
    }
    double gain = 0;  // (|va + w|^2 - |va|^2 + |vb - w|^2 - |vb|^2) / 2
    for (int k = 0; k < D; ++k) {
      gain += w[k] * (va[k] - vb[k] + w[k]);
      va[k] += w[k];
      vb[k] -= w[k];
    }
    state_.injected += gain;
    state_.next += wait();
  }

 private:
  static constexpr std::uint64_t kStream = 0x6a09e667f3bcc909ull;  // fractional bits of sqrt(2)
  double uniform() { return state_.random.uniform(); }
  std::uint32_t below(std::size_t m) { return state_.random.below(m); }
  double wait() { return -std::log(1 - uniform()) / pair_rate_; }  // exponential, mean 2 / (F N)

  std::size_t n_ = 0;
  double pair_rate_ = 0, kick_sd_ = 0;
  DriveState state_;
};

// The default kick rate F: kRatePerCollision kicks per particle per collision at the temperature
// where the energy put in balances the collisional loss (docs/PHYSICS.md "Driven gas"),
// 2 XI^2 = (1 - e^2) omega(T) T / d with the Enskog collision frequency
// omega(T) = 2 pi^((d-1)/2) / Gamma(d/2) rho g(sigma) sqrt(T) (unit diameter and mass), or at T0
// if the gas is elastic (e = 1, no steady state). A kick then changes a velocity component by a
// fraction sqrt((1 - e^2) / (d kRatePerCollision)) of the thermal speed at most (e = 0: 0.16 in 2D):
// small steps of a diffusion in velocity, as white noise is, for 2 kRatePerCollision kicks of a
// pair per collision (the cost of a run grows by about that factor).
inline constexpr double kRatePerCollision = 20;
// omega(T) / sqrt(T) of the Enskog theory at number density rho (unit diameter and mass).
inline double enskog_frequency_at_unit_temperature(int d, double rho) {
  double eta = rho, g = 1 / (1 - eta);  // hard rods: exact
  if (d == 2) eta = std::numbers::pi * rho / 4, g = (1 - 7 * eta / 16) / ((1 - eta) * (1 - eta));  // Henderson
  if (d == 3) eta = std::numbers::pi * rho / 6, g = (1 - eta / 2) / std::pow(1 - eta, 3);         // Carnahan-Starling
  return 2 * std::pow(std::numbers::pi, 0.5 * (d - 1)) / std::tgamma(0.5 * d) * rho * g;
}
inline double default_drive_rate(int d, double rho, double e, double strength, double T0) {
  const double omega1 = enskog_frequency_at_unit_temperature(d, rho);
  const double T = e < 1 ? std::pow(2 * d * strength * strength / ((1 - e * e) * omega1), 2.0 / 3) : T0;
  return kRatePerCollision * omega1 * std::sqrt(T);
}

// Its entry in the registry (effects/registry.hpp, registry_entry.hpp).
struct DrivenEffect {
  static constexpr std::string_view kName = "driven";
  template <int D>
  using Unit = WhiteNoiseDrive<D>;
  static const SceneEffect& scene();  // src/scene/drive_scene.cpp
};

}  // namespace ggsim
