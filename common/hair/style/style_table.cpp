#include "hair/style/style_table.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "hair/core/atomic_file.h"
#include "hair/core/error.h"

namespace hair {
namespace {

const char* const kStyleWords[] = {"normal", "fixed", "short", "braided"};

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

int8_t style_code(const std::string& word) {
  for (int8_t code = 0; code < 4; ++code)
    if (word == kStyleWords[code]) return code;
  return -1;
}

/// Writes `text` to `path` atomically.
void write_text_file(const std::filesystem::path& path, const std::string& text) {
  AtomicFile output(path);
  {
    std::ofstream stream(output.temporary_path());
    stream << text;
    if (!stream.flush()) throw Error::runtime(path.string(), "cannot write");
  }
  output.commit();
}

}  // namespace

void StyleTable::append(const Eigen::RowVectorXd& features, int8_t style,
                        const std::string& model_name, int32_t cluster_id, bool real, double purity,
                        int64_t strands) {
  if (features.size() != static_cast<Eigen::Index>(feature_names.size()))
    throw Error::usage("style table: a row of " + std::to_string(features.size()) +
                       " features for " + std::to_string(feature_names.size()) + " names");
  rows.conservativeResize(rows.rows() + 1, static_cast<Eigen::Index>(feature_names.size()));
  rows.row(rows.rows() - 1) = features;
  label.push_back(style);
  model.push_back(model_name);
  cluster.push_back(cluster_id);
  real_mesh.push_back(real ? 1 : 0);
  label_purity.push_back(purity);
  strand_count.push_back(strands);
}

void write_style_table_tsv(const std::filesystem::path& path, const StyleTable& table) {
  std::ostringstream text;
  text << "model\tcluster\treal_mesh\tlabel\tlabel_purity\tstrands";
  for (const std::string& name : table.feature_names) text << '\t' << name;
  text << '\n';
  for (int64_t r = 0; r < table.row_count(); ++r) {
    auto i = static_cast<size_t>(r);
    text << table.model[i] << '\t' << table.cluster[i] << '\t' << int(table.real_mesh[i]) << '\t'
         << kStyleWords[table.label[i]] << '\t' << number_text(table.label_purity[i]) << '\t'
         << table.strand_count[i];
    for (Eigen::Index f = 0; f < table.rows.cols(); ++f)
      text << '\t' << number_text(table.rows(r, f));
    text << '\n';
  }
  write_text_file(path, text.str());
}

StyleTable read_style_table_tsv(const std::filesystem::path& path) {
  std::ifstream stream(path);
  if (!stream) throw Error::bad_input(path.string(), "cannot open the feature table");
  auto fields_of = [](const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream split(line);
    for (std::string field; std::getline(split, field, '\t');) fields.push_back(field);
    return fields;
  };
  std::string line;
  std::getline(stream, line);
  std::vector<std::string> header = fields_of(line);
  if (header.size() < 6 || header[0] != "model" || header[3] != "label")
    throw Error::bad_input(path.string(), "line 1: not a style feature table header");
  StyleTable table;
  const size_t first_feature = header[5] == "strands" ? 6 : 5;
  if (header.size() <= first_feature)
    throw Error::bad_input(path.string(), "line 1: a style feature table header without features");
  table.feature_names.assign(header.begin() + static_cast<std::ptrdiff_t>(first_feature),
                             header.end());
  std::vector<Eigen::RowVectorXd> rows;
  for (int line_number = 2; std::getline(stream, line); ++line_number) {
    if (line.empty()) continue;
    std::vector<std::string> fields = fields_of(line);
    auto where = "line " + std::to_string(line_number) + ": ";
    if (fields.size() != header.size())
      throw Error::bad_input(path.string(), where + std::to_string(fields.size()) +
                                                " fields, the header has " +
                                                std::to_string(header.size()));
    int8_t style = style_code(fields[3]);
    if (style < 0)
      throw Error::bad_input(path.string(), where + "unknown style '" + fields[3] + "'");
    Eigen::RowVectorXd values(static_cast<Eigen::Index>(table.feature_names.size()));
    try {
      for (Eigen::Index f = 0; f < values.size(); ++f) {
        values(f) = std::stod(fields[static_cast<size_t>(f) + first_feature]);
        if (!std::isfinite(values(f))) throw std::invalid_argument("not finite");
      }
      table.model.push_back(fields[0]);
      table.cluster.push_back(std::stoi(fields[1]));
      table.real_mesh.push_back(fields[2] == "1" ? 1 : 0);
      table.label_purity.push_back(std::stod(fields[4]));
      table.strand_count.push_back(first_feature == 6 ? std::stoll(fields[5]) : 0);
    } catch (const std::exception&) {
      throw Error::bad_input(path.string(), where + "a value is not a finite number");
    }
    table.label.push_back(style);
    rows.push_back(values);
  }
  table.rows.resize(static_cast<Eigen::Index>(rows.size()),
                    static_cast<Eigen::Index>(table.feature_names.size()));
  for (size_t r = 0; r < rows.size(); ++r) table.rows.row(static_cast<Eigen::Index>(r)) = rows[r];
  return table;
}

void write_style_table_arff(const std::filesystem::path& path, const StyleTable& table,
                            const std::string& relation) {
  std::ostringstream text;
  text << "% hairstyle: cluster features for hairstyle classification (docs/classify.md)\n"
       << "@RELATION " << relation << "\n\n";
  for (const std::string& name : table.feature_names) text << "@ATTRIBUTE " << name << " NUMERIC\n";
  text << "@ATTRIBUTE style {normal,fixed,short,braided}\n\n@DATA\n";
  for (int64_t r = 0; r < table.row_count(); ++r) {
    auto i = static_cast<size_t>(r);
    text << "% " << table.model[i] << " cluster " << table.cluster[i] << "\n";
    for (Eigen::Index f = 0; f < table.rows.cols(); ++f)
      text << number_text(table.rows(r, f)) << ',';
    text << kStyleWords[table.label[i]] << '\n';
  }
  write_text_file(path, text.str());
}

}  // namespace hair
