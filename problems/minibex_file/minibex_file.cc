#include "problems/minibex_file/minibex_file.h"

#include "core/minibex_parser.h"

namespace icp {

void Describe(MinibexFileParams& p, ParamSet& set) {
  set.Add("file", &p.file, "path of the Minibex file");
}

namespace {
class MinibexFileProblem : public Problem {
 public:
  explicit MinibexFileProblem(ConstraintSystem csp) : csp_(std::move(csp)) {}
  std::string_view Name() const override { return "minibex-file"; }
  int NumSteps() const override { return 1; }
  bool Next(const Box*, Step* step) override {
    if (done_) return false;
    done_ = true;
    step->index = 0;
    step->csp = csp_;
    step->truth.clear();
    return true;
  }

 private:
  ConstraintSystem csp_;
  bool done_ = false;
};
}  // namespace

std::unique_ptr<Problem> MakeMinibexFile(const ParamMap& params, std::uint64_t) {
  auto p = ParseParams<MinibexFileParams>("minibex-file", params);
  if (p.file.empty()) throw ParamError("minibex-file.file = \"\": a file path is required");
  return std::make_unique<MinibexFileProblem>(ParseMinibexFile(p.file));
}

}  // namespace icp
