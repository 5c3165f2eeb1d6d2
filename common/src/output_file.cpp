// OutputFile: the same publish-whole rule as H5Output (h5_output.cpp), for files HDF5 does not write.
#include "gg/output_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>

#include <unistd.h>

#include "gg/errors.hpp"
#include "output_target.hpp"
#include "temp_files.hpp"

namespace gg {
namespace {

std::string named(const std::string& s) { return "'" + s + "'"; }

std::string failed(const std::string& what, const std::string& path) {
  return "cannot " + what + " " + named(path) + ": " + std::strerror(errno) + "; check disk space";
}

}  // namespace

OutputFile::OutputFile(const std::string& path, bool binary) : path_(path) {
  namespace fs = std::filesystem;
  if (path.empty()) throw UsageError("empty output file name; give -o FILE or -o - for stdout");
  if (path == "-") {
    if (binary && isatty(STDOUT_FILENO))
      throw UsageError("'-o -' writes a binary file to stdout, which is a terminal; pipe it on or give a file");
    file_ = std::tmpfile();
    if (!file_) throw RuntimeError(failed("create a temporary file for", "<stdout>"));
    return;
  }
  // Where the output goes, as for HDF5 (output_target.hpp): a device or FIFO is written through at
  // commit(), never replaced; a symbolic link keeps pointing to the file it names, which is replaced.
  const detail::OutputTarget target = detail::resolve_output(path, binary);
  if (target.kind == detail::OutputTarget::kStream) {
    stream_to_ = target.path;
    file_ = std::tmpfile();
    if (!file_) throw RuntimeError(failed("create a temporary file for", path));
    return;
  }
  final_ = target.path;
  tmp_ = (fs::path(target.dir) / ('.' + fs::path(final_).filename().string() + ".tmp." + std::to_string(getpid()))).string();
  detail::track_temp_file(tmp_);
  file_ = std::fopen(tmp_.c_str(), "w+b");
  if (!file_) {
    detail::untrack_temp_file(tmp_);
    throw RuntimeError("cannot create a file in " + named(target.dir) + " for " + named(path) + " (" + std::strerror(errno) +
                       "); choose a directory you can write to");
  }
}

OutputFile::~OutputFile() {
  if (file_) std::fclose(file_);
  if (!committed_ && !tmp_.empty()) {
    std::remove(tmp_.c_str());
    detail::untrack_temp_file(tmp_);
  }
}

void OutputFile::write(const void* data, std::size_t bytes) {
  if (bytes > 0 && std::fwrite(data, 1, bytes, file_) != bytes) throw RuntimeError(failed("write", path_));
  size_ += bytes;
}

void OutputFile::write_at(std::uint64_t offset, const void* data, std::size_t bytes) {
  if (std::fseek(file_, static_cast<long>(offset), SEEK_SET) != 0 || std::fwrite(data, 1, bytes, file_) != bytes ||
      std::fseek(file_, 0, SEEK_END) != 0)
    throw RuntimeError(failed("write", path_));
}

void OutputFile::commit() {
  if (path_ == "-" || !stream_to_.empty()) {
    const std::string name = path_ == "-" ? "<stdout>" : path_;
    std::FILE* to = path_ == "-" ? stdout : std::fopen(stream_to_.c_str(), "wb");
    if (!to) throw RuntimeError(failed("open", name));
    std::rewind(file_);
    std::vector<char> chunk(std::size_t{1} << 20);
    bool ok = true;
    for (std::size_t n; ok && (n = std::fread(chunk.data(), 1, chunk.size(), file_)) > 0;) ok = std::fwrite(chunk.data(), 1, n, to) == n;
    ok = ok && !std::ferror(file_) && std::fflush(to) == 0;
    if (to != stdout) ok = std::fclose(to) == 0 && ok;
    if (!ok) throw RuntimeError(failed("write", name));
    std::fclose(file_);
    file_ = nullptr;
    committed_ = true;
    return;
  }
  const int closed = std::fclose(file_);
  file_ = nullptr;
  if (closed != 0) throw RuntimeError(failed("finish writing", tmp_));
  if (std::rename(tmp_.c_str(), final_.c_str()) != 0)
    throw RuntimeError("cannot rename " + named(tmp_) + " to " + named(final_) + ": " + std::strerror(errno) +
                       "; nothing was replaced");
  committed_ = true;
  detail::untrack_temp_file(tmp_);
}

}  // namespace gg
