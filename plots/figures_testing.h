// Helpers for the tests that draw figures (plots/figures_test.cc,
// experiments/*/..._test.cc).
#ifndef ICPBENCH_PLOTS_FIGURES_TESTING_H_
#define ICPBENCH_PLOTS_FIGURES_TESTING_H_

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

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

}  // namespace icp::testing

#endif  // ICPBENCH_PLOTS_FIGURES_TESTING_H_
