#pragma once
// What every fuzz target shares. A refusal by the library (InvalidArgument) is a clean outcome; any other
// exception and any broken invariant abort with a message, so that libFuzzer and the corpus replay
// (replay_main.cpp) report the input that caused it.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "rbcstab/core/error.hpp"

namespace rbcstab::fuzz {

[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz: invariant broken: %s\n", what.c_str());
  std::abort();
}

inline void expect(bool ok, const std::string& what) {
  if (!ok) fail(what);
}

// Runs f: true when it returns, false when the library refuses the input with InvalidArgument.
template <class F>
bool accepted(F&& f) {
  try {
    f();
    return true;
  } catch (const InvalidArgument&) {
    return false;
  } catch (const std::exception& e) {
    fail(std::string("an exception other than InvalidArgument: ") + e.what());
  } catch (...) {
    fail("a non-standard exception");
  }
}

inline std::string text_of(const uint8_t* data, std::size_t size) {
  return size ? std::string(reinterpret_cast<const char*>(data), size) : std::string();
}

// The pieces of text between separators ("a\nb" -> a, b; "" -> one empty piece).
inline std::vector<std::string> split(std::string_view text, char separator) {
  std::vector<std::string> out;
  for (std::size_t start = 0;;) {
    const std::size_t end = text.find(separator, start);
    out.emplace_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return out;
    start = end + 1;
  }
}

// The same double, bit for bit (NaN payloads aside): what a round trip must give back.
inline bool same(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  std::uint64_t x = 0, y = 0;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x == y;
}

}  // namespace rbcstab::fuzz
