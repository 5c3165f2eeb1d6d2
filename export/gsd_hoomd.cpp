// Snapshots as GSD frames in the HOOMD schema (glotzerlab/gsd doc/schema-hoomd.rst, version 1.4).
// HOOMD knows 2D and 3D boxes: a 2D box has Lz = 0 and dimensions = 2. A 1D system of rods goes in
// as a 2D strip one diameter wide (Ly = 1, every y = 0), so that HOOMD readers, which refuse
// dimensions = 1, show it as the row of touching-or-apart disks it is. HOOMD's box is periodic
// along every axis, the schema has no other: a box the run closed along an axis (walls, H5MD
// boundary "none") is written as it is, periodic there too.
#include <cmath>
#include <cstdint>
#include <string>

#include "frame_sink.hpp"
#include "gg/gsd_file.hpp"

namespace gg::exporter {
namespace {

class GsdSink : public FrameSink {
 public:
  GsdSink(OutputFile& file, const std::string& application) : gsd_(file, application, "hoomd", 1, 4) {}

  void frame(const Frame& f) override {
    const auto n = static_cast<std::uint32_t>(f.n);
    const auto step = static_cast<std::uint64_t>(f.step);
    const std::uint8_t dimensions = f.dim == 3 ? 3 : 2;
    // HOOMD's tilt factor xy: a2 = (xy L_y, L_y, 0) (HOOMD-blue's documentation of its box).
    const auto xy = static_cast<float>(f.dim >= 2 ? sliding_shift(f) / f.edges[1] : 0.0);
    float box[6] = {static_cast<float>(f.edges[0]), f.dim >= 2 ? static_cast<float>(f.edges[1]) : 1.0f,
                    f.dim == 3 ? static_cast<float>(f.edges[2]) : 0.0f, xy, 0, 0};
    gsd_.chunk("configuration/step", gsd::Type::kUint64, 1, 1, &step);
    gsd_.chunk("configuration/dimensions", gsd::Type::kUint8, 1, 1, &dimensions);
    gsd_.chunk("configuration/box", gsd::Type::kFloat, 6, 1, box);
    gsd_.chunk("log/time", gsd::Type::kDouble, 1, 1, &f.time);
    gsd_.chunk("particles/N", gsd::Type::kUint32, 1, 1, &n);
    if (first_) {  // attributes: frame 0's values hold for every frame of the same N
      const std::string type_name = f.dim == 1 ? "rod" : f.dim == 2 ? "disk" : "sphere";
      gsd_.chunk("particles/types", gsd::Type::kInt8, 1, static_cast<std::uint32_t>(type_name.size() + 1),
                 type_name.c_str());
      if (!f.radius) {
        const std::vector<float> ones(f.n, 1.0f);
        gsd_.chunk("particles/diameter", gsd::Type::kFloat, n, 1, ones.data());
        gsd_.chunk("particles/mass", gsd::Type::kFloat, n, 1, ones.data());
      }
      first_ = false;
    }
    if (f.radius) {  // aggregates grow: every frame its own diameters and masses
      std::vector<float> diameter(f.n), mass(f.n);
      for (std::size_t i = 0; i < f.n; ++i)
        diameter[i] = static_cast<float>(2 * f.radius[i]), mass[i] = static_cast<float>(f.mass[i]);
      gsd_.chunk("particles/diameter", gsd::Type::kFloat, n, 1, diameter.data());
      gsd_.chunk("particles/mass", gsd::Type::kFloat, n, 1, mass.data());
    }
    std::vector<std::int32_t> image(f.image ? 3 * f.n : 0);
    gsd_.chunk("particles/position", gsd::Type::kFloat, n, 3, centred(f, xy, image).data());
    if (f.velocity) gsd_.chunk("particles/velocity", gsd::Type::kFloat, n, 3, padded(f, f.velocity).data());
    // HOOMD's unwrapped position is position + image_x a1 + image_y a2 + image_z a3: the centring
    // shifts every position by the same half box, so the image is that of the lattice
    // (lattice_image()) less the whole L_x a sheared run's positions moved by into HOOMD's cell.
    if (f.image) gsd_.chunk("particles/image", gsd::Type::kInt32, n, 3, image.data());
    gsd_.end_frame();
  }

  void finish() override { gsd_.finish(); }

 private:
  // [n][dim] doubles as [n][3] floats, the missing axes 0.
  static std::vector<float> padded(const Frame& f, const double* v) {
    std::vector<float> out(3 * f.n, 0.0f);
    for (std::size_t i = 0; i < f.n; ++i)
      for (int a = 0; a < f.dim; ++a) out[3 * i + a] = static_cast<float>(v[i * f.dim + a]);
    return out;
  }

  // x - L/2 in [-L/2, L/2): a float that rounds up to L/2 steps back below it. In a sheared box
  // (tilt xy) HOOMD's cell is x - xy y in [-L_x/2, L_x/2) (BoxDim::wrap), so x then moves by whole
  // L_x, the lattice vector a1, into it: never by a2, so the velocities need no change (a move by a2
  // would add a L_y to v_x). `image` (empty: none) gets each particle's lattice image, less those moves.
  static std::vector<float> centred(const Frame& f, float xy, std::vector<std::int32_t>& image) {
    std::vector<float> out(3 * f.n, 0.0f);
    for (std::size_t i = 0; i < f.n; ++i) {
      if (!image.empty()) {
        const std::array<double, 3> n = lattice_image(f, i);
        for (int a = 0; a < 3; ++a) image[3 * i + a] = static_cast<std::int32_t>(n[a]);
      }
      for (int a = f.dim - 1; a >= 0; --a) {  // y before x, whose cell leans with y
        const double L = f.edges[a], half = 0.5 * L;
        const double lean = a == 0 && xy != 0 ? static_cast<double>(xy) * static_cast<double>(out[3 * i + 1]) : 0.0;
        double x = f.position[i * f.dim + a] - half;
        if (lean != 0) {
          const double moves = std::floor((x - lean) / L + 0.5);
          x -= L * moves;
          if (!image.empty()) image[3 * i] += static_cast<std::int32_t>(moves);
        }
        float stored = static_cast<float>(x);
        while (static_cast<double>(stored) - lean >= half) stored = std::nextafter(stored, -HUGE_VALF);
        while (static_cast<double>(stored) - lean < -half) stored = std::nextafter(stored, HUGE_VALF);
        out[3 * i + a] = stored;
      }
    }
    return out;
  }

  gsd::Writer gsd_;
  bool first_ = true;
};

}  // namespace

std::unique_ptr<FrameSink> gsd_sink(OutputFile& file, const std::string& application) {
  return std::make_unique<GsdSink>(file, application);
}

}  // namespace gg::exporter
