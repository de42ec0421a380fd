// Pin-track CSV reader (strict, with line-numbered errors) and writer.

#include "detectors/pin_csv.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string_view>
#include <utility>

#include "detectors/detector.h"
#include "sim/base/files.h"

namespace tactip {
namespace {

/// Largest pin index accepted before the pin count is known (guards the bookkeeping).
constexpr int kMaxPins = 1 << 20;

/// One data row of the current frame.
struct Row {
  int pin;
  float x, y;
  unsigned char valid;
};

/// Error naming the file and the line.
InputError LineError(const std::string& path, long line, const std::string& what) {
  return InputError("pin CSV '" + path + "' line " + std::to_string(line) + ": " + what);
}

/// Text `s` without surrounding spaces, tabs and carriage returns.
std::string_view Trim(std::string_view s) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

/// Splits a line at commas into trimmed fields (reusing `out`).
void Split(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    if (comma == std::string_view::npos) {
      out.push_back(Trim(line.substr(start)));
      return;
    }
    out.push_back(Trim(line.substr(start, comma - start)));
    start = comma + 1;
  }
}

/// Parses the whole field as a number of type T (an optional leading '+' allowed).
template <typename T>
bool ParseField(std::string_view s, T& out) {
  if (s.size() > 1 && s.front() == '+') s.remove_prefix(1);
  const char* end = s.data() + s.size();
  const auto [p, ec] = std::from_chars(s.data(), end, out);
  return !s.empty() && ec == std::errc() && p == end;
}

/// Shortest text that reads back as exactly `v`, appended to `out`.
template <typename T>
void AppendNumber(std::string& out, T v) {
  char buf[64];
  const auto [p, ec] = std::to_chars(buf, buf + sizeof(buf), v);
  out.append(buf, p);
}

}  // namespace

std::vector<PinFrame> ReadPinCsv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("pin CSV '" + path + "': cannot open: " + std::strerror(errno));

  // Header (an optional UTF-8 byte-order mark first).
  std::string line;
  long line_no = 0;
  bool have_header_line = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (line_no == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    if (!Trim(line).empty()) {
      have_header_line = true;
      break;
    }
  }
  if (!have_header_line) throw InputError("pin CSV '" + path + "': empty file");
  std::vector<std::string_view> f;
  Split(line, f);
  static constexpr std::string_view kColumns[] = {"frame", "time_s", "pin", "x_px", "y_px", "valid"};
  const bool header_ok = (f.size() == 5 || f.size() == 6) && [&] {
    for (size_t c = 0; c < f.size(); ++c) {
      if (f[c] != kColumns[c]) return false;
    }
    return true;
  }();
  if (!header_ok) {
    throw LineError(path, line_no,
                    "bad header '" + std::string(Trim(line)) +
                        "', expected 'frame,time_s,pin,x_px,y_px' with an optional ',valid'");
  }
  const size_t n_cols = f.size();

  // Rows, grouped into frames by frame number.
  std::vector<PinFrame> frames;
  std::vector<Row> rows;            // rows of the frame being read
  std::vector<unsigned char> seen;  // pin index seen in the frame being read
  int n_pins = -1;                  // pin count of the first frame, once known
  long first_frame_no = 0;          // frame number of the first frame
  bool in_frame = false;
  long frame_no = 0, frame_line = 0;  // frame being read and its first line
  double frame_time = 0.0;

  // Checks the frame being read and appends it.
  const auto close_frame = [&] {
    const int count = static_cast<int>(rows.size());
    if (n_pins < 0) {
      n_pins = count;
      first_frame_no = frame_no;
    } else if (count != n_pins) {
      throw LineError(path, frame_line,
                      "frame " + std::to_string(frame_no) + " has " + std::to_string(count) + " pins, frame " +
                          std::to_string(first_frame_no) + " has " + std::to_string(n_pins));
    }
    for (int i = 0; i < n_pins; ++i) {
      if (i >= static_cast<int>(seen.size()) || !seen[i]) {
        throw LineError(path, frame_line, "frame " + std::to_string(frame_no) + " is missing pin " + std::to_string(i));
      }
    }
    PinFrame pf;
    pf.time_s = frame_time;
    pf.pos_px.resize(n_pins, 2);
    pf.valid.assign(n_pins, 1);
    for (const Row& r : rows) {
      pf.pos_px(r.pin, 0) = r.x;
      pf.pos_px(r.pin, 1) = r.y;
      pf.valid[r.pin] = r.valid;
    }
    frames.push_back(std::move(pf));
    rows.clear();
    std::fill(seen.begin(), seen.end(), 0);
  };

  while (std::getline(in, line)) {
    ++line_no;
    if (Trim(line).empty()) continue;
    Split(line, f);
    if (f.size() != n_cols) {
      throw LineError(path, line_no, "expected " + std::to_string(n_cols) + " fields, got " + std::to_string(f.size()));
    }
    // Fields.
    long fr = 0;
    int pin = 0;
    double t = 0.0, x = 0.0, y = 0.0;
    const auto bad = [&](const char* name, std::string_view v, const char* kind) {
      return LineError(path, line_no, std::string(name) + " '" + std::string(v) + "' is not " + kind);
    };
    if (!ParseField(f[0], fr)) throw bad("frame", f[0], "an integer");
    if (!ParseField(f[1], t)) throw bad("time_s", f[1], "a number");
    if (!ParseField(f[2], pin)) throw bad("pin", f[2], "an integer");
    if (!ParseField(f[3], x)) throw bad("x_px", f[3], "a number");
    if (!ParseField(f[4], y)) throw bad("y_px", f[4], "a number");
    if (!std::isfinite(t)) throw bad("time_s", f[1], "finite");
    if (!std::isfinite(static_cast<float>(x))) throw bad("x_px", f[3], "finite");
    if (!std::isfinite(static_cast<float>(y))) throw bad("y_px", f[4], "finite");
    unsigned char valid = 1;
    if (n_cols == 6) {
      int v = 0;
      if (!ParseField(f[5], v) || (v != 0 && v != 1)) throw bad("valid", f[5], "0 or 1");
      valid = static_cast<unsigned char>(v);
    }

    // Frame bookkeeping: same frame, or a new one with larger number and later time.
    if (in_frame && fr < frame_no) {
      throw LineError(
          path, line_no,
          "frame numbers not increasing: frame " + std::to_string(fr) + " after frame " + std::to_string(frame_no));
    }
    if (in_frame && fr == frame_no) {
      if (t != frame_time) {
        throw LineError(
            path, line_no,
            "time_s " + std::string(f[1]) + " differs from the time_s of frame " + std::to_string(fr) + "'s first row");
      }
    } else {
      if (in_frame) {
        close_frame();
        if (!(t > frame_time)) {
          throw LineError(path, line_no,
                          "time not increasing: frame " + std::to_string(fr) + " at time_s " + std::string(f[1]) +
                              " is not after frame " + std::to_string(frame_no));
        }
      }
      in_frame = true;
      frame_no = fr;
      frame_line = line_no;
      frame_time = t;
    }

    // Pin index: in range, once per frame.
    if (pin < 0) throw LineError(path, line_no, "pin " + std::to_string(pin) + " is negative");
    if (n_pins >= 0 && pin >= n_pins) {
      throw LineError(path, line_no,
                      "pin " + std::to_string(pin) + " out of range: frame " + std::to_string(first_frame_no) +
                          " has " + std::to_string(n_pins) + " pins");
    }
    if (pin >= kMaxPins) throw LineError(path, line_no, "pin " + std::to_string(pin) + " is too large");
    if (pin >= static_cast<int>(seen.size())) seen.resize(pin + 1, 0);
    if (seen[pin]) {
      throw LineError(path, line_no, "duplicate pin " + std::to_string(pin) + " in frame " + std::to_string(fr));
    }
    seen[pin] = 1;
    rows.push_back({pin, static_cast<float>(x), static_cast<float>(y), valid});
  }
  if (in.bad()) throw InputError("pin CSV '" + path + "': read error");
  if (!in_frame) throw LineError(path, line_no, "empty file: no data rows after the header");
  close_frame();
  return frames;
}

void WritePinCsv(const std::string& path, const std::vector<PinFrame>& frames) {
  const auto fail = [&](const std::string& what) { return InputError("pin CSV '" + path + "': " + what); };
  if (frames.empty()) throw fail("no frames to write");
  const int n = frames.front().size();
  if (n == 0) throw fail("frame 0 has no pins");
  std::string text = "frame,time_s,pin,x_px,y_px,valid\n";
  text.reserve(text.size() + frames.size() * static_cast<size_t>(n) * 40);
  for (size_t k = 0; k < frames.size(); ++k) {
    const PinFrame& pf = frames[k];
    const std::string fk = "frame " + std::to_string(k);
    // Refuse anything ReadPinCsv would reject.
    if (pf.size() != n)
      throw fail(fk + " has " + std::to_string(pf.size()) + " pins, frame 0 has " + std::to_string(n));
    if (!pf.valid.empty() && static_cast<int>(pf.valid.size()) != n) {
      throw fail(fk + " has " + std::to_string(pf.valid.size()) + " valid flags for " + std::to_string(n) + " pins");
    }
    if (!std::isfinite(pf.time_s)) throw fail(fk + " has a non-finite time");
    if (k > 0 && !(pf.time_s > frames[k - 1].time_s)) throw fail(fk + ": time not increasing");
    for (int i = 0; i < n; ++i) {
      const float x = pf.pos_px(i, 0), y = pf.pos_px(i, 1);
      if (!std::isfinite(x) || !std::isfinite(y)) throw fail(fk + " pin " + std::to_string(i) + " is not finite");
      AppendNumber(text, static_cast<long>(k));
      text += ',';
      AppendNumber(text, pf.time_s);
      text += ',';
      AppendNumber(text, i);
      text += ',';
      AppendNumber(text, x);
      text += ',';
      AppendNumber(text, y);
      text += (pf.valid.empty() || pf.valid[i]) ? ",1\n" : ",0\n";
    }
  }
  WriteFileAtomic(path, text);
}

}  // namespace tactip
