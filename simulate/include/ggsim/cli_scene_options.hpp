#pragma once
// The effects' scene options (scene_effect.hpp) as options of a CLI11 application: gg-sim's.
#include <optional>
#include <string>

#include "ggsim/scene_effect.hpp"

namespace CLI {
class App;
}

namespace ggsim {

class CliSceneOptions final : public SceneOptions {
 public:
  explicit CliSceneOptions(CLI::App& app) : app_(app) {}
  void number(const std::string& flag, double& value, const std::string& help) override;
  void number(const std::string& flag, std::optional<double>& value, const std::string& help) override;
  void text(const std::string& flag, std::string& value, const std::string& help) override;
  void flag(const std::string& flag, bool& value, const std::string& help) override;
  void list(const std::string& flag, std::string& value, const std::string& help) override;

 private:
  CLI::App& app_;
};

}  // namespace ggsim
