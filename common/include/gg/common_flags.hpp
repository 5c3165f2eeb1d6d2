#pragma once
// The flags every tool takes besides its own (gg/cli.hpp adds them to a command line), in a header
// of their own so that code which only reads them does not compile the CLI library.

namespace gg {

struct CommonFlags {
  bool progress = false;  // force progress on stderr
  bool quiet = false;     // never show progress
  // Progress is shown when stderr is a terminal, unless --quiet; --progress forces it.
  bool show_progress() const;
};

}  // namespace gg
