// Pin CSV: exact round trip, tolerated variations, and one message per malformed input.

#include "detectors/pin_csv.h"

#include <gtest/gtest.h>

#include "scratch.h"

#include <fstream>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "detectors/detector.h"

namespace tactip {
namespace {

using testing::TempPath;
using testing::WriteFile;


/// Writes `text` to a scratch file and returns its path.
std::string WriteCsv(const std::string& name, const std::string& text) {
  const std::string path = TempPath(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

/// The message of the InputError thrown by ReadPinCsv(path), or "" if none.
std::string ReadError(const std::string& path) {
  try {
    ReadPinCsv(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PinCsvTest, WriteReadRoundTripIsExact) {
  std::mt19937_64 gen(5);
  std::uniform_real_distribution<float> u(0.0f, 640.0f);
  std::vector<PinFrame> frames;
  for (int k = 0; k < 6; ++k) {
    PinFrame f;
    f.time_s = 0.1 + k / 30.0;  // not short decimals
    f.pos_px.resize(7, 2);
    f.valid.assign(7, 1);
    for (int i = 0; i < 7; ++i) {
      f.pos_px(i, 0) = u(gen);
      f.pos_px(i, 1) = u(gen);
    }
    f.valid[k % 7] = 0;
    frames.push_back(f);
  }
  const std::string path = TempPath("round.csv");
  WritePinCsv(path, frames);
  const std::vector<PinFrame> back = ReadPinCsv(path);
  ASSERT_EQ(back.size(), frames.size());
  for (size_t k = 0; k < frames.size(); ++k) {
    EXPECT_EQ(back[k].time_s, frames[k].time_s);
    EXPECT_EQ(back[k].pos_px, frames[k].pos_px);
    EXPECT_EQ(back[k].valid, frames[k].valid);
    EXPECT_EQ(back[k].external_px.size(), 0);
  }
}

TEST(PinCsvTest, ToleratesWhitespaceCrlfBlankLinesAndAnyPinOrder) {
  const std::string path = WriteCsv("loose.csv",
                                    "\xEF\xBB\xBF frame , time_s ,pin,x_px, y_px \r\n"
                                    "0, 0.0, 1, 11.5, 21\r\n"
                                    "0, 0.0, 0, 10, 20\r\n"
                                    "\r\n"
                                    "3,+0.5,0,10.25,20\r\n"
                                    "3,0.5,1,11,21.75\r\n");
  const std::vector<PinFrame> f = ReadPinCsv(path);
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f[0].size(), 2);
  EXPECT_EQ(f[0].pos_px(1, 0), 11.5f);
  EXPECT_EQ(f[0].pos_px(0, 1), 20.0f);
  EXPECT_EQ(f[1].time_s, 0.5);
  EXPECT_EQ(f[1].pos_px(0, 0), 10.25f);
  EXPECT_EQ(f[1].pos_px(1, 1), 21.75f);
  EXPECT_EQ(f[1].valid, (std::vector<unsigned char>{1, 1}));  // no valid column: all detected
}

TEST(PinCsvTest, ValidColumnIsRead) {
  const std::string path = WriteCsv("valid.csv",
                                    "frame,time_s,pin,x_px,y_px,valid\n"
                                    "0,0,0,1,2,1\n"
                                    "0,0,1,3,4,0\n");
  const std::vector<PinFrame> f = ReadPinCsv(path);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].valid, (std::vector<unsigned char>{1, 0}));
}

TEST(PinCsvTest, MalformedFilesGiveOneLineMessagesWithFileAndLine) {
  const std::string h = "frame,time_s,pin,x_px,y_px\n";
  const std::string ok2 = "0,0.00,0,1,1\n0,0.00,1,2,2\n";  // frame 0 with 2 pins (lines 2-3)
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "empty file"},
      {h, "empty file"},
      {"frame,time,pin,x,y\n0,0,0,1,1\n", "line 1: bad header"},
      {"frame,time_s,pin,x_px,y_px,valid,extra\n", "line 1: bad header"},
      {h + "0,0.00,0,abc,1\n", "line 2: x_px 'abc' is not a number"},
      {h + "0,0.00,0,1,\n", "line 2: y_px '' is not a number"},
      {h + "0,0.00,0.5,1,1\n", "line 2: pin '0.5' is not an integer"},
      {h + "x,0.00,0,1,1\n", "line 2: frame 'x' is not an integer"},
      {h + "0,0.00,0,nan,1\n", "line 2: x_px 'nan' is not finite"},
      {h + "0,inf,0,1,1\n", "line 2: time_s 'inf' is not finite"},
      {h + "0,nan,0,1,1\n", "line 2: time_s 'nan' is not finite"},
      {h + "0,0.00,0,1\n", "line 2: expected 5 fields, got 4"},
      {h + ok2 + "1,0.01,0,1,1\n2,0.02,0,1,1\n", "line 4: frame 1 has 1 pins, frame 0 has 2"},
      {h + ok2 + "1,0.01,0,1,1\n1,0.01,0,1,1\n", "line 5: duplicate pin 0 in frame 1"},
      {h + "0,0.00,0,1,1\n0,0.00,2,2,2\n", "line 2: frame 0 is missing pin 1"},
      {h + ok2 + "1,0.01,0,1,1\n1,0.01,2,1,1\n", "line 5: pin 2 out of range: frame 0 has 2 pins"},
      {h + "0,0.00,-1,1,1\n", "line 2: pin -1 is negative"},
      {h + ok2 + "1,0.00,0,1,1\n1,0.00,1,1,1\n", "line 4: time not increasing"},
      {h + ok2 + "1,0.01,0,1,1\n1,0.01,1,1,1\n0,0.02,0,1,1\n", "line 6: frame numbers not increasing"},
      {h + "0,0.00,0,1,1\n0,0.01,1,1,1\n", "line 3: time_s 0.01 differs"},
      {"frame,time_s,pin,x_px,y_px,valid\n0,0,0,1,1,2\n", "line 2: valid '2' is not 0 or 1"},
  };
  for (size_t c = 0; c < cases.size(); ++c) {
    const std::string path = WriteCsv("bad" + std::to_string(c) + ".csv", cases[c].first);
    const std::string msg = ReadError(path);
    EXPECT_NE(msg.find("'" + path + "'"), std::string::npos) << "case " << c << ": " << msg;
    EXPECT_NE(msg.find(cases[c].second), std::string::npos) << "case " << c << ": " << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "case " << c << ": " << msg;
  }
}

TEST(PinCsvTest, MissingFileNamesThePath) {
  const std::string path = TempPath("does_not_exist.csv");
  const std::string msg = ReadError(path);
  EXPECT_NE(msg.find("'" + path + "'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("cannot open"), std::string::npos) << msg;
}

TEST(PinCsvTest, WriterRefusesFramesTheReaderWouldReject) {
  PinFrame a;
  a.time_s = 0.0;
  a.pos_px = Eigen::Matrix<float, Eigen::Dynamic, 2>::Zero(3, 2);
  PinFrame b = a;
  b.time_s = 0.01;
  b.pos_px.resize(2, 2);
  const std::string path = TempPath("w.csv");
  EXPECT_THROW(WritePinCsv(path, {}), InputError);
  EXPECT_THROW(WritePinCsv(path, {a, b}), InputError);  // pin count changes
  EXPECT_THROW(WritePinCsv(path, {a, a}), InputError);  // time does not increase
  EXPECT_NO_THROW(WritePinCsv(path, {a}));
  EXPECT_EQ(ReadPinCsv(path).size(), 1u);
}

}  // namespace
}  // namespace tactip
