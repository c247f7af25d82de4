#include "algorithms/registry.h"

#include <stdexcept>

#include "algorithms/accumulator/accumulator.h"
#include "algorithms/bc3/bc3.h"
#include "algorithms/bc4/bc4.h"
#include "algorithms/fault/fault.h"
#include "algorithms/hc3/hc3.h"
#include "algorithms/hc4/hc4.h"
#include "algorithms/icsp_graph/icsp_graph.h"
#include "algorithms/landmark_tracking/landmark_tracking.h"
#include "algorithms/particle_filter/particle_filter.h"
#include "algorithms/polynomial/polynomial.h"
#include "algorithms/q_relaxed/q_relaxed.h"
#include "algorithms/test_estimators/test_estimators.h"
#include "algorithms/three_b/three_b.h"
#include "core/near_names.h"

namespace icp {

namespace {
std::deque<AlgorithmInfo>& Table() {
  static std::deque<AlgorithmInfo> table = {
      CspAlgorithm<HC3Params, &MakeHC3>(
          "hc3", "HC3: constraints decomposed into primitives with auxiliary variables, AC3 queue",
          {"HC3", 10, "#8c564b"}),
      CspAlgorithm<HC4Params, &MakeHC4>(
          "hc4", "HC4: HC4Revise (forward-backward on each constraint's tree) propagated to a fixpoint",
          {"HC4", 20, "#1f77b4"}),
      CspAlgorithm<BC3Params, &MakeBC3>(
          "bc3", "BC3: box consistency per (constraint, variable) by interval Newton and bisection",
          {"BC3", 30, "#ff7f0e"}),
      CspAlgorithm<BC4Params, &MakeBC4>(
          "bc4", "BC4: HC4Revise for single occurrences, BC3 narrowing for multiple ones",
          {"BC4", 40, "#2ca02c"}),
      CspAlgorithm<ThreeBParams<BC4Params>, &MakeThreeBBC4>(
          "3b-bc4", "3B consistency: bounds shaved in slices refuted by BC4 (the paper's 3B-BC4)",
          {"3B-BC4", 50, "#d62728"}),
      CspAlgorithm<ThreeBParams<HC4Params>, &MakeThreeBHC4>(
          "3b-hc4", "3B consistency: bounds shaved in slices refuted by HC4",
          {"3B-HC4", 60, "#9467bd"}),
      {"digo", "paper 004's DIGO: the window's graph of ICSPs by an inner contractor, landmarks kept",
       &MakeDigo, &DefaultParams<IcspGraphParams>, &ResolveIcspGraph, View::kCsp,
       {"DIGO", 70, "#1b9e77"}, &MakeDigoContractor},
      {"lic", "paper 004's LIC: each ICSP of the newest step solved alone, landmarks kept",
       &MakeLic, &DefaultParams<IcspGraphParams>, &ResolveIcspGraph, View::kCsp,
       {"LIC", 80, "#d95f02"}, &MakeLicContractor},
      {"landmark-tracking", "paper 002: typed landmarks tracked, matches by belief functions fused by constraint propagation",
       &MakeLandmarkTracking, &DefaultParams<LandmarkTrackingParams>, &ResolveLandmarkTracking,
       View::kLandmarkObservations, {"landmark tracking", 90, "#66a61e"}},
      {"dead-reckoning", "paper 002's baseline: the odometry's pose box alone (eq. 5-7)",
       &MakeDeadReckoning, &DefaultParams<DeadReckoningParams>, &ResolveParams<DeadReckoningParams>,
       View::kLandmarkObservations, {"dead reckoning", 95, "#a6761d"}},
      {"q-relaxed", "q-relaxed intersection of the measurement contractors, to a fixpoint or paved (RSIVIA)",
       &MakeQRelaxed, &DefaultParams<QRelaxedParams>, &ResolveParams<QRelaxedParams>,
       View::kMeasurementSet, {"q-relaxed", 100, "#17a2b8"}},
      {"polynomial", "contractor polynomial by the Horner scheme: the set for every number of outliers",
       &MakePolynomial, &DefaultParams<PolynomialParams>, &ResolveParams<PolynomialParams>,
       View::kMeasurementSet, {"polynomial", 110, "#6f42c1"}},
      {"accumulator", "grid accumulator of the measurements (OpenCV, TBB); cells with the highest count",
       &MakeAccumulator, &DefaultParams<AccumulatorParams>, &ResolveParams<AccumulatorParams>,
       View::kMeasurementSet, {"accumulator", 120, "#e83e8c"}},
      {"particle-filter", "particle filter (SIR): systematic resampling, random particles injected, thesis 003 §6.7",
       &MakeParticleFilter, &DefaultParams<ParticleFilterParams>, &ResolveParticleFilter,
       View::kProbabilistic, {"particle filter", 200, "#8c6d31"}},
      {"fault", "not an algorithm: injects a crash, hang, exception or bad box (harness tests)",
       &MakeFault, &DefaultParams<FaultParams>, &ResolveParams<FaultParams>, View::kCsp,
       {"fault", 900, "#7f7f7f"}, nullptr, true},
      {"test-paving", "not an algorithm: a paving of the newest state's box (harness tests)",
       &MakeTestPaving, &DefaultParams<TestPavingParams>, &ResolveParams<TestPavingParams>,
       View::kCsp, {"test paving", 910, "#17becf"}, nullptr, true},
      {"test-accumulator", "not an algorithm: a grid accumulator over the newest state's x-y box (harness tests)",
       &MakeTestAccumulator, &DefaultParams<TestAccumulatorParams>,
       &ResolveParams<TestAccumulatorParams>, View::kCsp, {"test accumulator", 920, "#bcbd22"},
       nullptr, true},
      {"test-particles", "not an algorithm: particles drawn in the newest state's box (harness tests)",
       &MakeTestParticles, &DefaultParams<TestParticlesParams>,
       &ResolveParams<TestParticlesParams>, View::kCsp, {"test particles", 930, "#e377c2"},
       nullptr, true},
  };
  return table;
}
}  // namespace

const std::deque<AlgorithmInfo>& Algorithms() { return Table(); }

const AlgorithmInfo& FindAlgorithm(const std::string& name) {
  std::string known;
  std::vector<std::string> names;
  for (const AlgorithmInfo& a : Algorithms()) {
    if (a.name == name) return a;
    known += (known.empty() ? "" : ", ") + a.name;
    names.push_back(a.name);
  }
  throw std::invalid_argument("unknown algorithm '" + name + "'" + DidYouMean(name, names) +
                              " (known: " + known + ")");
}

ContractorFactory InnerContractorFactory(const std::string& owner, const std::string& inner) {
  ContractorFactory factory = nullptr;
  try {
    factory = FindAlgorithm(inner).contractor;
  } catch (const std::invalid_argument& e) {
    throw ParamError(owner + ".inner = " + inner + ": " + e.what());
  }
  if (factory == nullptr || inner == "digo" || inner == "lic")
    throw ParamError(owner + ".inner = " + inner + ": not a CSP contractor (hc4, bc4, 3b-bc4, ...)");
  return factory;
}

void DescribeAlgorithm(const std::string& name, std::string description) {
  FindAlgorithm(name);  // the error for an unknown name
  for (AlgorithmInfo& a : Table())
    if (a.name == name) a.description = std::move(description);
}

void RegisterAlgorithm(AlgorithmInfo info) {
  for (const AlgorithmInfo& a : Algorithms())
    if (a.name == info.name)
      throw std::invalid_argument("algorithm '" + info.name + "' is already registered");
  // Its parameters are declared now, so that a name declared twice or one
  // that cannot be written (ParamError) refuses the algorithm, not every run.
  if (info.params != nullptr) info.params(info.name);
  Table().push_back(std::move(info));
}

}  // namespace icp
