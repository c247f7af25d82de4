// Writes the benchmark's chain windows as Minibex files, so that any binary
// with `solve` (an older icpbench, IBEX's tools) contracts the same CSPs:
//   build/bench/write_chain_windows DIR
// gives DIR/chain_w{5,10,20}_{prior,cold}_s{1..12}.bch (DIR is created if need be).
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "bench/chain_windows.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: " << argv[0] << " DIR\n";
    return 2;
  }
  const std::string dir = argv[1];
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) {
    std::cerr << "write_chain_windows: cannot create " << dir << ": " << error.message() << "\n";
    return 1;
  }
  int written = 0;
  for (int w : icp::kChainWindowLengths) {
    for (bool known : {true, false}) {
      const auto windows = icp::ChainWindows(w, known);
      for (std::size_t i = 0; i < windows.size(); ++i) {
        const std::string path = dir + "/chain_w" + std::to_string(w) + "_" + icp::HeadingName(known) +
                                 "_s" + std::to_string(i + 1) + ".bch";
        std::ofstream out(path);
        out << windows[i].ToMinibex();
        if (!out) {
          std::cerr << "write_chain_windows: cannot write " << path << "\n";
          return 1;
        }
        ++written;
      }
    }
  }
  std::cout << written << " windows in " << dir << "\n";
  return 0;
}
