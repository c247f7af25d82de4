#include "core/random.h"

#include <boost/random/uniform_int_distribution.hpp>
#include <boost/random/uniform_real_distribution.hpp>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/params.h"

namespace icp {

double UniformReal(RandomEngine& engine, double lo, double hi) {
  if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi))
    throw std::invalid_argument("UniformReal(" + FormatDouble(lo) + ", " + FormatDouble(hi) +
                                "): needs finite lo <= hi");
  // Boost draws until the value is below hi, forever when lo == hi.
  if (lo == hi) return lo;
  return boost::random::uniform_real_distribution<double>(lo, hi)(engine);
}

std::int64_t UniformInt(RandomEngine& engine, std::int64_t lo, std::int64_t hi) {
  if (lo > hi)
    throw std::invalid_argument("UniformInt(" + std::to_string(lo) + ", " + std::to_string(hi) +
                                "): needs lo <= hi");
  return boost::random::uniform_int_distribution<std::int64_t>(lo, hi)(engine);
}

std::size_t UniformIndex(RandomEngine& engine, std::size_t n) {
  if (n == 0) throw std::invalid_argument("UniformIndex(0): no index to draw");
  return boost::random::uniform_int_distribution<std::size_t>(0, n - 1)(engine);
}

}  // namespace icp
