// Data and JSON between Python and usvid: a dict of channel name to 1-D numpy array (with the
// time "t") is a Dataset, NaN a sample not taken; a JSON value is the Python value json.loads
// gives.
#pragma once

#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

#include "core/dataset.h"

namespace usvid::python {

// Throws InputError for a dict without "t", a time that does not strictly increase, arrays that
// are not 1-D numbers or whose lengths differ from t's.
Dataset ToDataset(const pybind11::dict& data);
pybind11::dict ToDict(const Dataset& data);

// Throws InputError for a value JSON cannot hold.
nlohmann::json ToJson(const pybind11::handle& value);
pybind11::dict FromJson(const nlohmann::json& value);

}  // namespace usvid::python
