#include "python/python_data.h"

#include <pybind11/numpy.h>

#include <cmath>
#include <string>

#include "core/error.h"

namespace py = pybind11;

namespace usvid::python {
namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

Eigen::VectorXd ToVector(const py::handle& value, const std::string& name) {
  Array a;
  try {
    a = Array::ensure(value);
  } catch (const py::error_already_set&) {
  }
  if (!a || a.ndim() != 1)
    throw InputError("data: channel '" + name + "' is not a 1-D array of numbers");
  Eigen::VectorXd v(a.shape(0));
  for (py::ssize_t i = 0; i < a.shape(0); ++i) v(i) = a.at(i);
  return v;
}

}  // namespace

Dataset ToDataset(const py::dict& data) {
  if (!data.contains("t")) throw InputError("data: no time channel 't'");
  Eigen::VectorXd t = ToVector(data["t"], "t");
  for (Eigen::Index i = 0; i < t.size(); ++i)
    if (!std::isfinite(t(i)) || (i > 0 && !(t(i) > t(i - 1))))
      throw InputError("data: t must be finite and strictly increasing (row " +
                       std::to_string(i + 1) + ")");
  Dataset d(t);
  for (const auto& [key, value] : data) {
    const std::string name = py::str(key).cast<std::string>();
    if (name == "t") continue;
    Eigen::VectorXd v = ToVector(value, name);
    if (v.size() != t.size())
      throw InputError("data: channel '" + name + "' has " + std::to_string(v.size()) +
                       " values, t has " + std::to_string(t.size()));
    const Eigen::Array<bool, Eigen::Dynamic, 1> sampled = v.array().isFinite();
    if (sampled.all()) {
      d.Set(name, std::move(v));
    } else {
      for (Eigen::Index i = 0; i < v.size(); ++i)
        if (std::isinf(v(i)))
          throw InputError("data: channel '" + name + "' has an infinite value (row " +
                           std::to_string(i + 1) + ")");
      d.Set(name, std::move(v), sampled);
    }
  }
  return d;
}

py::dict ToDict(const Dataset& data) {
  py::dict out;
  auto array = [](const Eigen::VectorXd& v) {
    Array a(v.size());
    std::copy(v.data(), v.data() + v.size(), a.mutable_data());
    return a;
  };
  out["t"] = array(data.t());
  for (const Channel& c : data.channels()) out[py::str(c.name)] = array(c.values());
  return out;
}

nlohmann::json ToJson(const py::handle& value) {
  std::string text;
  try {
    text = py::module_::import("json").attr("dumps")(value).cast<std::string>();
  } catch (const py::error_already_set& e) {
    throw InputError(std::string("not a JSON value: ") + e.what());
  }
  return nlohmann::json::parse(text);
}

py::dict FromJson(const nlohmann::json& value) {
  return py::module_::import("json").attr("loads")(value.dump()).cast<py::dict>();
}

}  // namespace usvid::python
