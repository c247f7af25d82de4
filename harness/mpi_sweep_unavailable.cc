// The MPI sweep of a build without MPI (CMake found none): `--mpi` is a
// usage error that says how to get it.
#include <stdexcept>

#include "harness/mpi_sweep.h"

namespace icp {

bool MpiBuilt() { return false; }

MpiSweepResult RunMpiSweep(const std::string&, const RunnerOptions&, const MpiSweepOptions&, std::ostream&,
                           bool) {
  throw std::invalid_argument(
      "--mpi: this icpbench was built without MPI (install libopenmpi-dev and openmpi-bin, e.g. with "
      "scripts/deps.sh, and rebuild)");
}

}  // namespace icp
