// What a Python estimator, or a notebook stepping by hand, sees of a step:
// icpbench.View, a copy of the step's views (core/view.h) with the CSP's
// domains, the measurements' contractors and the probabilistic model
// callable from Python.
#ifndef ICPBENCH_PYTHON_MODULE_VIEWS_H_
#define ICPBENCH_PYTHON_MODULE_VIEWS_H_

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <vector>

#include "core/box.h"
#include "core/view.h"
#include "python/module_internal.h"

namespace icp::python {

struct PyView {
  std::shared_ptr<const Views> views;
};

py::array_t<double> Array(const std::vector<double>& values);
// A box as (lo, hi) arrays.
py::tuple BoundsOf(const Box& box);
// (lo, hi) sequences as a box; throws ValueError unless both have `size` bounds.
Box BoxFromBounds(const py::handle& lo, const py::handle& hi, std::size_t size);
// The same from bounds already converted.
Box BoxFromBounds(const std::vector<double>& lo, const std::vector<double>& hi, std::size_t size);

void BindViews(py::module_& m);

}  // namespace icp::python

#endif  // ICPBENCH_PYTHON_MODULE_VIEWS_H_
