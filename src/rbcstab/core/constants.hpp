#pragma once
// Constants that several modules and their tests use, declared once.
#include <numbers>

namespace rbcstab {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2 * std::numbers::pi;

}  // namespace rbcstab
