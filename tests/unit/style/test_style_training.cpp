// Labels of groups and clusters for training, and the feature tables (TSV, ARFF).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "hair/core/error.h"
#include "hair/style/style_table.h"
#include "hair/style/style_training.h"
#include "unit/file_test.h"

namespace hair {
namespace {

TEST(GroupStylesFromTruth, TakeThePatchMostOfAGroupsCornersLieIn) {
  // Patches: vertices 0-3 normal (0), 4-7 braided (3), 8-9 fixed (1).
  std::vector<int64_t> patch_first_vertex = {0, 4, 8, 10};
  std::vector<int8_t> patch_style = {0, 3, 1};
  // Faces: two quads of group 0 in patch 0; a quad of group 1 with three corners in patch
  // 1 and one in patch 2; group 2 has no face.
  std::vector<int64_t> face_offsets = {0, 4, 8, 12};
  std::vector<int32_t> face_vertices = {0, 1, 2, 3, 1, 2, 3, 0, 4, 5, 6, 8};
  std::vector<int32_t> face_group = {0, 0, 1};
  std::vector<int8_t> styles = group_styles_from_truth(face_offsets, face_vertices, face_group, 3,
                                                       patch_first_vertex, patch_style);
  EXPECT_EQ(styles, (std::vector<int8_t>{0, 3, -1}));
}

TEST(ClusterStylesByMajority, WeighGroupsAndBreakTiesTowardsTheLowerCode) {
  std::vector<int32_t> group_cluster = {0, 0, 0, 1, 1, 2};
  std::vector<int8_t> group_style = {1, 3, 3, 0, 2, -1};
  std::vector<double> weight = {10, 4, 4, 5, 5, 7};
  EXPECT_EQ(cluster_styles_by_majority(group_cluster, group_style, weight, 4),
            (std::vector<int8_t>{1, 0, -1, -1}));
  std::vector<double> purity = cluster_label_purity(group_cluster, group_style, weight, 4);
  EXPECT_NEAR(purity[0], 10.0 / 18.0, 1e-12);
  EXPECT_NEAR(purity[1], 0.5, 1e-12);
  EXPECT_EQ(purity[2], 0.0);
  EXPECT_THROW(cluster_styles_by_majority({0}, {0, 1}, {1}, 1), Error);
}

StyleTable small_table() {
  StyleTable table;
  table.feature_names = {"a", "b"};
  Eigen::RowVectorXd row(2);
  row << 0.1, 1.0 / 3.0;
  table.append(row, 3, "braid_006", 2, false, 0.75, 412);
  row << -2.5e-7, 12;
  table.append(row, 1, "ponytail01", 0, true, 1, 6488);
  return table;
}

TEST(StyleTable, TsvReadsBackExactly) {
  test::TemporaryDirectory directory("style_table");
  StyleTable table = small_table();
  write_style_table_tsv(directory / "t.tsv", table);
  StyleTable back = read_style_table_tsv(directory / "t.tsv");
  EXPECT_EQ(back.feature_names, table.feature_names);
  EXPECT_EQ(back.rows, table.rows);
  EXPECT_EQ(back.label, table.label);
  EXPECT_EQ(back.model, table.model);
  EXPECT_EQ(back.cluster, table.cluster);
  EXPECT_EQ(back.real_mesh, table.real_mesh);
  EXPECT_EQ(back.label_purity, table.label_purity);
  EXPECT_EQ(back.strand_count, table.strand_count);
  EXPECT_THROW(table.append(Eigen::RowVectorXd::Zero(3), 0, "m", 0, false, 1, 1), Error);
}

TEST(StyleTable, TablesWrittenBeforeTheStrandsColumnStillRead) {
  test::TemporaryDirectory directory("style_table");
  std::ofstream(directory / "old.tsv") << "model\tcluster\treal_mesh\tlabel\tlabel_purity\ta\n"
                                       << "m\t0\t1\tfixed\t1\t0.5\n";
  StyleTable old = read_style_table_tsv(directory / "old.tsv");
  EXPECT_EQ(old.feature_names, std::vector<std::string>{"a"});
  EXPECT_EQ(old.strand_count, std::vector<int64_t>{0});
  EXPECT_EQ(old.rows(0, 0), 0.5);
}

TEST(StyleTable, TsvErrorsNameTheLine) {
  test::TemporaryDirectory directory("style_table");
  std::ofstream(directory / "bad.tsv") << "model\tcluster\treal_mesh\tlabel\tlabel_purity\ta\n"
                                       << "m\t0\t0\tnormal\t1\t0.5\n"
                                       << "m\t1\t0\tcurly\t1\t0.5\n";
  try {
    read_style_table_tsv(directory / "bad.tsv");
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("line 3: unknown style 'curly'"), std::string::npos)
        << error.what();
  }
  std::ofstream(directory / "nan.tsv") << "model\tcluster\treal_mesh\tlabel\tlabel_purity\ta\n"
                                       << "m\t0\t0\tnormal\t1\tnan\n";
  EXPECT_THROW(read_style_table_tsv(directory / "nan.tsv"), Error);
}

TEST(StyleTable, ArffHasTheFeaturesAndTheStyleClass) {
  test::TemporaryDirectory directory("style_table");
  write_style_table_arff(directory / "t.arff", small_table(), "test");
  std::ifstream stream(directory / "t.arff");
  std::stringstream text;
  text << stream.rdbuf();
  EXPECT_NE(text.str().find("@RELATION test"), std::string::npos);
  EXPECT_NE(text.str().find("@ATTRIBUTE b NUMERIC\n@ATTRIBUTE style {normal,fixed,short,braided}"),
            std::string::npos);
  EXPECT_NE(text.str().find("0.10000000000000001,0.33333333333333331,braided\n"),
            std::string::npos);
  EXPECT_NE(text.str().find("% ponytail01 cluster 0\n"), std::string::npos);
}

}  // namespace
}  // namespace hair
