// gg-sim --aggregate (the ballistic aggregation model) against its published scaling, from what the
// runs write (/observables/mean_mass = N0 / N(t), /observables/kinetic_energy per unit mass), each
// exponent fitted per run with the project's power-law fit (gg::fit::fit_power_law, what gg-fit
// power-law does) and averaged over an ensemble (mean and standard error over the runs):
//  - 1D: m ~ t^(2/3) exactly (Frachebourg, PRL 82, 1502 (1999); the paper's eq. 3). Rods whose
//    lengths add keep every gap between them, so the run is point particles at the density of
//    the free space, N0 / (L - N0) = 1 at rho = 0.5: one unit of time per collision at the start.
//    The local exponent comes up from below (over the decades [10, 1e3]: 0.62, [1e2, 1e4]: 0.65,
//    [1e3, 1e5]: 0.668 in one run of 2e5 rods), so the fit takes [1e3, 1e5], where 200 or more
//    particles are left; the tolerance is 0.03.
//  - 2D: the hyperscaling relation 2 zeta + d theta = 2d of Trizac & Hansen (PRL 74, 4114 (1995);
//    the paper's eq. 5, found valid in simulations up to d = 3 by Paul & Das, the paper's ref.
//    paul2), i.e. zeta + theta = 2, with m ~ t^zeta and E ~ t^-theta; and zeta below the mean-field
//    2d/(d+2) = 1 of Carnevale, Pomeau & Young (PRL 64, 2913 (1990)), as the simulations the paper
//    cites (paul3, trizac1, trizac2) found at low packing fraction. At rho = 0.1 (packing 0.079) over
//    [1e2, 1e4] the runs give zeta ~ 0.885 and theta ~ 1.08; the sum drifts up with the window
//    ([30, 3e3]: 1.94, [1e2, 1e4]: 1.97), so the relation is asked within 0.05 (that drift) plus
//    three standard errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "fit/power_law.hpp"
#include "gg/h5file.hpp"
#include "gg/trajectory.hpp"
#include "ggsim/config.hpp"
#include "ggsim/run.hpp"
#include "test_support.hpp"

namespace {

struct Exponents {
  double mean = 0, stderr_ = 0;
};

Exponents over_runs(const std::vector<double>& z) {
  double m = 0, v = 0;
  for (double x : z) m += x;
  m /= static_cast<double>(z.size());
  for (double x : z) v += (x - m) * (x - m);
  v /= static_cast<double>(z.size() - 1);
  return {m, std::sqrt(v / static_cast<double>(z.size()))};
}

double exponent(const gg::TimeSeries& ts, double t1, double t2) {
  gg::fit::Series s;
  s.t = ts.time, s.y = ts.value;
  return gg::fit::fit_power_law(s, {t1, t2}).exponent;
}

// Runs seeds 1..runs of an aggregating scene and fits m(t) and E(t) of each over [t1, t2].
void run_ensemble(int dim, double L, double rho, double t_max, int runs, double t1, double t2, std::vector<double>* zeta,
                  std::vector<double>* theta) {
  gg::test::TempDir dir;
  for (int seed = 1; seed <= runs; ++seed) {
    ggsim::SimConfig c;
    c.dim = dim, c.L = L, c.rho = rho, c.aggregate = true, c.t_max = t_max, c.samples_per_decade = 10;
    c.seed = static_cast<std::uint64_t>(seed);
    c.output = dir.file("run" + std::to_string(seed) + ".h5");
    c.resolve(false, true, true);
    ASSERT_EQ(ggsim::run(c, {"gg-sim"}, false), 0);
    gg::H5Input in(c.output);
    zeta->push_back(exponent(gg::read_observable(in, "mean_mass"), t1, t2));
    theta->push_back(-exponent(gg::read_observable(in, "kinetic_energy"), t1, t2));
  }
}

TEST(AggregationExponents, MassGrowsAsTwoThirdsPowerIn1D) {
  std::vector<double> zeta, theta;
  run_ensemble(1, 4e5, 0.5, 1e5, 6, 1e3, 1e5, &zeta, &theta);
  const Exponents z = over_runs(zeta);
  EXPECT_NEAR(z.mean, 2.0 / 3, 0.03) << "zeta = " << z.mean << " +- " << z.stderr_;
  // m ~ 1/E in 1D (the paper's eq. 3): the energy exponent is the same.
  const Exponents th = over_runs(theta);
  std::printf("1D: zeta = %.4f +- %.4f, theta = %.4f +- %.4f\n", z.mean, z.stderr_, th.mean, th.stderr_);
  EXPECT_NEAR(th.mean, 2.0 / 3, 0.05) << "theta = " << th.mean << " +- " << th.stderr_;
}

TEST(AggregationExponents, HyperscalingHoldsAndMassGrowsSlowerThanMeanFieldIn2D) {
  std::vector<double> zeta, theta, sum;
  run_ensemble(2, 1024, 0.1, 1e4, 8, 1e2, 1e4, &zeta, &theta);
  for (std::size_t k = 0; k < zeta.size(); ++k) sum.push_back(zeta[k] + theta[k]);
  const Exponents z = over_runs(zeta), s = over_runs(sum), th = over_runs(theta);
  std::printf("2D: zeta = %.4f +- %.4f, theta = %.4f +- %.4f, zeta + theta = %.4f +- %.4f\n", z.mean, z.stderr_,
              th.mean, th.stderr_, s.mean, s.stderr_);
  EXPECT_NEAR(s.mean, 2.0, 0.05 + 3 * s.stderr_) << "zeta + theta = " << s.mean << " +- " << s.stderr_;
  EXPECT_LT(z.mean + 3 * z.stderr_, 1.0) << "zeta = " << z.mean << " +- " << z.stderr_;
  EXPECT_GT(z.mean, 0.75) << "zeta = " << z.mean << " +- " << z.stderr_;
}

}  // namespace
