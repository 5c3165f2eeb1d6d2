#pragma once
// Hard flat walls across the last axis (gg-sim --walls; docs/PHYSICS.md "Walls and gravity"), a
// boundary (boundary.hpp): the planes z = 0 (bottom) and z = H (top), which a particle's centre
// meets at z = sigma/2 and H - sigma/2. A wall reverses the normal velocity, scaled by the wall's
// restitution (--wall-e), or, if the bottom wall is thermal (--wall-T), sends the particle off with
// a velocity drawn from the flux of a Maxwellian at the wall's temperature: normal component with
// density v exp(-v^2 / 2 T_w) / T_w, tangential ones Gaussian of variance T_w (the thermal wall of
// Cercignani; Lebowitz & Spohn). A vibrated bottom wall (--wall-amplitude A, --wall-frequency f)
// moves with velocity V(t) = A w cos(w t), w = 2 pi f, in the zero-amplitude model of a vibrated bed
// (its position stays 0; Kumaran, J. Fluid Mech. 364, 163 (1998); McNamara & Luding, PRE 58, 813
// (1998)): a particle meeting it leaves with V - e_w (v_z - V), or with e_w |v_z| when the wall
// recedes faster than the particle falls (it could not have met a wall that moves). The other axes
// stay periodic.
//
// A particle's meeting with a wall is one of its events, predicted with its collisions (as
// DynamO's walls are "local" events of one particle): its pending event names the particle itself
// as the partner (edge_event(), is_edge_event()). The box is one diameter longer than H along the
// last axis (the scene's start, walls_scene.cpp): a pair then never touches through that axis's
// periodic image before one of the two has met its wall, so every other answer is the periodic
// box's and the periodic cell grid needs no change.
//
// Observables: the energy the walls have put into the gas per particle (negative when they take
// it) and the momentum along the last axis each wall has given the gas per particle; in a steady
// state under gravity g, the two momenta together grow at g per unit time (the walls carry the
// weight). A checkpoint keeps them with the thermal wall's random numbers.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "gg/box.hpp"
#include "gg/errors.hpp"
#include "gg/trajectory.hpp"
#include "ggsim/boundary/periodic.hpp"
#include "ggsim/effects/effect_state.hpp"
#include "ggsim/particles.hpp"
#include "ggsim/prediction.hpp"
#include "ggsim/split_mix.hpp"

namespace ggsim {

// What a scene asks of the walls and of gravity (the walls' motion law, effects/walls.hpp, reads
// the gravity); height 0: no walls.
struct WallParameters {
  double height = 0;        // H
  double restitution = 1;   // normal restitution of both walls (of the top one if the bottom is thermal)
  double temperature = 0;   // > 0: the bottom wall is thermal at this temperature
  double gravity = 0;       // g: a constant acceleration -g along the last axis
  double amplitude = 0;     // A of a vibrated bottom wall (0: at rest)
  double frequency = 0;     // f of its vibration
  std::uint64_t seed = 0;
};

template <int D>
class WalledBoundary : public PeriodicBoundary<D> {
 public:
  // `par`: the engine's parameters, whose effects' store (effects/effect_parameters.hpp) holds the
  // walls'; `start`: the number of particles, and a checkpoint's arrays, from which the walls take theirs.
  template <class Parameters>
  WalledBoundary(const gg::Box<D>& box, const Parameters& par, const EffectStart& start)
      : PeriodicBoundary<D>(box),
        p_(par.rule.effects.template get<WallParameters>()),
        n_(static_cast<double>(start.n)),
        random_{p_.seed ^ kStream} {
    if (!start.records) return;
    const std::vector<double> saved = start.records->take_real("walls", 3);
    const std::vector<std::int64_t> random = start.records->take_integer("walls_random", 1);
    if (saved.empty() != random.empty()) throw gg::RuntimeError("the walls' saved state is incomplete; the checkpoint is damaged");
    if (saved.empty()) return;
    energy_ = saved[0], bottom_momentum_ = saved[1], top_momentum_ = saved[2];
    random_.state = std::bit_cast<std::uint64_t>(random[0]);
  }

  // --- what the engine asks (boundary.hpp); the rest is the periodic box's ---

  // Particle i's meeting with a wall (q at now): partner i itself.
  PendingEvent edge_event(const Particle<D>& q, std::uint32_t i, double now) const {
    return {now + time_to_wall(q), i, q.collisions};
  }
  static bool is_edge_event(const PendingEvent& ev, std::uint32_t i) { return ev.partner == i; }

  // Particle q (at the wall now) meets it.
  void meet_edge(Particle<D>& q) {
    Vec<D>& v = q.v;
    const double before = dot<D>(v, v), vz = v[D - 1];
    const bool bottom = q.r[D - 1] < 0.5 * p_.height;
    if (bottom && p_.temperature > 0) {
      const double sd = std::sqrt(p_.temperature);
      v[D - 1] = sd * std::sqrt(-2 * std::log(1 - random_.uniform()));
      for (int k = 0; k + 1 < D; k += 2) {  // Box-Muller, two tangential components a time
        const double rad = sd * std::sqrt(-2 * std::log(1 - random_.uniform()));
        const double ang = 2 * std::numbers::pi * random_.uniform();
        v[k] = rad * std::cos(ang);
        if (k + 1 < D - 1) v[k + 1] = rad * std::sin(ang);
      }
    } else if (bottom && p_.amplitude > 0) {
      const double w = 2 * std::numbers::pi * p_.frequency, V = p_.amplitude * w * std::cos(w * q.t);
      v[D - 1] = vz < V ? V - p_.restitution * (vz - V) : p_.restitution * std::abs(vz);
    } else {
      v[D - 1] = (bottom ? 1 : -1) * p_.restitution * std::abs(vz);
    }
    energy_ += 0.5 * (dot<D>(v, v) - before);
    (bottom ? bottom_momentum_ : top_momentum_) += v[D - 1] - vz;
  }

  void observables(const ObservableSink& out) const {
    out("wall_energy", gg::kUnitEnergy, energy_ / n_);
    out("bottom_wall_momentum", kUnitMomentum, bottom_momentum_ / n_);
    out("top_wall_momentum", kUnitMomentum, top_momentum_ / n_);
  }
  void save(const EffectSink& out) const {
    out.real("walls", {energy_, bottom_momentum_, top_momentum_});
    out.integer("walls_random", {std::bit_cast<std::int64_t>(random_.state)});
  }

 private:
  // How long after its record particle q (its position and velocity at that time) meets a wall
  // along its parabola (a line without gravity); kNever if it never does. A centre a rounding
  // beyond its wall and moving out meets it at once.
  double time_to_wall(const Particle<D>& q) const {
    const double z = q.r[D - 1], vz = q.v[D - 1], g = p_.gravity;
    const double below = std::max(z - kRadius, 0.0), above = std::max(p_.height - kRadius - z, 0.0);
    double bottom = kNever, top = kNever;
    if (g == 0) {
      if (vz < 0) bottom = below / -vz;
      if (vz > 0) top = above / vz;
      return std::min(bottom, top);
    }
    // Roots of z + vz t - g t^2 / 2 = sigma/2 (always one ahead) and = H - sigma/2 (if the
    // parabola rises that high), each written without cancellation.
    const double s = std::sqrt(vz * vz + 2 * g * below);
    bottom = vz > 0 ? (vz + s) / g : (s - vz > 0 ? 2 * below / (s - vz) : 0.0);
    const double rise = vz * vz - 2 * g * above;
    if (vz > 0 && rise >= 0) top = 2 * above / (vz + std::sqrt(rise));
    return std::min(bottom, top);
  }

  static constexpr double kRadius = 0.5;  // sigma / 2: where a centre meets a wall
  static constexpr std::uint64_t kStream = 0xbb67ae8584caa73bull;  // fractional bits of sqrt(3)
  inline static const std::string kUnitMomentum = "m sigma tau-1";

  WallParameters p_;
  double n_;
  SplitMix64 random_;
  double energy_ = 0, bottom_momentum_ = 0, top_momentum_ = 0;
};

}  // namespace ggsim
