// GSD frames in the HOOMD schema (glotzerlab/gsd doc/schema-hoomd.rst), read through the file layer of
// gg/gsd_file.hpp. The schema's rule for a chunk a frame lacks: frame 0's chunk, else the default.
// HOOMD's box is [Lx, Ly, Lz, xy, xz, yz], centred on the origin and periodic on every axis;
// configuration/dimensions says 2 or 3 (default 3); a 2D system lies in the xy plane.
#include <cmath>
#include <optional>

#include "frames_internal.hpp"
#include "gg/errors.hpp"
#include "gg/gsd_file.hpp"

namespace gg::frames {
namespace {

class GsdSource : public FrameSource {
 public:
  explicit GsdSource(const std::string& path) : FrameSource(FrameFormat::kGsd, path), gsd_(path) {
    if (gsd_.schema() != "hoomd")
      throw RuntimeError("'" + path + "': a GSD file of schema '" + gsd_.schema() + "'; the analyses read the HOOMD "
                         "schema ('hoomd'), as HOOMD-blue and gsd.hoomd write it");
    if (frames() > 0) {
      const std::vector<double> d = chunk(0, "configuration/dimensions").value_or(std::vector<double>{3});
      if (d.size() != 1 || (d[0] != 2 && d[0] != 3))
        throw RuntimeError(where(0) + ": configuration/dimensions is not 2 or 3; the file is damaged");
      dim_ = static_cast<int>(d[0]);
    }
  }

  std::size_t frames() const override { return gsd_.frames(); }

  ParticleFrame read(std::size_t k) const override {
    RawFrame f;
    const std::vector<double> box = chunk(k, "configuration/box").value_or(std::vector<double>{1, 1, 1, 0, 0, 0});
    if (box.size() != 6) throw RuntimeError(where(k) + ": configuration/box does not hold 6 numbers; the file is damaged");
    if (box[3] != 0 || box[4] != 0 || box[5] != 0)
      throw RuntimeError(where(k) + ": a triclinic box (tilt factors xy, xz, yz not 0); the analyses need a "
                         "rectangular periodic box");
    for (int a = 0; a < 3; ++a) f.edges[a] = box[a], f.lower[a] = -0.5 * box[a];
    const std::vector<double> n = chunk(k, "particles/N").value_or(std::vector<double>{0});
    f.n = n.size() == 1 ? static_cast<std::size_t>(n[0]) : 0;
    const std::vector<double> step = chunk(k, "configuration/step").value_or(std::vector<double>{0});
    f.step = step.size() == 1 && step[0] < 9e18 ? static_cast<std::int64_t>(step[0]) : 0;
    // HOOMD writes no time; gg-export writes log/time. Without it a frame's time is its step.
    const std::optional<std::vector<double>> time = chunk(k, "log/time");
    f.time = time && time->size() == 1 ? (*time)[0] : static_cast<double>(f.step);
    if (f.n > 0 && !gsd_.find(k, "particles/position") && !gsd_.find(0, "particles/position"))
      throw RuntimeError(where(k) + ": no particles/position; the analyses need positions");
    f.position = per_particle(k, "particles/position", f.n, 3).value_or(std::vector<double>{});
    f.velocity = per_particle(k, "particles/velocity", f.n, 3).value_or(std::vector<double>{});
    if (auto diameter = per_particle(k, "particles/diameter", f.n, 1)) {
      f.radius = std::move(*diameter);
      for (double& r : f.radius) r *= 0.5;
    }
    f.mass = per_particle(k, "particles/mass", f.n, 1).value_or(std::vector<double>{});
    return to_particle_frame(std::move(f), dim_, where(k));
  }

 private:
  std::string where(std::size_t k) const { return "'" + path() + "' frame " + std::to_string(k); }

  std::optional<std::vector<double>> chunk(std::size_t k, const std::string& name) const {
    std::optional<gsd::Reader::Chunk> c = gsd_.find(k, name);
    if (!c) c = gsd_.find(0, name);
    if (!c) return std::nullopt;
    return gsd_.read(*c);
  }

  std::optional<std::vector<double>> per_particle(std::size_t k, const std::string& name, std::size_t n, std::uint32_t m) const {
    std::optional<gsd::Reader::Chunk> c = gsd_.find(k, name);
    if (!c) c = gsd_.find(0, name);
    if (!c) return std::nullopt;
    if (c->n != n || c->m != m)
      throw RuntimeError(where(k) + ": " + name + " is " + std::to_string(c->n) + " x " + std::to_string(c->m) +
                         " for " + std::to_string(n) + " particles (" + std::to_string(n) + " x " + std::to_string(m) +
                         " expected); the file is damaged");
    return gsd_.read(*c);
  }

  gsd::Reader gsd_;
  int dim_ = 3;
};

}  // namespace

std::unique_ptr<FrameSource> open_gsd(const std::string& path) { return std::make_unique<GsdSource>(path); }

}  // namespace gg::frames
