#pragma once
// The per-particle and run state of the effects as named arrays: how a start hands an effect its
// initial values (the periodic images of a file, the angular velocities drawn at --T0-rot), and
// how a checkpoint keeps them (/checkpoint/effects/NAME, docs/DESIGN.md "Checkpoints"). Each
// effect names its own arrays; the engine and the checkpoint code pass them on unread.
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "gg/errors.hpp"

namespace ggsim {

struct EffectRecords {
  std::map<std::string, std::vector<double>> real;
  std::map<std::string, std::vector<std::int64_t>> integer;

  // The array `name` taken out (empty if there is none), which must then hold `size` values:
  // anything else is a damaged checkpoint.
  std::vector<double> take_real(const std::string& name, std::size_t size) { return take(real, name, size); }
  std::vector<std::int64_t> take_integer(const std::string& name, std::size_t size) {
    return take(integer, name, size);
  }
  // The same for an array whose size its owner checks (one not per particle).
  std::vector<std::int64_t> take_all_integer(const std::string& name) {
    const auto it = integer.find(name);
    if (it == integer.end()) return {};
    std::vector<std::int64_t> a = std::move(it->second);
    integer.erase(it);
    return a;
  }

 private:
  template <class T>
  static std::vector<T> take(std::map<std::string, std::vector<T>>& from, const std::string& name, std::size_t size) {
    const auto it = from.find(name);
    if (it == from.end()) return {};
    std::vector<T> a = std::move(it->second);
    from.erase(it);
    if (a.size() != size)
      throw gg::RuntimeError("the effect state '" + name + "' holds " + std::to_string(a.size()) + " values where " +
                             std::to_string(size) + " belong; the checkpoint is damaged");
    return a;
  }
};

// Where an effect in use reports its observables at each sample time of the recorder: a name
// (the output's /observables/NAME), its unit (H5MD units, gg/trajectory.hpp) and its value, or its
// values when it is an array (the same length at every sample time: a mixture's temperature of
// each species, written [T][k]).
class ObservableSink {
 public:
  using Put = std::function<void(const std::string&, const std::string&, const std::vector<double>&)>;
  explicit ObservableSink(Put put) : put_(std::move(put)) {}
  void operator()(const std::string& name, const std::string& unit, double value) const { put_(name, unit, {value}); }
  void operator()(const std::string& name, const std::string& unit, const std::vector<double>& values) const {
    put_(name, unit, values);
  }

 private:
  Put put_;
};

// The gas at a sample time, for an effect whose observable depends on it (the pressure).
struct Sample {
  double t;               // the sample time
  double kinetic_energy;  // per particle
  double n;               // particles
  double volume;          // of the box
  int dim;
  // sum over the particles of m V_a V_b (V: the velocity less the mean flow), row-major d x d, on
  // request (the pressure tensor of a sheared gas)
  std::function<std::vector<double>()> velocity_tensor = {};
  // |v|^2 of each particle in the engine's numbering, on request (a mixture's species temperatures)
  std::function<std::vector<double>()> squared_speeds = {};
};

// A per-particle field an effect in use adds to every snapshot (the output's /particles/all/NAME
// beside the positions, and the checkpoint's frames): its name, its values per particle and their
// H5MD unit; `with_velocities`: kept only when the snapshots keep velocities (gg-sim --velocities).
struct FrameField {
  std::string name;
  std::size_t components = 1;
  std::string unit;
  bool with_velocities = false;
};

// Where an effect hands a snapshot the values of one of its fields: the field's name and its
// values in the engine's numbering, `components` per particle.
using FrameSink = std::function<void(const std::string&, const std::vector<double>&)>;

// Where an effect writes its arrays for a checkpoint, one at a time (a checkpoint adds at most one
// array to the memory of a run).
struct EffectSink {
  std::function<void(const std::string&, const std::vector<double>&)> real;
  std::function<void(const std::string&, const std::vector<std::int64_t>&)> integer;
};

// What an effect is given at the start of an engine: the number of particles, the clock, the
// number in the start of each particle (empty: particle i is number i) and its saved or initial
// arrays, from which it takes its own.
struct EffectStart {
  std::size_t n = 0;
  double t0 = 0;
  const std::vector<std::uint32_t>* id = nullptr;
  EffectRecords* records = nullptr;

  std::uint32_t start_number(std::uint32_t i) const { return id && !id->empty() ? (*id)[i] : i; }
};

}  // namespace ggsim
