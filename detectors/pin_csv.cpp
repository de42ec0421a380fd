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

/// Reads a pin CSV: the header, then rows grouped into frames by frame number, every
/// defect a one-line error naming the file and line.
class PinCsvReader {
 public:
  explicit PinCsvReader(const std::string& path) : path_(path), in_(path, std::ios::binary) {
    if (!in_) throw InputError("pin CSV '" + path + "': cannot open: " + std::strerror(errno));
  }

  std::vector<PinFrame> Read() {
    ReadHeader();
    while (std::getline(in_, line_)) {
      ++line_no_;
      if (Trim(line_).empty()) continue;
      const RowFields r = ParseRow();
      AdvanceFrame(r);
      AddPin(r);
    }
    if (in_.bad()) throw InputError("pin CSV '" + path_ + "': read error");
    if (!in_frame_) throw Error(line_no_, "empty file: no data rows after the header");
    CloseFrame();
    return std::move(frames_);
  }

 private:
  /// One data row's parsed fields.
  struct RowFields {
    long frame = 0;
    double time = 0.0;
    Row row{};
  };

  InputError Error(long line, const std::string& what) const { return LineError(path_, line, what); }

  // Header (an optional UTF-8 byte-order mark first).
  void ReadHeader() {
    bool have_header_line = false;
    while (std::getline(in_, line_)) {
      ++line_no_;
      if (line_no_ == 1 && line_.rfind("\xEF\xBB\xBF", 0) == 0) line_.erase(0, 3);
      if (!Trim(line_).empty()) {
        have_header_line = true;
        break;
      }
    }
    if (!have_header_line) throw InputError("pin CSV '" + path_ + "': empty file");
    Split(line_, fields_);
    static constexpr std::string_view kColumns[] = {"frame", "time_s", "pin", "x_px", "y_px", "valid"};
    const bool header_ok = (fields_.size() == 5 || fields_.size() == 6) && [&] {
      for (size_t c = 0; c < fields_.size(); ++c) {
        if (fields_[c] != kColumns[c]) return false;
      }
      return true;
    }();
    if (!header_ok) {
      throw Error(line_no_, "bad header '" + std::string(Trim(line_)) +
                                "', expected 'frame,time_s,pin,x_px,y_px' with an optional ',valid'");
    }
    n_cols_ = fields_.size();
  }

  // The current line's fields: numbers, finite, valid 0 or 1.
  RowFields ParseRow() {
    Split(line_, fields_);
    const auto& f = fields_;
    if (f.size() != n_cols_) {
      throw Error(line_no_, "expected " + std::to_string(n_cols_) + " fields, got " + std::to_string(f.size()));
    }
    const auto bad = [&](const char* name, std::string_view v, const char* kind) {
      return Error(line_no_, std::string(name) + " '" + std::string(v) + "' is not " + kind);
    };
    RowFields r;
    double x = 0.0, y = 0.0;
    if (!ParseField(f[0], r.frame)) throw bad("frame", f[0], "an integer");
    if (!ParseField(f[1], r.time)) throw bad("time_s", f[1], "a number");
    if (!ParseField(f[2], r.row.pin)) throw bad("pin", f[2], "an integer");
    if (!ParseField(f[3], x)) throw bad("x_px", f[3], "a number");
    if (!ParseField(f[4], y)) throw bad("y_px", f[4], "a number");
    if (!std::isfinite(r.time)) throw bad("time_s", f[1], "finite");
    if (!std::isfinite(static_cast<float>(x))) throw bad("x_px", f[3], "finite");
    if (!std::isfinite(static_cast<float>(y))) throw bad("y_px", f[4], "finite");
    r.row.x = static_cast<float>(x);
    r.row.y = static_cast<float>(y);
    r.row.valid = 1;
    if (n_cols_ == 6) {
      int v = 0;
      if (!ParseField(f[5], v) || (v != 0 && v != 1)) throw bad("valid", f[5], "0 or 1");
      r.row.valid = static_cast<unsigned char>(v);
    }
    return r;
  }

  // Frame bookkeeping: same frame, or a new one with larger number and later time.
  void AdvanceFrame(const RowFields& r) {
    const std::string time_text(fields_[1]);
    if (in_frame_ && r.frame < frame_no_) {
      throw Error(line_no_, "frame numbers not increasing: frame " + std::to_string(r.frame) + " after frame " +
                                std::to_string(frame_no_));
    }
    if (in_frame_ && r.frame == frame_no_) {
      if (r.time != frame_time_) {
        throw Error(line_no_, "time_s " + time_text + " differs from the time_s of frame " +
                                  std::to_string(r.frame) + "'s first row");
      }
      return;
    }
    if (in_frame_) {
      CloseFrame();
      if (!(r.time > frame_time_)) {
        throw Error(line_no_, "time not increasing: frame " + std::to_string(r.frame) + " at time_s " + time_text +
                                  " is not after frame " + std::to_string(frame_no_));
      }
    }
    in_frame_ = true;
    frame_no_ = r.frame;
    frame_line_ = line_no_;
    frame_time_ = r.time;
  }

  // Pin index: in range, once per frame.
  void AddPin(const RowFields& r) {
    const int pin = r.row.pin;
    if (pin < 0) throw Error(line_no_, "pin " + std::to_string(pin) + " is negative");
    if (n_pins_ >= 0 && pin >= n_pins_) {
      throw Error(line_no_, "pin " + std::to_string(pin) + " out of range: frame " + std::to_string(first_frame_no_) +
                                " has " + std::to_string(n_pins_) + " pins");
    }
    if (pin >= kMaxPins) throw Error(line_no_, "pin " + std::to_string(pin) + " is too large");
    if (pin >= static_cast<int>(seen_.size())) seen_.resize(pin + 1, 0);
    if (seen_[pin]) {
      throw Error(line_no_, "duplicate pin " + std::to_string(pin) + " in frame " + std::to_string(r.frame));
    }
    seen_[pin] = 1;
    rows_.push_back(r.row);
  }

  // Checks the frame being read (pin count as the first frame's, no pin missing) and
  // appends it.
  void CloseFrame() {
    const int count = static_cast<int>(rows_.size());
    if (n_pins_ < 0) {
      n_pins_ = count;
      first_frame_no_ = frame_no_;
    } else if (count != n_pins_) {
      throw Error(frame_line_, "frame " + std::to_string(frame_no_) + " has " + std::to_string(count) +
                                   " pins, frame " + std::to_string(first_frame_no_) + " has " + std::to_string(n_pins_));
    }
    for (int i = 0; i < n_pins_; ++i) {
      if (i >= static_cast<int>(seen_.size()) || !seen_[i]) {
        throw Error(frame_line_, "frame " + std::to_string(frame_no_) + " is missing pin " + std::to_string(i));
      }
    }
    PinFrame pf;
    pf.time_s = frame_time_;
    pf.pos_px.resize(n_pins_, 2);
    pf.valid.assign(n_pins_, 1);
    for (const Row& r : rows_) {
      pf.pos_px(r.pin, 0) = r.x;
      pf.pos_px(r.pin, 1) = r.y;
      pf.valid[r.pin] = r.valid;
    }
    frames_.push_back(std::move(pf));
    rows_.clear();
    std::fill(seen_.begin(), seen_.end(), 0);
  }

  const std::string path_;
  std::ifstream in_;
  std::string line_;
  long line_no_ = 0;
  std::vector<std::string_view> fields_;  // views into line_
  size_t n_cols_ = 0;
  std::vector<PinFrame> frames_;
  std::vector<Row> rows_;            // rows of the frame being read
  std::vector<unsigned char> seen_;  // pin index seen in the frame being read
  int n_pins_ = -1;                  // pin count of the first frame, once known
  long first_frame_no_ = 0;          // frame number of the first frame
  bool in_frame_ = false;
  long frame_no_ = 0, frame_line_ = 0;  // frame being read and its first line
  double frame_time_ = 0.0;
};

}  // namespace

std::vector<PinFrame> ReadPinCsv(const std::string& path) { return PinCsvReader(path).Read(); }

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
