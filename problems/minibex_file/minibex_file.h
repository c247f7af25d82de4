// A single CSP read from a Minibex file; the truth is unknown. Its one step
// offers the CSP view (the whole system) and the measurement-set view (the
// domains as prior, one contractor per constraint, outliers unknown).
#ifndef ICPBENCH_PROBLEMS_MINIBEX_FILE_MINIBEX_FILE_H_
#define ICPBENCH_PROBLEMS_MINIBEX_FILE_MINIBEX_FILE_H_

#include <memory>
#include <string>

#include "core/params.h"
#include "problems/problem.h"

namespace icp {

struct MinibexFileParams {
  // Path of the Minibex file.
  std::string file;
};
void Describe(MinibexFileParams& p, ParamSet& set);

// The registry's resolver: the effective parameters, once the file is read
// and parsed (so a bad file fails before the first run).
ParamMap ResolveMinibexFile(const std::string& owner, const ParamMap& values);

std::unique_ptr<Problem> MakeMinibexFile(const ParamMap& params, std::uint64_t seed);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_MINIBEX_FILE_MINIBEX_FILE_H_
