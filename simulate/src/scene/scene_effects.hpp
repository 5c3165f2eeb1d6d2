#pragma once
// What the scene parts of the effects (src/scene/*.cpp) share: the checks and number texts of the
// scene code (config.cpp uses the same).
#include <string>

#include "ggsim/scene_effect.hpp"

namespace ggsim {

// Throws gg::UsageError(message) unless ok.
void require(bool ok, const std::string& message);
// The shortest text that reads back as x (1.5, not 1.500000; 1e-07, not 0.000000).
std::string str(double x);
// A fingerprint's number as it was written.
double number(const std::string& s);

}  // namespace ggsim
