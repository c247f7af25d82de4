// The paper's LaTeX template, paper/template/icpbench.tex, compiled into the
// library (template.cc.in) so that the binary needs no source tree.
#ifndef ICPBENCH_PAPER_TEMPLATE_H_
#define ICPBENCH_PAPER_TEMPLATE_H_

namespace icp {

const char* PaperTemplate();

}  // namespace icp

#endif  // ICPBENCH_PAPER_TEMPLATE_H_
