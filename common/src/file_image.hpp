#pragma once
// Repair of HDF5 file images taken with H5Fget_file_image (for "-o -").
#include <vector>

namespace gg::detail {

// HDF5 before 1.14.7 clears the "open for write" flag in the image's superblock but keeps the
// checksum computed with the flag set, so the image cannot be opened again (HDFGroup/hdf5 #1915,
// fixed upstream by PR #5489). This recomputes the checksum of a version 2 or 3 superblock at
// offset 0, as the fixed library does; other images are left alone.
void fix_superblock_checksum(std::vector<char>& image);

}  // namespace gg::detail
