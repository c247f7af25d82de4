// The claims files of experiments/*/claims.yaml, compiled in by CMake
// (paper/CMakeLists.txt) so that the binary needs no source tree.
#ifndef ICPBENCH_PAPER_CLAIMS_FILES_H_
#define ICPBENCH_PAPER_CLAIMS_FILES_H_

#include <vector>

namespace icp {

struct EmbeddedClaims {
  const char* path;  // "experiments/paper000/claims.yaml"
  const char* text;
};
const std::vector<EmbeddedClaims>& EmbeddedClaimsFiles();

}  // namespace icp

#endif  // ICPBENCH_PAPER_CLAIMS_FILES_H_
