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
  EXPECT_EQ(ErrorOf([] { Outer c; ApplyFlat(c, FlattenYaml("rail:\n  speed_mm_s: [1, 2]\n", "list.yaml")); }),
            "rail.speed_mm_s: expected one value, not a list or a section");
  EXPECT_EQ(ErrorOf([] { Outer c; ApplyFlat(c, FlattenYaml("rail:\n  mode:\n    x: 1\n", "map.yaml")); }),
            "rail.mode: expected one value, not a list or a section");
  EXPECT_NE(ErrorOf([] { FlattenYaml("- 1\n- 2\n", "seq.yaml"); }).find("top level must be a mapping"),
            std::string::npos);
}

// A 10^9-leaf "billion laughs" of nested anchors and aliases, in under 1 kB.
std::string AliasBomb() {
  std::string y = "l0: &l0 {a: x, b: x, c: x, d: x, e: x, f: x, g: x, h: x, i: x, j: x}\n";
  for (int level = 1; level <= 8; ++level) {
    const std::string prev = "*l" + std::to_string(level - 1);
    y += "l" + std::to_string(level) + ": &l" + std::to_string(level) + " {";
    for (char k = 'a'; k <= 'j'; ++k) y += std::string(k == 'a' ? "" : ", ") + k + ": " + prev;
    y += "}\n";
  }
  return y;
}

TEST(ConfigTest, AliasBombIsRefusedBeforeItExpands) {
  const std::string yaml = AliasBomb();
  ASSERT_LT(yaml.size(), 1000u);
  EXPECT_EQ(ErrorOf([&] { FlattenYaml(yaml, "bomb.yaml"); }),
            "bomb.yaml: expands to more than 10000 YAML nodes (nested aliases?); a config file has one value per key");
  // A few aliases that expand to a handful of keys are still fine.
  const FlatConfig flat = FlattenYaml("rail: &r {count: 4, mode: b}\nother: *r\n", "alias.yaml");
  EXPECT_EQ(flat.at("other.count"), "4");
  EXPECT_EQ(flat.at("other.mode"), "b");
}

TEST(ConfigTest, DuplicateKeyIsRefusedNamingTheKeyAndLine) {
  EXPECT_EQ(ErrorOf([] { FlattenYaml("rail:\n  count: 2\n  count: 4\n", "dup.yaml"); }),
            "dup.yaml: key 'rail.count' appears twice (line 3); give each key once");
  EXPECT_EQ(ErrorOf([] { FlattenYaml("rail:\n  count: 2\nother:\n  flag: true\nrail:\n  mode: b\n", "dup.yaml"); }),
            "dup.yaml: key 'rail' appears twice (line 5); give each key once");
}

TEST(ConfigTest, SecondYamlDocumentIsRefused) {
  EXPECT_EQ(ErrorOf([] { FlattenYaml("rail:\n  count: 2\n---\nrail:\n  count: 4\n", "two.yaml"); }),
            "two.yaml: holds 2 YAML documents (the second starts after the '---' before line 4); a config file is "
            "one document");
  // An explicit start marker on the one document is fine.
  EXPECT_EQ(FlattenYaml("---\nrail:\n  count: 2\n", "one.yaml").at("rail.count"), "2");
}

TEST(ConfigTest, LineBreakInAValueGivesAOneLineMessageShowingItEscaped) {
  EXPECT_EQ(ErrorOf([] { ParseAssignment("rail.count=5\nx"); }),
            "--set 'rail.count=5\\nx': holds a line break or another control character; a key=value is one line");
  Outer c;
  const std::string msg = ErrorOf([&] { ApplyFlat(c, FlattenYaml("rail:\n  count: \"5\\nx\"\n", "nl.yaml")); });
  EXPECT_EQ(msg, "rail.count = '5\\nx': not an integer");
  EXPECT_EQ(ErrorOf([&] { ApplyFlat(c, FlatConfig{{"rail.mode", "a\tb"}}); }),
            "rail.mode = 'a\\tb': must be one of a, b");
  EXPECT_EQ(config_detail::Escaped(std::string("a\x01" "b\r")), "a\\x01b\\r");
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
