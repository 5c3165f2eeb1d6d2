#pragma once
// The HDF5 layer: its .cpp files (common/src/h5_*.cpp) are the only tool code that includes HDF5
// (tests use it directly, to build damaged files). Everything else sees plain arrays.
//  - H5Input opens a file for reading; "-" reads an HDF5 file image from stdin.
//  - H5Output builds a file and publishes it atomically on commit(): a temporary name in the
//    same directory, then rename() over the file (over the file a symbolic link points to, not
//    the link). "-", and an existing device or FIFO, get the finished file written through them
//    (built in $TMPDIR first); a device node is never replaced. If commit() is never reached
//    (exception, signal), the destructor removes the temporary.
//  - require_output_is_not_an_input refuses an output that names a file the tool reads: the
//    rename on commit would replace that input.
// Dataset and group paths are absolute HDF5 paths ("/cluster/mean_mass"); parents are created.
#include <concepts>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gg {

class ScratchFile;

// A dense row-major array of doubles with its shape (rank 0 = scalar).
struct Array {
  std::vector<std::size_t> shape;
  std::vector<double> data;
  std::size_t rows() const { return shape.empty() ? 1 : shape[0]; }
};

class H5Input {
 public:
  // Throws RuntimeError naming the file if it is missing, a directory, empty, or not HDF5;
  // UsageError for "-" when stdin is a terminal (nothing was piped in).
  explicit H5Input(const std::string& path);
  ~H5Input();
  H5Input(const H5Input&) = delete;
  H5Input& operator=(const H5Input&) = delete;

  const std::string& path() const { return path_; }  // "-" shown as "<stdin>"
  bool exists(const std::string& object) const;      // group or dataset
  bool is_dataset(const std::string& object) const;
  // Shape of a dataset without reading it (empty = scalar). Throws like read() if missing.
  std::vector<std::size_t> shape(const std::string& dataset) const;
  // Any integer or float dataset, converted to double. Throws RuntimeError naming the file and
  // dataset if missing or not numeric. `rank` >= 0 additionally checks the rank.
  Array read(const std::string& dataset, int rank = -1) const;
  // Only the listed indices along the first dimension, in the order given (e.g. chosen frames
  // of a [T][N][d] dataset). Throws RuntimeError if an index is out of range.
  Array read_rows(const std::string& dataset, const std::vector<std::size_t>& rows) const;
  // Integer dataset (any rank, flattened); a float dataset is accepted if every value is integral.
  std::vector<std::int64_t> read_int(const std::string& dataset) const;
  // Attributes: nullopt / empty if the object or attribute is missing; RuntimeError if it has
  // the wrong type (or, for attr_string / attr_double, more than one element).
  std::optional<std::string> attr_string(const std::string& object, const std::string& name) const;
  std::optional<double> attr_double(const std::string& object, const std::string& name) const;
  std::vector<std::string> attr_strings(const std::string& object, const std::string& name) const;
  std::vector<double> attr_doubles(const std::string& object, const std::string& name) const;
  // Names of the members of a group (sorted), empty if not a group.
  std::vector<std::string> members(const std::string& group) const;
  // Every group and dataset below `group` reached through hard links, depth first in name order,
  // each object once: hard links may form a cycle (legal HDF5; h5ls prints "same as"), and a
  // damaged file may link a group to itself under an empty name. Throws RuntimeError naming the
  // file for groups nested deeper than 256 levels.
  std::vector<std::string> objects_below(const std::string& group) const;
  std::int64_t hid() const;  // hid_t, for H5Output::copy_from

 private:
  std::string path_;
  std::int64_t file_ = -1;
  std::unique_ptr<ScratchFile> piped_;  // stdin's bytes when stdin is a pipe (HDF5 must seek)
};

class H5Output {
 public:
  // Throws UsageError if the directory of `path` does not exist or is not writable, or for "-"
  // when stdout is a terminal (binary HDF5 would garble it) or was closed. `sealed`: the file
  // gets a whole-file checksum (gg/seal.hpp) on commit; only for a regular file.
  explicit H5Output(const std::string& path, bool sealed = false);
  ~H5Output();  // removes the temporary unless committed
  H5Output(const H5Output&) = delete;
  H5Output& operator=(const H5Output&) = delete;

  void write(const std::string& dataset, const Array& a);
  void write(const std::string& dataset, const std::vector<double>& values);  // rank 1
  void write(const std::string& dataset, const std::vector<std::int64_t>& values);  // rank 1
  // Rank-N doubles stored as 32-bit floats (snapshots at lower precision).
  void write_float(const std::string& dataset, const Array& a);
  // A [rows][...] dataset of doubles (float32 if `single_precision`) written one row at a time:
  // `fill(k, values)` puts row k's values into `values` (as many as shape[1] x shape[2] ...), so
  // only one row is ever in memory (gg-sim's snapshots, kept on disk until the output is written).
  using RowFill = std::function<void(std::size_t k, double* values)>;
  void write_rows(const std::string& dataset, const std::vector<std::size_t>& shape, const RowFill& fill,
                  bool single_precision = false);
  // The same, stored as 32-bit integers: the values `fill` gives are whole numbers (H5MD's image).
  void write_int_rows(const std::string& dataset, const std::vector<std::size_t>& shape, const RowFill& fill);
  // A second name for the existing `object` (an HDF5 hard link): H5MD shares an element's step and
  // time with position's this way.
  void link(const std::string& object, const std::string& name);
  void write_scalar(const std::string& dataset, double value);
  void write_scalar(const std::string& dataset, std::int64_t value);
  // Any other integer (int, size_t, ...) is stored as int64; without this, `write_scalar(p, 3)`
  // would be ambiguous between double and int64.
  template <std::integral T>
  void write_scalar(const std::string& dataset, T value) { write_scalar(dataset, static_cast<std::int64_t>(value)); }
  void create_group(const std::string& group);
  // Attributes are attached to an existing group or dataset; a missing `object` is created as a
  // group. Writing an attribute again replaces it. Strings are variable-length UTF-8.
  void attr(const std::string& object, const std::string& name, const std::string& value);
  void attr(const std::string& object, const std::string& name, double value);
  void attr(const std::string& object, const std::string& name, std::int64_t value);
  void attr(const std::string& object, const std::string& name, std::uint64_t value);  // e.g. seeds
  // Other integers (int, bool, ...) as int64, for the same reason as write_scalar.
  template <std::integral T>
  void attr(const std::string& object, const std::string& name, T value) { attr(object, name, static_cast<std::int64_t>(value)); }
  void attr(const std::string& object, const std::string& name, const std::vector<double>& value);
  void attr(const std::string& object, const std::string& name, const std::vector<std::int64_t>& value);
  void attr(const std::string& object, const std::string& name, const std::vector<std::string>& value);
  // Deep copy of `object` from `src` to `dest` in this file (used for input provenance).
  void copy_from(const H5Input& src, const std::string& object, const std::string& dest);
  // Flush, close and publish (rename, or copy the file to stdout for "-").
  void commit();

 private:
  std::string path_;   // as given, for messages
  std::string final_;  // the file the output replaces (a link followed), and its temporary
  std::string tmp_;
  bool sealed_;
  std::int64_t file_ = -1;
  bool committed_ = false;
  std::unique_ptr<ScratchFile> stream_;  // the file being built for stdout or a stream
  std::string stream_to_;                // the stream's name ("" = stdout)
};

// Checks now what H5Output(path) and its commit() will need at the end of a long run: for a file,
// that a file can be created and renamed in its directory (one is, then removed); `flag` names
// the option in the message (-o, --checkpoint). Throws UsageError.
void require_writable_output(const std::string& path, const std::string& flag);

// Whether output `path` is written through as a stream: "-" (stdout), or an existing device or
// FIFO. Such an output has no directory to put files beside it (a checkpoint, say).
bool is_stream_output(const std::string& path);

// Where data on its way to output `path` is best kept meanwhile: the directory the file goes to,
// or $TMPDIR (else /tmp) for stdout and streams. Throws like H5Output(path).
std::string scratch_dir_for_output(const std::string& path);

// Throws UsageError naming `output` when it is the same existing file as one of `inputs`, however
// spelled (a.h5, ./a.h5, a symlink or hard link: std::filesystem::equivalent). H5Output's commit
// renames over its path, so `gg-cluster sim.h5 -o sim.h5` would read the simulation and then
// replace it with the analysis (docs/DESIGN.md: bad input gets one line and no output). An input may be
// a dataset reference "file.h5:/group/dataset" (its file is compared). "-" (stdin/stdout) and an
// empty `output` (none asked for) never clash. Call it before opening the inputs and the output.
void require_output_is_not_an_input(const std::string& output, const std::vector<std::string>& inputs);

// Whether two names are one file: the same existing file however spelled (equivalent()), or, if
// one does not exist yet, the same path once `.`, `..` and symlinked directories are resolved.
// "-" (stdin/stdout) and an empty name are no file.
bool same_file(const std::string& a, const std::string& b);

// "1.10.8": the HDF5 library this program runs with (for provenance).
std::string hdf5_version();

}  // namespace gg
