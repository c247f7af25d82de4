// Prints "HC4 chain", read from the embedded registries.
#include <iostream>

#include "algorithms/registry.h"
#include "problems/registry.h"

int main() {
  std::cout << icp::FindAlgorithm("hc4").display.label << " " << icp::FindProblem("chain").name
            << "\n";
  return 0;
}
