#pragma once
// What the tests of the gg-fit library share: reproducible normal deviates (GSL's generator, so every
// platform draws the same samples), log-spaced times, and the check that error bars are honest over
// many noisy trials.
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace gg::fit::testing {

struct Rng {
  std::unique_ptr<gsl_rng, decltype(&gsl_rng_free)> r;
  explicit Rng(unsigned long seed) : r(gsl_rng_alloc(gsl_rng_mt19937), &gsl_rng_free) { gsl_rng_set(r.get(), seed); }
  double normal() { return gsl_ran_gaussian(r.get(), 1.0); }
};

// n times spaced evenly in log t over [a, b].
inline std::vector<double> log_times(double a, double b, int n) {
  std::vector<double> t;
  for (int i = 0; i < n; ++i) t.push_back(a * std::pow(b / a, static_cast<double>(i) / (n - 1)));
  return t;
}

struct Coverage {
  int n = 0, in1 = 0, in2 = 0;
  void add(double estimate, double stderr_, double truth) {
    ++n;
    const double pull = std::abs(estimate - truth) / stderr_;
    in1 += pull <= 1;
    in2 += pull <= 2;
  }
  double f1() const { return static_cast<double>(in1) / n; }
  double f2() const { return static_cast<double>(in2) / n; }
};

// Honest error bars: the truth lies within 2 standard errors in >= 90% of the trials (not too small)
// and within 1 standard error in 55-80% of them (not wildly large; 68% for Gaussian errors).
inline void expect_honest(const Coverage& c, const std::string& what) {
  std::printf("  %s: within 1 sigma %.1f%%, within 2 sigma %.1f%% of %d trials\n", what.c_str(), 100 * c.f1(),
              100 * c.f2(), c.n);
  EXPECT_GE(c.f2(), 0.90) << what << ": within 2 sigma in " << c.f2() * 100 << "% of " << c.n << " trials";
  EXPECT_GE(c.f1(), 0.55) << what << ": within 1 sigma in " << c.f1() * 100 << "% (error bars too wide)";
  EXPECT_LE(c.f1(), 0.80) << what << ": within 1 sigma in " << c.f1() * 100 << "% (error bars too wide)";
}

}  // namespace gg::fit::testing
