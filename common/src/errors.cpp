// One line on stderr and the exit status of DESIGN.md: 2 for usage errors, 1 for the rest.
#include "gg/errors.hpp"

#include <algorithm>
#include <iostream>

namespace gg {
namespace {

int report(const std::string& program, std::string message, int status) {
  std::replace(message.begin(), message.end(), '\n', ' ');  // the contract is one line
  std::cerr << program << ": error: " << message << '\n';
  return status;
}

}  // namespace

int guarded_main(const std::string& program, const std::function<int()>& body) {
  try {
    return body();
  } catch (const UsageError& e) {
    return report(program, e.what(), kExitUsage);
  } catch (const std::exception& e) {
    return report(program, e.what(), kExitRuntime);
  }
}

}  // namespace gg
