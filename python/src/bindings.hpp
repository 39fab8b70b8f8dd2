#pragma once
// Shared pieces of the Python module _rbcstab: JSON to Python objects, the Ctrl-C poll, and one bind_* function
// per source file. The module holds no logic of its own: every call is a library call (rbcstab/*).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rbcstab/core/progress.hpp"
#include "rbcstab/io/scene_file.hpp"

namespace rbcstab::python {

namespace py = pybind11;

// null -> None, numbers -> int/float, arrays -> list, objects -> dict (key order kept): json.loads of the CLI's
// --json output gives the same object.
py::object to_python(const nlohmann::json& j);

// A 1-D numpy array that owns v's buffer (moved into a capsule): no copy.
py::array_t<double> own(std::vector<double>&& v);

// A poll for the library's long loops (IntegratorOptions::poll, the continuation stop): at most every 0.1 s it
// takes the GIL and runs Python's signal handlers, so that Ctrl-C raises KeyboardInterrupt out of the C++ call.
// Call it only on the thread that released the GIL.
std::function<void()> signal_poll();

// A long call's on_progress (core/progress.hpp) as calls of a Python progress(done, total, eta), made on the
// thread that released the GIL (the library's calls come from there) at most every 0.1 s, with the GIL; finish()
// reports the last count if the throttle held it back. done and total in the call's unit (total 0: not known;
// eta 0 then). It borrows `progress`: the caller keeps it alive for the call.
class PythonProgress {
 public:
  explicit PythonProgress(const py::object& progress);
  ProgressCallback callback() const;  // empty for None: the library then skips the work
  void finish() const;                // with the GIL, after the call

 private:
  static py::object count(double v);
  struct State;
  std::shared_ptr<State> state_;
};

// The Python type name of v ("float", "str"), for TypeError messages.
std::string type_name(const py::handle& v);

// A scene key's Python keyword: the key itself, but lambda_ for lambda (a Python reserved word).
std::string keyword_of(const std::string& key);

// A library message in Python's words: each CLI flag it names becomes the keyword (--max-points: max_points,
// --L: L, --lambda: lambda_; "[--min, --max]": "[min, max]"), as docs/python.md maps them (snake_case).
std::string python_words(const std::string& message);

// The SceneFile behind a rbcstab.Scene (TypeError for anything else).
const SceneFile& scene_file(const py::handle& scene);

void bind_scene(py::module_& m);
void bind_runs(py::module_& m);
void bind_model(py::module_& m);
void bind_continuation(py::module_& m);
void bind_sweep(py::module_& m);
void bind_inverse(py::module_& m);

}  // namespace rbcstab::python
