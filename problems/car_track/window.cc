#include "problems/car_track/window.h"

#include <numbers>
#include <string>

namespace icp {

StateSpace CarStateSpace() {
  StateSpace space;
  space.names = {"x", "y", "theta"};
  space.periods = {0, 0, 2 * std::numbers::pi};
  space.x = 0;
  space.y = 1;
  return space;
}

CspView BuildCarWindow(int oldest, const std::vector<CarWindowState>& states) {
  CspView view;
  ConstraintSystem& csp = view.csp;
  const int n = static_cast<int>(states.size());
  for (int i = 0; i < n; ++i) {
    const int j = oldest + i;
    const std::string index = "[" + std::to_string(j) + "]";
    csp.AddVariable("x" + index, states[i].x);
    csp.AddVariable("y" + index, states[i].y);
    csp.AddVariable("th" + index, states[i].th);
    for (int c = 0; c < 3; ++c) view.states.push_back({j, c});
  }
  for (int i = 1; i < n; ++i) {
    const int b = 3 * (i - 1);
    Expr xp = csp.Var(b), yp = csp.Var(b + 1), thp = csp.Var(b + 2);
    Expr xj = csp.Var(b + 3), yj = csp.Var(b + 4), thj = csp.Var(b + 5);
    Expr ds = csp.Constant(states[i].ds);
    Expr dth = csp.Constant(states[i].dth);
    Expr mid_heading = thp + dth / 2.0;
    csp.AddConstraint(xj, Relation::kEq, xp + ds * Cos(mid_heading));
    csp.AddConstraint(yj, Relation::kEq, yp + ds * Sin(mid_heading));
    csp.AddConstraint(thj, Relation::kEq, thp + dth);
  }
  view.newest = oldest + n - 1;
  return view;
}

}  // namespace icp
