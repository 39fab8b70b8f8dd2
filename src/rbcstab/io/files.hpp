#pragma once
#include <string>

namespace rbcstab {

// Writes the whole content to path atomically (temporary file in the same folder, then rename):
// a reader never sees a half-written file. Throws std::runtime_error naming the path on failure.
void write_file_atomic(const std::string& path, const std::string& content);
std::string read_file(const std::string& path);  // throws InvalidArgument("file", ...) if unreadable

}  // namespace rbcstab
