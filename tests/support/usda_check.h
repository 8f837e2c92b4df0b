#pragma once
// A small reader of the ASCII USD that hair-export writes, for tests: it tokenises the
// whole layer (strings, numbers, punctuation, words), checks that every bracket, brace
// and parenthesis is matched, and reads the BasisCurves' arrays by name. Not a full USD
// parser: enough to tell a well-formed layer that lists every strand from a broken one.

#include <cctype>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace hair::test {

struct UsdaLayer {
  std::string header;                                 ///< first line, "#usda 1.0"
  std::map<std::string, std::vector<double>> arrays;  ///< "int[] curveVertexCounts", ...
  std::map<long, std::vector<double>> point_samples;  ///< time code -> flat xyz
  std::map<std::string, std::string> metadata;        ///< layer metadata, key = value text
  std::vector<std::string> prims;  ///< "Xform Groom", "BasisCurves Strands", "over Groom"
};

namespace usda_detail {

struct Token {
  enum Kind { word, number, string, punct } kind;
  std::string text;
};

inline std::vector<Token> tokenise(const std::string& text) {
  std::vector<Token> tokens;
  size_t i = text.find('\n');  // the header line is not a comment
  if (i == std::string::npos) throw std::runtime_error("no header line");
  ++i;
  std::vector<char> open;
  while (i < text.size()) {
    char c = text[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else if (c == '@') {  // an asset path, @file.usda@
      size_t end = text.find('@', i + 1);
      if (end == std::string::npos) throw std::runtime_error("unterminated asset path");
      tokens.push_back({Token::string, text.substr(i + 1, end - i - 1)});
      i = end + 1;
    } else if (c == '"') {
      size_t end = text.find('"', i + 1);
      if (end == std::string::npos) throw std::runtime_error("unterminated string");
      tokens.push_back({Token::string, text.substr(i + 1, end - i - 1)});
      i = end + 1;
    } else if (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.') {
      size_t end = i + 1;
      while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) ||
                                   text[end] == '.' || text[end] == '-' || text[end] == '+'))
        ++end;
      std::string number = text.substr(i, end - i);
      size_t used = 0;
      std::stod(number, &used);
      if (used != number.size()) throw std::runtime_error("bad number " + number);
      tokens.push_back({Token::number, number});
      i = end;
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      size_t end = i + 1;
      while (end < text.size() &&
             (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_' ||
              text[end] == ':' || text[end] == '.' || text[end] == '[' || text[end] == ']')) {
        if (text[end] == '[' && (end + 1 >= text.size() || text[end + 1] != ']')) break;
        ++end;
      }
      tokens.push_back({Token::word, text.substr(i, end - i)});
      i = end;
    } else if (std::string("()[]{},=:").find(c) != std::string::npos) {
      if (c == '(' || c == '[' || c == '{') open.push_back(c);
      if (c == ')' || c == ']' || c == '}') {
        char want = c == ')' ? '(' : c == ']' ? '[' : '{';
        if (open.empty() || open.back() != want)
          throw std::runtime_error(std::string("unmatched ") + c);
        open.pop_back();
      }
      tokens.push_back({Token::punct, std::string(1, c)});
      ++i;
    } else {
      throw std::runtime_error(std::string("unexpected character ") + c);
    }
  }
  if (!open.empty()) throw std::runtime_error("unclosed bracket");
  return tokens;
}

/// Reads the numbers of a [...] list starting at tokens[i] == "[", tuples flattened.
inline std::vector<double> number_list(const std::vector<Token>& tokens, size_t& i) {
  std::vector<double> values;
  if (tokens.at(i).text != "[") throw std::runtime_error("expected [");
  int depth = 0;
  do {
    const Token& t = tokens.at(i);
    if (t.text == "[" || t.text == "(") ++depth;
    if (t.text == "]" || t.text == ")") --depth;
    if (t.kind == Token::number) values.push_back(std::stod(t.text));
    ++i;
  } while (depth > 0);
  return values;
}

}  // namespace usda_detail

/// Parses `text`; throws std::runtime_error saying what is malformed.
inline UsdaLayer parse_usda(const std::string& text) {
  using usda_detail::Token;
  UsdaLayer layer;
  layer.header = text.substr(0, text.find('\n'));
  if (layer.header.rfind("#usda 1.0", 0) != 0) throw std::runtime_error("no #usda 1.0 header");
  std::vector<Token> tokens = usda_detail::tokenise(text);
  size_t i = 0;
  // Layer metadata: ( key = value ... )
  if (!tokens.empty() && tokens[0].text == "(") {
    i = 1;
    while (tokens.at(i).text != ")") {
      std::string key = tokens.at(i).text;
      if (tokens.at(i + 1).text != "=") throw std::runtime_error("metadata " + key + " without =");
      if (tokens.at(i + 2).text == "[") {  // a list (subLayers): its items, comma-separated
        std::string items;
        size_t j = i + 3;
        for (; tokens.at(j).text != "]"; ++j)
          if (tokens[j].text != ",") items += (items.empty() ? "" : ",") + tokens[j].text;
        layer.metadata[key] = items;
        i = j + 1;
        continue;
      }
      layer.metadata[key] = tokens.at(i + 2).text;
      i += 3;
    }
    ++i;
  }
  for (; i < tokens.size(); ++i) {
    const Token& t = tokens[i];
    if (t.kind == Token::word && t.text == "def") {
      layer.prims.push_back(tokens.at(i + 1).text + " " + tokens.at(i + 2).text);
      i += 2;
    } else if (t.kind == Token::word && t.text == "over") {
      layer.prims.push_back("over " + tokens.at(i + 1).text);
      i += 1;
    } else if (t.kind == Token::word && i + 2 < tokens.size() &&
               tokens[i + 1].kind == Token::word && tokens[i + 2].text == "=" &&
               tokens.at(i + 3).text == "[") {
      std::string name = tokens[i + 1].text;
      size_t j = i + 3;
      layer.arrays[name] = usda_detail::number_list(tokens, j);
      i = j - 1;
    } else if (t.kind == Token::word && tokens.at(i + 1).text == "points.timeSamples") {
      size_t j = i + 2;
      if (tokens.at(j).text != "=" || tokens.at(j + 1).text != "{")
        throw std::runtime_error("points.timeSamples without = {");
      j += 2;
      while (tokens.at(j).text != "}") {
        long code = std::stol(tokens.at(j).text);
        if (tokens.at(j + 1).text != ":") throw std::runtime_error("time sample without :");
        j += 2;
        layer.point_samples[code] = usda_detail::number_list(tokens, j);
        if (tokens.at(j).text == ",") ++j;
      }
      i = j;
    }
  }
  return layer;
}

}  // namespace hair::test
