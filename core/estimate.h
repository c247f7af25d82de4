// What an estimator returns for one step (DESIGN.md "An estimate answers the
// same questions whatever it is"): a box (ICP), a paving (inner and boundary
// boxes), a grid accumulator (counts over a grid of the search box) or
// weighted particles. Every metric, table and figure asks only the common
// queries below, so a new kind of estimate needs no change to the harness.
//
// An estimate lives in the state space of its step (StateSpace): one
// component per state variable (x, y, theta of a car), each possibly periodic.
#ifndef ICPBENCH_CORE_ESTIMATE_H_
#define ICPBENCH_CORE_ESTIMATE_H_

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <opencv2/core.hpp>

#include "core/box.h"
#include "core/grid.h"

namespace icp {

// The components of a state, e.g. {"x", "y", "theta"} with x = 0, y = 1.
struct StateSpace {
  std::vector<std::string> names;
  // Period of each component: 0 for a plain one, 2 pi for a heading (its
  // values are equal modulo the period). Empty means none is periodic.
  std::vector<double> periods;
  int x = -1;  // component of the planar position, -1 when there is none
  int y = -1;
  int size() const { return static_cast<int>(names.size()); }
  double Period(int component) const {
    return component < static_cast<int>(periods.size()) ? periods[component] : 0;
  }
};

// An open, typed property that an estimator reports beyond the shared metrics
// (work counters, a message, the q found, the number of boxes, ...).
struct Property {
  std::string name;
  std::variant<std::int64_t, double, std::string> value;
};
using Properties = std::vector<Property>;
// "int", "real" or "text".
std::string_view TypeName(const Property& p);
// The value of the integer property called name; nullopt when there is none
// (or it is not an integer).
std::optional<std::int64_t> IntProperty(const Properties& properties, std::string_view name);
// The value of the numeric (integer or real) property called name, as a
// double; nullopt when there is none.
std::optional<double> NumberProperty(const Properties& properties, std::string_view name);

class Estimate {
 public:
  virtual ~Estimate() = default;
  // "box", "paving", "accumulator", "particles".
  virtual std::string_view Kind() const = 0;
  // The smallest box holding the estimate, one interval per component; an
  // empty box when the estimate holds nothing.
  virtual Box Hull() const = 0;
  // True when point (one value per component) belongs to the estimate's set.
  virtual bool Contains(const std::vector<double>& point) const = 0;
  // Area of the set projected on components x and y, m^2, rounded up; 0 for
  // an empty set.
  virtual double Area(int x, int y) const = 0;
  // The point estimate (one value per component); the hull's midpoint unless
  // the kind knows better. Empty for an empty estimate.
  virtual std::vector<double> Centre() const;
  // What this kind knows beyond the queries (box count, max count, ESS...).
  virtual Properties Extras() const { return {}; }
  // The box holding about `level` (in (0, 1)) of a probabilistic estimate's
  // mass (core/credible_box.h), whose coverage of the truth the harness
  // measures; nullopt for a set, which claims no level.
  virtual std::optional<Box> CredibleRegion(double /*level*/) const { return std::nullopt; }
  // Why the estimate's parts cannot describe states of its dimension (named
  // by names, one per component): a paving box or a particle of another
  // size, a NaN bound, coordinate or weight, which the queries above would
  // skip as empty; "" when they can. The harness refuses such a result.
  virtual std::string Malformed(const std::vector<std::string>& /*names*/) const { return ""; }
  // Whether the estimate claims to hold every state the data allow (a box,
  // a paving, an accumulator), which the harness checks against the step's
  // domains, or weighs states by a model that may place them anywhere (a
  // particle cloud, whose containment is measured instead).
  virtual bool ClaimsEnclosure() const { return true; }
};

class BoxEstimate : public Estimate {
 public:
  explicit BoxEstimate(Box box) : box_(std::move(box)) {}
  std::string_view Kind() const override { return "box"; }
  Box Hull() const override { return box_; }
  bool Contains(const std::vector<double>& point) const override { return box_.Contains(point); }
  double Area(int x, int y) const override;

 private:
  Box box_;
};

// A paving (Jaulin et al. 2001; paper 003 §2.3): inner boxes, proven inside
// the solution set, and boundary boxes, which may hold solutions; together
// they enclose the set.
class PavingEstimate : public Estimate {
 public:
  // dimension: the boxes' number of components, so that an empty paving
  // still has an empty hull of the state's dimension.
  PavingEstimate(std::size_t dimension, std::vector<Box> inner, std::vector<Box> boundary)
      : dimension_(dimension), inner_(std::move(inner)), boundary_(std::move(boundary)) {}
  std::string_view Kind() const override { return "paving"; }
  Box Hull() const override;
  bool Contains(const std::vector<double>& point) const override;
  // The summed x-y areas of all boxes (assumed not to overlap).
  double Area(int x, int y) const override;
  Properties Extras() const override;
  std::string Malformed(const std::vector<std::string>& names) const override;
  const std::vector<Box>& inner() const { return inner_; }
  const std::vector<Box>& boundary() const { return boundary_; }

 private:
  std::size_t dimension_;
  std::vector<Box> inner_;
  std::vector<Box> boundary_;
};

// A grid accumulator (paper 003 §2.6, §5.2): counts (CV_32S) over a regular
// grid of the x-y search box, row r covering y, column c covering x. The set
// is the union of the cells whose count reaches `threshold` (m - q for a
// q-relaxed solution set); `others` bounds the components other than x, y.
class AccumulatorEstimate : public Estimate {
 public:
  AccumulatorEstimate(cv::Mat counts, Box search, int x, int y, int threshold);
  std::string_view Kind() const override { return "accumulator"; }
  Box Hull() const override;
  bool Contains(const std::vector<double>& point) const override;
  double Area(int x, int y) const override;
  Properties Extras() const override;
  const cv::Mat& counts() const { return counts_; }
  const Grid& grid() const { return grid_; }
  int threshold() const { return threshold_; }

 private:
  cv::Mat counts_;
  Grid grid_;
  int threshold_;
};

// Weighted particles (a particle filter's posterior). As a set it is the
// region box when one is given (a filter's credible region, see
// algorithms/particle_filter/particle_filter.h), else the box hull of the
// particles with positive weight (a cloud encloses nothing, so the
// consistency criterion asks whether the truth is in that box); the centre
// is the given one (a filter's mean, circular for periodic components), else
// the weighted mean.
class ParticleEstimate : public Estimate {
 public:
  // particles: one row per particle, one column per component (CV_64F);
  // weights: one per particle, not necessarily normalised.
  ParticleEstimate(cv::Mat particles, std::vector<double> weights);
  // With the region that stands for the set (one interval per component, or
  // an empty box) and the centre (one value per component, or empty for the
  // weighted mean). Throws std::invalid_argument on a size mismatch.
  ParticleEstimate(cv::Mat particles, std::vector<double> weights, Box region,
                   std::vector<double> centre);
  std::string_view Kind() const override { return "particles"; }
  Box Hull() const override;
  bool Contains(const std::vector<double>& point) const override { return Hull().Contains(point); }
  double Area(int x, int y) const override;
  std::vector<double> Centre() const override;
  // particles and effective_sample_size (1 / sum of squared normalised weights).
  Properties Extras() const override;
  // CredibleBox of the particles; an empty box when no weight is positive.
  std::optional<Box> CredibleRegion(double level) const override;
  std::string Malformed(const std::vector<std::string>& names) const override;
  bool ClaimsEnclosure() const override { return false; }
  const cv::Mat& particles() const { return particles_; }
  const std::vector<double>& weights() const { return weights_; }
  // The box hull of the particles with positive weight, whatever the region.
  Box ParticleHull() const;

 private:
  cv::Mat particles_;
  std::vector<double> weights_;
  std::optional<Box> region_;
  std::vector<double> centre_;
};

// x-y area of a box, rounded up; 0 when empty.
double BoxArea(const Box& box, int x, int y);

}  // namespace icp

#endif  // ICPBENCH_CORE_ESTIMATE_H_
