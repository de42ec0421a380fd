// Design sweeps: --param specs and the Cartesian grid.

#include "scenarios/studies/sweeps/sweep_grid.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sim/config.h"

namespace tactip {
namespace {

using Values = std::vector<std::string>;

/// The InputError message ParseSweepParam throws for `spec` ("" if it does not throw).
std::string ParseError(const std::string& spec) {
  try {
    ParseSweepParam(spec);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SweepParamTest, RangeIncludesStop) {
  const SweepParam p = ParseSweepParam("skin.ridge_spacing_mm=2:5:0.5");
  EXPECT_EQ(p.key, "skin.ridge_spacing_mm");
  EXPECT_EQ(p.values, (Values{"2", "2.5", "3", "3.5", "4", "4.5", "5"}));
}

TEST(SweepParamTest, RangeHasNoFloatingNoise) {
  EXPECT_EQ(ParseSweepParam("skin.thickness_mm=0.3:1.5:0.3").values, (Values{"0.3", "0.6", "0.9", "1.2", "1.5"}));
  EXPECT_EQ(ParseSweepParam("a=0:1:0.1").values.size(), 11u);
  EXPECT_EQ(ParseSweepParam("a=0:1:0.1").values[3], "0.3");
  // Through zero: 0 is printed as "0", not 5.55e-17.
  EXPECT_EQ(ParseSweepParam("a=-0.3:0.3:0.1").values, (Values{"-0.3", "-0.2", "-0.1", "0", "0.1", "0.2", "0.3"}));
}

TEST(SweepParamTest, RangeStopsBeforeAnUnreachedStop) {
  EXPECT_EQ(ParseSweepParam("a=1:2:0.4").values, (Values{"1", "1.4", "1.8"}));
  EXPECT_EQ(ParseSweepParam("a=3:3:1").values, (Values{"3"}));
  EXPECT_EQ(ParseSweepParam("a=1e3:3e3:1e3").values, (Values{"1000", "2000", "3000"}));
  EXPECT_EQ(ParseSweepParam("a=1:1000:1").values.size(), 1000u);
}

TEST(SweepParamTest, ListsAndSingleValues) {
  const SweepParam list = ParseSweepParam("skin.pattern=smooth,fingerprint-v2");
  EXPECT_EQ(list.key, "skin.pattern");
  EXPECT_EQ(list.values, (Values{"smooth", "fingerprint-v2"}));
  EXPECT_EQ(ParseSweepParam("a=1,0.5,2").values, (Values{"1", "0.5", "2"}));  // given order, verbatim
  EXPECT_EQ(ParseSweepParam("rail.stimulus=curved40").values, (Values{"curved40"}));
  EXPECT_EQ(ParseSweepParam("a=x=y").values, (Values{"x=y"}));  // split at the first '='
}

TEST(SweepParamTest, MalformedSpecsNameTheSpecAndProblem) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"skin.x", "expected key="},
      {"=1", "empty key"},
      {"skin.x=", "empty value"},
      {"skin.x=a:2:1", "start 'a' is not a number"},
      {"skin.x=1:b:1", "stop 'b' is not a number"},
      {"skin.x=1:2:", "step '' is not a number"},
      {"skin.x=1:2:nan", "not a number"},
      {"skin.x=1:2", "start:stop:step"},
      {"skin.x=1:2:3:4", "start:stop:step"},
      {"skin.x=1:2:0", "step <= 0"},
      {"skin.x=1:2:-1", "step <= 0"},
      {"skin.x=1:0:1", "stop < start"},
      {"skin.x=0:1000:1", "more than 1000 values"},
      {"skin.x=0:1e300:1e-300", "more than 1000 values"},
      {"skin.x=1:1.000000000001:1e-13", "duplicate values"},
      {"skin.x=a,b,a", "duplicate value 'a'"},
      {"skin.x=a,,b", "empty value in list"},
      {"skin.x=a,", "empty value in list"},
  };
  for (const auto& [spec, problem] : cases) {
    const std::string msg = ParseError(spec);
    EXPECT_NE(msg.find("--param '" + spec + "': "), std::string::npos) << spec << " -> " << msg;
    EXPECT_NE(msg.find(problem), std::string::npos) << spec << " -> " << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << spec << " -> " << msg;
  }
  EXPECT_EQ(ParseError("skin.x=1:0:1"), "--param 'skin.x=1:0:1': stop < start");
  EXPECT_EQ(ParseError("a\nb"), "--param 'a\\nb': expected key=start:stop:step, key=v1,v2,... or key=value");
}

TEST(ExpandGridTest, FirstParameterVariesSlowest) {
  const auto grid = ExpandGrid({ParseSweepParam("a=1:3:1"), ParseSweepParam("b=x,y"), ParseSweepParam("c=z")});
  ASSERT_EQ(grid.size(), 6u);
  const std::vector<std::string> got = [&] {
    std::vector<std::string> s;
    for (const SweepDesign& d : grid) {
      EXPECT_EQ(d.size(), 3u);
      EXPECT_EQ(d[0].first, "a");
      EXPECT_EQ(d[1].first, "b");
      EXPECT_EQ(d[2].first, "c");
      s.push_back(d[0].second + d[1].second + d[2].second);
    }
    return s;
  }();
  EXPECT_EQ(got, (Values{"1xz", "1yz", "2xz", "2yz", "3xz", "3yz"}));
}

TEST(ExpandGridTest, EmptyParamsGiveOneEmptyDesign) {
  const auto grid = ExpandGrid({});
  ASSERT_EQ(grid.size(), 1u);
  EXPECT_TRUE(grid[0].empty());
}

TEST(ExpandGridTest, RejectsDuplicateKeysEmptyParamsAndHugeGrids) {
  try {
    ExpandGrid({ParseSweepParam("a=1,2"), ParseSweepParam("b=3"), ParseSweepParam("a=4")});
    FAIL() << "duplicate key accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'a'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ExpandGrid({SweepParam{"a", {}}}), InputError);
  const SweepParam big = ParseSweepParam("a=1:1000:1");
  EXPECT_THROW(ExpandGrid({big, SweepParam{"b", big.values}}), InputError);
}

}  // namespace
}  // namespace tactip
