// OutputFile: the same publish-whole rule as H5Output (h5_output.cpp), for files HDF5 does not write.
#include "gg/output_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>

#include <unistd.h>

#include "gg/errors.hpp"
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
  const fs::path target(path);
  std::error_code ec;
  if (fs::is_directory(target, ec)) throw UsageError("output " + named(path) + " is a directory; give a file name");
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(dir, ec))
    throw UsageError("output directory " + named(dir.string()) + " does not exist; create it first (mkdir -p)");
  if (access(dir.c_str(), W_OK) != 0)
    throw UsageError("output directory " + named(dir.string()) + " is not writable; choose another -o");
  tmp_ = (dir / ('.' + target.filename().string() + ".tmp." + std::to_string(getpid()))).string();
  detail::track_temp_file(tmp_);
  file_ = std::fopen(tmp_.c_str(), "w+b");
  if (!file_) {
    detail::untrack_temp_file(tmp_);
    throw RuntimeError(failed("create", tmp_));
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
  if (path_ == "-") {
    std::rewind(file_);
    std::vector<char> chunk(std::size_t{1} << 20);
    for (std::size_t n; (n = std::fread(chunk.data(), 1, chunk.size(), file_)) > 0;)
      if (std::fwrite(chunk.data(), 1, n, stdout) != n) throw RuntimeError(failed("write", "<stdout>"));
    if (std::ferror(file_) || std::fflush(stdout) != 0) throw RuntimeError(failed("write", "<stdout>"));
    std::fclose(file_);
    file_ = nullptr;
    committed_ = true;
    return;
  }
  const int closed = std::fclose(file_);
  file_ = nullptr;
  if (closed != 0) throw RuntimeError(failed("finish writing", tmp_));
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0)
    throw RuntimeError("cannot rename " + named(tmp_) + " to " + named(path_) + ": " + std::strerror(errno));
  committed_ = true;
  detail::untrack_temp_file(tmp_);
}

}  // namespace gg
