#pragma once
// Each effect's parameters (docs/DESIGN.md "Where an effect lives"): one value of the effect's own
// struct (CutoffParameters, DriveParameters, ...), which its scene part (src/scene/) sets from the
// options and its class reads when the engine builds it. Keyed by the struct's type, so that no
// list of effects or of their fields is kept here or in SimConfig.
// An effect copies what it needs into members at construction: nothing here is read per collision.
#include <any>
#include <map>
#include <typeindex>

namespace ggsim {

class EffectParameters {
 public:
  // The effect's parameters to set, P{} until they are set.
  template <class P>
  P& set() {
    std::any& a = values_[std::type_index(typeid(P))];
    if (!a.has_value()) a = P{};
    return std::any_cast<P&>(a);
  }
  // The effect's parameters, P{} (the effect unused) if no scene part set them.
  template <class P>
  const P& get() const {
    static const P kUnset{};
    const auto it = values_.find(std::type_index(typeid(P)));
    return it == values_.end() ? kUnset : std::any_cast<const P&>(it->second);
  }

 private:
  std::map<std::type_index, std::any> values_;
};

// The parameters P of an effect in the engine's parameters `par` (engine.hpp, EngineParameters:
// the store is its collision rule's, collision_rule.hpp), for the effect's constructor.
template <class P, class Parameters>
const P& effect_parameters(const Parameters& par) {
  return par.rule.effects.template get<P>();
}

}  // namespace ggsim
