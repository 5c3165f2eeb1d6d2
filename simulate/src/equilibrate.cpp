// The elastic equilibration before t = 0 (--equilibrate), in a translation unit of its own: it
// runs an engine of its own, the one without effects.
#include <cmath>
#include <cstdint>

#include "gg/errors.hpp"
#include "ggsim/engine.hpp"
#include "ggsim/initial_state.hpp"
#include "ggsim/stop_request.hpp"
#include "start.hpp"

namespace ggsim {

namespace {

struct NoObserver {
  double next_time() const { return kNever; }
  template <class E> void observe(E&, double) {}
  template <class E> bool poll(const E&) { return g_stop_requested != 0; }
};

}  // namespace

template <int D>
void equilibrate(State<D>& st, const SimConfig& cfg) {
  EngineParameters par;
  par.skin = cfg.skin;
  Engine<D, Effects<>> eng(st.box, st.r, st.v, par);
  NoObserver none;
  const auto budget = static_cast<std::uint64_t>(std::llround(cfg.equilibrate * static_cast<double>(st.r.size()) / 2));
  const StopReason why = eng.run(kNever, budget, none);
  if (why == StopReason::kInterrupted) throw gg::RuntimeError("interrupted during equilibration; nothing written");
  eng.for_each_particle(eng.now(), [&](std::uint32_t i, const Vec<D>& r, const Vec<D>& v) {
    st.r[i] = r;
    st.v[i] = v;
  });
  st.effects.integer.erase("image");  // displacements count from t = 0
  set_temperature<D>(st.v, cfg.T0);
}

template void equilibrate<1>(State<1>&, const SimConfig&);
template void equilibrate<2>(State<2>&, const SimConfig&);
template void equilibrate<3>(State<3>&, const SimConfig&);

}  // namespace ggsim
