// Running LaTeX: finding latexmk on PATH and compiling a document with it.
#ifndef ICPBENCH_PAPER_LATEX_H_
#define ICPBENCH_PAPER_LATEX_H_

#include <string>

namespace icp {

// The path of an executable program on PATH; "" when there is none.
std::string FindOnPath(const std::string& program);

// Throws EnvironmentError, saying what to install, unless latexmk and
// pdflatex are on PATH.
void RequireLatex();

// Compiles dir/NAME.tex to dir/NAME.pdf with latexmk (pdflatex, no
// interaction, stopping at the first error), its output in dir/latexmk.log.
// Throws EnvironmentError when LaTeX misses a package (a .sty or .cls
// file), std::logic_error for any other LaTeX error (the first error line
// and the log's path in the message), std::runtime_error when latexmk
// cannot be started.
void RunLatexmk(const std::string& dir, const std::string& name);

}  // namespace icp

#endif  // ICPBENCH_PAPER_LATEX_H_
