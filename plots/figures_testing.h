// Helpers for the tests that draw figures (plots/figures_test.cc,
// experiments/*/..._test.cc).
#ifndef ICPBENCH_PLOTS_FIGURES_TESTING_H_
#define ICPBENCH_PLOTS_FIGURES_TESTING_H_

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "harness/run_record.h"

namespace icp::testing {

inline bool GnuplotMissing() { return std::system("gnuplot --version >/dev/null 2>&1") != 0; }

// A fresh, not yet created directory under the system's temporary one.
inline std::filesystem::path TempDir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("icpbench_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

// What PlotOutput::files holds for these figures: PNG then PDF of each.
inline std::vector<std::string> FigureFiles(const std::filesystem::path& dir,
                                            std::initializer_list<const char*> names) {
  std::vector<std::string> files;
  for (const char* name : names) {
    files.push_back((dir / (std::string(name) + ".png")).string());
    files.push_back((dir / (std::string(name) + ".pdf")).string());
  }
  return files;
}

// The run as a store recorded with `record: runs` holds it: its run row
// (status, metrics) without step rows.
inline RunRecord RunsOnly(RunRecord run) {
  if (run.metrics.steps == 0) run.metrics.steps = static_cast<int>(run.steps.size());
  if (run.metrics.steps == 0) run.metrics.steps = 1;
  run.steps.clear();
  run.spec.record_steps = false;
  return run;
}

// What draw printed on stderr, gnuplot's warnings included (gnuplot is a
// child process and writes to this process' stderr, which this redirects).
inline std::string StderrOf(const std::function<void()>& draw) {
  ::testing::internal::CaptureStderr();
  draw();
  return ::testing::internal::GetCapturedStderr();
}

// How many pixels of the PNG at path have the colour (r, g, b); -1 when it
// cannot be read.
inline int PixelsOfColour(const std::string& path, int r, int g, int b) {
  const cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
  if (image.empty()) return -1;
  int n = 0;
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      const cv::Vec3b& p = image.at<cv::Vec3b>(y, x);  // BGR
      n += p[0] == b && p[1] == g && p[2] == r;
    }
  }
  return n;
}

}  // namespace icp::testing

#endif  // ICPBENCH_PLOTS_FIGURES_TESTING_H_
