// The image contractor (paper 003 §4.8) on a 1000 x 1000 map of random
// walls at 0.1 m a pixel (100 m x 100 m), on random boxes 0.1 m to 10 m
// wide: one contraction is four dichotomies of about log2(block side) ψ
// look-ups each.
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "core/image_contractor.h"
#include "core/random.h"

namespace icp {
namespace {

constexpr int kSide = 1000;
const ImageFrame kFrame{0, 0, 0.1};

// Axis-aligned walls, 1 to 3 pixels thick and up to a fifth of the map long.
cv::Mat RandomWalls(RandomEngine& rng, int walls) {
  cv::Mat image = cv::Mat::zeros(kSide, kSide, CV_8UC1);
  for (int i = 0; i < walls; ++i) {
    const int thick = static_cast<int>(UniformInt(rng, 1, 3));
    const int length = static_cast<int>(UniformInt(rng, 10, kSide / 5));
    const int r = static_cast<int>(UniformInt(rng, 0, kSide - thick));
    const int c = static_cast<int>(UniformInt(rng, 0, kSide - length));
    const bool horizontal = UniformInt(rng, 0, 1) == 0;
    if (horizontal)
      image(cv::Rect(c, r, length, thick)).setTo(1);
    else
      image(cv::Rect(r, c, thick, length)).setTo(1);
  }
  return image;
}

std::vector<Box> RandomBoxes(RandomEngine& rng, int n) {
  std::vector<Box> boxes;
  for (int i = 0; i < n; ++i) {
    const double x = UniformReal(rng, 0, 100), y = UniformReal(rng, 0, 100);
    const double w = UniformReal(rng, 0.1, 10), h = UniformReal(rng, 0.1, 10);
    boxes.push_back(Box{{x - w / 2, x + w / 2}, {y - h / 2, y + h / 2}});
  }
  return boxes;
}

void BM_ImageContract(benchmark::State& state) {
  RandomEngine rng(1);
  const BinaryImage image(RandomWalls(rng, 400), kFrame);
  const std::vector<Box> boxes = RandomBoxes(rng, 1024);
  std::size_t i = 0, empty = 0;
  for (auto _ : state) {
    const Box out = image.Contract(boxes[i++ & 1023]);
    empty += out.IsEmpty();
    benchmark::DoNotOptimize(out);
  }
  state.counters["empty_fraction"] =
      static_cast<double>(empty) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_ImageContract);

// The same through the Contractor interface, on a box with extra components.
void BM_ImageContractorContract(benchmark::State& state) {
  RandomEngine rng(1);
  ImageContractor contractor(std::make_shared<BinaryImage>(RandomWalls(rng, 400), kFrame), 1, 2);
  const std::vector<Box> boxes = RandomBoxes(rng, 1024);
  ContractContext context;
  std::size_t i = 0;
  for (auto _ : state) {
    const Box& xy = boxes[i++ & 1023];
    Box box{Interval(0, 1), xy[0], xy[1]};
    benchmark::DoNotOptimize(contractor.Contract(box, context));
  }
}
BENCHMARK(BM_ImageContractorContract);

// Building the ψ transform once per map.
void BM_BuildBinaryImage(benchmark::State& state) {
  RandomEngine rng(1);
  const cv::Mat walls = RandomWalls(rng, 400);
  for (auto _ : state) benchmark::DoNotOptimize(BinaryImage(walls, kFrame));
  state.SetItemsProcessed(state.iterations() * kSide * kSide);
}
BENCHMARK(BM_BuildBinaryImage)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace icp
