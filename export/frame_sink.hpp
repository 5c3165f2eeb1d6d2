#pragma once
// One snapshot as gg-export hands it to a format, and the three formats it writes. Coordinates
// come as H5MD holds them, in [0, L) per axis (sigma units); each format says how it places them.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gg/output_file.hpp"

namespace gg::exporter {

struct Frame {
  int dim = 2;
  std::vector<double> edges;  // [dim]
  std::vector<bool> periodic; // [dim]: false along an axis the run closed (H5MD boundary "none": walls)
  // a of a sheared run (gg-sim --shear-rate, /parameters shear_rate), or 0: its images one L_y above
  // slide along x, which makes the box triclinic (sliding_shift).
  double shear_rate = 0;
  std::size_t n = 0;
  double time = 0;            // tau
  std::int64_t step = 0;      // collisions so far
  const double* position = nullptr;  // [n][dim]
  const double* velocity = nullptr;  // [n][dim], or null
  const double* image = nullptr;     // [n][dim] whole numbers (H5MD image), or null
  // Per particle, as an aggregating run (gg-sim --aggregate) records them; null: every particle of
  // radius sigma/2 and mass 1. A particle merged into another has radius and mass 0.
  const double* radius = nullptr;    // [n]
  const double* mass = nullptr;      // [n]
};

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  virtual void frame(const Frame& f) = 0;
  virtual void finish() = 0;  // then the file is committed
};

enum class Format { kGsd, kXyz, kLammps };

// "gsd", "xyz", "lammps"; nullopt-like: throws UsageError naming the choices.
Format parse_format(const std::string& name);
// The format of `output`: `given` (--format, "" if not given) or its extension (.gsd, .xyz, .dump or
// .lammpstrj). Throws UsageError when neither tells it, or when they disagree (a .xyz file in GSD).
Format output_format(const std::string& output, const std::string& given);

// At the frame's time, a sheared run's images one L_y above are shifted along x by a L_y t modulo
// L_x, as gg-sim's Lees-Edwards boundary has them (simulate's ShearedBoundary::offset): the lattice of
// images is that of a1 = (L_x, 0, 0), a2 = (shift, L_y, 0), a triclinic box. The shift is taken in
// [-L_x/2, L_x/2), so that it is at most half the box (HOOMD's and LAMMPS's usual cell); 0 without
// shear.
double sliding_shift(const Frame& f);
// Particle i's image (f.image) in that lattice, its axes past f.dim 0. H5MD's image of a sheared run
// counts the images of the sliding brick, whose images above have slid by the whole a L_y t
// (docs/DESIGN.md "Files"), Q L_x more than sliding_shift: the lattice's x image is n_x + n_y Q.
std::array<double, 3> lattice_image(const Frame& f, std::size_t i);

// GSD, HOOMD schema 1.4 (gsd_hoomd.cpp): positions centred on the box, as HOOMD's box is (a sheared
// one triclinic, the positions in its cell); the image (lattice_image()) as particles/image. HOOMD's box is periodic
// along every axis, also where the run's is not.
std::unique_ptr<FrameSink> gsd_sink(OutputFile& file, const std::string& application);
// Extended XYZ (text_frames.cpp): positions in [0, L), the cell given by Lattice (a sheared box's
// tilted), pbc F where the box is not periodic.
std::unique_ptr<FrameSink> xyz_sink(OutputFile& file);
// LAMMPS text dump (text_frames.cpp): positions in [0, L), ids from 1, the image as ix iy iz; ff
// where the box is not periodic, a sheared box triclinic.
std::unique_ptr<FrameSink> lammps_sink(OutputFile& file);

}  // namespace gg::exporter
