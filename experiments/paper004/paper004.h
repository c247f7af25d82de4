// Paper 004 (Wang, Lambert, Zhang: a dynamic ICSP graph over a sliding
// window): its published values, for the paper's comparison (paper/). It
// adds no table or figure to `report` and `plot` yet, so it has no line in
// experiments/registry.cc.
//
//   consistency   eq. 31: an estimate is consistent when its box holds the
//                 reference (0 in the interval error of eq. 30); the paper's
//                 localization is consistent at every step (§5.2, Fig. 12).
//   post-localization  §4.2, Fig. 13: propagating each new observation back
//                 through a window of Xi = 50 steps keeps every step
//                 consistent and narrows the interval error corridor. Not
//                 implemented in icpbench yet: its runs are those of a spec
//                 experiment named kPaper004PostLocalization.
#ifndef ICPBENCH_EXPERIMENTS_PAPER004_PAPER004_H_
#define ICPBENCH_EXPERIMENTS_PAPER004_PAPER004_H_

namespace icp {

inline constexpr char kPaper004PostLocalization[] = "post-localization";

struct Paper004Published {
  double consistency_rate = 1;        // share of steps whose box holds the truth
  int post_localization_window = 50;  // Xi, steps
};
inline constexpr Paper004Published kPaper004;

}  // namespace icp

#endif  // ICPBENCH_EXPERIMENTS_PAPER004_PAPER004_H_
