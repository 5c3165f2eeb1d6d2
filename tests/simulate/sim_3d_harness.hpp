#pragma once
// Runs a gg-sim scene in 3D through the library call ggsim::run() (what the executable does after
// parsing its flags) and reads what it wrote.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "gg/h5file.hpp"
#include "gg/trajectory.hpp"
#include "ggsim/config.hpp"
#include "ggsim/run.hpp"
#include "test_support.hpp"

namespace ggtest {

// Number density of spheres at packing fraction eta (eta = pi rho / 6, unit diameter).
inline double sphere_density(double eta) { return 6 * eta / std::numbers::pi; }

// A 3D scene of n spheres at packing fraction eta writing `output` (the rest at SimConfig's defaults).
inline ggsim::SimConfig scene_3d(std::uint64_t n, double eta, double e, const std::string& output) {
  ggsim::SimConfig c;
  c.dim = 3;
  c.N = n;
  c.rho = sphere_density(eta);
  c.e = e;
  c.output = output;
  return c;
}

// resolve() (N and rho given) and run(); returns the exit status.
inline int simulate(ggsim::SimConfig c) {
  c.resolve(true, false, true);
  return ggsim::run(c, {"gg-sim"}, false);
}

}  // namespace ggtest
