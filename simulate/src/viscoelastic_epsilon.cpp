// epsilon(kappa) of the dissipative Hertz law (effects/viscoelastic_restitution.hpp): in units of
// its own scales the compression x obeys
//   x'' = -x^(3/2) - kappa x^(1/2) x',   x(0) = 0, x'(0) = 1,
// and epsilon = -x' when x returns to 0. Near x = 0 the right side is not smooth in time (x^(1/2)),
// which would cost a time-stepping integrator its order, but it is in w = sqrt(x): with v = x',
//   dv/dw = -2 w^4 / v - 2 kappa w^2,
// smooth wherever v != 0. So the compression is integrated in w up to a speed of kSwitch, the
// turning point (v = 0) in time, and the recovery in w again, down to w = 0 (classical RK4 in each).
#include <cmath>
#include <vector>

#include "ggsim/effects/viscoelastic_restitution.hpp"

namespace ggsim {

namespace {

constexpr double kStep = 2e-3;   // RK4 step in w and in time: error ~1e-11 in epsilon
constexpr double kSwitch = 0.3;  // |v| below which the turning point is integrated in time

double dv_dw(double w, double v, double kappa) { return -2 * w * w * w * w / v - 2 * kappa * w * w; }

// v carried in w from w0 to w1 (either direction) in steps of at most kStep.
double carry_in_w(double w0, double w1, double v, double kappa) {
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(w1 - w0) / kStep)));
  const double h = (w1 - w0) / n;
  for (int k = 0; k < n; ++k) {
    const double w = w0 + k * h;
    const double a = dv_dw(w, v, kappa), b = dv_dw(w + h / 2, v + h / 2 * a, kappa);
    const double c = dv_dw(w + h / 2, v + h / 2 * b, kappa), d = dv_dw(w + h, v + h * c, kappa);
    v += h / 6 * (a + 2 * b + 2 * c + d);
  }
  return v;
}

// A point of the collision: w = sqrt(x) and v = x'.
struct Point {
  double w, v;
};

// The compression in w, a step of kStep at a time, up to the last w where v is still above kSwitch
// (where exactly does not matter: any point with v well away from 0 hands over to the time steps).
Point compress(double kappa) {
  double w = 0, v = 1;
  for (;;) {
    const double v1 = carry_in_w(w, w + kStep, v, kappa);
    if (!(v1 > kSwitch)) return {w, v};  // v stays above kSwitch up to w
    w += kStep, v = v1;
  }
}

// x, v carried in time from the compression's end through the turning point until x has fallen
// back to a quarter of its maximum (v then well below 0).
Point turn(Point p, double kappa) {
  double x = p.w * p.w, v = p.v, x_max = x;
  const auto acc = [kappa](double x_, double v_) {
    const double s = std::sqrt(std::max(x_, 0.0));
    return -x_ * s - kappa * s * v_;
  };
  while (!(v < 0 && x < x_max / 4)) {
    const double h = kStep;
    const double ax = v, av = acc(x, v);
    const double bx = v + h / 2 * av, bv = acc(x + h / 2 * ax, v + h / 2 * av);
    const double cx = v + h / 2 * bv, cv = acc(x + h / 2 * bx, v + h / 2 * bv);
    const double dx = v + h * cv, dv = acc(x + h * cx, v + h * cv);
    x += h / 6 * (ax + 2 * bx + 2 * cx + dx);
    v += h / 6 * (av + 2 * bv + 2 * cv + dv);
    x_max = std::max(x_max, x);
  }
  return {std::sqrt(x), v};
}

double integrate(double kappa) {
  const Point p = turn(compress(kappa), kappa);
  return -carry_in_w(p.w, 0, p.v, kappa);
}

// The table: epsilon at kappa = k kKappaMax / kIntervals, read by four-point (cubic) Lagrange
// interpolation (error ~1e-10); beyond kKappaMax (epsilon < 0.005, impacts far faster than the
// law's speed scale) the law is integrated for each collision.
constexpr double kKappaMax = 4;
constexpr int kIntervals = 1024;

std::vector<double> make_table() {
  std::vector<double> t(kIntervals + 3);
  for (int k = 1; k < kIntervals + 3; ++k) t[k] = integrate(k * kKappaMax / kIntervals);
  t[0] = 1;  // no damping: the elastic Hertz collision, exactly (its integration rounds to 1 - 1e-12)
  return t;
}

}  // namespace

double viscoelastic_epsilon(double kappa) {
  static const std::vector<double> table = make_table();
  const double u = kappa * (kIntervals / kKappaMax);
  if (!(u < kIntervals)) return integrate(kappa);
  // Nodes k-1..k+2 around u (k >= 1, so the first interval uses nodes 0..3).
  const int k = std::max(1, static_cast<int>(u));
  const double s = u - k;
  const double* f = &table[k - 1];
  return f[0] * (-s * (s - 1) * (s - 2) / 6) + f[1] * ((s + 1) * (s - 1) * (s - 2) / 2) +
         f[2] * (-(s + 1) * s * (s - 2) / 2) + f[3] * ((s + 1) * s * (s - 1) / 6);
}

}  // namespace ggsim
