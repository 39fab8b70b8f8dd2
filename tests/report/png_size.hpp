#pragma once
// Width and height from a PNG's IHDR chunk (bytes 16..23, big endian), after checking the signature:
// {-1, -1} for an unreadable file, {-2, -2} for one that is not a PNG.
#include <filesystem>
#include <fstream>
#include <utility>

namespace rbcstab::test_support {

inline std::pair<int, int> png_size(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char b[24] = {};
  in.read(reinterpret_cast<char*>(b), 24);
  if (!in) return {-1, -1};
  const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  for (int k = 0; k < 8; ++k)
    if (b[k] != sig[k]) return {-2, -2};
  auto be32 = [&](int o) { return int(b[o]) << 24 | int(b[o + 1]) << 16 | int(b[o + 2]) << 8 | int(b[o + 3]); };
  return {be32(16), be32(20)};
}

}  // namespace rbcstab::test_support
