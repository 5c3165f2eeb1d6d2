// One line on stderr and the exit status of docs/DESIGN.md: 2 for usage errors, 1 for the rest.
#include "gg/errors.hpp"

#include <algorithm>
#include <iostream>
#include <new>

#include "gg/standard_streams.hpp"

namespace gg {
namespace {

int report(const std::string& program, std::string message, int status) {
  std::replace(message.begin(), message.end(), '\n', ' ');  // the contract is one line
  std::cerr << program << ": error: " << message << '\n';
  return status;
}

}  // namespace

int guarded_main(const std::string& program, const std::function<int()>& body, const std::string& memory_hint) {
  guard_standard_streams();
  try {
    return body();
  } catch (const UsageError& e) {
    return report(program, e.what(), kExitUsage);
  } catch (const std::bad_alloc&) {
    // Its what() is just "std::bad_alloc". The unwinding has freed the memory, and removed the
    // temporary output (H5Output's destructor).
    return report(program, "out of memory; reduce " + memory_hint + " (or run where more memory is available)",
                  kExitRuntime);
  } catch (const std::exception& e) {
    return report(program, e.what(), kExitRuntime);
  }
}

}  // namespace gg
