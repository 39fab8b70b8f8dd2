// rbcstab.Model: the system a scene runs on (make_scene_system: the System object simulate integrates) as an ODE
// y' = F(t, y) for SciPy and users' own code: its right-hand side, its analytic Jacobian (the structured
// J = M + v w^T, densified), its initial state and the observables simulate reports. Every value is a library
// call; this file only checks arguments and moves numbers between numpy and the library.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "rbcstab/analysis/truncation.hpp"
#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/model/modal_model.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab::python {

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

// x as a C-contiguous float64 array: the caller's own buffer when it already is one (no copy), else converted.
// Only real numbers convert (integer or float dtypes, or sequences of them): strings, booleans, complex values and
// other objects are a TypeError.
Array real_array(const py::handle& x, const std::string& name) {
  if (py::isinstance<py::array_t<double>>(x)) {  // a float64 array: copied only if it is not C-contiguous
    Array out = Array::ensure(x);
    if (out) return out;
  }
  if (py::isinstance<py::str>(x) || py::isinstance<py::bytes>(x) || x.is_none())
    throw py::type_error(name + " must be an array of real numbers, got " + type_name(x));
  py::array a = py::isinstance<py::array>(x) ? py::reinterpret_borrow<py::array>(x) : py::array::ensure(x);
  if (!a) throw py::type_error(name + " must be an array of real numbers, got " + type_name(x));
  const py::object dtype = a.attr("dtype");
  const std::string kind = py::str(dtype.attr("kind"));
  if (kind != "f" && kind != "i" && kind != "u")
    throw py::type_error(name + " must be an array of real numbers, got dtype " + std::string(py::str(dtype)));
  Array out = Array::ensure(a);
  if (!out) throw py::type_error(name + " cannot be converted to float64 (dtype " + std::string(py::str(dtype)) + ")");
  return out;
}

void require_finite(const Array& a, const std::string& name) {
  const double* p = a.data();
  for (py::ssize_t i = 0; i < a.size(); ++i)
    if (!std::isfinite(p[i]))
      throw py::value_error(name + " must be finite: element " + std::to_string(i) + " is " + std::to_string(p[i]));
}

double time_of(const py::handle& t) {
  if (py::isinstance<py::str>(t) || py::isinstance<py::bytes>(t) || py::isinstance<py::bool_>(t) ||
      !py::hasattr(t, "__float__"))
    throw py::type_error("t must be a real number, got " + type_name(t));
  const double v = py::float_(py::reinterpret_borrow<py::object>(t));
  if (!std::isfinite(v)) throw py::value_error("t must be finite, got " + std::to_string(v));
  return v;
}

// One state: a finite 1-D array of length n.
Array state_of(const py::handle& y, std::size_t n) {
  Array a = real_array(y, "y");
  if (a.ndim() != 1 || std::size_t(a.shape(0)) != n)
    throw py::value_error("y must have shape (" + std::to_string(n) + ",) (the model's state), got shape " +
                          shape_text(a));
  require_finite(a, "y");
  return a;
}

// The state's components by name, in the order of each level's layout (full_model.hpp, modal_model.hpp,
// reduced_model.hpp).
std::vector<std::string> state_names(const System& s) {
  std::vector<std::string> names(s.dimension());
  auto f = [](int l, int m) { return "f[" + std::to_string(l) + "," + std::to_string(m) + "]"; };
  switch (s.level()) {
    case ModelLevel::full:
      for (int l = 2; l <= s.L(); ++l)
        for (int m = -l; m <= l; ++m) {
          const std::size_t k = ModeAmplitudes::index(l, m);
          names[2 * k] = "Re " + f(l, m);
          names[2 * k + 1] = "Im " + f(l, m);
        }
      break;
    case ModelLevel::modal: {
      names = {f(2, 0), "Re " + f(2, 1), "Im " + f(2, 1), "Re " + f(2, 2), "Im " + f(2, 2)};
      for (int l : dynamic_cast<const ModalModel&>(s).active_modes()) names.push_back("ln Delta_" + std::to_string(l));
      break;
    }
    case ModelLevel::reduced:
      names = {"Re z", "Im z", "w"};
      break;
    case ModelLevel::automatic:
      throw std::logic_error("state_names: a system has a concrete level");
  }
  return names;
}

class Model {
 public:
  explicit Model(const py::handle& scene) : file_(scene_file(scene)) {
    py::gil_scoped_release release;
    apply_truncation(file_, TruncationUse::simulation);
    built_ = make_scene_system(file_.scene);
    names_ = state_names(*built_.system);
  }

  std::size_t n() const { return built_.system->dimension(); }
  const System& system() const { return *built_.system; }
  const SceneFile& file() const { return file_; }
  const SceneSystem& built() const { return built_; }
  const std::vector<std::string>& names() const { return names_; }

  py::array_t<double> y0() const { return own(system().initial_state()); }

  // One state y (n,) gives F (n,); k states as the columns of y (n, k) give F column by column (n, k), as SciPy's
  // solve_ivp(..., vectorized=True) calls it.
  py::array_t<double> rhs(const py::handle& t, const py::handle& y) const {
    const double tt = time_of(t);
    const Array a = real_array(y, "y");
    if (a.ndim() == 1) {
      state_of(y, n());  // the shape and finiteness checks, with their messages
      py::array_t<double> out{py::ssize_t(n())};
      const std::span<const double> in(a.data(), n());
      const std::span<double> dydt(out.mutable_data(), n());
      py::gil_scoped_release release;
      system().rhs(tt, in, dydt);
      return out;
    }
    if (a.ndim() != 2 || std::size_t(a.shape(0)) != n())
      throw py::value_error("y must have shape (" + std::to_string(n()) + ",) (one state) or (" + std::to_string(n()) +
                            ", k) (k states as columns), got shape " + shape_text(a));
    require_finite(a, "y");
    const std::size_t k = std::size_t(a.shape(1));
    py::array_t<double> out({py::ssize_t(n()), py::ssize_t(k)});
    {
      py::gil_scoped_release release;
      std::vector<double> column(n()), dydt(n());
      const double* ys = a.data();
      double* F = out.mutable_data();
      for (std::size_t j = 0; j < k; ++j) {
        for (std::size_t i = 0; i < n(); ++i) column[i] = ys[i * k + j];
        system().rhs(tt, column, dydt);
        for (std::size_t i = 0; i < n(); ++i) F[i * k + j] = dydt[i];
      }
    }
    return out;
  }

  // dF/dq at (t, y): the library's difference of the systems built at q +- h (the same level and L).
  py::array_t<double> jacobian_p(const std::string& parameter, const py::handle& t, const py::handle& y) const {
    const double tt = time_of(t);
    const Array a = state_of(y, n());
    const ContinuationParameter q = continuation_parameter_from_string(parameter);
    Scene scene = file_.scene;
    scene.model = built_.level.level;
    py::array_t<double> out{py::ssize_t(n())};
    {
      py::gil_scoped_release release;
      rhs_parameter_derivative(scene, q, tt, std::span<const double>(a.data(), n()),
                               std::span<double>(out.mutable_data(), n()));
    }
    return out;
  }

  // Where dF/dy can be nonzero: the 1x1 and 2x2 blocks of J = M + v w^T and the rank-one part's rows (v_i != 0)
  // times columns (w_j != 0), at the initial state and at a perturbed one (so a component that vanishes at y0
  // alone is not taken for a structural zero).
  py::array_t<bool> jacobian_sparsity() const {
    const std::size_t N = n();
    py::array_t<bool> out({py::ssize_t(N), py::ssize_t(N)});
    bool* P = out.mutable_data();
    std::fill(P, P + N * N, false);
    std::vector<double> y = system().initial_state(), dfdt(N);
    for (int pass = 0; pass < 2; ++pass) {
      if (pass == 1)
        for (std::size_t i = 0; i < N; ++i) y[i] += 1e-3 * (1.0 + 0.37 * double(i % 7)) * (i % 2 ? -1 : 1);
      StructuredJacobian J;
      system().jacobian(0.25, y, J, dfdt);
      for (std::size_t i = 0; i < N; ++i) {
        P[i * N + i] = true;
        if (J.block_start[i] == 2) P[i * N + i + 1] = P[(i + 1) * N + i] = true;
        if (J.v.empty() || J.v[i] == 0) continue;
        for (std::size_t j = 0; j < N; ++j) P[i * N + j] = P[i * N + j] || J.w[j] != 0;
      }
    }
    return out;
  }

  py::array_t<double> jacobian(const py::handle& t, const py::handle& y) const {
    const double tt = time_of(t);
    const Array a = state_of(y, n());
    const py::ssize_t size = py::ssize_t(n());
    py::array_t<double> out({size, size});
    const std::span<const double> in(a.data(), n());
    const std::span<double> dense(out.mutable_data(), n() * n());
    {
      py::gil_scoped_release release;
      StructuredJacobian J;
      std::vector<double> dfdt(n());
      system().jacobian(tt, in, J, dfdt);
      J.to_dense(dense);
    }
    return out;
  }

  // One state (y 1-D): scalars and Delta_l (index l - 2), Psi in (-pi, pi]. Several states (y of shape (n, k), the
  // columns of solve_ivp's sol.y, at the k times t): arrays, Delta of shape (k, L - 1), Psi unwrapped along the
  // columns as simulate unwraps it along its steps.
  py::dict observables(const py::handle& t, const py::handle& y) const {
    const Array a = real_array(y, "y");
    if ((a.ndim() != 1 && a.ndim() != 2) || std::size_t(a.shape(0)) != n())
      throw py::value_error("y must have shape (" + std::to_string(n()) + ",) (one state) or (" + std::to_string(n()) +
                            ", k) (k states as columns), got shape " + shape_text(a));
    require_finite(a, "y");
    const int L = system().L();
    py::dict out;
    if (a.ndim() == 1) {
      const double tt = time_of(t);
      const Observation o = system().observe(tt, std::span<const double>(a.data(), n()));
      out["t"] = tt;
      out["Delta"] = own(std::vector<double>(o.Delta_l));
      out["sigma"] = o.sigma;
      out["r"] = o.r();
      out["Psi"] = o.Psi();
      return out;
    }
    const std::size_t k = std::size_t(a.shape(1));
    const Array times = real_array(t, "t");
    if (times.ndim() != 1 || std::size_t(times.shape(0)) != k)
      throw py::value_error("t must have shape (" + std::to_string(k) + ",) (one time per column of y), got shape " +
                            shape_text(times));
    require_finite(times, "t");
    py::array_t<double> Delta({py::ssize_t(k), py::ssize_t(L - 1)});
    std::vector<double> sigma(k), r(k), Psi(k);
    {
      py::gil_scoped_release release;
      const double* ys = a.data();
      double* D = Delta.mutable_data();
      std::vector<double> column(n());
      for (std::size_t j = 0; j < k; ++j) {
        for (std::size_t i = 0; i < n(); ++i) column[i] = ys[i * k + j];
        const Observation o = system().observe(times.data()[j], column);
        std::copy(o.Delta_l.begin(), o.Delta_l.end(), D + j * std::size_t(L - 1));
        sigma[j] = o.sigma;
        r[j] = o.r();
        Psi[j] = j == 0 ? o.Psi() : o.Psi_near(Psi[j - 1]);
      }
    }
    out["t"] = py::array_t<double>(times.size(), times.data());  // a copy: not the caller's array
    out["Delta"] = Delta;
    out["sigma"] = own(std::move(sigma));
    out["r"] = own(std::move(r));
    out["Psi"] = own(std::move(Psi));
    return out;
  }

 private:
  SceneFile file_;
  SceneSystem built_;
  std::vector<std::string> names_;
};

}  // namespace

void bind_model(py::module_& m) {
  py::class_<Model> cls(m, "Model", "The system a scene runs on (use rbcstab.Model, which documents it).");
  cls.def(py::init([](const py::handle& scene) { return std::make_unique<Model>(scene); }), py::arg("scene"));
  // The time every method takes, once for all of them.
  const std::string t_doc = " t: the time in the unit 1/shear rate, finite.";
  cls.def_property_readonly("n", &Model::n, "the state's dimension, an integer >= 1");
  cls.def_property_readonly(
      "level", [](const Model& s) { return to_string(s.built().level.level); },
      "the model level: 'full', 'modal' or 'reduced'");
  cls.def_property_readonly(
      "exact", [](const Model& s) { return s.built().level.exact; },
      "whether the level represents the scene without approximation");
  cls.def_property_readonly(
      "level_reason", [](const Model& s) { return s.built().level.reason; },
      "why this level (and what it drops if it is not exact)");
  cls.def_property_readonly(
      "warnings", [](const Model& s) { return s.built().warnings; }, "the warnings a simulation of this scene reports");
  cls.def_property_readonly(
      "L", [](const Model& s) { return s.file().scene.L; }, "the truncation: modes l = 2..L, an integer in [2, 100]");
  cls.def_property_readonly(
      "L_reason", [](const Model& s) { return s.file().L_reason; }, "why this L (as L_reason in simulate's output)");
  cls.def_property_readonly("y0", &Model::y0, "the initial state (a new array on each access)");
  cls.def_property_readonly("state_names", &Model::names, "the name of each state component, in order");
  cls.def("rhs", &Model::rhs, py::arg("t"), py::arg("y"),
          ("F(t, y): a new array of shape (n,), or (n, k) for k states as the columns of y (n, k)." + t_doc).c_str());
  cls.def("jacobian_p", &Model::jacobian_p, py::arg("parameter"), py::arg("t"), py::arg("y"),
          ("dF/dq at (t, y) for a continuation parameter q: a new array of shape (n,)." + t_doc).c_str());
  cls.def("jacobian_sparsity", &Model::jacobian_sparsity, "where dF/dy can be nonzero: a bool array (n, n).");
  cls.def("jacobian", &Model::jacobian, py::arg("t"), py::arg("y"),
          ("dF/dy at (t, y): a new array of shape (n, n)." + t_doc).c_str());
  cls.def("observables", &Model::observables, py::arg("t"), py::arg("y"),
          "Delta_l (index l - 2), sigma, r and Psi at one state y (n,) or at the columns of y (n, k) at times t (k,): "
          "t in the time unit 1/shear rate, finite.");
}

}  // namespace rbcstab::python
