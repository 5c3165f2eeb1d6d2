// CLI11 wrapped into the conventions of every tool (docs/DESIGN.md): --version, --progress/--quiet,
// parse errors as one line and exit status 2 (with "did you mean" for a near miss), scene files
// whose unknown keys are errors and whose keys may use _ for -.
#include "gg/cli.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <iostream>
#include <memory>

#include <unistd.h>

#include "did_you_mean.hpp"
#include "gg/errors.hpp"
#include "gg/fmt.hpp"
#include "gg/version.hpp"

namespace gg {
namespace {

// CLI11 takes the name from argv[0] when none was given; show "gg-sim", not "./build/gg-sim".
std::string program_name(const CLI::App& app) {
  const std::string& name = app.get_name();
  return name.substr(name.find_last_of('/') + 1);
}

std::string dashed(std::string key) {
  std::replace(key.begin(), key.end(), '_', '-');
  return key;
}

// Scene files read as CLI11 reads INI/TOML (keys without sections, `key = value`), with `t_max`
// taken for `t-max`: Python and TOML writers spell keys with underscores. A key that names no
// option either way keeps its spelling, for the error message.
class SceneFile : public CLI::ConfigTOML {
 public:
  explicit SceneFile(const CLI::App& app) : app_(app) {}
  std::vector<CLI::ConfigItem> from_config(std::istream& input) const override {
    std::vector<CLI::ConfigItem> items = CLI::ConfigTOML::from_config(input);
    for (CLI::ConfigItem& item : items) {
      if (app_.get_option_no_throw("--" + dashed(item.name))) item.name = dashed(item.name);
    }
    return items;
  }

 private:
  const CLI::App& app_;
};

std::vector<std::string> long_option_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options())
    for (const std::string& name : option->get_lnames()) names.push_back(name);
  return names;
}

// "; did you mean --t-max?" for the first unknown --option among CLI11's leftovers, else "".
std::string suggestion_for(const CLI::App& app, const std::vector<std::string>& leftovers) {
  for (const std::string& arg : leftovers) {
    if (!arg.starts_with("--")) continue;
    const std::string typed = arg.substr(2, arg.find('=') == std::string::npos ? std::string::npos : arg.find('=') - 2);
    if (const auto name = detail::closest_name(typed, long_option_names(app))) return "; did you mean --" + *name + "?";
    return {};
  }
  return {};
}

}  // namespace

bool CommonFlags::show_progress() const { return !quiet && (progress || isatty(STDERR_FILENO)); }

void add_common_flags(CLI::App& app, CommonFlags& flags) {
  // The name is read when --version is seen, after parse() may have filled it in from argv[0].
  app.set_version_flag("--version", [&app] {
    return program_name(app) + " " + kVersion + " (git " + kGitHash + ")";
  }, "Print the version and git hash, then exit");
  CLI::Option* progress = app.add_flag("--progress", flags.progress, "Show progress on stderr even when it is not a terminal");
  app.add_flag("--quiet", flags.quiet, "Never show progress (default: shown when stderr is a terminal)")->excludes(progress);
  // A misspelt key in a scene file must not be silently ignored.
  app.allow_config_extras(false);
  app.config_formatter(std::make_shared<SceneFile>(app));
  app.footer("Outputs are HDF5 files; '-' means stdin/stdout (an HDF5 file through the pipe). "
             "Exit status: 0 success, 1 runtime error, 2 usage error.");
}

namespace {

// "" when `value` holds something, else the message for an empty or blank value.
std::string blank_value_error(const std::string& value) {
  if (value.find_first_not_of(" \t\r\n") != std::string::npos) return {};
  return "empty value; give one (is a shell variable unset?)";
}

// An empty or blank value is an error, never a 0: `--e "$E"` with E unset must not run a totally
// inelastic gas (CLI11 converts "" to 0). Every option that takes a value, in every subcommand,
// from the command line and from a scene file alike.
void refuse_blank_values(CLI::App& app) {
  for (CLI::Option* opt : app.get_options()) {
    if (opt->get_type_size() == 0) continue;  // a flag
    opt->check(blank_value_error, "", "non-blank");  // no description: --help shows the type and default alone
  }
  for (CLI::App* sub : app.get_subcommands({})) refuse_blank_values(*sub);
}

}  // namespace

int parse_cli(CLI::App& app, int argc, char** argv) {
  refuse_blank_values(app);
  try {
    app.parse(argc, argv);
    return -1;
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string message = e.what();
    // CLI11 2.1 words an unknown scene key as "INI was not able to parse <key>".
    const std::string ini = "INI was not able to parse ";
    // A section header [name] reaches it as the key "name.++" (CLI11's mark of a section's start).
    const std::string section_mark = ".++";
    if (message.rfind(ini, 0) == 0) {
      const std::string key = message.substr(ini.size());
      if (key.size() > section_mark.size() && key.ends_with(section_mark))
        message = "section [" + key.substr(0, key.size() - section_mark.size()) + "] in the scene file: a scene has "
                  "no sections; remove that line (its keys then belong to the scene)";
      else if (const auto name = detail::closest_name(dashed(key), long_option_names(app)))
        message = "unknown key '" + key + "' in the scene file; did you mean '" + *name + "'?";
      else
        message = "unknown key '" + key + "' in the scene file (scene keys are the long option names without the "
                  "leading --, with - or _)";
    } else if (dynamic_cast<const CLI::ExtrasError*>(&e)) {
      message += suggestion_for(app, app.remaining());
    } else if (dynamic_cast<const CLI::RequiredError*>(&e) && app.get_require_subcommand_min() > 0 &&
               app.get_subcommands().empty() && !app.remaining().empty()) {
      // What was given in the subcommand's place (CLI11 says only that one is required).
      message = "'" + app.remaining().front() + "' is not a subcommand; give one first (" + program_name(app) +
                " SUBCOMMAND [options])";
    }
    std::replace(message.begin(), message.end(), '\n', ' ');
    std::cerr << program_name(app) << ": error: " << message << "; see --help\n";
    return kExitUsage;
  }
}

namespace {

// The number `text` spells, all of it; NaN when it spells none or has more after it.
double whole_text_number(const std::string& text) {
  std::size_t used = 0;
  try {
    const double x = std::stod(text, &used);
    if (used == text.size()) return x;
  } catch (const std::exception&) {
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

CLI::Validator whole_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (std::string blank = blank_value_error(text); !blank.empty()) return blank;  // runs before the general check
        if (!text.empty() && text.find_first_not_of("0123456789") == std::string::npos) return {};  // CLI11's
        const double x = whole_text_number(text);
        // 2^63: every whole double below it converts exactly.
        if (!(x >= 0) || x != std::floor(x) || !(x < 9223372036854775808.0))
          return "'" + text + "' is not a whole number below 2^63 (write e.g. 4000000 or 4e6)";
        text = std::to_string(static_cast<std::uint64_t>(x));
        return {};
      },
      "", "whole number");
}

CLI::Validator number_at_least(double low, bool strictly) {
  return CLI::Validator(
      [low, strictly](std::string& text) -> std::string {
        const double x = whole_text_number(text);
        if (!std::isfinite(x)) return "'" + text + "' is not a finite number";
        if (strictly ? !(x > low) : !(x >= low))
          return "'" + text + "' is not " + (strictly ? "above " : "at least ") + fmt(low);
        return {};
      },
      "", strictly ? "number > " + fmt(low) : "number >= " + fmt(low));
}

CLI::Validator finite_number() { return number_at_least(-std::numeric_limits<double>::infinity(), true); }

std::vector<std::string> list_items(const std::string& option, const std::vector<std::string>& texts) {
  std::vector<std::string> items;
  for (const std::string& text : texts) {
    std::size_t begin = 0;
    while (true) {
      const std::size_t end = text.find(',', begin);
      const std::string item = text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
      if (!blank_value_error(item).empty())
        throw CLI::ValidationError(option, "empty item in '" + text + "' (two commas in a row or one at an end); "
                                           "write the list as 1,10,100");
      items.push_back(item);
      if (end == std::string::npos) break;
      begin = end + 1;
    }
  }
  return items;
}

std::vector<std::string> argv_strings(int argc, char** argv) { return {argv, argv + argc}; }

}  // namespace gg
