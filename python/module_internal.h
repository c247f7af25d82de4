// What the three parts of the _icpbench extension share.
#ifndef ICPBENCH_PYTHON_MODULE_INTERNAL_H_
#define ICPBENCH_PYTHON_MODULE_INTERNAL_H_

#include <pybind11/pybind11.h>

#include <string>

#include "core/params.h"

namespace icp::python {

namespace py = pybind11;

// A Python dict of parameters as the command line's key=value strings:
// True/False become true/false, numbers and strings their str().
ParamMap ToParamMap(const py::dict& params);

void BindRuns(py::module_& m);   // module_runs.cc: run_sweep
void BindSteps(py::module_& m);  // module_steps.cc: Problem, Estimator, Estimate
void BindAlgorithms(py::module_& m);  // module_algorithms.cc: estimators written in Python

}  // namespace icp::python

#endif  // ICPBENCH_PYTHON_MODULE_INTERNAL_H_
