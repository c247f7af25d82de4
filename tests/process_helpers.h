// Watching processes from a test through /proc (harness/runner_process_test.cc,
// harness/mpi_sweep_test.cc).
#ifndef ICPBENCH_TESTS_PROCESS_HELPERS_H_
#define ICPBENCH_TESTS_PROCESS_HELPERS_H_

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>

namespace icp::testing {

// The state letter and parent of a process from /proc; 0 when it is gone.
inline char State(pid_t pid, pid_t* parent = nullptr) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto close = text.rfind(')');
  if (close == std::string::npos) return 0;
  std::istringstream rest(text.substr(close + 1));
  char state = 0;
  pid_t ppid = 0;
  rest >> state >> ppid;
  if (parent) *parent = ppid;
  return state;
}

// Alive: present and not a zombie (an orphan's zombie may wait for a PID 1
// that never reaps it).
inline bool Alive(pid_t pid) {
  const char s = State(pid);
  return s != 0 && s != 'Z' && s != 'X';
}

// The PIDs of the live children of parent, in /proc order, that pass keep(pid).
template <class Keep>
std::vector<pid_t> LiveChildren(pid_t parent, Keep keep) {
  std::vector<pid_t> out;
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const pid_t pid = std::stoi(name);
    pid_t ppid = 0;
    const char s = State(pid, &ppid);
    if (ppid == parent && s != 0 && s != 'Z' && s != 'X' && keep(pid)) out.push_back(pid);
  }
  return out;
}

// Polls until pred() or the time is up; returns pred().
template <class Pred>
bool WaitFor(Pred pred, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return pred();
}

}  // namespace icp::testing

#endif  // ICPBENCH_TESTS_PROCESS_HELPERS_H_
