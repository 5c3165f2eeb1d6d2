#pragma once
// CLI conventions shared by every tool: --version (version + git hash), --progress/--quiet,
// CLI11 parse errors turned into one line on stderr and exit status 2.
#include <CLI/CLI.hpp>
#include <string>
#include <type_traits>
#include <vector>

#include "gg/common_flags.hpp"

namespace gg {

// Adds --version and --progress/--quiet to `app`; sets the footer and the config-file error policy.
void add_common_flags(CLI::App& app, CommonFlags& flags);

// Parses argv with CLI11. Returns -1 to continue, or the exit status to return now
// (0 after --help/--version, 2 after a parse error, already reported in one line).
int parse_cli(CLI::App& app, int argc, char** argv);

// For options that count (particles, collisions, a seed): a whole number may also be written as
// a physicist writes it, 4e6 or 1.5e6; it is rewritten to its digits before CLI11 converts it.
// A count that is not whole (2.5, 1e-3) or not below 2^63 is refused with what to write instead.
CLI::Validator whole_number();

// For real-valued options: a finite number (CLI11 takes "nan" and "inf" for numbers, and its Range and
// PositiveNumber let NaN through), and one above `low` (at least `low` unless `strictly`).
CLI::Validator finite_number();
CLI::Validator number_at_least(double low, bool strictly);

// The items of a comma-separated list option ("0.1,1,10", or one list per occurrence). An empty item
// ("0.1,,1", a trailing comma) is a usage error naming the option, not skipped: CLI11's own delimiter drops
// it silently, which hides a typo in a list of snapshot times or frames.
std::vector<std::string> list_items(const std::string& option, const std::vector<std::string>& texts);

// Adds a list option (see list_items) whose items convert to T; an item that does not is a usage error.
template <class T>
CLI::Option* add_list_option(CLI::App& app, const std::string& name, std::vector<T>& values,
                             const std::string& description) {
  return app.add_option_function<std::vector<std::string>>(
      name,
      [&values, name](const std::vector<std::string>& texts) {
        values.clear();
        for (const std::string& item : list_items(name, texts)) {
          T value{};
          if (!CLI::detail::lexical_cast(item, value))
            throw CLI::ValidationError(name, "'" + item + "' is not " +
                                                 (std::is_integral_v<T> ? "a whole number" : "a number"));
          values.push_back(value);
        }
      },
      description);
}

// argv as strings, for provenance.
std::vector<std::string> argv_strings(int argc, char** argv);

}  // namespace gg
