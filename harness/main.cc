// icpbench: the command-line tool. Exit codes: 0 success, 2 bad input
// (unknown algorithm or parameter, unreadable or malformed file, bad option),
// 1 an unexpected internal error.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <iostream>

#include "harness/list_command.h"
#include "harness/solve_command.h"

namespace {
constexpr int kUsageError = 2;
}

int main(int argc, char** argv) {
  CLI::App app{"icpbench: interval constraint propagation benchmarks"};
  app.require_subcommand(1);

  icp::SolveOptions solve;
  CLI::App* solve_cmd = app.add_subcommand("solve", "contract the box of a Minibex file");
  solve_cmd->add_option("FILE", solve.file, "Minibex file")->required();
  solve_cmd->add_option("--algorithm,-a", solve.algorithm, "algorithm name (see `list algorithms`)")
      ->capture_default_str();
  solve_cmd->add_option("--param,-p", solve.params, "algorithm parameter key=value (repeatable)");
  solve_cmd->add_option("--format,-f", solve.format, "output format: text or json")
      ->capture_default_str();
  solve_cmd->add_option("--repeat,-r", solve.repeat,
                        "contract a fresh copy N times; time_s is the median")
      ->capture_default_str();

  std::string what;
  std::string list_format = "text";
  CLI::App* list_cmd = app.add_subcommand("list", "list registered algorithms or problems");
  list_cmd->add_option("WHAT", what, "algorithms or problems")->required();
  list_cmd->add_option("--format,-f", list_format, "output format: text or json")
      ->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kUsageError;
  }

  try {
    if (*solve_cmd) {
      icp::SolveResult result = icp::Solve(solve);
      std::cout << (solve.format == "json" ? icp::SolveResultToJson(result) + "\n"
                                           : icp::SolveResultToText(result));
    } else if (*list_cmd) {
      std::cout << icp::ListPlugins(what, list_format);
    }
  } catch (const std::invalid_argument& e) {  // ParamError, unknown names, options
    std::cerr << "icpbench: " << e.what() << "\n";
    return kUsageError;
  } catch (const std::runtime_error& e) {  // MinibexError: unreadable or malformed file
    std::cerr << "icpbench: " << e.what() << "\n";
    return kUsageError;
  } catch (const std::exception& e) {
    std::cerr << "icpbench: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
