#include <cmath>
#include <limits>

#include "hair/h5/attribute.h"
#include "hair/h5/dataset.h"
#include "hair/h5/dataset_blocks.h"
#include "hair/h5/enum_dataset.h"
#include "hair/h5/file.h"
#include "hair/h5/tree.h"
#include "hair/h5/tree_text.h"
#include "unit/test_h5_support.h"

namespace hair::h5 {
namespace {

using H5TreeTest = testing::TemporaryDirectoryTest;

const TreeEntry* entry_at(const std::vector<TreeEntry>& entries, const std::string& path) {
  for (const TreeEntry& entry : entries) {
    if (entry.path == path) return &entry;
  }
  return nullptr;
}

TEST_F(H5TreeTest, ListsGroupsDatasetsAttributesAndSummaries) {
  File file = File::create(path("tree.h5"));
  write_string_attribute(file, "/", "schema", "hairstyle.test");
  write_vector<float>(file, "/b/values", {2.0f, -1.0f, std::numeric_limits<float>::quiet_NaN()});
  write_vector<int32_t>(file, "/a/ids", {4, 9, -1});
  write_enum_dataset(file, "/a/kind", {0, 1, 1}, {{"strip", 0}, {"grid", 1}});
  write_double_attribute(file, "/b/values", "scale", 0.5);

  const std::vector<TreeEntry> entries = list_tree(file, true);
  std::vector<std::string> paths;
  for (const TreeEntry& entry : entries) paths.push_back(entry.path);
  EXPECT_EQ(paths, (std::vector<std::string>{"/", "/a", "/a/ids", "/a/kind", "/b", "/b/values"}));

  const TreeEntry* root = entry_at(entries, "/");
  ASSERT_EQ(root->attributes.size(), 1u);
  EXPECT_EQ(root->attributes[0].text, "hairstyle.test");

  const TreeEntry* values = entry_at(entries, "/b/values");
  EXPECT_EQ(values->kind, ObjectKind::dataset);
  EXPECT_EQ(values->dataset.type_name, "float32");
  EXPECT_EQ(values->dataset.shape, (Shape{3}));
  ASSERT_TRUE(values->summary.has_value());
  EXPECT_EQ(values->summary->min, -1.0);
  EXPECT_EQ(values->summary->max, 2.0);
  EXPECT_EQ(values->summary->non_finite, 1);

  const TreeEntry* ids = entry_at(entries, "/a/ids");
  EXPECT_EQ(ids->summary->min, -1.0);
  EXPECT_EQ(ids->summary->max, 9.0);

  const TreeEntry* kind = entry_at(entries, "/a/kind");
  EXPECT_EQ(kind->dataset.type_name, "enum int8");
  EXPECT_EQ(kind->enum_counts,
            (std::vector<std::pair<std::string, int64_t>>{{"strip", 1}, {"grid", 2}}));

  const std::string text = format_tree(entries);
  EXPECT_NE(text.find("/b/values  float32 [3]  chunked [3] fletcher32  range [-1, 2], 1 non-finite"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("@scale (float64) = 0.5"), std::string::npos) << text;
  EXPECT_NE(text.find("strip 1, grid 2"), std::string::npos) << text;
}

TEST_F(H5TreeTest, WithoutSummariesNothingIsRead) {
  File file = File::create(path("tree.h5"));
  write_vector<float>(file, "/v", {1.0f});
  const std::vector<TreeEntry> entries = list_tree(file, false);
  EXPECT_FALSE(entry_at(entries, "/v")->summary.has_value());
}

TEST_F(H5TreeTest, LongAttributeValuesAreCutInTheListing) {
  File file = File::create(path("long.h5"));
  write_string_attribute(file, "/", "parameters", std::string(500, 'x'));
  const std::string text = format_tree(list_tree(file, false));
  EXPECT_NE(text.find("... (500 characters)"), std::string::npos) << text;
  EXPECT_EQ(text.find(std::string(kAttributeTextLimit + 1, 'x')), std::string::npos);
}

TEST_F(H5TreeTest, BlocksCoverEveryValueInOrderAndCanStop) {
  File file = File::create(path("blocks.h5"));
  std::vector<int64_t> values(1000);
  for (size_t index = 0; index < values.size(); ++index)
    values[index] = static_cast<int64_t>(index);
  write_dataset(file, "/t", values, {250, 4});
  std::vector<int64_t> seen;
  int blocks = 0;
  for_each_block<int64_t>(
      file, "/t",
      [&](int64_t first, std::span<const int64_t> block) {
        EXPECT_EQ(first, static_cast<int64_t>(seen.size()));
        EXPECT_EQ(block.size() % 4, 0u);  // whole rows
        seen.insert(seen.end(), block.begin(), block.end());
        ++blocks;
        return true;
      },
      100);
  EXPECT_EQ(seen, values);
  EXPECT_EQ(blocks, 10);
  int visits = 0;
  for_each_block<double>(
      file, "/t", [&](int64_t, std::span<const double>) { return ++visits < 2; }, 100);
  EXPECT_EQ(visits, 2);
  write_vector<float>(file, "/f", {1.5f});
  EXPECT_THROW(
      for_each_block<int64_t>(file, "/f", [](int64_t, std::span<const int64_t>) { return true; }),
      Error);
}

}  // namespace
}  // namespace hair::h5
