// A logged drive for visual-landmarks (`log=PATH`): odometry, gyro, GPS and
// matched feature tracks, so that a real data set whose features are
// already associated with landmarks can be replayed (paper 004 §5.2 matches
// SURF features; icpbench takes the matches as given). `#` lines and blank
// lines are ignored (CRLF accepted, blanks around fields ignored, a UTF-8
// byte-order mark skipped); every other line is a row whose first field is
// its kind, with a fixed number of fields:
//
//   step,t,ds,ds_error,dtheta,dtheta_error,gps_x,gps_y,gps_error,truth_x,truth_y,truth_theta
//   track,t,landmark,u,v,pixel_error
//   landmark,landmark,x,y,z
//
// step: one time step. t in s, strictly increasing; ds, dtheta the motion
//   from the previous step (m, rad; ignored on the first row) with their
//   half-widths (>= 0); gps_x, gps_y, gps_error the GPS box (all three empty
//   without a fix); truth_x, truth_y, truth_theta the reference pose (all
//   three or none empty; the heading unwrapped, as the gyro sums it).
// track: a feature of landmark `landmark` (a non-negative integer) seen at
//   the pixel (u, v) +- pixel_error (px) in the image of the step row above,
//   whose t it repeats.
// landmark: a landmark's reference position (m), optional, for scoring.
// Values beyond 1e9 in magnitude (1e6 for angles) are errors. Throws
// std::invalid_argument naming the source, the line and the field.
#ifndef ICPBENCH_PROBLEMS_VISUAL_LANDMARKS_FEATURE_LOG_H_
#define ICPBENCH_PROBLEMS_VISUAL_LANDMARKS_FEATURE_LOG_H_

#include <iosfwd>
#include <string>

#include "problems/visual_landmarks/visual_drive.h"

namespace icp {

// The drive of a log: its steps; the poses and landmarks hold NaN where the
// log gives no reference. Landmarks are numbered as the log numbers them
// (the vector holds every identity up to the largest).
VisualDrive ReadFeatureLog(std::istream& in, const std::string& source);
VisualDrive ReadFeatureLog(const std::string& path);
// Writes a drive in that format (shortest round-trip doubles; t = the step
// number), after '#' lines holding comment, if any. Intervals are written as
// centre and half-width, the half-width rounded up, so they read back
// enclosing what was written.
void WriteFeatureLog(const VisualDrive& drive, std::ostream& out, const std::string& comment = "");

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_VISUAL_LANDMARKS_FEATURE_LOG_H_
