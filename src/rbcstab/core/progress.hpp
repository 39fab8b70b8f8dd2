#pragma once
// Progress of a long computation as it goes: `done` of `total` in the computation's own unit (time t of T,
// branch points, criterion evaluations, runs); total 0 when not known in advance. Called often (every
// integration step): the receiver throttles what it shows. An empty callback costs nothing.
#include <functional>

namespace rbcstab {

using ProgressCallback = std::function<void(double done, double total)>;

}  // namespace rbcstab
