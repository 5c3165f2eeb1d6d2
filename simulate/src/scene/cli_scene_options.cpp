#include "ggsim/cli_scene_options.hpp"

#include <vector>

#include "gg/cli.hpp"

namespace ggsim {

void CliSceneOptions::number(const std::string& flag, double& value, const std::string& help) {
  app_.add_option(flag, value, help);
}

void CliSceneOptions::number(const std::string& flag, std::optional<double>& value, const std::string& help) {
  app_.add_option(flag, value, help);
}

void CliSceneOptions::text(const std::string& flag, std::string& value, const std::string& help) {
  app_.add_option(flag, value, help);
}

void CliSceneOptions::flag(const std::string& flag, bool& value, const std::string& help) {
  app_.add_flag(flag, value, help);
}

void CliSceneOptions::list(const std::string& flag, std::string& value, const std::string& help) {
  app_.add_option_function<std::vector<std::string>>(
      flag,
      [&value](const std::vector<std::string>& items) {
        value.clear();
        for (const std::string& item : items) value += (value.empty() ? "" : ",") + item;
      },
      help);
}

}  // namespace ggsim
