#include "ggsim/checkpoint.hpp"

#include "gg/errors.hpp"
#include "gg/h5file.hpp"

namespace ggsim {

namespace {

const char* const kGroup = "/checkpoint";

// The layout of the engine state in a checkpoint; raised whenever that state changes (2: shell
// centres beside the cell links, pending events inside the particles, the numbering /id). A
// checkpoint of another format is refused, never misread.
constexpr std::int64_t kFormat = 2;

template <class T>
std::vector<std::int64_t> as_int64(const std::vector<T>& v) {
  return std::vector<std::int64_t>(v.begin(), v.end());
}

}  // namespace

template <int D>
void write_checkpoint(const SimConfig& cfg, const gg::Box<D>& box, const EngineState<D>& st, const Recorder& rec) {
  gg::H5Output out(cfg.checkpoint_path());
  const std::string g = kGroup;
  out.attr(g, "scene", cfg.fingerprint());
  out.attr(g, "format", kFormat);
  out.attr(g, "dim", static_cast<std::int64_t>(D));
  out.write(g + "/edges", std::vector<double>(box.L.begin(), box.L.end()));
  const std::size_t n = st.particles.size();
  std::vector<double> r, v, centre, t, ctime;
  std::vector<std::int64_t> coll, at_time, partner, pcoll;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& q = st.particles[i];
    r.insert(r.end(), q.r.begin(), q.r.end());
    v.insert(v.end(), q.v.begin(), q.v.end());
    centre.insert(centre.end(), st.centres[i].begin(), st.centres[i].end());
    t.push_back(q.t);
    coll.push_back(q.collisions);
    at_time.push_back(q.events_at_this_time);
    ctime.push_back(q.next.collision_time);
    partner.push_back(q.next.partner);
    pcoll.push_back(q.next.partner_collisions);
  }
  out.write(g + "/r", r);
  out.write(g + "/v", v);
  out.write(g + "/centre", centre);
  out.write(g + "/t", t);
  out.write(g + "/collisions", coll);
  out.write(g + "/events_at_this_time", at_time);
  out.write(g + "/collision_time", ctime);
  out.write(g + "/partner", partner);
  out.write(g + "/partner_collisions", pcoll);
  out.write(g + "/event_time", st.event_time);
  out.write(g + "/id", as_int64(st.id));
  out.write(g + "/cell_head", as_int64(st.cell_head));
  out.write(g + "/cell_next", as_int64(st.cell_next));
  out.write(g + "/last_collision", st.last_collision);
  out.write(g + "/clock", std::vector<double>{st.now, st.virial});
  out.write(g + "/counters", as_int64(std::vector<std::uint64_t>{st.collisions, st.events, st.shell_exits, st.stale_events}));
  rec.save(out, g + "/recorder");
  out.commit();
}

int checkpoint_dimension(const std::string& path) {
  gg::H5Input in(path);
  const auto d = in.attr_double(kGroup, "dim");
  if (!d) throw gg::RuntimeError(path + " is not a gg-sim checkpoint (no /checkpoint); give a file written by --checkpoint");
  return static_cast<int>(*d);
}

template <int D>
EngineState<D> read_checkpoint(const SimConfig& cfg, gg::Box<D>* box) {
  gg::H5Input in(cfg.resume);
  const std::string g = kGroup;
  const auto scene = in.attr_string(g, "scene");
  if (!scene) throw gg::RuntimeError(cfg.resume + " is not a gg-sim checkpoint (no /checkpoint); give a file written by --checkpoint");
  const auto format = in.attr_double(g, "format");
  if (!format || *format != static_cast<double>(kFormat))
    throw gg::UsageError("--resume " + cfg.resume + " was written by another version of gg-sim (checkpoint format " +
                         (format ? std::to_string(static_cast<std::int64_t>(*format)) : std::string("1")) +
                         ", this gg-sim reads " + std::to_string(kFormat) +
                         "); resume with the gg-sim that wrote it, or delete the checkpoint to start over");
  if (*scene != cfg.fingerprint())
    throw gg::UsageError("--resume " + cfg.resume + " was written by another scene (" + *scene +
                         "); resume with the same scene and flags as the interrupted run");
  const auto edges = in.read(g + "/edges").data;
  std::array<double, D> e{};
  for (int k = 0; k < D; ++k) e[k] = edges.at(k);
  *box = gg::Box<D>(e);
  const auto r = in.read(g + "/r").data, v = in.read(g + "/v").data, centre = in.read(g + "/centre").data;
  const auto t = in.read(g + "/t").data, ctime = in.read(g + "/collision_time").data;
  const auto coll = in.read_int(g + "/collisions"), at_time = in.read_int(g + "/events_at_this_time");
  const auto partner = in.read_int(g + "/partner"), pcoll = in.read_int(g + "/partner_collisions");
  EngineState<D> st;
  const std::size_t n = t.size();
  st.particles.resize(n);
  st.centres.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    auto& q = st.particles[i];
    for (int k = 0; k < D; ++k) q.r[k] = r[i * D + k], q.v[k] = v[i * D + k], st.centres[i][k] = centre[i * D + k];
    q.t = t[i];
    q.collisions = static_cast<std::uint32_t>(coll[i]);
    q.events_at_this_time = static_cast<std::uint32_t>(at_time[i]);
    q.next.collision_time = ctime[i];
    q.next.partner = static_cast<std::uint32_t>(partner[i]);
    q.next.partner_collisions = static_cast<std::uint32_t>(pcoll[i]);
  }
  st.event_time = in.read(g + "/event_time").data;
  for (auto x : in.read_int(g + "/id")) st.id.push_back(static_cast<std::uint32_t>(x));
  for (auto x : in.read_int(g + "/cell_head")) st.cell_head.push_back(static_cast<std::int32_t>(x));
  for (auto x : in.read_int(g + "/cell_next")) st.cell_next.push_back(static_cast<std::int32_t>(x));
  st.last_collision = in.read(g + "/last_collision").data;
  const auto clock = in.read(g + "/clock").data;
  st.now = clock.at(0), st.virial = clock.at(1);
  const auto counters = in.read_int(g + "/counters");
  st.collisions = static_cast<std::uint64_t>(counters.at(0));
  st.events = static_cast<std::uint64_t>(counters.at(1));
  st.shell_exits = static_cast<std::uint64_t>(counters.at(2));
  st.stale_events = static_cast<std::uint64_t>(counters.at(3));
  return st;
}

void restore_recorder(const SimConfig& cfg, Recorder& rec) {
  gg::H5Input in(cfg.resume);
  rec.restore(in, std::string(kGroup) + "/recorder");
}

template void write_checkpoint<1>(const SimConfig&, const gg::Box<1>&, const EngineState<1>&, const Recorder&);
template void write_checkpoint<2>(const SimConfig&, const gg::Box<2>&, const EngineState<2>&, const Recorder&);
template EngineState<1> read_checkpoint<1>(const SimConfig&, gg::Box<1>*);
template EngineState<2> read_checkpoint<2>(const SimConfig&, gg::Box<2>*);

}  // namespace ggsim
