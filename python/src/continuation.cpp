#include "bindings.hpp"

namespace rbcstab::python {

void bind_continuation(py::module_&) {}

}  // namespace rbcstab::python
