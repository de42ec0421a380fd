// Lists in configs: a section of several entries ("sensors.0.name", "sensors.1.name"),
// from YAML lists and from key=value overrides, written back and read again.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "input_error.h"
#include "sim/config.h"

namespace tactip {
namespace {

struct Entry {
  std::string name = "first";
  double offset_mm = 0.0;
  template <class V>
  void Visit(V& v) {
    v("name", name, "", "The entry's name.", Choices{});
    v("offset_mm", offset_mm, "mm", "Its offset.", Bounds::Closed(-50.0, 50.0));
  }
};

struct Main {
  double gain = 1.0;
  template <class V>
  void Visit(V& v) {
    v("gain", gain, "", "A gain.", Bounds::Positive());
  }
};

struct WithList {
  Main main;
  std::vector<Entry> entries{Entry{}};
  template <class V>
  void Visit(V& v) {
    v.Section("main", main);
    v.List("entries", entries);
  }
  void ValidateRules() const {}
};

TEST(ConfigListTest, AYamlListSetsOneEntryPerItem) {
  WithList c;
  ApplyFlat(c, FlattenYaml("main:\n  gain: 2\nentries:\n  - name: left\n    offset_mm: -24\n  - name: right\n    offset_mm: 24\n", "t.yaml"));
  ASSERT_EQ(c.entries.size(), 2u);
  EXPECT_EQ(c.entries[0].name, "left");
  EXPECT_EQ(c.entries[0].offset_mm, -24.0);
  EXPECT_EQ(c.entries[1].name, "right");
  EXPECT_EQ(c.entries[1].offset_mm, 24.0);
}

TEST(ConfigListTest, OverridesEditAnEntryOrAddTheNextOne) {
  WithList c = LoadConfig<WithList>("", {"entries.0.offset_mm=3", "entries.1.name=second", "entries.2.offset_mm=-7"});
  ASSERT_EQ(c.entries.size(), 3u);
  EXPECT_EQ(c.entries[0].name, "first");
  EXPECT_EQ(c.entries[0].offset_mm, 3.0);
  EXPECT_EQ(c.entries[1].name, "second");
  EXPECT_EQ(c.entries[1].offset_mm, 0.0);  // a new entry starts from the defaults
  EXPECT_EQ(c.entries[2].offset_mm, -7.0);
  // Keys of many entries at once (a file) are taken in the order of their indices, not as text.
  WithList many;
  FlatConfig flat;
  for (int i = 0; i < 12; ++i) flat["entries." + std::to_string(i) + ".offset_mm"] = std::to_string(i);
  ApplyFlat(many, flat);
  ASSERT_EQ(many.entries.size(), 12u);
  EXPECT_EQ(many.entries[11].offset_mm, 11.0);
}

TEST(ConfigListTest, AnIndexPastTheNextEntryOrABadFieldIsRefusedByName) {
  EXPECT_EQ(InputErrorOf([] { LoadConfig<WithList>("", {"entries.2.name=x"}); }),
            "entries.2.name: the list 'entries' has 1 entry; add entries.1 first");
  EXPECT_EQ(InputErrorOf([] { LoadConfig<WithList>("", {"entries.64.name=x"}); }),
            "entries.64.name: the list 'entries' has at most 64 entries");
  EXPECT_EQ(InputErrorOf([] { LoadConfig<WithList>("", {"entries.99999999999999999999999.name=x"}); }),
            "entries.99999999999999999999999.name: the list 'entries' has at most 64 entries");
  EXPECT_EQ(InputErrorOf([] { LoadConfig<WithList>("", {"entries.0.colour=red"}); }),
            "unknown config key 'entries.0.colour'");
  EXPECT_EQ(InputErrorOf([] { LoadConfig<WithList>("", {"entries.name=x"}); }), "unknown config key 'entries.name'");
  EXPECT_EQ(InputErrorOf([] { LoadConfig<WithList>("", {"entries.01.name=x"}); }), "unknown config key 'entries.01.name'");
  EXPECT_EQ(InputErrorOf([] { LoadConfig<WithList>("", {"entries.1.offset_mm=60"}); }),
            "entries.1.offset_mm = 60: must be <= 50");
  EXPECT_EQ(InputErrorOf([] { FlattenYaml("- a\n- b\n", "t.yaml"); }), "t.yaml: top level must be a mapping of sections");
}

TEST(ConfigListTest, TheWrittenConfigReadsBackToTheSameEntries) {
  const WithList c = LoadConfig<WithList>("", {"entries.0.name=left", "entries.1.name=right", "entries.1.offset_mm=24.5"});
  const std::vector<FieldDoc> docs = DescribeConfig(c);
  ASSERT_EQ(docs.size(), 5u);
  EXPECT_EQ(docs[3].key, "entries.1.name");
  const std::string yaml = FieldsToYaml(docs);
  EXPECT_NE(yaml.find("entries:\n  - name: \"left\""), std::string::npos) << yaml;
  const std::string commented = FieldsToCommentedYaml(docs, "# header\n");
  EXPECT_NE(commented.find("entries:\n    # The entry's name.\n  - name: \"left\"\n"), std::string::npos) << commented;
  for (const std::string& text : {yaml, commented}) {
    WithList back;
    back.entries.clear();
    ApplyFlat(back, FlattenYaml(text, "written.yaml"));
    ASSERT_EQ(back.entries.size(), 2u) << text;
    EXPECT_EQ(back.entries[0].name, "left");
    EXPECT_EQ(back.entries[1].name, "right");
    EXPECT_EQ(back.entries[1].offset_mm, 24.5);
    EXPECT_EQ(back.main.gain, 1.0);
  }
}

}  // namespace
}  // namespace tactip
