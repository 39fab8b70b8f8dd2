#include "bindings.hpp"

namespace rbcstab::python {

void bind_model(py::module_&) {}

}  // namespace rbcstab::python
