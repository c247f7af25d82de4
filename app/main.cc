// icpbench: the command-line tool. Exit codes: 0 success, 2 bad input
// (unknown algorithm or parameter, unreadable or malformed file, bad option,
// an output directory locked by another run), 3 the environment (disk full,
// descriptors, processes or memory exhausted, permissions, LaTeX missing
// for `paper`, a port `serve` cannot bind), 130/143 `run`
// stopped by SIGINT/SIGTERM, 1 an unexpected internal error.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <new>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "core/memory_budget.h"
#include "core/params.h"
#include "experiments/registry.h"
#include "harness/environment_error.h"
#include "harness/list_command.h"
#include "harness/map_command.h"
#include "harness/mpi_sweep.h"
#include "harness/output_directory.h"
#include "harness/plugin_loader.h"
#include "report/report.h"
#include "harness/results_store.h"
#include "harness/runner.h"
#include "harness/solve_command.h"
#include "harness/worker_pool.h"
#include "harness/spec.h"
#include "paper/paper.h"
#include "plots/figures.h"
#include "web/serve.h"

namespace {
constexpr int kUsageError = 2;
constexpr int kEnvironmentError = 3;

// A finite number of seconds in [lo, hi]; the message gives the range (CLI11's
// own range checks let NaN through and print an open end as DBL_MAX).
CLI::Validator SecondsIn(double lo, double hi) {
  const std::string range = "[" + icp::FormatDouble(lo) + ", " + icp::FormatDouble(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        const bool number = !text.empty() && end == text.c_str() + text.size();
        if (number && std::isfinite(v) && v >= lo && v <= hi) return "";
        return "'" + text + "' must be a number of seconds in " + range;
      },
      "SECONDS in " + range);
}

// What the process must hold before it opens anything. Descriptors 0-2 that
// were closed (2>&-, a daemon) would be taken by the first files opened (the
// output's lock, a worker's step file), which a message meant for stderr
// would then corrupt: they are /dev/null instead. A file-size limit
// (ulimit -f) makes a write fail with EFBIG, an error reported like a full
// disk (exit 3), instead of SIGXFSZ ending the process without a word.
void SetUpProcess() {
  for (int fd = 0; fd <= 2; ++fd)
    if (fcntl(fd, F_GETFD) < 0 && errno == EBADF && open("/dev/null", O_RDWR) < 0) break;
  std::signal(SIGXFSZ, SIG_IGN);
}

// A closed stderr (a pipe to `head` that ended) must not end a sweep before
// it starts, nor at its summary line: run ignores SIGPIPE from its first
// message to its last (writes to the pipe then fail, and are lost).
void KeepRunningWithoutStderr() { std::signal(SIGPIPE, SIG_IGN); }
}  // namespace

int main(int argc, char** argv) {
  SetUpProcess();
  CLI::App app{"icpbench: interval constraint propagation benchmarks"};
  app.require_subcommand(1);

  // Set before the subcommands, which inherit fallthrough: then --plugin is
  // accepted after the subcommand too.
  std::vector<std::string> plugins;
  app.add_option("--plugin", plugins,
                 "shared library that registers algorithms or problems (repeatable)")
      ->type_name("LIB.so")
      ->allow_extra_args(false);
  app.fallthrough();

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
  solve_cmd->add_option("--timeout", solve.timeout_s,
                        "seconds each contraction may take, then it stops with a sound box "
                        "(default inf: no limit)")
      ->type_name("S");

  std::string what;
  std::string list_format = "text";
  CLI::App* list_cmd = app.add_subcommand("list", "list registered algorithms or problems");
  list_cmd->add_option("WHAT", what, "algorithms or problems")->required();
  list_cmd->add_option("--format,-f", list_format, "output format: text or json")
      ->capture_default_str();

  std::string spec_file;
  icp::RunnerOptions run;
  run.jobs = icp::UsableCpus();
  std::string shard = "0/1";
  CLI::App* run_cmd = app.add_subcommand("run", "run an experiment spec (YAML) into a results store");
  run_cmd->add_option("SPEC", spec_file, "experiment spec, e.g. specs/default.yaml")->required();
  CLI::Option* run_out =
      run_cmd->add_option("--out,-o", run.out_dir, "output directory (default results/<spec name>)");
  run_cmd->add_option("--jobs,-j", run.jobs,
                      "runs in parallel (default: the cores this process may use; with --mpi, on each rank)")
      ->capture_default_str();
  run_cmd->add_option("--shard", shard,
                      "run only share i of n (i/n, 0-based) of the matrix; auto: this Slurm "
                      "array task's (SLURM_ARRAY_TASK_ID and _COUNT or _MIN/_MAX)")
      ->capture_default_str();
  bool mpi = false;
  icp::MpiSweepOptions mpi_options;
  CLI::Option* mpi_flag =
      run_cmd->add_flag("--mpi", mpi,
                        "one sweep over the ranks of mpirun -n N: rank 0 dispatches and stores, "
                        "the others run --jobs runs each");
  run_cmd->add_option("--rank-timeout", mpi_options.rank_timeout_s,
                      "with --mpi: seconds without a message after which a rank is lost (its runs "
                      "in flight go to other ranks)")
      ->capture_default_str()
      ->check(SecondsIn(icp::kMinRankTimeoutS, icp::kMaxRankTimeoutS))
      ->needs(mpi_flag);
  run_cmd->add_flag("--force", run.force, "rerun runs that are already stored");
  run_cmd->add_flag("--no-retry", run.no_retry,
                    "keep stored failed and timeout runs instead of retrying them");

  std::string merge_out;
  std::vector<std::string> merge_in;
  CLI::App* merge_cmd = app.add_subcommand("merge", "join results stores (e.g. from shards)");
  merge_cmd->add_option("OUT", merge_out, "output directory")->required();
  merge_cmd->add_option("IN", merge_in, "input directories")->required();

  std::string map_dir, map_out;
  std::vector<std::string> map_terms;
  CLI::App* map_cmd = app.add_subcommand(
      "map", "the landmark map of a visual-landmarks teach run, for a repeat run's map");
  map_cmd->add_option("DIR", map_dir, "output directory of `icpbench run`")->required();
  map_cmd->add_option("TERM", map_terms, "strings the run's key holds (digo w=10 seed=1)");
  map_cmd->add_option("--out,-o", map_out, "the map file (default: standard output)");

  std::string report_dir;
  std::string report_format = "md";
  CLI::App* report_cmd = app.add_subcommand("report", "timing and accuracy tables of a results store");
  report_cmd->add_option("DIR", report_dir, "output directory of `icpbench run`")->required();
  report_cmd->add_option("--format,-f", report_format, "md, tex or csv")->capture_default_str();

  std::string plot_dir;
  std::string plot_out;
  CLI::App* plot_cmd = app.add_subcommand("plot", "figures (PNG and PDF) of a results store");
  plot_cmd->add_option("DIR", plot_dir, "output directory of `icpbench run`")->required();
  plot_cmd->add_option("--out,-o", plot_out, "where to write the figures (default DIR/figures)");

  std::string paper_dir;
  CLI::App* paper_cmd =
      app.add_subcommand("paper", "the LaTeX paper of a results store (DIR/paper/icpbench.pdf)");
  paper_cmd->add_option("DIR", paper_dir, "output directory of `icpbench run`")->required();

  icp::web::ServeOptions serve;
  CLI::App* serve_cmd =
      app.add_subcommand("serve", "a read-only web page over a results store (docs/web.md)");
  serve_cmd->add_option("DIR", serve.dir, "output directory of `icpbench run`")->required();
  serve_cmd->add_option("--port", serve.port, "port (0: a free one)")
      ->capture_default_str()
      ->check(CLI::Range(0, 65535));
  serve_cmd->add_option("--host", serve.host,
                        "address to bind (another than localhost exposes the results)")
      ->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // A first word that is no command: CLI11 would only say that one is required.
    if (argc > 1 && argv[1][0] != '-') {
      std::string commands;
      bool known = false;
      for (const CLI::App* sub : std::as_const(app).get_subcommands([](const CLI::App*) { return true; })) {
        known = known || sub->get_name() == argv[1];
        commands += (commands.empty() ? "" : ", ") + sub->get_name();
      }
      if (!known) {
        std::cerr << "icpbench: unknown command '" << argv[1] << "' (commands: " << commands << ")\n";
        return kUsageError;
      }
    }
    app.exit(e);
    return kUsageError;
  }

  // How the command writes its output elsewhere, for the advice on an
  // output it may not write.
  std::string elsewhere = icp::kChooseAnotherOut;
  try {
    for (const std::string& plugin : plugins) icp::LoadPlugin(plugin);
    if (*solve_cmd) {
      // Past the limit a solve still finishes what it holds (an accumulator's
      // grid of 10^8 cells takes seconds): only one that goes on far longer
      // is taken for a hang.
      solve.kill_grace_s = 5;
      icp::SolveResult result = icp::Solve(solve);
      std::cout << (solve.format == "json" ? icp::SolveResultToJson(result) + "\n"
                                           : icp::SolveResultToText(result));
    } else if (*list_cmd) {
      std::cout << icp::ListPlugins(what, list_format);
    } else if (*run_cmd) {
      KeepRunningWithoutStderr();
      std::tie(run.shard_index, run.shard_count) = icp::ParseShard(shard);
      if (run.jobs < 1) throw std::invalid_argument("--jobs must be at least 1");
      // More workers than this only share the cores and use up processes
      // and descriptors.
      const int max_jobs = 4 * static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));  // all cores
      if (run.jobs > max_jobs) {
        std::cerr << "icpbench: note: --jobs " << run.jobs << " capped to " << max_jobs
                  << " (4 x the number of cores)\n";
        run.jobs = max_jobs;
      }
      if (run_out->count() > 0 && run.out_dir.empty())
        throw std::invalid_argument("--out is empty: give a directory, or leave --out out for results/<spec name>");
      if (run.out_dir.empty())
        run.out_dir = "results/" + std::filesystem::path(spec_file).stem().string();
      const bool terminal = isatty(STDERR_FILENO);
      icp::SweepSummary s;
      if (mpi) {
        const icp::MpiSweepResult r = icp::RunMpiSweep(spec_file, run, mpi_options, std::cerr, terminal);
        if (!r.dispatcher) return r.worker_exit_code;
        s = r.summary;
      } else {
        const icp::Spec spec = icp::LoadSpec(spec_file);
        std::cerr << "icpbench: " << spec.runs.size() << " runs in " << spec_file;
        if (run.shard_count > 1)
          std::cerr << ", shard " << run.shard_index << "/" << run.shard_count << " of them";
        std::cerr << ", " << run.jobs << " in parallel, results in " << icp::StorePath(run.out_dir) << "\n";
        s = icp::RunSweep(spec, run, std::cerr, terminal);
        if (s.planned == 0 && !spec.runs.empty())
          std::cerr << "icpbench: note: shard " << run.shard_index << "/" << run.shard_count
                    << " holds none of the " << spec.runs.size() << " runs (more shards than runs)\n";
      }
      std::cerr << "icpbench: " << s.planned << " planned, " << s.already_stored
                << " already stored, " << s.ok << " ok, " << s.failed << " failed, "
                << s.timed_out << " timed out, " << s.skipped << " skipped\n";
      if (s.interrupted_by != 0) {
        std::cerr << "icpbench: interrupted: " << s.stopped << " runs in flight were stopped, "
                  << s.Finished() << " finished runs kept\n";
        return 128 + s.interrupted_by;
      }
    } else if (*map_cmd) {
      std::string key;
      std::vector<int> left_out;
      const icp::LandmarkMap map = icp::MapOfStoredRun(map_dir, map_terms, &key, &left_out);
      if (!left_out.empty()) {
        std::cerr << "icpbench: left out " << left_out.size()
                  << " landmarks whose last box is empty or unbounded:";
        for (int n : left_out) std::cerr << " " << n;
        std::cerr << "\n";
      }
      if (map_out.empty()) {
        icp::WriteLandmarkMap(map, std::cout, "from run " + key);
      } else {
        // Opening or writing: the errno says why (EIO when none is set).
        auto cannot_write = [&] {
          icp::ThrowErrno("cannot write the map " + map_out, errno != 0 ? errno : EIO, "give another --out");
        };
        errno = 0;
        std::ofstream out(map_out);
        if (!out) cannot_write();
        icp::WriteLandmarkMap(map, out, "from run " + key);
        out.close();
        if (!out) cannot_write();
        std::cerr << "icpbench: " << map.size() << " landmarks in " << map_out << "\n";
      }
    } else if (*report_cmd) {
      std::cout << icp::ReportDirectory(report_dir, report_format, icp::PaperTables);
    } else if (*plot_cmd) {
      if (plot_out.empty()) plot_out = plot_dir + "/figures";
      icp::CheckWritableDirectory(plot_out, elsewhere);
      std::vector<std::string> messages;
      for (const std::string& file :
           icp::PlotDirectory(plot_dir, plot_out, &messages, icp::PaperFigures))
        std::cout << file << "\n";
      for (const std::string& m : messages) std::cerr << "icpbench: " << m << "\n";
    } else if (*paper_cmd) {
      elsewhere = icp::PaperElsewhere(paper_dir);
      const icp::PaperOutput paper = icp::BuildPaper(paper_dir);
      for (const std::string& m : paper.messages) std::cerr << "icpbench: " << m << "\n";
      std::cout << paper.pdf << "\n";
    } else if (*serve_cmd) {
      icp::web::Serve(serve, [](const std::string& url) { std::cout << url << std::endl; });
    } else if (*merge_cmd) {
      // An OUT_DIR it may not write is said as such (SQLite's own error on
      // the new store would not say why). MergeStores validates every input,
      // then writes OUT in one rename.
      elsewhere = "choose another OUT_DIR";
      icp::CheckWritableDirectory(merge_out, elsewhere);
      const icp::MergeSummary m = icp::MergeStores(merge_out, merge_in);
      for (std::size_t i = 0; i < merge_in.size(); ++i)
        std::cerr << "icpbench: merged " << m.from_input[i] << " runs from " << merge_in[i] << "\n";
      if (!m.ConflictMessage().empty()) std::cerr << "icpbench: " << m.ConflictMessage() << "\n";
      std::cerr << "icpbench: " << m.runs << " runs in " << icp::StorePath(merge_out) << "\n";
    }
  } catch (const std::filesystem::filesystem_error& e) {  // creating or replacing an output
    const int error = e.code().value();
    const bool os_error = e.code().category() == std::generic_category() ||
                          e.code().category() == std::system_category();
    if (os_error && icp::IsEnvironmentErrno(error)) {
      std::cerr << "icpbench: " << e.what() << " (" << icp::EnvironmentAdvice(error, elsewhere)
                << ")\n";
      return kEnvironmentError;
    }
    std::cerr << "icpbench: " << e.what() << "\n";
    return kUsageError;
  } catch (const icp::EnvironmentError& e) {  // disk, descriptors, processes, permissions
    std::cerr << "icpbench: " << e.what() << "\n";
    return kEnvironmentError;
  } catch (const std::bad_alloc& e) {
    // A size checked before it was allocated says what needed how much.
    if (const auto* budget = dynamic_cast<const icp::MemoryBudgetError*>(&e))
      std::cerr << "icpbench: out of memory: " << budget->what()
                << " (raise the limit, ulimit -d, or lower the size)\n";
    else
      std::cerr << "icpbench: out of memory (free memory or raise the limit, ulimit -v; or reduce "
                   "--jobs or the size of the spec or file)\n";
    return kEnvironmentError;
  } catch (const std::invalid_argument& e) {  // ParamError, unknown names, options
    std::cerr << "icpbench: " << e.what() << "\n";
    return kUsageError;
  } catch (const icp::AlgorithmFault& e) {  // a plugin's bug, or ours; named
    std::cerr << "icpbench: " << e.what() << "\n";
    return 1;
  } catch (const std::runtime_error& e) {  // MinibexError: unreadable or malformed file
    std::cerr << "icpbench: " << e.what() << "\n";
    return kUsageError;
  } catch (const std::exception& e) {
    std::cerr << "icpbench: internal error: " << e.what() << "\n";
    return 1;
  } catch (...) {  // a plugin's throw of a non-exception
    std::cerr << "icpbench: internal error: an exception of unknown type\n";
    return 1;
  }
  return 0;
}
