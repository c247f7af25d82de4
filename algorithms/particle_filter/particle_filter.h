// particle-filter: the sampling importance resampling filter (Gordon et al.
// 1993), the probabilistic baseline of thesis 003 §6.7 (600 particles, a
// share of random particles injected at resampling to recover from a wrong
// convergence). It needs the probabilistic view (core/view.h). Per step:
//   1. the particles are drawn from sample_prior at the first step, else
//      each is moved by sample_motion (in order, from the filter's one
//      seeded engine, so a seed gives the same run);
//   2. each weight is multiplied by exp(log_likelihood), the likelihoods
//      computed in parallel (TBB, when they are costly enough to gain from
//      it), the weights normalised by log-sum-exp. When every particle is
//      impossible (all log-weights -inf), the cloud is drawn anew from
//      sample_global (sample_prior when unset) and weighed again; if those
//      are all impossible too, they keep equal weights. The step reports it
//      (`reinitialised`); no weight is ever NaN;
//   3. the estimate is made from the weighted cloud (below);
//   4. if the effective sample size ESS = 1 / sum w_i^2 (normalised
//      weights) is below resample_threshold * particles, or the threshold is
//      1, the cloud is resampled to equal weights, then a share `inject` of
//      it is replaced by draws of sample_global (none when unset), then,
//      every particle jittered when roughen (ParticleFilterParams; by
//      default the view's) is positive.
//
// Periodic components (StateSpace::periods, a heading) are never wrapped by
// the motion; after each weighing every particle's value is moved by a
// multiple of the period to lie within half a period of the component's
// mean, in the frame of the previous step's centre (at the first step, of
// the values' weighted mean), so the cloud stays in one frame and the
// statistics below are those of angles. The mean: the weighted mean of each
// particle's offset from that centre, wrapped into half a period, when the
// offsets' standard deviation is below 1/16 of the period (a concentrated
// cloud, where it agrees with the circular mean to second order in the
// spread and needs no sine or cosine per particle); else the weighted
// circular mean (a spread cloud, a global start).
//
// The estimate is a ParticleEstimate: the particles, their normalised
// weights, the centre (the weighted mean; the mean above for periodic
// components) and the region, the box that stands for the set in the shared
// metrics (containment, area):
//   - "95": the credible box at level 0.95 (core/credible_box.h): per
//     component, the weighted quantiles t and 1 - t, t = (1 - 0.95^(1/d)) /
//     2 (Šidák, d components), so each component's interval holds 0.95^(1/d)
//     of the weight and the box 95 % of it when the components are
//     independent, at least 1 - 2 d t otherwise (94.9 % for d = 3; the
//     union bound: particle_filter_test) (a credible region of the cloud, not a guaranteed
//     enclosure of the truth; the harness measures how often it holds the
//     truth, and that of the 50 % and 90 % boxes: harness/coverage.h);
//   - "hull": the box hull of the particles with positive weight.
// Step properties: mean_<component> and cov_<a>_<b> (a before or equal to
// b in the state's order; weighted, normalised by the total weight, about
// the centre), resampled and reinitialised (0 or 1), injected (particles
// replaced), and from the estimate `particles` and `effective_sample_size`
// (of the weights before resampling). Run properties: resamplings,
// reinitialisations, injected (totals).
//
// A drawn state may carry hidden components after the state space's (the
// marina's sensor biases, core/view.h): they move and are resampled with
// the particle, and the estimate holds the space's components only.
//
// Not sound: a particle cloud is a sample, so the truth may lie outside the
// region; the containment rate is measured, never assumed.
#ifndef ICPBENCH_ALGORITHMS_PARTICLE_FILTER_PARTICLE_FILTER_H_
#define ICPBENCH_ALGORITHMS_PARTICLE_FILTER_PARTICLE_FILTER_H_

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "algorithms/estimator.h"
#include "core/params.h"
#include "core/random.h"

namespace icp {

// ParticleFilterParams::roughen's value for "the probabilistic view's".
inline constexpr double kRoughenOfView = -1;

struct ParticleFilterParams {
  // Number of particles; time per step is linear in it. The thesis' filter
  // used 600 on the marina; a few hundred track the car with GPS.
  int particles = 600;
  // "systematic" (one uniform draw, each particle copied floor or ceil of N
  // times its weight: the least resampling noise) or "multinomial" (N
  // independent draws).
  std::string resampling = "systematic";
  // Resample when the effective sample size falls below this fraction of
  // the particles, in [0, 1]: 1 resamples at every step, 0 never (the
  // weights then only multiply); 0.5 is the usual choice.
  double resample_threshold = 0.5;
  // Share of the particles replaced by draws of the global prior at each
  // resampling, in [0, 0.5]: the recovery of §6.7; 0 for none. Each
  // injected particle costs accuracy while it survives; a few per cent
  // suffice to recover in tens of steps.
  double inject = 0.02;
  // Regularisation after each resampling, >= 0: every particle's
  // state-space components moved by a uniform draw of standard deviation
  // roughen times the weighted cloud's in that component (hidden
  // components are left alone); 0 for none. It keeps a cloud diverse where
  // a narrow motion model and a box likelihood would leave few distinct
  // particles (docs/reproduction/thesis003.md, "Particle-filter coverage").
  // kRoughenOfView, the default: the model's own, ProbabilisticView::roughen.
  double roughen = kRoughenOfView;
  // The box that stands for the set: "95" (the 95 % credible box) or
  // "hull" (every particle of positive weight).
  std::string region = "95";
};
void Describe(ParticleFilterParams& p, ParamSet& set);

// Systematic resampling: n indices into weights (non-negative, not all 0,
// not necessarily normalised) at the positions (u + i) / n, i = 0..n-1, of
// the cumulative normalised weights, u in [0, 1) the one uniform draw. Index
// j appears floor(n w_j) or ceil(n w_j) times (w normalised), in increasing
// order. Throws std::invalid_argument for a bad weight or u.
std::vector<std::size_t> SystematicResample(const std::vector<double>& weights, std::size_t n,
                                            double u);
// Multinomial resampling: n independent draws of an index with probability
// proportional to its weight, in increasing order.
std::vector<std::size_t> MultinomialResample(const std::vector<double>& weights, std::size_t n,
                                             RandomEngine& rng);

// The regularisation's kernel (ParticleFilterParams::roughen): the first
// sd.size() components of state each moved by a uniform draw of standard
// deviation h * sd[c]. Shared with the MRPT wrapper, which jitters alike.
void Jitter(std::vector<double>& state, const std::vector<double>& sd, double h, RandomEngine& rng);

std::unique_ptr<Estimator> MakeParticleFilter(const ParamMap& params, std::uint64_t seed);
// The registry's resolver: ResolveParams, and roughen -1 or >= 0.
ParamMap ResolveParticleFilter(const std::string& owner, const ParamMap& values);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_PARTICLE_FILTER_PARTICLE_FILTER_H_
