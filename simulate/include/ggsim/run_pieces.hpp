#pragma once
// The pieces of a run: each stretch of simulated time one gg-sim process ran, from the start or a
// --resume to the end or a checkpoint, with the build that ran it and the CPU it took. A checkpoint
// carries the pieces so far and a resumed run's output lists them all
// (/parameters/provenance/pieces, docs/DESIGN.md "Files"), so a result names every build behind it.
#include <string>
#include <vector>

#include "gg/h5file.hpp"

namespace ggsim {

// This program's build: its git hash (gg/version.hpp) and the checksum of its executable. Two
// builds of one commit with other compilers or flags differ in the second; a tree with uncommitted
// changes in the first ("-dirty") too.
struct Build {
  std::string git_hash;
  std::string executable;  // 16 hex digits; empty where the executable cannot be read
  bool clean() const;      // built from a committed tree
  static Build this_program();
};

struct RunPiece {
  std::string program;  // "gg-sim 0.1.0"
  Build build;
  // Whether this piece resumed a checkpoint another build wrote (--allow-other-build).
  bool other_build = false;
  double t_start = 0, t_end = 0;
  double cpu_seconds = 0;  // user + system CPU of the process up to t_end
  std::string utc_start, utc_end;
  std::string command;  // the command line, words separated by spaces
};

class RunPieces {
 public:
  // The pieces a checkpoint's `group` lists (none for a group without them).
  static RunPieces read(const gg::H5Input& in, const std::string& group);
  // Starts this process's piece at clock t; `other_build`: it resumes another build's checkpoint.
  void start(double t, const std::vector<std::string>& argv, bool other_build);
  // Ends this process's piece (so far) at clock t, with the CPU taken up to now.
  void end_at(double t);
  // Every piece in `group`, one array per field with an element per piece: the text fields as its
  // attributes, the numbers as its datasets.
  void write(gg::H5Output& out, const std::string& group) const;
  const std::vector<RunPiece>& pieces() const { return pieces_; }

 private:
  std::vector<RunPiece> pieces_;  // the last one is this process's once started
};

// Refuses (gg::UsageError, one line) to resume the checkpoint `path`, whose last piece is `pieces`',
// with another build than this one, unless `allowed` (--allow-other-build); returns whether the
// builds differ.
bool check_resume_build(const std::string& path, const RunPieces& pieces, bool allowed);

}  // namespace ggsim
