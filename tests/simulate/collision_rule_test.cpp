// The collision rule (collision_rule.hpp, with the effects of effects/) on one pair at contact:
// restitution e, and the two ways of making a collision elastic, each exactly below its threshold:
// the velocity cutoff (|n.v_ij| < delta, Ben-Naim et al.) and the TC model (a partner collided less
// than t_c before, Luding & McNamara 1998). A collision at the threshold itself is inelastic.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "ggsim/collision_rule.hpp"
#include "ggsim/engine.hpp"

namespace {

using ggsim::Particle;

// Particle a at the origin, b one diameter to its right (n, from b to a, is -x), closing at
// normal speed `closing` and sliding past at tangential speed 0.3 (which no rule may change).
struct Pair {
  Particle<2> a{}, b{};
  explicit Pair(double closing) {
    a.r = {0.0, 0.0}, b.r = {1.0, 0.0};
    a.v = {0.5 * closing, 0.3}, b.v = {-0.5 * closing, 0.0};
  }
  ggsim::Vec<2> separation() const { return {a.r[0] - b.r[0], a.r[1] - b.r[1]}; }
  double closing_after() const { return a.v[0] - b.v[0]; }  // > 0: approaching
};

constexpr double kE = 0.5;

// The collision of two particles (numbers 0 and 1) with the effects Fx, for the restitution e, the
// cutoff delta and the TC model's t_c.
template <class Fx>
struct Rule {
  double e;
  typename Fx::template Set<2> effects;
  Rule(double e, double delta, double tc) : e(e), effects(parameters(e, delta, tc), ggsim::EffectStart{.n = 2}) {}
  double apply(Pair& pair, double t) { return ggsim::collide<2>(pair.a, pair.b, 0, 1, pair.separation(), t, e, effects); }
  std::vector<double>& last_collision() { return effects.template get<ggsim::TcModel>().last_collision(); }
  static ggsim::EngineParameters parameters(double e, double delta, double tc) {
    ggsim::EngineParameters par;
    par.rule.e = e;
    par.rule.effects.set<ggsim::CutoffParameters>().delta = delta;
    par.rule.effects.set<ggsim::TcParameters>().tc = tc;
    par.rule.effects.set<ggsim::PressureParameters>().on = true;
    return par;
  }
};

// The normal relative velocity after the collision, for a pair that closed at `closing`:
// -closing if elastic, -e closing if not (the tangential velocities stay as they were).
template <class Fx>
double after(Rule<Fx>& rule, double closing, double t = 1.0) {
  Pair p(closing);
  rule.apply(p, t);
  EXPECT_EQ(p.a.v[1], 0.3);
  EXPECT_EQ(p.b.v[1], 0.0);
  EXPECT_EQ(p.a.collisions, 1u);
  EXPECT_EQ(p.b.collisions, 1u);
  EXPECT_NEAR(p.a.v[0] + p.b.v[0], 0.0, 1e-16);  // momentum
  return p.closing_after();
}

}  // namespace

TEST(CollisionRule, RestitutionScalesTheNormalRelativeVelocityByMinusE) {
  Rule<ggsim::Effects<>> rule(kE, 0.7, 0.0);  // a delta the rule without the cutoff must ignore
  EXPECT_DOUBLE_EQ(after(rule, 1.0), -kE);
  EXPECT_DOUBLE_EQ(after(rule, 0.01), -kE * 0.01);
}

TEST(CollisionRule, VelocityCutoffMakesExactlyTheSlowerCollisionsElastic) {
  const double delta = 0.25;
  Rule<ggsim::Effects<ggsim::CutoffEffect>> rule(kE, delta, 0.0);
  const double below = std::nextafter(delta, 0.0), above = std::nextafter(delta, 1.0);
  EXPECT_DOUBLE_EQ(after(rule, 0.1), -0.1);               // well below: elastic
  EXPECT_DOUBLE_EQ(after(rule, below), -below);           // one ulp below: still elastic
  EXPECT_DOUBLE_EQ(after(rule, delta), -kE * delta);      // at the threshold: inelastic
  EXPECT_DOUBLE_EQ(after(rule, above), -kE * above);
  EXPECT_DOUBLE_EQ(after(rule, 2.0), -kE * 2.0);
}

TEST(CollisionRule, TcModelMakesExactlyTheCollisionsWithinTcOfAPartnersLastElastic) {
  const double tc = 0.25, t = 1.0;  // t - tc = 0.75 exactly
  const auto with_last = [&](double last_a, double last_b) {
    Rule<ggsim::Effects<ggsim::TcEffect>> rule(kE, 0.0, tc);
    rule.last_collision() = {last_a, last_b};
    const double v = after(rule, 1.0, t);
    EXPECT_EQ(rule.last_collision()[0], t);  // both remember this collision, elastic or not
    EXPECT_EQ(rule.last_collision()[1], t);
    return v;
  };
  const double never = -std::numeric_limits<double>::infinity();
  EXPECT_DOUBLE_EQ(with_last(never, never), -kE);                    // first collision of both
  EXPECT_DOUBLE_EQ(with_last(0.5, never), -kE);                      // 0.5 ago: beyond t_c
  EXPECT_DOUBLE_EQ(with_last(0.75, never), -kE);                     // exactly t_c ago: inelastic
  EXPECT_DOUBLE_EQ(with_last(std::nextafter(0.75, 1.0), never), -1.0);  // just within t_c: elastic
  EXPECT_DOUBLE_EQ(with_last(never, 0.9), -1.0);                     // the partner's counts too
  EXPECT_DOUBLE_EQ(with_last(0.9, 0.9), -1.0);
}

TEST(CollisionRule, BothEffectsTogetherEachSufficeForAnElasticCollision) {
  Rule<ggsim::Effects<ggsim::CutoffEffect, ggsim::TcEffect>> rule(kE, 0.25, 0.25);
  rule.last_collision() = {-1.0, -1.0};
  EXPECT_DOUBLE_EQ(after(rule, 0.1, 1.0), -0.1);        // slow, no recent collision: the cutoff
  EXPECT_DOUBLE_EQ(after(rule, 2.0, 1.1), -2.0);        // fast, but both collided 0.1 ago: t_c
  EXPECT_DOUBLE_EQ(after(rule, 2.0, 2.0), -kE * 2.0);   // fast and long after: inelastic
}

TEST(CollisionRule, VirialIsTheContactVectorDotTheImpulse) {
  Rule<ggsim::Effects<ggsim::VirialEffect>> rule(kE, 0.0, 0.0);
  Pair p(1.0);
  // r_ab = (-1, 0) = n and n.v_ab = -1, so a's impulse is -(1+e)/2 (n.v_ab) n = (-0.75, 0) and
  // r_ab . Delta p_a = +0.75: positive, as for every repulsive contact.
  EXPECT_DOUBLE_EQ(rule.apply(p, 1.0), 0.75);
  // What the pressure sees: with no kinetic part (E = 0), P = 0.75 / (d V dt) = 0.75 / (2 * 3 * 0.5).
  double pressure = 0;
  rule.effects.observables(ggsim::ObservableSink([&](const std::string&, const std::string&, const std::vector<double>& P) { pressure = P.at(0); }),
                           {.t = 0.5, .kinetic_energy = 0, .n = 2, .volume = 3, .dim = 2});
  EXPECT_DOUBLE_EQ(pressure, 0.25);
}
