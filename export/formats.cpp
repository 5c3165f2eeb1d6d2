#include <cmath>
#include <map>
#include <optional>

#include "frame_sink.hpp"
#include "gg/errors.hpp"

namespace gg::exporter {

Format parse_format(const std::string& name) {
  static const std::map<std::string, Format> formats{{"gsd", Format::kGsd}, {"xyz", Format::kXyz}, {"lammps", Format::kLammps}};
  const auto it = formats.find(name);
  if (it == formats.end()) throw UsageError("--format " + name + " is not known; give gsd, xyz or lammps");
  return it->second;
}

Format output_format(const std::string& output, const std::string& given) {
  const auto ends = [&output](const std::string& tail) { return output.ends_with(tail); };
  std::optional<Format> named;
  if (ends(".gsd")) named = Format::kGsd;
  else if (ends(".xyz")) named = Format::kXyz;
  else if (ends(".dump") || ends(".lammpstrj")) named = Format::kLammps;
  if (given.empty()) {
    if (!named)
      throw UsageError("cannot tell the format of '" + output + "' from its name; give --format gsd, xyz or lammps "
                       "(or name it .gsd, .xyz, .dump)");
    return *named;
  }
  const Format f = parse_format(given);
  if (named && *named != f)
    throw UsageError("--format " + given + " writes another format than the name '" + output +
                     "' says; drop --format or give the file a name of its format");
  return f;
}

double sliding_shift(const Frame& f) {
  if (f.shear_rate == 0 || f.dim < 2) return 0;
  const double Lx = f.edges[0];
  const double shift = std::fmod(f.shear_rate * f.edges[1] * f.time, Lx);  // (a L_y) t, as the engine's
  return shift >= 0.5 * Lx ? shift - Lx : shift < -0.5 * Lx ? shift + Lx : shift;
}

std::array<double, 3> lattice_image(const Frame& f, std::size_t i) {
  std::array<double, 3> n{};
  for (int a = 0; a < f.dim; ++a) n[a] = f.image[i * f.dim + a];
  if (f.shear_rate != 0 && f.dim >= 2) {
    const double slid = f.shear_rate * f.edges[1] * f.time - sliding_shift(f);  // Q L_x
    n[0] += n[1] * std::nearbyint(slid / f.edges[0]);
  }
  return n;
}

}  // namespace gg::exporter
