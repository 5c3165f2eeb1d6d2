// gg-velocity: the velocity distribution (temperature per component, Sonine a2 and a3, f(c) and its
// tail) and the coarse-grained flow field (energy fraction, velocity correlations, vorticity).
// Thin main: velocity_main of analyze/structure/structure_tools (CLI11 -> VelocityConfig -> run_velocity).
#include "structure_tools.hpp"

int main(int argc, char** argv) {
  return gg::velocity_main(argc, argv,
                           "gg-velocity: velocity distribution (a2, a3, f(c) and its tail) and coarse-grained flow "
                           "field (energy fraction, longitudinal and transverse correlations, vorticity) of the "
                           "snapshots of a gg-sim --velocities run (docs/DESIGN.md \"Velocities\")");
}
