#pragma once
// The tables behind `tactip plot`'s figures of one run: pin motion over time, pin-velocity
// quiver frames around the onset, internal vs external markers and the indentation field.
// Each is a CSV text (columns in docs/viewer-and-plots.md "Figures of one run") computed from one
// sensor's recording; scripts/plots/tactip_plot.py draws them.

#include <string>
#include <vector>

#include "sensors/dataset.h"

namespace tactip {

/// Frames each side of the onset that the quiver figure shows ("before" and "after").
inline constexpr int kQuiverOffsetFrames = 3;

/// Where the run's pins are measured from in the image: the camera's principal point (px).
struct ImageCentre {
  double u_px = 0.0;  ///< horizontal (px)
  double v_px = 0.0;  ///< vertical, downwards (px)
};

/// The frame a figure is drawn at, and why.
struct ChosenFrame {
  int frame = 0;       ///< frame index
  double time_s = 0;   ///< its time (s)
  std::string reason;  ///< e.g. "gross-slip onset", "deepest press before the onset"
};

/// The frames of the quiver figure: the onset frame and the frames kQuiverOffsetFrames
/// before and after it (clamped to the run; frame 0 has no velocity, so at least 1).
struct QuiverFrames {
  std::string onset_name;  ///< "gross-slip onset", "incipient onset" or "peak mean pin speed"
  double onset_s = 0.0;    ///< the onset's time (s)
  int before = 1, at = 1, after = 1;  ///< frame indices
};

/// The three events a run's figures mark, NaN when they did not happen (s).
struct RunEvents {
  double gross_slip_onset_s;  ///< gross slip starts
  double incipient_onset_s;   ///< partial slip starts
  double object_fall_s;       ///< the object has dropped labels.fall_threshold_mm
};

/// The run's event times (from its attrs; NaN when absent).
RunEvents EventsOf(const RunRecord& run);

/// events.csv: `event,time_s,frame` for gross_slip_onset, incipient_onset, object_fall
/// (frame = first frame at or after the time; both cells empty when it did not happen).
std::string EventsCsv(const RunRecord& run);

/// A pin shown on its own on the motion figure, and why.
struct ShownPin {
  int pin = 0;       ///< pin index
  std::string role;  ///< "centre", "mid radius", "outermost", "farthest moving" (joined by " and " if several)
};

/// Pins shown one by one on the motion figure: the pin nearest the centre, the pin nearest half the
/// largest rest radius, the outermost pin and the pin that moves farthest from frame 0 (each
/// once, in that order; the first index wins ties). Rest radius from frame 0's image
/// positions around `centre`.
std::vector<ShownPin> RepresentativePins(const SensorRecord& s, const ImageCentre& centre);

/// motion.csv, one row per frame: `frame,time_s,mean_disp_px,pinK_disp_px` (one column
/// per pin of `pins`), `mean_speed_px_frame,max_speed_px_frame,gross_slip,incipient`.
/// Displacement: |pos_px(f) − pos_px(0)|; speed: |pos_px(f) − pos_px(f−1)|, empty at frame 0;
/// mean and max over all pins.
std::string MotionCsv(const RunRecord& run, const SensorRecord& s, const std::vector<ShownPin>& pins);

/// The quiver frames around the gross-slip onset, else the incipient onset, else the frame
/// of the largest mean pin speed. Throws InputError if the run has fewer than 2 frames.
QuiverFrames ChooseQuiverFrames(const RunRecord& run, const SensorRecord& s);

/// quiver.csv, one row per pin of each of the three frames: `panel,frame,time_s,pin,u_px,
/// v_px,du_px,dv_px,contact` (panel before/at/after; du, dv = pos_px(f) − pos_px(f−1), px/frame).
std::string QuiverCsv(const RunRecord& run, const SensorRecord& s, const QuiverFrames& q);

/// markers.csv, one row per frame: `frame,time_s,internal_disp_px,external_disp_px,
/// internal_speed_px_frame,external_speed_px_frame` (means over pins of the internal pins'
/// pos_px and the external markers' external_px, as in MotionCsv). Throws std::logic_error
/// if `s` has no external markers.
std::string MarkersCsv(const RunRecord& run, const SensorRecord& s);

/// The frame of deepest press before the run's first onset (gross or incipient; all frames
/// when neither happened): the largest mean inward pin displacement along the camera axis
/// (−x of pos_m from frame 0), the earliest on a tie.
ChosenFrame DeepestPressFrame(const RunRecord& run, const SensorRecord& s);

/// The rest frame of the indentation field: the last frame before any pin first touches
/// the stimulus (frame 0 when a pin touches from the start or none ever does), so the pins'
/// settling after the run starts is not counted as indentation.
int RestFrame(const SensorRecord& s);

/// indentation.csv, one row per pin at frame `f` against frame `rest`: `pin,rest_u_px,
/// rest_v_px,rest_radius_px,radial_disp_px,axial_in_mm,contact,normal_N`. Radial displacement
/// = (pos_px(f) − pos_px(rest)) along the direction from `centre` to the rest position (0 for
/// a pin at the centre); axial_in_mm = −(x(f) − x(rest)) of pos_m in mm (positive: pushed
/// in); contact and normal_N at frame f.
std::string IndentationCsv(const SensorRecord& s, int rest, int f, const ImageCentre& centre);

}  // namespace tactip
