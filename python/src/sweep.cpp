#include "bindings.hpp"

namespace rbcstab::python {

void bind_sweep(py::module_&) {}

}  // namespace rbcstab::python
