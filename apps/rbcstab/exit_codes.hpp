#pragma once
// Exit codes of the rbcstab tool (docs/cli.md).
namespace rbcstab::cli {
constexpr int kOk = 0;              // done, every run succeeded
constexpr int kRunFailed = 1;       // input valid, but a computation ended with a failure status
constexpr int kInvalidInput = 2;    // bad flag, scene key or value: nothing was computed or written
constexpr int kOutputError = 3;     // an output file could not be written
constexpr int kInternalError = 4;   // a bug: please report
}  // namespace rbcstab::cli
