#include "paper/latex.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "harness/environment_error.h"

namespace icp {

namespace {

constexpr char kInstall[] =
    "install LaTeX: Debian's texlive-latex-base, texlive-latex-recommended and latexmk "
    "(bash scripts/deps.sh installs them)";

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::string FindOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return "";
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + program;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

void RequireLatex() {
  for (const char* program : {"latexmk", "pdflatex"}) {
    if (FindOnPath(program).empty())
      throw EnvironmentError(std::string("the paper needs ") + program +
                             ", which is not on PATH: " + kInstall);
  }
}

void RunLatexmk(const std::string& dir, const std::string& name) {
  const std::string log = dir + "/latexmk.log";
  // Fonts LaTeX makes on the fly (mktexpk) are cached under HOME: without a
  // writable one (env -i, cron), under the paper's directory.
  const char* home = std::getenv("HOME");
  const bool home_writable = home != nullptr && *home != '\0' && access(home, W_OK) == 0;
  const std::string font_cache = std::filesystem::absolute(dir + "/.texmf-var").string();
  const pid_t pid = fork();
  if (pid < 0) ThrowErrno("cannot start latexmk", errno);
  if (pid == 0) {
    // The child: in dir, output to the log, no terminal input.
    if (chdir(dir.c_str()) != 0) _exit(127);
    if (!home_writable) setenv("TEXMFVAR", font_cache.c_str(), 1);
    const int fd = open("latexmk.log", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int null = open("/dev/null", O_RDONLY);
    if (fd < 0 || null < 0) _exit(127);
    dup2(null, STDIN_FILENO);
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    const std::string file = name + ".tex";
    execlp("latexmk", "latexmk", "-pdf", "-interaction=nonstopmode", "-halt-on-error",
           "-file-line-error", file.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) ThrowErrno("waiting for latexmk", errno);
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
    throw EnvironmentError("latexmk could not be run in " + dir + " (see " + log +
                           "): " + kInstall);
  // LaTeX's own log says what went wrong: a missing package, or an error
  // in the generated text.
  const std::string tex_log = ReadFile(dir + "/" + name + ".log");
  const std::size_t missing = tex_log.find("LaTeX Error: File `");
  if (missing != std::string::npos) {
    const std::size_t start = missing + std::strlen("LaTeX Error: File `");
    const std::string file = tex_log.substr(start, tex_log.find('\'', start) - start);
    throw EnvironmentError("LaTeX misses " + file + " (see " + dir + "/" + name +
                           ".log): " + kInstall);
  }
  if (tex_log.find("not found") != std::string::npos && tex_log.find("Font ") != std::string::npos)
    throw EnvironmentError("LaTeX could not make a font (see " + dir + "/" + name +
                           ".log): give it a writable HOME, or install cm-super");
  std::string first_error = "see the log";
  std::istringstream lines(tex_log);
  for (std::string line; std::getline(lines, line);) {
    if (line.find(": ") != std::string::npos && line.find(".tex:") != std::string::npos) {
      first_error = line;
      break;
    }
    if (!line.empty() && line[0] == '!') {
      first_error = line;
      break;
    }
  }
  throw std::logic_error("LaTeX failed on the generated paper: " + first_error + " (" + dir + "/" +
                         name + ".log, " + log + ")");
}

}  // namespace icp
