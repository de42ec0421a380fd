#include "sim/config.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <fstream>
#include <string>

namespace tactip {
namespace {

// A small two-section config exercising every field kind.
struct Inner {
  double speed_mm_s = 0.1;
  int count = 3;
  bool flag = false;
  std::string mode = "a";
  template <class V>
  void Visit(V& v) {
    v("speed_mm_s", speed_mm_s, "mm/s", "A speed.", Bounds::Positive());
    v("count", count, "", "A count.", Bounds::Closed(1, 10));
    v("flag", flag, "", "A flag.");
    v("mode", mode, "", "A mode.", Choices{"a", "b"});
  }
};
struct Outer {
  Inner rail;
  Inner other;
  template <class V>
  void Visit(V& v) {
    v.Section("rail", rail);
    v.Section("other", other);
  }
  void ValidateRules() const {
    if (rail.count > other.count + 5) FailRule("rail.count", rail.count, "must be <= other.count + 5");
  }
};

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ConfigTest, DefaultsAreValid) {
  Outer c;
  EXPECT_NO_THROW(ValidateConfig(c));
}

TEST(ConfigTest, YamlAndOverridesApplyInOrder) {
  Outer c;
  ApplyFlat(c, FlattenYaml("rail:\n  speed_mm_s: 2.5\n  mode: b\nother:\n  flag: true\n", "t.yaml"));
  ApplyFlat(c, FlatConfig{{"rail.speed_mm_s", "0.3"}});
  EXPECT_DOUBLE_EQ(c.rail.speed_mm_s, 0.3);
  EXPECT_EQ(c.rail.mode, "b");
  EXPECT_TRUE(c.other.flag);
  EXPECT_EQ(c.other.count, 3);
}

TEST(ConfigTest, OutOfRangeValueNamesKeyValueAndRule) {
  Outer c;
  c.rail.speed_mm_s = -1;
  EXPECT_EQ(ErrorOf([&] { ValidateConfig(c); }), "rail.speed_mm_s = -1: must be > 0");
  Outer d;
  d.other.count = 11;
  EXPECT_EQ(ErrorOf([&] { ValidateConfig(d); }), "other.count = 11: must be <= 10");
}

TEST(ConfigTest, UnknownKeyIsAnError) {
  Outer c;
  EXPECT_EQ(ErrorOf([&] { ApplyFlat(c, FlatConfig{{"rail.sped_mm_s", "1"}}); }), "unknown config key 'rail.sped_mm_s'");
}

TEST(ConfigTest, BadValuesAreRejectedWithTheKey) {
  Outer c;
  EXPECT_EQ(ErrorOf([&] { ApplyFlat(c, FlatConfig{{"rail.speed_mm_s", "fast"}}); }),
            "rail.speed_mm_s = 'fast': not a number");
  EXPECT_EQ(ErrorOf([&] { ApplyFlat(c, FlatConfig{{"rail.count", "2.5"}}); }), "rail.count = '2.5': not an integer");
  EXPECT_EQ(ErrorOf([&] { ApplyFlat(c, FlatConfig{{"rail.flag", "maybe"}}); }),
            "rail.flag = 'maybe': not a boolean (true/false)");
  EXPECT_EQ(ErrorOf([&] { ApplyFlat(c, FlatConfig{{"rail.mode", "c"}}); }), "rail.mode = 'c': must be one of a, b");
  EXPECT_EQ(ErrorOf([&] { ApplyFlat(c, FlatConfig{{"rail.speed_mm_s", "nan"}}); ValidateConfig(c); }),
            "rail.speed_mm_s = nan: must be a finite number");
}

TEST(ConfigTest, CrossFieldRuleNamesTheField) {
  Outer c;
  c.rail.count = 10;
  c.other.count = 1;
  EXPECT_EQ(ErrorOf([&] { ValidateConfig(c); }), "rail.count = 10: must be <= other.count + 5");
}

TEST(ConfigTest, MalformedYamlNamesFileAndLine) {
  const std::string msg = ErrorOf([] { FlattenYaml("rail:\n  speed_mm_s: [1, 2\n", "bad.yaml"); });
  EXPECT_NE(msg.find("bad.yaml: malformed YAML at line"), std::string::npos) << msg;
  EXPECT_NE(ErrorOf([] { FlattenYaml("rail:\n  speed_mm_s: [1, 2]\n", "list.yaml"); }).find("must be a scalar"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { FlattenYaml("- 1\n- 2\n", "seq.yaml"); }).find("top level must be a mapping"),
            std::string::npos);
}

TEST(ConfigTest, MissingFileIsAnError) {
  EXPECT_EQ(ErrorOf([] { FlattenYamlFile("/nonexistent/x.yaml"); }), "cannot read config file '/nonexistent/x.yaml'");
}

TEST(ConfigTest, AssignmentNeedsEquals) {
  EXPECT_EQ(ErrorOf([] { ParseAssignment("rail.count"); }), "--set 'rail.count': expected key=value");
  EXPECT_EQ(ParseAssignment("a.b=c=d").second, "c=d");
}

TEST(ConfigTest, ResolvedYamlRoundTripsExactly) {
  Outer c;
  c.rail.speed_mm_s = 0.1 + 0.2;  // not representable in short decimal
  c.other.mode = "b";
  c.other.flag = true;
  const std::string yaml = ConfigToYaml(c);
  Outer d;
  ApplyFlat(d, FlattenYaml(yaml, "roundtrip"));
  EXPECT_EQ(d.rail.speed_mm_s, c.rail.speed_mm_s);
  EXPECT_EQ(d.other.mode, "b");
  EXPECT_TRUE(d.other.flag);
  EXPECT_EQ(ConfigToYaml(d), yaml);
}

TEST(ConfigTest, DescribeListsUnitsAndBounds) {
  const auto docs = DescribeConfig(Outer{});
  ASSERT_EQ(docs.size(), 8u);
  EXPECT_EQ(docs[0].key, "rail.speed_mm_s");
  EXPECT_EQ(docs[0].unit, "mm/s");
  EXPECT_EQ(docs[0].allowed, "(0, inf)");
  EXPECT_EQ(docs[3].allowed, "a|b");
}

}  // namespace
}  // namespace tactip
