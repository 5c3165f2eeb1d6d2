// Text frames: LAMMPS dumps (the `dump atom` and `dump custom` styles, docs.lammps.org/dump.html) and
// extended XYZ (the comment line's Lattice= and Properties=, as ASE, OVITO and QUIP write it). On
// opening, the file is scanned once for where each frame starts; a frame is parsed when read.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>

#include "frames_internal.hpp"
#include "gg/errors.hpp"

namespace gg::frames {
namespace {

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

std::string lower_case(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// A number, or nullopt when `word` is not one whole.
std::optional<double> number(const std::string& word) {
  double x = 0;
  const char* end = word.data() + word.size();
  const auto [at, error] = std::from_chars(word.data(), end, x);
  if (error != std::errc() || at != end) return std::nullopt;
  return x;
}

// The text sources' common part: the file, where each frame starts, and the frame's place in messages.
class TextSource : public FrameSource {
 public:
  TextSource(FrameFormat format, const std::string& path) : FrameSource(format, path), file_(path) {
    if (!file_) throw RuntimeError("'" + path + "': cannot open; check the path and its permissions");
    file_.seekg(0, std::ios::end);
    size_ = static_cast<double>(file_.tellg());
    file_.seekg(0);
  }
  std::size_t frames() const override { return starts_.size(); }

 protected:
  std::string where(std::size_t k) const { return "'" + path() + "' frame " + std::to_string(k); }
  [[noreturn]] void bad(std::size_t k, const std::string& what) const { throw RuntimeError(where(k) + ": " + what); }
  // The next line of frame k; a file that ends first is truncated.
  std::string line(std::size_t k) const {
    std::string text;
    if (!std::getline(file_, text)) bad(k, "the file ends inside the frame; it is truncated, write it again");
    if (!text.empty() && text.back() == '\r') text.pop_back();
    return text;
  }
  // The first word of the next line as a number, or nullopt.
  std::optional<double> first_number(std::size_t k) const {
    const std::vector<std::string> w = words(line(k));
    return w.empty() ? std::nullopt : number(w[0]);
  }
  void seek(std::size_t k) const {
    file_.clear();
    file_.seekg(starts_.at(k));
  }
  void skip_lines(std::size_t k, std::size_t count) const {
    for (std::size_t i = 0; i < count; ++i)
      if (!file_.ignore(std::numeric_limits<std::streamsize>::max(), '\n'))
        bad(k, "the file ends inside the frame; it is truncated, write it again");
  }
  // The frame's rows, each split into `columns` numbers (a word that is no number is NaN: a species
  // name, which no analysis reads).
  std::vector<double> rows(std::size_t k, std::size_t n, std::size_t columns) const {
    // Each value takes at least two bytes (itself and a space or newline).
    if (static_cast<double>(n) * static_cast<double>(columns) * 2 > size_)
      bad(k, "the file is shorter than its " + std::to_string(n) + " rows of " + std::to_string(columns) +
                 " values; it is truncated, write it again");
    std::vector<double> values(n * columns);
    for (std::size_t i = 0; i < n; ++i) {
      const std::vector<std::string> w = words(line(k));
      if (w.size() != columns)
        bad(k, "particle row " + std::to_string(i) + " has " + std::to_string(w.size()) + " values, the header names " +
                   std::to_string(columns));
      for (std::size_t c = 0; c < columns; ++c) values[i * columns + c] = number(w[c]).value_or(NAN);
    }
    return values;
  }

  // A particle count, checked: a whole number no larger than the file could hold (a row per particle).
  std::size_t count(std::size_t k, std::optional<double> v, const std::string& what) const {
    if (!v || *v < 0 || *v != std::floor(*v) || *v > size_) bad(k, what + " is not a particle count the file can hold");
    return static_cast<std::size_t>(*v);
  }
  // A step: a whole number within 64 bits.
  std::int64_t whole(std::size_t k, std::optional<double> v, const std::string& what) const {
    if (!v || *v != std::floor(*v) || std::abs(*v) > 9e18) bad(k, what + " is not a whole number");
    return static_cast<std::int64_t>(*v);
  }

  mutable std::ifstream file_;
  std::vector<std::streampos> starts_;
  double size_ = 0;  // bytes
};

// LAMMPS: ITEM: TIMESTEP, NUMBER OF ATOMS, BOX BOUNDS [xy xz yz] xx yy zz, ATOMS <columns>, in any
// order, optionally ITEM: TIME and ITEM: UNITS; pp means periodic. Positions from x (unscaled), xs
// (scaled by the box), xu or xsu (unwrapped); rows sorted by id when there is one.
class LammpsDumpSource : public TextSource {
 public:
  explicit LammpsDumpSource(const std::string& path) : TextSource(FrameFormat::kLammpsDump, path) {
    for (;;) {
      const std::streampos start = file_.tellg();
      Header h;
      if (!header(starts_.size(), h, true)) break;
      starts_.push_back(start);
      skip_lines(starts_.size() - 1, *h.n);
    }
    if (!starts_.empty()) dim_ = used_axes(raw(0));
  }

  ParticleFrame read(std::size_t k) const override { return to_particle_frame(raw(k), dim_, where(k)); }

 private:
  struct Header {
    std::optional<std::int64_t> step;
    std::optional<double> time;
    std::optional<std::size_t> n;
    std::optional<RawFrame> box;
    std::vector<std::string> columns;
  };

  // Reads a frame's items up to and with ITEM: ATOMS; false at the end of the file when `at_end_ok`.
  bool header(std::size_t k, Header& h, bool at_end_ok) const {
    std::string text;
    for (;;) {
      if (!std::getline(file_, text)) {
        if (at_end_ok && !h.step && !h.n && !h.box) return false;
        bad(k, "the file ends inside the frame's header; it is truncated, write it again");
      }
      if (!text.empty() && text.back() == '\r') text.pop_back();
      const std::vector<std::string> w = words(text);
      if (w.empty()) continue;
      if (w[0] != "ITEM:") bad(k, "expected a line 'ITEM: ...', found '" + text.substr(0, 40) + "'");
      const std::string item = w.size() > 1 ? w[1] : "";
      if (item == "TIMESTEP") {
        h.step = whole(k, first_number(k), "ITEM: TIMESTEP's value");
      } else if (item == "TIME") {
        const auto v = first_number(k);
        if (!v) bad(k, "ITEM: TIME is not followed by a number");
        h.time = *v;
      } else if (item == "UNITS") {
        line(k);
      } else if (item == "NUMBER") {
        h.n = count(k, first_number(k), "ITEM: NUMBER OF ATOMS's value");
      } else if (item == "BOX") {
        // "ITEM: BOX BOUNDS [xy xz yz] xx yy zz": the tilt factors come first when the box is triclinic.
        std::vector<std::string> flags(w.begin() + std::min<std::size_t>(3, w.size()), w.end());
        if (!flags.empty() && flags[0] == "xy")
          bad(k, "a triclinic box (BOX BOUNDS xy xz yz); the analyses need a rectangular periodic box");
        RawFrame box;
        for (int a = 0; a < 3; ++a) {
          const std::vector<std::string> bounds = words(line(k));
          const auto lo = bounds.size() >= 2 ? number(bounds[0]) : std::nullopt;
          const auto hi = bounds.size() >= 2 ? number(bounds[1]) : std::nullopt;
          if (!lo || !hi) bad(k, "a BOX BOUNDS line is not two numbers");
          box.lower[a] = *lo;
          box.edges[a] = *hi - *lo;
          box.periodic[a] = flags.size() < 3 || flags[a] == "pp";
        }
        h.box = box;
      } else if (item == "ATOMS") {
        h.columns.assign(w.begin() + 2, w.end());
        if (!h.step || !h.n || !h.box)
          bad(k, "ITEM: ATOMS before ITEM: TIMESTEP, NUMBER OF ATOMS and BOX BOUNDS; not a LAMMPS dump");
        return true;
      } else {
        bad(k, "unknown item '" + text.substr(0, 40) + "'; not a LAMMPS text dump");
      }
    }
  }

  RawFrame raw(std::size_t k) const {
    seek(k);
    Header h;
    header(k, h, false);
    RawFrame f = *h.box;
    f.n = *h.n;
    f.step = *h.step;
    f.time = h.time.value_or(static_cast<double>(f.step));
    std::map<std::string, std::size_t> column;
    for (std::size_t c = 0; c < h.columns.size(); ++c) column[h.columns[c]] = c;
    const auto has = [&](const std::string& name) { return column.count(name) > 0; };
    const std::size_t width = h.columns.size();
    const std::vector<double> values = rows(k, f.n, width);
    const auto value = [&](std::size_t i, const std::string& name) { return values[i * width + column.at(name)]; };

    // Each axis from the first of its forms the dump has; an axis it lacks is 0 (a 2D or 1D run).
    static const char* const kAxis[] = {"x", "y", "z"};
    f.position.assign(3 * f.n, 0.0);
    for (int a = 0; a < 3; ++a) {
      const std::string x = kAxis[a];
      const bool scaled = !has(x) && !has(x + "u") && (has(x + "s") || has(x + "su"));
      const std::string name = has(x) ? x : has(x + "u") ? x + "u" : has(x + "s") ? x + "s" : x + "su";
      if (!has(name)) {
        if (a == 0) bad(k, "ITEM: ATOMS has no x, xs, xu or xsu column; the analyses need positions");
        continue;
      }
      for (std::size_t i = 0; i < f.n; ++i)
        f.position[3 * i + a] = scaled ? f.lower[a] + value(i, name) * f.edges[a] : value(i, name);
    }
    if (has("vx")) {
      f.velocity.assign(3 * f.n, 0.0);
      for (std::size_t i = 0; i < f.n; ++i)
        for (int a = 0; a < 3; ++a)
          if (has(std::string("v") + kAxis[a])) f.velocity[3 * i + a] = value(i, std::string("v") + kAxis[a]);
    }
    if (has("radius") || has("diameter")) {
      f.radius.resize(f.n);
      for (std::size_t i = 0; i < f.n; ++i) f.radius[i] = has("radius") ? value(i, "radius") : 0.5 * value(i, "diameter");
    }
    if (has("mass")) {
      f.mass.resize(f.n);
      for (std::size_t i = 0; i < f.n; ++i) f.mass[i] = value(i, "mass");
    }
    if (has("id")) sort_by_id(k, f, values, width, column.at("id"));
    return f;
  }

  // LAMMPS writes atoms in no fixed order (by processor): sorted by id, row i is the same particle in
  // every frame.
  void sort_by_id(std::size_t k, RawFrame& f, const std::vector<double>& values, std::size_t width, std::size_t id) const {
    std::vector<std::size_t> order(f.n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a * width + id] < values[b * width + id]; });
    for (std::size_t j = 1; j < f.n; ++j)
      if (values[order[j] * width + id] == values[order[j - 1] * width + id])
        bad(k, "two atoms have id " + std::to_string(static_cast<long long>(values[order[j] * width + id])));
    const auto permute = [&](std::vector<double>& v, std::size_t per) {
      if (v.empty()) return;
      std::vector<double> out(v.size());
      for (std::size_t j = 0; j < f.n; ++j) std::copy_n(v.begin() + order[j] * per, per, out.begin() + j * per);
      v = std::move(out);
    };
    permute(f.position, 3);
    permute(f.velocity, 3);
    permute(f.radius, 1);
    permute(f.mass, 1);
  }

  int dim_ = 3;
};

// Extended XYZ: a count line, a comment line of key=value pairs (values in double quotes may hold
// spaces), then one row per particle laid out by Properties=name:type:columns:... (type S, R, I or L).
// Lattice= gives the three cell vectors (rows), which must be diagonal; pbc= the periodic axes
// (default "T T T" with a Lattice); Origin= the cell's corner (default 0); Time= and Step= (any case).
class ExtendedXyzSource : public TextSource {
 public:
  explicit ExtendedXyzSource(const std::string& path) : TextSource(FrameFormat::kExtendedXyz, path) {
    for (std::string text;;) {
      const std::streampos start = file_.tellg();
      if (!std::getline(file_, text)) break;
      if (words(text).empty()) continue;  // blank lines after the last frame
      const std::size_t n = count(starts_.size(), number(words(text)[0]), "the first line of a frame ('" + text.substr(0, 40) + "')");
      starts_.push_back(start);
      skip_lines(starts_.size() - 1, n + 1);
    }
    if (!starts_.empty()) dim_ = used_axes(raw(0));
  }

  ParticleFrame read(std::size_t k) const override { return to_particle_frame(raw(k), dim_, where(k)); }

 private:
  std::map<std::string, std::string> comment_keys(std::size_t k, const std::string& text) const {
    std::map<std::string, std::string> keys;
    std::size_t at = 0;
    while (at < text.size()) {
      at = text.find_first_not_of(" \t", at);
      if (at == std::string::npos) break;
      const std::size_t eq = text.find_first_of("= \t", at);
      const std::string key = lower_case(text.substr(at, eq - at));
      if (eq == std::string::npos || text[eq] != '=') {  // a bare word: a flag
        keys[key] = "T";
        at = eq;
        continue;
      }
      std::string value;
      at = eq + 1;
      if (at < text.size() && text[at] == '"') {
        const std::size_t close = text.find('"', at + 1);
        if (close == std::string::npos) bad(k, "the comment line has a '\"' that is never closed");
        value = text.substr(at + 1, close - at - 1);
        at = close + 1;
      } else {
        const std::size_t end = text.find_first_of(" \t", at);
        value = text.substr(at, end - at);
        at = end;
      }
      keys[key] = value;
    }
    return keys;
  }

  RawFrame raw(std::size_t k) const {
    seek(k);
    RawFrame f;
    f.n = count(k, first_number(k), "the particle count");
    const std::map<std::string, std::string> keys = comment_keys(k, line(k));
    const auto key = [&](const std::string& name) -> std::optional<std::string> {
      const auto it = keys.find(name);
      return it == keys.end() ? std::nullopt : std::optional<std::string>(it->second);
    };
    const auto numbers = [&](const std::string& name, std::size_t count) {
      std::vector<double> out;
      for (const std::string& w : words(*key(name)))
        if (const auto v = number(w)) out.push_back(*v);
      if (out.size() != count) bad(k, name + "= must hold " + std::to_string(count) + " numbers");
      return out;
    };
    if (!key("lattice"))
      bad(k, "no Lattice= in the comment line; the analyses need the periodic box (extended XYZ's Lattice)");
    const std::vector<double> lattice = numbers("lattice", 9);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        if (a != b && lattice[3 * a + b] != 0)
          bad(k, "a triclinic cell (Lattice= has off-diagonal components); the analyses need a rectangular periodic box");
    for (int a = 0; a < 3; ++a) f.edges[a] = lattice[4 * a];
    if (key("origin")) {
      const std::vector<double> origin = numbers("origin", 3);
      std::copy(origin.begin(), origin.end(), f.lower.begin());
    }
    if (key("pbc")) {
      const std::vector<std::string> pbc = words(*key("pbc"));
      if (pbc.size() != 3) bad(k, "pbc= must hold 3 values (T or F)");
      for (int a = 0; a < 3; ++a) f.periodic[a] = pbc[a] == "T" || pbc[a] == "True" || pbc[a] == "true" || pbc[a] == "1";
    }
    if (key("time") && !number(*key("time"))) bad(k, "Time= is not a number");
    f.step = key("step") ? whole(k, number(*key("step")), "Step=") : static_cast<std::int64_t>(k);
    f.time = key("time") ? *number(*key("time")) : static_cast<double>(f.step);

    // Properties: the columns of each property.
    const std::vector<std::string> spec = split(key("properties").value_or("species:S:1:pos:R:3"), ':');
    if (spec.size() % 3 != 0) bad(k, "Properties= is not a list of name:type:columns");
    std::map<std::string, std::pair<std::size_t, std::size_t>> property;  // lower-case name -> first column, columns
    std::size_t width = 0;
    for (std::size_t p = 0; p < spec.size(); p += 3) {
      const auto columns = number(spec[p + 2]);
      if (!columns || *columns < 1 || *columns > 1000 || *columns != std::floor(*columns))
        bad(k, "Properties= gives '" + spec[p + 2] + "' columns for " + spec[p]);
      property[lower_case(spec[p])] = {width, static_cast<std::size_t>(*columns)};
      width += static_cast<std::size_t>(*columns);
    }
    const auto find = [&](std::initializer_list<const char*> names, std::size_t columns) -> std::optional<std::size_t> {
      for (const char* name : names)
        if (const auto it = property.find(name); it != property.end()) {
          if (it->second.second != columns)
            bad(k, std::string("the property ") + name + " has " + std::to_string(it->second.second) + " columns, not " +
                       std::to_string(columns));
          return it->second.first;
        }
      return std::nullopt;
    };
    const std::optional<std::size_t> pos = find({"pos", "positions", "position"}, 3);
    if (!pos) bad(k, "Properties= names no pos column; the analyses need positions");
    const std::optional<std::size_t> velo = find({"velo", "vel", "velocities", "velocity"}, 3);
    const std::optional<std::size_t> momenta = find({"momenta"}, 3);
    const std::optional<std::size_t> radius = find({"radius", "radii"}, 1);
    const std::optional<std::size_t> mass = find({"masses", "mass"}, 1);
    const std::vector<double> values = rows(k, f.n, width);
    const auto column = [&](std::size_t first, std::size_t per, std::vector<double>& out) {
      out.resize(f.n * per);
      for (std::size_t i = 0; i < f.n; ++i)
        for (std::size_t c = 0; c < per; ++c) out[i * per + c] = values[i * width + first + c];
    };
    column(*pos, 3, f.position);
    if (radius) column(*radius, 1, f.radius);
    if (mass) column(*mass, 1, f.mass);
    if (velo) {
      column(*velo, 3, f.velocity);
    } else if (momenta) {  // ASE writes momenta; velocity = p / m (mass 1 without masses)
      column(*momenta, 3, f.velocity);
      for (std::size_t i = 0; mass && i < f.n; ++i)
        for (int a = 0; a < 3; ++a) f.velocity[3 * i + a] /= f.mass[i];
    }
    return f;
  }

  static std::vector<std::string> split(const std::string& text, char sep) {
    std::vector<std::string> out;
    std::string piece;
    std::istringstream in(text);
    while (std::getline(in, piece, sep)) out.push_back(piece);
    return out;
  }

  int dim_ = 3;
};

}  // namespace

std::unique_ptr<FrameSource> open_lammps_dump(const std::string& path) { return std::make_unique<LammpsDumpSource>(path); }
std::unique_ptr<FrameSource> open_extended_xyz(const std::string& path) { return std::make_unique<ExtendedXyzSource>(path); }

}  // namespace gg::frames
