#include <cctype>
#include <cmath>
#include <memory>

#include "bindings.hpp"
#include "rbcstab/core/progress.hpp"

namespace rbcstab::python {

py::object to_python(const nlohmann::json& j) {
  using value_t = nlohmann::json::value_t;
  switch (j.type()) {
    case value_t::null:
    case value_t::discarded:
      return py::none();
    case value_t::boolean:
      return py::bool_(j.get<bool>());
    case value_t::number_integer:
      return py::int_(j.get<long long>());
    case value_t::number_unsigned:
      return py::int_(j.get<unsigned long long>());
    case value_t::number_float:
      return py::float_(j.get<double>());
    case value_t::string:
      return py::str(j.get_ref<const std::string&>());
    case value_t::array: {
      py::list out;
      for (const auto& v : j) out.append(to_python(v));
      return out;
    }
    case value_t::object: {
      py::dict out;
      for (auto it = j.begin(); it != j.end(); ++it) out[py::str(it.key())] = to_python(it.value());
      return out;
    }
    case value_t::binary:
      break;
  }
  throw std::logic_error("to_python: a binary JSON value");
}

std::string python_words(const std::string& message) {
  auto letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
  auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-'; };
  std::string out;
  for (std::size_t i = 0; i < message.size(); ++i) {
    const bool starts = message.compare(i, 2, "--") == 0 && i + 2 < message.size() && letter(message[i + 2]) &&
                        (i == 0 || !(word(message[i - 1]) || message[i - 1] == '/' || message[i - 1] == '_'));
    if (!starts) {
      out += message[i];
      continue;
    }
    std::size_t end = i + 2;
    while (end < message.size() && word(message[end])) ++end;
    while (message[end - 1] == '-') --end;  // "--max-": the dash is punctuation
    std::string flag = message.substr(i + 2, end - i - 2);
    for (char& c : flag)
      if (c == '-') c = '_';
    if (out.size() >= 5 && out.compare(out.size() - 5, 5, "from ") == 0) out += "keyword ";  // "T from --T"
    out += keyword_of(flag);
    i = end - 1;
  }
  return out;
}

std::string type_name(const py::handle& v) { return py::str(py::type::handle_of(v).attr("__name__")); }

py::array_t<double> own(std::vector<double>&& v) {
  auto* heap = new std::vector<double>(std::move(v));
  py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>({py::ssize_t(heap->size())}, {py::ssize_t(sizeof(double))}, heap->data(), owner);
}

std::function<void()> signal_poll() {
  auto throttle = std::make_shared<Throttle>(0.1);  // the command line's throttle (core/progress.hpp)
  return [throttle] {
    if (!throttle->due()) return;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  };
}

struct PythonProgress::State {
  PyObject* progress = nullptr;  // borrowed; nullptr: none
  double done = 0, total = 0, reported = -1;
  Throttle throttle{0.1, true};  // the first report at once
};

PythonProgress::PythonProgress(const py::object& progress) : state_(std::make_shared<State>()) {
  if (!progress.is_none()) state_->progress = progress.ptr();
}

ProgressCallback PythonProgress::callback() const {
  if (!state_->progress) return nullptr;
  return [state = state_](double done, double total) {
    state->done = done, state->total = total;
    if (!state->throttle.due()) return;
    const double elapsed = state->throttle.elapsed();
    const double eta = total > 0 && done > 0 ? elapsed * (total - done) / done : 0.0;
    py::gil_scoped_acquire gil;
    state->reported = done;
    py::handle(state->progress)(count(done), count(total), eta);
  };
}

void PythonProgress::finish() const {
  if (state_->progress && state_->done != state_->reported)
    py::handle(state_->progress)(count(state_->done), count(state_->total), 0.0);
}

// A whole number as a Python int (points, runs, evaluations), a time as a float.
py::object PythonProgress::count(double v) {
  if (v == std::floor(v) && std::abs(v) < 1e15) return py::int_(static_cast<long long>(v));
  return py::float_(v);
}

}  // namespace rbcstab::python
