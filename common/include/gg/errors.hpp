#pragma once
// Error reporting shared by every tool (docs/DESIGN.md "Conventions of every tool"):
// one clear line on stderr, exit status 2 for usage errors, 1 for runtime errors.
#include <functional>
#include <stdexcept>
#include <string>

namespace gg {

// Bad command line or scene value: exit status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Problem found while running (missing file, not HDF5, wrong shape, NaN, ...): exit status 1.
struct RuntimeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr int kExitUsage = 2;
inline constexpr int kExitRuntime = 1;

// Runs `body`, turning UsageError / RuntimeError / std::exception into one line
// "<program>: error: <message>" on stderr and the matching exit status. Running out of memory
// (std::bad_alloc) reads "out of memory; reduce <memory_hint> ...", exit status 1.
int guarded_main(const std::string& program, const std::function<int()>& body,
                 const std::string& memory_hint = "the sizes asked for");

}  // namespace gg
