#pragma once
// The parameter an InvalidArgument names (and its message), for the validation tests.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "rbcstab/core/error.hpp"

namespace rbcstab::test {

// Runs f, which must throw InvalidArgument; returns the parameter it names ("" and a failure otherwise).
inline std::string invalid_parameter(const std::function<void()>& f, std::string* message = nullptr) {
  try {
    f();
  } catch (const InvalidArgument& e) {
    if (message) *message = e.what();
    return e.parameter();
  }
  ADD_FAILURE() << "expected InvalidArgument";
  return "";
}

}  // namespace rbcstab::test
