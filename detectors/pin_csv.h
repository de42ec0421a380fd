#pragma once
// Reading and writing pin tracks as CSV, the documented exchange format for real TacTip
// recordings:
//
//   frame,time_s,pin,x_px,y_px[,valid]
//   0,0.00,0,312.5,240.1,1
//   0,0.00,1,318.2,240.0,1
//   ...
//
// One row per pin per frame; frames ascending with strictly increasing time_s (the same
// time_s on every row of a frame); pins 0..N-1 in each frame, in any order; whitespace
// around fields, blank lines, CRLF line ends and a UTF-8 byte-order mark are tolerated;
// `valid` is 0 or 1 and defaults to 1. Positions are pixels (u right, v down).

#include <string>
#include <vector>

#include "detectors/pin_frame.h"

namespace tactip {

/// Reads a pin CSV. Throws InputError (one line naming the file and the line
/// number) on a missing or empty file, a bad header, a wrong field count, a non-numeric
/// or non-finite field, a frame whose pin count differs from the first frame's, a
/// duplicate or missing pin index, frame numbers that do not increase, or time_s that
/// does not strictly increase from frame to frame.
std::vector<PinFrame> ReadPinCsv(const std::string& path);

/// Writes frames as a pin CSV with a `valid` column, frames numbered 0.., values with
/// round-trip precision, atomically. Throws InputError naming the file if the
/// frames could not be read back (no frames, no pins, pin counts differ, non-finite
/// values, time not strictly increasing) or the file cannot be written.
void WritePinCsv(const std::string& path, const std::vector<PinFrame>& frames);

}  // namespace tactip
