// Thesis 003 chapter 6's figures, from the runs of experiments `marina` and
// `marina-*` (experiments/thesis003/marina.h):
//
//   fig6_7_dead_reckoning  the dead-reckoning boxes (every 50th step) and
//                          their centre against the truth, re-driven from
//                          the reference run's problem (its first prior
//                          carried by the motion's intervals alone);
//   fig6_8_marina_tracks   one panel per start (known, area, unknown): the
//                          set-membership boxes (every step) and their
//                          centres against the truth, from the stored steps
//                          of q-relaxed's configuration with the lowest
//                          centre RMSE, in a frame that shows the boxes;
//   fig6_9_particles       the particle filter from the area start (the
//                          thesis' 600 particles over 10,368 m²): the cloud
//                          of the first step and a sample of later ones,
//                          re-run from the stored run's definition, with the
//                          stored weighted-mean track and the truth;
//   fig6_errors            centre error over time, both methods.
//
// The reference run of a start: an ok run of experiment `marina` (else
// `marina-drive`, else any marina-*) at that start with steps, the smallest
// seed; each algorithm's run of that experiment, problem and seed with the
// lowest centre RMSE.
#ifndef ICPBENCH_EXPERIMENTS_THESIS003_MARINA_FIGURES_H_
#define ICPBENCH_EXPERIMENTS_THESIS003_MARINA_FIGURES_H_

#include <string>
#include <vector>

#include "core/box.h"
#include "harness/run_record.h"
#include "plots/figures.h"
#include "plots/map_figure.h"

namespace icp {

// The runs the figures draw at a start ("": any, known first), in algorithm
// display order; empty when no marina experiment has an ok run there. Runs
// stored with `record: runs` (no steps to draw) count only where no run with
// steps takes their place: as the reference when no ok run has steps, and as
// an algorithm's run when it has none with steps; the figures name them.
// Of an algorithm's configurations, the one the claims judge (q-relaxed
// with auto_q=false, particle-filter with inject=0), else the first stored.
std::vector<const RunRecord*> MarinaFigureRuns(const std::vector<RunRecord>& runs,
                                               const std::string& start = "");

// The whole map of a run's problem (the shipped one unless its params name
// another).
MapFrame MarinaMapFrame(const ParamMap& problem_params);

// The dead-reckoning boxes of a run's drive, re-driven from its problem and
// seed: the first step's prior, then each box carried by the step's motion.
std::vector<Box> MarinaDeadReckoning(const RunRecord& run);

// The particle filter of a run re-run from its definition: every particle of
// the first step, per_step particles of every every-th step after, and the
// weighted mean of every step.
struct ParticleReplay {
  std::vector<std::vector<double>> first_cloud;
  std::vector<std::vector<double>> later;
  std::vector<std::vector<double>> means;
  Box prior;  // the first step's prior
};
ParticleReplay ReplayParticles(const RunRecord& run, int every, int per_step);

// The panels of the figures (what PlotMapFigure draws), in map.
MapPanel DeadReckoningPanel(const RunRecord& run, const std::vector<Box>& reckoned,
                            const MapFrame& map);
MapPanel SetMembershipPanel(const RunRecord& run, int boxes_every, const MapFrame& map);
MapPanel ParticlePanel(const RunRecord& run, const ParticleReplay& replay, const MapFrame& map);

// The truth track of a run's stored steps, {x, y} per step.
std::vector<std::vector<double>> TruthTrack(const RunRecord& run);

// Draws the four figures; each skipped with a message when there is no ok
// run to draw (naming `record: runs` when the runs were stored without
// steps).
void MarinaFigures(const std::vector<RunRecord>& runs, const std::string& out_dir,
                   PlotOutput* out);

}  // namespace icp

#endif  // ICPBENCH_EXPERIMENTS_THESIS003_MARINA_FIGURES_H_
