#include "ggsim/checkpoint.hpp"

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string_view>
#include <type_traits>

#include "gg/errors.hpp"
#include "gg/h5file.hpp"
#include "gg/seal.hpp"

namespace ggsim {

namespace {

const char* const kGroup = "/checkpoint";

// The layout of the engine state in a checkpoint; raised whenever that state changes (2: shell
// centres beside the cell links, pending events inside the particles, the numbering /id; 3: the
// recorder's snapshots [T][N][d], read back one frame at a time, velocities only if recorded; 4: the
// layout of 3 in a sealed file, gg/seal.hpp; 5: each effect's arrays under /checkpoint/effects,
// effects/effect_state.hpp; 6: the snapshots' per-particle fields of the effects under their own
// names, a mixture's sizes among them; 7: the sizes in the engine's numbering with the effects, an
// aggregating run's merges, and the event count of the next renumbering; 8: a mixture's species
// with its sizes, and its temperatures with the effects' observables; 9: aggregates' N(t) and mean
// mass with the effects' observables; 10: the run's pieces, run_pieces.hpp; 11: the effects its engine
// holds, which a resume holds too). A checkpoint of another format is refused, never misread, but one
// of format 10, the layout of 11 without the list of effects, which resumes with the effects its scene
// names.
constexpr std::int64_t kFormat = 11;
constexpr std::int64_t kFormatWithoutEffects = 10;
// Where the effects' arrays go: real and integer ones apart, so that each reads back as it was.
const char* const kEffectReals = "/checkpoint/effects/real/";
const char* const kEffectIntegers = "/checkpoint/effects/integer/";

template <class T>
std::vector<std::int64_t> as_int64(const std::vector<T>& v) {
  return std::vector<std::int64_t>(v.begin(), v.end());
}

}  // namespace

template <int D>
void write_checkpoint(const SimConfig& cfg, const gg::Box<D>& box, const EngineView<D>& eng, const Recorder& rec,
                      const RunPieces& pieces, unsigned effects) {
  gg::H5Output out(cfg.checkpoint_path(), true);
  const std::string g = kGroup;
  out.attr(g, "scene", cfg.fingerprint());
  out.attr(g, "format", kFormat);
  out.attr(g, "effects", effect_words(effects));
  out.attr(g, "dim", static_cast<std::int64_t>(D));
  out.write(g + "/edges", std::vector<double>(box.L.begin(), box.L.end()));
  // One dataset at a time, gathered from the engine as it stands: writing a checkpoint adds at
  // most one dataset (8 D bytes per particle) to the memory of the run.
  const std::size_t n = eng.particles.size();
  const auto per_particle = [&](const std::string& name, auto value) {
    using T = std::conditional_t<std::is_floating_point_v<decltype(value(std::size_t{0}))>, double, std::int64_t>;
    std::vector<T> a(n);
    for (std::size_t i = 0; i < n; ++i) a[i] = static_cast<T>(value(i));
    out.write(g + name, a);
  };
  const auto vectors = [&](const std::string& name, auto vec) {
    std::vector<double> a;
    a.reserve(n * D);
    for (std::size_t i = 0; i < n; ++i) {
      const Vec<D> x = vec(i);
      a.insert(a.end(), x.begin(), x.end());
    }
    out.write(g + name, a);
  };
  const auto& p = eng.particles;
  const auto k = [](std::size_t i) { return static_cast<std::uint32_t>(i); };
  vectors("/r", [&](std::size_t i) { return p[i].r; });
  vectors("/v", [&](std::size_t i) { return p[i].v; });
  vectors("/centre", [&](std::size_t i) { return eng.grid.centre(k(i)); });
  per_particle("/t", [&](std::size_t i) { return p[i].t; });
  per_particle("/collisions", [&](std::size_t i) { return p[i].collisions; });
  per_particle("/events_at_this_time", [&](std::size_t i) { return p[i].events_at_this_time; });
  per_particle("/collision_time", [&](std::size_t i) { return p[i].next.collision_time; });
  per_particle("/partner", [&](std::size_t i) { return p[i].next.partner; });
  per_particle("/partner_collisions", [&](std::size_t i) { return p[i].next.partner_collisions; });
  per_particle("/event_time", [&](std::size_t i) { return eng.calendar.time(k(i)); });
  per_particle("/id", [&](std::size_t i) { return eng.grid.label(k(i)); });
  out.write(g + "/cell_head", as_int64(eng.grid.heads()));
  out.write(g + "/cell_next", as_int64(eng.grid.links()));
  eng.save_effects({[&](const std::string& name, const std::vector<double>& a) { out.write(kEffectReals + name, a); },
                    [&](const std::string& name, const std::vector<std::int64_t>& a) {
                      out.write(kEffectIntegers + name, a);
                    }});
  out.write(g + "/clock", std::vector<double>{eng.now});
  out.write(g + "/counters",
            as_int64(std::vector<std::uint64_t>{eng.collisions, eng.events, eng.shell_exits, eng.stale_events, eng.renumber_at}));
  rec.save(out, g + "/recorder");
  pieces.write(out, g + "/pieces");
  out.commit();
}

SavedRun::SavedRun(const std::string& path, bool allow_other_build) : path_(path) {
  // The whole file is checked before anything is read from it: its seal, its format, its scene. (A
  // damaged file would otherwise resume a different run: HDF5 checks its metadata, not the data.)
  const gg::SealState seal = gg::read_seal(path);
  const std::string damaged = "--resume " + path + " is damaged (its bytes are not the ones gg-sim wrote";
  if (seal == gg::SealState::kBroken)
    throw gg::RuntimeError(damaged + ": the checksum does not match); remove it to start the run over");
  in_ = std::make_unique<gg::H5Input>(path);
  const auto scene = in_->attr_string(kGroup, "scene");
  if (!scene) throw gg::RuntimeError(path + " is not a gg-sim checkpoint (no /checkpoint); give a file written by --checkpoint");
  const auto format = in_->attr_double(kGroup, "format");
  if (!format || (*format != static_cast<double>(kFormat) && *format != static_cast<double>(kFormatWithoutEffects)))
    throw gg::UsageError("--resume " + path + " was written by another version of gg-sim (checkpoint format " +
                         (format ? std::to_string(static_cast<std::int64_t>(*format)) : std::string("1")) +
                         ", this gg-sim reads " + std::to_string(kFormat) +
                         "); resume with the gg-sim that wrote it, or delete the checkpoint to start over");
  if (seal != gg::SealState::kIntact)
    throw gg::RuntimeError(damaged + ": its seal is gone); remove it to start the run over");
  lists_effects_ = *format == static_cast<double>(kFormat);
  if (lists_effects_) {
    const auto words = in_->attr_string(kGroup, "effects");
    if (!words) throw gg::RuntimeError(path + " has no list of its effects (/checkpoint@effects); it is damaged");
    std::string_view unknown;
    effects_ = effects_named(*words, unknown);
    if (!unknown.empty())
      throw gg::UsageError("--resume " + path + " was written by a gg-sim with the effect '" + std::string(unknown) +
                           "', which this one does not have; resume it with the gg-sim that wrote it");
  }
  pieces_ = RunPieces::read(*in_, std::string(kGroup) + "/pieces");
  other_build_ = check_resume_build(path, pieces_, allow_other_build);
  scene_ = parse_scene(*scene, "--resume " + path);
  const auto d = in_->attr_double(kGroup, "dim");
  if (!d) throw gg::RuntimeError(path + " is not a gg-sim checkpoint (no /checkpoint); give a file written by --checkpoint");
  dimension_ = static_cast<int>(*d);
  const auto shape = in_->shape(std::string(kGroup) + "/t");
  if (shape.size() != 1) throw gg::RuntimeError(path + ": " + kGroup + "/t is not a list; the checkpoint is damaged");
  particles_ = shape[0];
}

SavedRun::~SavedRun() = default;

const gg::H5Input& SavedRun::file() const {
  if (!in_) throw std::logic_error("the checkpoint " + path_ + " was read and closed already");
  return *in_;
}

template <int D>
EngineState<D> SavedRun::engine_state(gg::Box<D>* box) const {
  const gg::H5Input& in = file();
  const std::string g = kGroup;
  const auto edges = in.read(g + "/edges").data;
  std::array<double, D> e{};
  for (int k = 0; k < D; ++k) e[k] = edges.at(k);
  *box = gg::Box<D>(e);
  // One dataset at a time into the state (the engine then takes the state over): resuming needs
  // about the memory of the run it continues, not that plus a copy of every dataset.
  EngineState<D> st;
  const std::size_t n = in.read(g + "/t").data.size();
  st.particles.resize(n);
  const auto doubles = [&](const std::string& name, std::size_t width, auto set) {
    const auto a = in.read(g + name).data;
    if (a.size() != n * width) throw gg::RuntimeError(path_ + ": " + g + name + " has the wrong size; the checkpoint is damaged");
    for (std::size_t i = 0; i < n; ++i) set(i, &a[i * width]);
  };
  const auto integers = [&](const std::string& name, auto set) {
    const auto a = in.read_int(g + name);
    if (a.size() != n) throw gg::RuntimeError(path_ + ": " + g + name + " has the wrong size; the checkpoint is damaged");
    for (std::size_t i = 0; i < n; ++i) set(i, a[i]);
  };
  const auto u32 = [](std::int64_t x) { return static_cast<std::uint32_t>(x); };
  auto& p = st.particles;
  doubles("/r", D, [&](std::size_t i, const double* x) { std::copy(x, x + D, p[i].r.begin()); });
  doubles("/v", D, [&](std::size_t i, const double* x) { std::copy(x, x + D, p[i].v.begin()); });
  st.centres.resize(n);
  doubles("/centre", D, [&](std::size_t i, const double* x) { std::copy(x, x + D, st.centres[i].begin()); });
  doubles("/t", 1, [&](std::size_t i, const double* x) { p[i].t = *x; });
  doubles("/collision_time", 1, [&](std::size_t i, const double* x) { p[i].next.collision_time = *x; });
  integers("/collisions", [&](std::size_t i, std::int64_t x) { p[i].collisions = u32(x); });
  integers("/events_at_this_time", [&](std::size_t i, std::int64_t x) { p[i].events_at_this_time = u32(x); });
  integers("/partner", [&](std::size_t i, std::int64_t x) { p[i].next.partner = u32(x); });
  integers("/partner_collisions", [&](std::size_t i, std::int64_t x) { p[i].next.partner_collisions = u32(x); });
  st.event_time.resize(n);
  doubles("/event_time", 1, [&](std::size_t i, const double* x) { st.event_time[i] = *x; });
  st.id.resize(n);
  integers("/id", [&](std::size_t i, std::int64_t x) { st.id[i] = u32(x); });
  st.cell_next.resize(n);
  integers("/cell_next", [&](std::size_t i, std::int64_t x) { st.cell_next[i] = static_cast<std::int32_t>(x); });
  for (auto x : in.read_int(g + "/cell_head")) st.cell_head.push_back(static_cast<std::int32_t>(x));
  // The effects' arrays as they are: each effect checks its own when it takes them.
  const std::string reals = kEffectReals, integers_at = kEffectIntegers;
  if (in.exists(reals))
    for (const std::string& name : in.members(reals)) st.effects.real[name] = in.read(reals + name).data;
  if (in.exists(integers_at))
    for (const std::string& name : in.members(integers_at)) st.effects.integer[name] = in.read_int(integers_at + name);
  st.now = in.read(g + "/clock").data.at(0);
  const auto counters = in.read_int(g + "/counters");
  st.collisions = static_cast<std::uint64_t>(counters.at(0));
  st.events = static_cast<std::uint64_t>(counters.at(1));
  st.shell_exits = static_cast<std::uint64_t>(counters.at(2));
  st.stale_events = static_cast<std::uint64_t>(counters.at(3));
  st.renumber_at = static_cast<std::uint64_t>(counters.at(4));
  return st;
}

void SavedRun::require_taken(const EffectRecords& left) const {
  std::string names;
  for (const auto& [name, values] : left.real) names += (names.empty() ? "" : ", ") + name;
  for (const auto& [name, values] : left.integer) names += (names.empty() ? "" : ", ") + name;
  if (names.empty()) return;
  if (!lists_effects_)
    throw gg::RuntimeError("--resume " + path_ + " holds the state (" + names + ") of effects its scene does not name, "
                           "which its format (" + std::to_string(kFormatWithoutEffects) + ") does not list; resume it "
                           "with the gg-sim that wrote it");
  throw gg::RuntimeError("--resume " + path_ + " holds state (" + names + ") that no effect it lists takes; it is damaged");
}

void SavedRun::restore(Recorder& rec) const {
  const double t_max = std::strtod(scene_value(scene_, "t_max").c_str(), nullptr);
  rec.restore(file(), std::string(kGroup) + "/recorder", t_max);
}

void SavedRun::close() { in_.reset(); }

template void write_checkpoint<1>(const SimConfig&, const gg::Box<1>&, const EngineView<1>&, const Recorder&,
                                     const RunPieces&, unsigned);
template void write_checkpoint<2>(const SimConfig&, const gg::Box<2>&, const EngineView<2>&, const Recorder&,
                                     const RunPieces&, unsigned);
template void write_checkpoint<3>(const SimConfig&, const gg::Box<3>&, const EngineView<3>&, const Recorder&,
                                     const RunPieces&, unsigned);
template EngineState<1> SavedRun::engine_state<1>(gg::Box<1>*) const;
template EngineState<2> SavedRun::engine_state<2>(gg::Box<2>*) const;
template EngineState<3> SavedRun::engine_state<3>(gg::Box<3>*) const;

}  // namespace ggsim
