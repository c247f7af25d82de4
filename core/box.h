// Box: a Cartesian product of intervals, one per variable of a CSP.
#ifndef ICPBENCH_CORE_BOX_H_
#define ICPBENCH_CORE_BOX_H_

#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

#include "core/interval.h"

namespace icp {

class Box {
 public:
  Box() = default;
  explicit Box(std::size_t n) : v_(n) {}
  Box(std::initializer_list<Interval> list) : v_(list) {}
  explicit Box(std::vector<Interval> v) : v_(std::move(v)) {}

  std::size_t size() const { return v_.size(); }
  void push_back(const Interval& x) { v_.push_back(x); }
  Interval& operator[](std::size_t i) { return v_[i]; }
  const Interval& operator[](std::size_t i) const { return v_[i]; }
  auto begin() const { return v_.begin(); }
  auto end() const { return v_.end(); }

  // A box is empty when any of its components is.
  bool IsEmpty() const {
    for (const Interval& x : v_)
      if (x.IsEmpty()) return true;
    return false;
  }
  void SetEmpty() {
    for (Interval& x : v_) x = Interval::Empty();
  }
  bool IsSubsetOf(const Box& other) const;
  bool Contains(const std::vector<double>& point) const;
  // Largest component width.
  double MaxWidth() const;

  friend bool operator==(const Box& a, const Box& b) { return a.v_ == b.v_; }

 private:
  std::vector<Interval> v_;
};

// The smallest box holding a and b; an empty box counts as no points.
Box Hull(const Box& a, const Box& b);
// Component by component; empty in every component when some is.
Box Intersect(const Box& a, const Box& b);
// The first component of box with a NaN bound, or -1. Asked before
// emptiness: a NaN bound reads as an empty component (!(lo <= hi)), which a
// result checked only for emptiness would pass as "no solution".
int FirstNaNComponent(const Box& box);
// Component i's name in messages: names[i], or "component i" past them.
std::string ComponentName(const std::vector<std::string>& names, std::size_t i);

}  // namespace icp

#endif  // ICPBENCH_CORE_BOX_H_
