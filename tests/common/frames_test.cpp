// Frames from other codes (gg/frames.hpp): small files written here by hand, each value known, and a
// seeded mutator over valid GSD, LAMMPS and XYZ files: every mutation is read cleanly or refused with
// gg::RuntimeError / gg::UsageError, never a crash, a hang or another exception (run again under the
// sanitizers, label memory).
#include "gg/frames.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <typeinfo>

#include "gg/errors.hpp"
#include "gg/gsd_file.hpp"
#include "gg/output_file.hpp"
#include "test_support.hpp"

namespace gg {
namespace {

using test::expect_error;
using test::TempDir;
using test::write_bytes;

// Three atoms in a box [-2, 6) x [1, 5) x [-0.5, 0.5): ids out of order, scaled x, unscaled y.
const std::string kDump =
    "ITEM: TIMESTEP\n40\nITEM: NUMBER OF ATOMS\n3\nITEM: BOX BOUNDS pp pp pp\n-2 6\n1 5\n-0.5 0.5\n"
    "ITEM: ATOMS y id xs vx z diameter\n"
    "2.5 3 0.25 -1 0 2\n4.5 1 0.5 0.5 0 2\n1 2 0.125 0 0 2\n"
    "ITEM: TIME\n0.75\nITEM: TIMESTEP\n80\nITEM: NUMBER OF ATOMS\n3\nITEM: BOX BOUNDS pp pp pp\n-2 6\n1 5\n-0.5 0.5\n"
    "ITEM: ATOMS id xs y z vx diameter\n1 1.5 9 0 1 2\n2 0 1 0 2 2\n3 -0.25 1 0 3 2\n";

TEST(CommonFrames, LammpsDumpBySortedIdsScaledAndUnscaled) {
  TempDir dir;
  write_bytes(dir.file("a.lammpstrj"), kDump);
  const auto source = open_frames(dir.file("a.lammpstrj"));
  ASSERT_EQ(source->format(), FrameFormat::kLammpsDump);
  ASSERT_EQ(source->frames(), 2u);
  const ParticleFrame f = source->read(0);
  EXPECT_EQ(f.dim, 2);  // every z is 0
  EXPECT_EQ(f.edges, (std::vector<double>{8, 4}));
  EXPECT_EQ(f.step, 40);
  EXPECT_EQ(f.time, 40);  // no ITEM: TIME in this frame
  // id 1: xs 0.5 -> x = 4 from the lower corner; y 4.5 - 1 = 3.5. id 2: 1, 0. id 3: 2, 1.5.
  EXPECT_EQ(f.position, (std::vector<double>{4, 3.5, 1, 0, 2, 1.5}));
  EXPECT_EQ(f.velocity, (std::vector<double>{0.5, 0, 0, 0, -1, 0}));
  EXPECT_EQ(f.radius, (std::vector<double>{1, 1, 1}));
  const ParticleFrame g = source->read(1);
  EXPECT_EQ(g.time, 0.75);
  // Unwrapped: xs 1.5 -> 12 -> 4 in the box; y 9 -> 8 -> 0; xs -0.25 -> -2 -> 6.
  EXPECT_EQ(g.position, (std::vector<double>{4, 0, 0, 0, 6, 0}));
}

TEST(CommonFrames, ExtendedXyzWithOriginMomentaAndMasses) {
  TempDir dir;
  write_bytes(dir.file("a.xyz"),
              "2\nlattice=\"10 0 0 0 20 0 0 0 30\" Properties=species:S:1:pos:R:3:momenta:R:3:masses:R:1 "
              "Origin=\"-5 0 0\" time=2.5\nAr -5 1 2 2 4 6 2\nAr 6 39 3 1 1 1 4\n");
  const auto source = open_frames(dir.file("a.xyz"));
  ASSERT_EQ(source->format(), FrameFormat::kExtendedXyz);
  const ParticleFrame f = source->read(0);
  EXPECT_EQ(f.dim, 3);
  EXPECT_EQ(f.edges, (std::vector<double>{10, 20, 30}));
  EXPECT_EQ(f.time, 2.5);
  EXPECT_EQ(f.position, (std::vector<double>{0, 1, 2, 1, 19, 3}));  // 11 - 10, 39 - 20
  EXPECT_EQ(f.velocity, (std::vector<double>{1, 2, 3, 0.25, 0.25, 0.25}));
  EXPECT_EQ(f.mass, (std::vector<double>{2, 4}));
  EXPECT_TRUE(f.radius.empty());
}

// A GSD file from gg's writer: frame 1 lacks the box and the diameters, which the HOOMD schema takes
// from frame 0.
void write_gsd(const std::string& path) {
  OutputFile file(path, true);
  gsd::Writer w(file, "test", "hoomd", 1, 4);
  const std::uint32_t n = 2;
  const std::uint8_t dims = 2;
  const float box[6] = {8, 4, 0, 0, 0, 0}, diameter[2] = {1, 0.5f};
  const float p0[6] = {-4, -2, 0, 3.5f, 1.5f, 0}, p1[6] = {0, 0, 0, 1, 1, 0};
  const std::uint64_t steps[2] = {10, 20};
  w.chunk("configuration/step", gsd::Type::kUint64, 1, 1, &steps[0]);
  w.chunk("configuration/dimensions", gsd::Type::kUint8, 1, 1, &dims);
  w.chunk("configuration/box", gsd::Type::kFloat, 6, 1, box);
  w.chunk("particles/N", gsd::Type::kUint32, 1, 1, &n);
  w.chunk("particles/diameter", gsd::Type::kFloat, 2, 1, diameter);
  w.chunk("particles/position", gsd::Type::kFloat, 2, 3, p0);
  w.end_frame();
  w.chunk("configuration/step", gsd::Type::kUint64, 1, 1, &steps[1]);
  w.chunk("particles/position", gsd::Type::kFloat, 2, 3, p1);
  w.end_frame();
  w.finish();
  file.commit();
}

TEST(CommonFrames, GsdHoomdSchemaWithFrameZeroDefaults) {
  TempDir dir;
  write_gsd(dir.file("a.gsd"));
  const auto source = open_frames(dir.file("a.gsd"));
  ASSERT_EQ(source->format(), FrameFormat::kGsd);
  ASSERT_EQ(source->frames(), 2u);
  const ParticleFrame f = source->read(0), g = source->read(1);
  EXPECT_EQ(f.dim, 2);
  EXPECT_EQ(f.position, (std::vector<double>{0, 0, 7.5, 3.5}));
  EXPECT_EQ(f.time, 10);  // no log/time: the step
  EXPECT_EQ(g.edges, (std::vector<double>{8, 4}));
  EXPECT_EQ(g.position, (std::vector<double>{4, 2, 5, 3}));
  EXPECT_EQ(g.radius, (std::vector<double>{0.5, 0.25}));
  EXPECT_EQ(g.step, 20);
}

TEST(CommonFrames, RefusalsNameTheFileAndTheFix) {
  TempDir dir;
  write_bytes(dir.file("walls.dump"), std::string(kDump).replace(kDump.find("pp pp pp"), 8, "pp ff pp"));
  expect_error<RuntimeError>([&] { open_frames(dir.file("walls.dump"))->read(0); },
                             {"walls.dump", "frame 0", "not periodic along y"});
  write_bytes(dir.file("novel.xyz"), "1\nLattice=\"1 0 0 0 1 0 0 0 1\"\nAr 0 0 0\n");
  EXPECT_THROW(read_with_velocities(*open_frames(dir.file("novel.xyz")), 0), RuntimeError);
  expect_error<RuntimeError>([&] { read_with_velocities(*open_frames(dir.file("novel.xyz")), 0); },
                             {"novel.xyz", "no velocities"});
  write_bytes(dir.file("notes.txt"), "mean mass\n");
  expect_error<RuntimeError>([&] { open_frames(dir.file("notes.txt")); }, {"notes.txt", "not an HDF5 file", "LAMMPS"});
}

// Flips, deletes, duplicates and overwrites bytes with digits and separators: the shapes a damaged or
// hand-edited text or GSD file takes.
std::string mutate(std::string bytes, std::mt19937_64& rng) {
  const int edits = 1 + static_cast<int>(rng() % 4);
  const std::string alphabet = "0123456789.-e \n\"=:ITEMxyzpf";
  for (int e = 0; e < edits && !bytes.empty(); ++e) {
    const std::size_t at = rng() % bytes.size();
    switch (rng() % 5) {
      case 0: bytes[at] = static_cast<char>(bytes[at] ^ (1 << (rng() % 8))); break;
      case 1: bytes.erase(at, 1 + rng() % 16); break;
      case 2: bytes.insert(at, bytes.substr(at, 1 + rng() % 32)); break;
      case 3: bytes[at] = alphabet[rng() % alphabet.size()]; break;
      case 4: bytes.resize(at); break;
    }
  }
  return bytes;
}

void fuzz(const std::string& name, const std::string& seed_bytes, int iterations) {
  TempDir dir;
  std::size_t refused = 0;
  for (int i = 0; i < iterations; ++i) {
    std::mt19937_64 rng(static_cast<std::uint64_t>(i) * 7919 + seed_bytes.size());
    const std::string path = dir.file(name);
    write_bytes(path, mutate(seed_bytes, rng));
    try {
      const auto source = open_frames(path);
      for (std::size_t k = 0; k < source->frames(); ++k) {
        const ParticleFrame f = source->read(k);
        ASSERT_EQ(f.position.size(), f.n * static_cast<std::size_t>(f.dim)) << name << " mutation " << i;
        for (std::size_t a = 0; a < f.position.size(); ++a)
          ASSERT_TRUE(f.position[a] >= 0 && f.position[a] < f.edges[a % f.dim]) << name << " mutation " << i;
      }
    } catch (const RuntimeError&) {
      ++refused;
    } catch (const UsageError&) {
      ++refused;
    } catch (const std::exception& e) {
      FAIL() << name << " mutation " << i << " threw " << typeid(e).name() << ": " << e.what();
    }
  }
  EXPECT_GT(refused, 0u) << "no mutation refused: the mutator does nothing";
}

TEST(CommonFrames, MutatedFilesAreReadOrRefusedCleanly) {
  TempDir dir;
  write_gsd(dir.file("seed.gsd"));
  fuzz("m.gsd", test::read_bytes(dir.file("seed.gsd")), 250);
  fuzz("m.dump", kDump, 250);
  fuzz("m.xyz",
       "2\nLattice=\"10 0 0 0 20 0 0 0 0\" Properties=species:S:1:pos:R:3:velo:R:3:radius:R:1 pbc=\"T T F\" Time=1\n"
       "Ar 1 2 0 1 1 0 0.5\nAr 3 4 0 1 1 0 0.25\n1\nLattice=\"10 0 0 0 20 0 0 0 0\" pbc=\"T T F\"\nAr 1 1 0\n",
       250);
}

}  // namespace
}  // namespace gg
