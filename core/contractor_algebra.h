// The contractor algebra of paper 003 §4.4 (eq. 4.2), over any Contractor:
// composition (SequenceContractor), repetition (FixpointContractor),
// intersection, union and q-relaxed intersection. Each is a Contractor, so
// they nest: Fixpoint(QIntersection(measurements, q)) is the repeated
// q-relaxed intersection of the relaxed solvers. Parts are shared, so one
// measurement's contractor can appear in several combinations; a part is
// used by one contraction at a time (contractors are not thread-safe).
//
// Each is sound when its parts are: intersection and composition keep the
// points all parts keep, union the points some part keeps, q-intersection
// the points that at least m - q of the m parts keep. When the stop
// condition fires mid-way, the parts not yet applied count as the identity
// (sound) and the status is kStopped.
#ifndef ICPBENCH_CORE_CONTRACTOR_ALGEBRA_H_
#define ICPBENCH_CORE_CONTRACTOR_ALGEBRA_H_

#include <memory>
#include <vector>

#include "core/contractor.h"

namespace icp {

using SharedContractors = std::vector<std::shared_ptr<Contractor>>;

// Composition C_n o ... o C_1: each part once, in order, each on the previous
// one's result; stops early on an empty box. Only the first part is told the
// context's changed variables: the later ones also see what the earlier parts
// changed, so they are told that all did.
class SequenceContractor : public Contractor {
 public:
  explicit SequenceContractor(SharedContractors parts) : parts_(std::move(parts)) {}
  std::string_view Name() const override { return "sequence"; }
  ContractSummary Contract(Box& box, ContractContext& context) override;

 private:
  SharedContractors parts_;
};

// Repetition C^p, stopped early at an approximate fixpoint: repeats inner
// until no component shrinks by more than ratio (relative width), the box is
// empty, or max_iterations is reached. Only the first iteration is told the
// context's changed variables.
class FixpointContractor : public Contractor {
 public:
  FixpointContractor(std::shared_ptr<Contractor> inner, double ratio, int max_iterations)
      : inner_(std::move(inner)), ratio_(ratio), max_iterations_(max_iterations) {}
  std::string_view Name() const override { return "fixpoint"; }
  ContractSummary Contract(Box& box, ContractContext& context) override;

 private:
  std::shared_ptr<Contractor> inner_;
  double ratio_;
  int max_iterations_;
};

// Intersection (C_1 ∩ ... ∩ C_m)(x) = C_1(x) ∩ ... ∩ C_m(x): every part on the
// same input box. The q = 0 case of QIntersectionContractor.
class IntersectionContractor : public Contractor {
 public:
  explicit IntersectionContractor(SharedContractors parts) : parts_(std::move(parts)) {}
  std::string_view Name() const override { return "intersection"; }
  ContractSummary Contract(Box& box, ContractContext& context) override;

 private:
  SharedContractors parts_;
};

// Union (C_1 ⊔ ... ⊔ C_m)(x): the hull of the parts' results on x.
class UnionContractor : public Contractor {
 public:
  explicit UnionContractor(SharedContractors parts) : parts_(std::move(parts)) {}
  std::string_view Name() const override { return "union"; }
  ContractSummary Contract(Box& box, ContractContext& context) override;

 private:
  SharedContractors parts_;
};

// q-relaxed intersection of contractors (eq. 4.4): x ∩ the q-relaxed
// intersection of the boxes C_i(x) (core/relaxed_intersection.h), which
// keeps every point of x that at least m - q parts keep. q counts the parts
// allowed to reject a point (not, as in IBEX's CtcQInter, those that must
// keep it). q >= m leaves x unchanged.
class QIntersectionContractor : public Contractor {
 public:
  // Throws std::invalid_argument when q < 0.
  QIntersectionContractor(SharedContractors parts, int q);
  std::string_view Name() const override { return "q-intersection"; }
  ContractSummary Contract(Box& box, ContractContext& context) override;
  int q() const { return q_; }

 private:
  SharedContractors parts_;
  int q_;
  Box last_input_;                // the box of the last contraction (empty: none)
  std::vector<Box> contracted_;   // the parts' boxes of the last contraction
  std::vector<char> known_empty_;
};

}  // namespace icp

#endif  // ICPBENCH_CORE_CONTRACTOR_ALGEBRA_H_
