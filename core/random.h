// The one way to draw random numbers (issue 8), so that a seed gives the
// same instance with every standard library: the engines of <random> are
// specified output for output, its distributions are not (libstdc++, libc++
// and MSVC turn the same engine output into different values). Boost.Random's
// distributions are fixed algorithms; these functions wrap them. Don't use
// std::*_distribution, std::shuffle or std::sample: draw through these.
// core/random_test.cc pins the first draws.
#ifndef ICPBENCH_CORE_RANDOM_H_
#define ICPBENCH_CORE_RANDOM_H_

#include <cstddef>
#include <cstdint>
#include <random>

namespace icp {

// Seeded with one integer: RandomEngine engine(seed).
using RandomEngine = std::mt19937_64;

// A uniform double in [lo, hi); lo when lo == hi. Throws
// std::invalid_argument unless lo <= hi, both finite.
double UniformReal(RandomEngine& engine, double lo, double hi);

// A uniform integer in [lo, hi], both included. Throws std::invalid_argument
// unless lo <= hi.
std::int64_t UniformInt(RandomEngine& engine, std::int64_t lo, std::int64_t hi);

// A uniform index in [0, n). Throws std::invalid_argument if n == 0.
std::size_t UniformIndex(RandomEngine& engine, std::size_t n);

}  // namespace icp

#endif  // ICPBENCH_CORE_RANDOM_H_
