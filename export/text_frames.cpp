// Snapshots as text: extended XYZ (as OVITO and ASE read it) and LAMMPS dump files. Both keep
// H5MD's coordinates in [0, L); the axes a 1D or 2D run lacks are 0, in a cell one diameter thick
// along them and, there, not periodic (XYZ pbc "F"; LAMMPS, whose 2D systems are periodic along z,
// gets bounds -0.5..0.5). An axis the run's box closes (H5MD boundary "none": walls) is not periodic
// either: XYZ pbc "F", LAMMPS "ff" (fixed). A sheared box's cell is the tilted one of its sliding
// images (sliding_shift); its positions stay in [0, L), a cell of the same lattice. Values are printed
// with 17 significant digits: read back, they are the H5MD doubles exactly.
#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

#include "frame_sink.hpp"

namespace gg::exporter {
namespace {

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

double axis(const Frame& f, const double* values, std::size_t i, int a) { return a < f.dim ? values[i * f.dim + a] : 0.0; }
double edge(const Frame& f, int a) { return a < f.dim ? f.edges[a] : 1.0; }

// After the header in `text`: one row per particle, `lead(i)` then x y z, the image ix iy iz (if
// stored and `images`), vx vy vz (if stored) and the radius, written out in pieces of about 1 MB so a
// frame of 1e6 particles is never held whole.
template <class Lead>
void write_particle_rows(OutputFile& file, const Frame& f, std::string& text, const Lead& lead, bool images) {
  for (std::size_t i = 0; i < f.n; ++i) {
    text += lead(i);
    for (int a = 0; a < 3; ++a) text += " " + number(axis(f, f.position, i, a));
    if (images && f.image)
      for (double n : lattice_image(f, i)) text += " " + std::to_string(static_cast<long>(n));
    if (f.velocity)
      for (int a = 0; a < 3; ++a) text += " " + number(axis(f, f.velocity, i, a));
    text += f.radius ? " " + number(f.radius[i]) + "\n" : std::string(" 0.5\n");
    if (text.size() > (1u << 20)) file.write(std::exchange(text, {}));
  }
  file.write(text);
}

class XyzSink : public FrameSink {
 public:
  explicit XyzSink(OutputFile& file) : file_(file) {}
  void frame(const Frame& f) override {
    // Lattice: the cell vectors a1 a2 a3 one after the other; a sheared box's a2 leans along x.
    const double shift = sliding_shift(f);
    std::string text = std::to_string(f.n) + "\nLattice=\"";
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        text += (a + b > 0 ? " " : "") + number(a == b ? edge(f, a) : a == 1 && b == 0 ? shift : 0.0);
    text += "\" Properties=species:S:1:pos:R:3";
    // ASE and OVITO read a column they do not know under its own name: the image as integers.
    if (f.image) text += ":image:I:3";
    if (f.velocity) text += ":velo:R:3";
    text += ":radius:R:1 Time=" + number(f.time) + " Step=" + std::to_string(f.step) + " pbc=\"";
    for (int a = 0; a < 3; ++a) text += std::string(a > 0 ? " " : "") + (a < f.dim && f.periodic[a] ? "T" : "F");
    text += "\"\n";
    const std::string species = f.dim == 1 ? "rod" : f.dim == 2 ? "disk" : "sphere";
    write_particle_rows(file_, f, text, [&](std::size_t) { return species; }, true);
  }
  void finish() override {}

 private:
  OutputFile& file_;
};

class LammpsSink : public FrameSink {
 public:
  explicit LammpsSink(OutputFile& file) : file_(file) {}
  void frame(const Frame& f) override {
    std::string text = "ITEM: TIME\n" + number(f.time) + "\nITEM: TIMESTEP\n" + std::to_string(f.step) +
                       "\nITEM: NUMBER OF ATOMS\n" + std::to_string(f.n) + "\nITEM: BOX BOUNDS";
    // A sheared box is triclinic (LAMMPS "dump", "Triclinic boxes"): "xy xz yz", and each line holds
    // the bounding box of the tilted cell along its axis and one tilt factor, xlo_bound xhi_bound xy,
    // ylo_bound yhi_bound xz, zlo_bound zhi_bound yz, with b = (xy, L_y, 0) and c = (xz, yz, L_z).
    const bool triclinic = f.shear_rate != 0;
    const double xy = sliding_shift(f);
    if (triclinic) text += " xy xz yz";
    for (int a = 0; a < 3; ++a) text += a >= f.dim || f.periodic[a] ? " pp" : " ff";
    text += "\n";
    for (int a = 0; a < 3; ++a) {
      const double lo = a < f.dim ? 0.0 : -0.5, hi = a < f.dim ? f.edges[a] : 0.5, lean = a == 0 ? xy : 0.0;
      text += number(lo + std::min(0.0, lean)) + " " + number(hi + std::max(0.0, lean));
      text += triclinic ? " " + number(lean) + "\n" : std::string("\n");
    }
    // LAMMPS's unwrapped coordinate is x + ix a + iy b + iz c (lattice_image()), as H5MD's position
    // + image x edge without shear.
    text += std::string("ITEM: ATOMS id type x y z") + (f.image ? " ix iy iz" : "") + (f.velocity ? " vx vy vz" : "") +
            " radius\n";
    write_particle_rows(file_, f, text, [](std::size_t i) { return std::to_string(i + 1) + " 1"; }, true);
  }
  void finish() override {}

 private:
  OutputFile& file_;
};

}  // namespace

std::unique_ptr<FrameSink> xyz_sink(OutputFile& file) { return std::make_unique<XyzSink>(file); }
std::unique_ptr<FrameSink> lammps_sink(OutputFile& file) { return std::make_unique<LammpsSink>(file); }

}  // namespace gg::exporter
