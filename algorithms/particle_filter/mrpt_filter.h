// The field's standard particle filter, MRPT's mrpt::bayes::CParticleFilter
// (SIR, pfStandardProposal), run on a problem's probabilistic view with the
// same models as particle-filter: the view's sample_motion and
// log_likelihood, the same particle count, systematic resampling when the
// normalised ESS falls below BETA = the threshold. For the cross-check test
// and the benchmark beside this file only (MRPT is an optional dependency:
// include this header only where ICPBENCH_HAVE_MRPT is defined).
//
// Two things the view needs that MRPT leaves to its users: the weighted mean
// is taken after the update and before MRPT resamples (as particle-filter
// does, so both report the same estimator), and a cloud whose particles are
// all impossible is drawn anew from sample_global (MRPT would stop on the
// zero sum of weights). And one that MRPT 2.5 gets wrong: performResampling
// resets the weights only for an explicit output count (its loop runs to
// out_particle_count, 0 by default), so after executeOn the copies would
// keep their old weights; performSubstitution below resets them. After a
// resampling the copies are jittered as particle-filter does with the view's
// roughen (uniform, roughen times the weighted cloud's standard deviation
// per component), which MRPT's SIR filter does not offer.
#ifndef ICPBENCH_ALGORITHMS_PARTICLE_FILTER_MRPT_FILTER_H_
#define ICPBENCH_ALGORITHMS_PARTICLE_FILTER_MRPT_FILTER_H_

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/bayes/CParticleFilterCapable.h>
#include <mrpt/bayes/CParticleFilterData.h>
#include <mrpt/random/RandomGenerators.h>

#include "algorithms/particle_filter/particle_filter.h"
#include "core/random.h"
#include "core/view.h"

namespace icp {

using MrptParticles =
    mrpt::bayes::CParticleFilterData<std::vector<double>, mrpt::bayes::particle_storage_mode::VALUE>;

class MrptFilter : public MrptParticles,
                   public mrpt::bayes::CParticleFilterDataImpl<MrptFilter, MrptParticles::CParticleList> {
 public:
  // MRPT draws its resampling from its global generator, seeded here.
  MrptFilter(int particles, double resample_threshold, std::uint64_t seed)
      : particles_(particles), rng_(seed) {
    mrpt::random::getRandomGenerator().randomize(static_cast<std::uint32_t>(seed));
    filter_.m_options.PF_algorithm = mrpt::bayes::CParticleFilter::pfStandardProposal;
    filter_.m_options.resamplingMethod = mrpt::bayes::CParticleFilter::prSystematic;
    filter_.m_options.BETA = resample_threshold;
    filter_.m_options.sampleSize = static_cast<unsigned>(particles);
    filter_.setMinLoggingLevel(mrpt::system::LVL_ERROR);
  }

  // One step: the weighted mean of the updated cloud (x, y, ... as the view's
  // states). Draws from sample_prior at the first call.
  std::vector<double> Step(const ProbabilisticView& view) {
    view_ = &view;
    if (m_particles.empty()) {
      m_particles.resize(static_cast<std::size_t>(particles_));
      for (auto& p : m_particles) {
        p.d = view.sample_prior(rng_);
        p.log_w = 0;
      }
    }
    filter_.executeOn(*this, nullptr, nullptr);
    return mean_;
  }

  void performSubstitution(const std::vector<std::size_t>& indx) override {
    CParticleFilterDataImpl::performSubstitution(indx);
    for (auto& p : m_particles) p.log_w = 0;
    if (!(view_->roughen > 0)) return;
    for (auto& p : m_particles) Jitter(p.d, sd_, view_->roughen, rng_);
  }

 protected:
  void prediction_and_update_pfStandardProposal(
      const mrpt::obs::CActionCollection*, const mrpt::obs::CSensoryFrame*,
      const mrpt::bayes::CParticleFilter::TParticleFilterOptions&) override {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    for (auto& p : m_particles) view_->sample_motion(p.d, rng_);
    double top = -kInf;
    for (auto& p : m_particles) {
      const double ll = view_->log_likelihood(p.d);
      p.log_w += std::isnan(ll) ? -kInf : ll;
      top = std::max(top, p.log_w);
    }
    if (top == -kInf) {
      for (auto& p : m_particles) {
        p.d = view_->sample_global ? view_->sample_global(rng_) : view_->sample_prior(rng_);
        const double ll = view_->log_likelihood(p.d);
        p.log_w = std::isnan(ll) ? -kInf : ll;
        top = std::max(top, p.log_w);
      }
      if (top == -kInf) {
        for (auto& p : m_particles) p.log_w = 0;
        top = 0;
      }
    }
    mean_.assign(m_particles.front().d.size(), 0.0);
    w_.resize(m_particles.size());
    double total = 0;
    for (std::size_t i = 0; i < m_particles.size(); ++i) {
      w_[i] = std::exp(m_particles[i].log_w - top);
      total += w_[i];
      for (std::size_t c = 0; c < mean_.size(); ++c) mean_[c] += w_[i] * m_particles[i].d[c];
    }
    for (double& m : mean_) m /= total;
    if (!(view_->roughen > 0)) return;
    sd_.assign(mean_.size(), 0.0);  // every component: the car has no hidden ones
    for (std::size_t i = 0; i < m_particles.size(); ++i)
      for (std::size_t c = 0; c < sd_.size(); ++c) {
        const double e = m_particles[i].d[c] - mean_[c];
        sd_[c] += w_[i] / total * e * e;
      }
    for (double& v : sd_) v = std::sqrt(v);
  }

 private:
  int particles_;
  RandomEngine rng_;
  mrpt::bayes::CParticleFilter filter_;
  const ProbabilisticView* view_ = nullptr;
  std::vector<double> mean_;
  std::vector<double> w_;   // the weights over the largest, for the mean
  std::vector<double> sd_;  // of the weighted cloud before resampling, for the jitter
};

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_PARTICLE_FILTER_MRPT_FILTER_H_
