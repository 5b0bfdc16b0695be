// Why a path given as an input file cannot be read, in one phrase: a user
// who passes a folder or a file without read permission should not be
// told that it does not exist.
#pragma once

#include <string>

namespace cooperage {

/// "" when `path` is a regular file this process can open for reading;
/// otherwise "no such file", "is a directory, not a file", "is not a
/// regular file" or "cannot be read (permission denied)".
std::string unreadable_file_reason(const std::string& path);

/// Throws MeshingError(FileNotFound, "PATH: reason") unless `path` is a
/// readable regular file.
void require_readable_file(const std::string& path);

}  // namespace cooperage
