#include "hair/h5/provenance.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <nlohmann/json.hpp>

#include "hair/core/digest.h"
#include "hair/core/error.h"
#include "hair/core/version.h"
#include "hair/h5/attribute.h"

namespace hair {

namespace {

using Json = nlohmann::ordered_json;

std::string inputs_json(const std::vector<ProvenanceInput>& inputs) {
  Json list = Json::array();
  for (const ProvenanceInput& input : inputs) {
    list.push_back({{"role", input.role}, {"path", input.path}, {"sha256", input.sha256}});
  }
  return list.dump();
}

std::vector<ProvenanceInput> parse_inputs(const std::string& text, const h5::File& file) {
  const Json list = Json::parse(text, nullptr, false);
  std::vector<ProvenanceInput> inputs;
  const auto is_input = [](const Json& item) {
    return item.is_object() && item.size() == 3 && item.contains("role") &&
           item["role"].is_string() && item.contains("path") && item["path"].is_string() &&
           item.contains("sha256") && item["sha256"].is_string();
  };
  if (!list.is_array() || !std::all_of(list.begin(), list.end(), is_input)) {
    throw Error::bad_dataset(
        file.name(), "/@inputs",
        "expected a JSON list of {\"role\", \"path\", \"sha256\"}, found " + text);
  }
  for (const Json& item : list) {
    inputs.push_back({item["role"].get<std::string>(), item["path"].get<std::string>(),
                      item["sha256"].get<std::string>()});
  }
  return inputs;
}

}  // namespace

std::string utc_timestamp_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

Provenance stage_provenance(
    std::string stage, std::string parameters_json,
    const std::vector<std::pair<std::string, std::filesystem::path>>& inputs, double wall_time_s,
    bool reproducible) {
  Provenance provenance;
  provenance.stage = std::move(stage);
  provenance.project_version = project_version();
  provenance.parameters = std::move(parameters_json);
  for (const auto& [role, path] : inputs) {
    provenance.inputs.push_back({role, path.string(), sha256_file(path)});
  }
  if (!reproducible) {
    provenance.wall_time_s = wall_time_s;
    provenance.created_utc = utc_timestamp_now();
  }
  return provenance;
}

void write_provenance(h5::File& file, const Provenance& provenance) {
  if (!Json::accept(provenance.parameters)) {
    throw Error(ErrorKind::runtime, file.name(), "/@parameters",
                "parameters are not JSON text: " + provenance.parameters);
  }
  h5::write_string_attribute(file, "/", "stage", provenance.stage);
  h5::write_string_attribute(file, "/", "project_version", provenance.project_version);
  h5::write_string_attribute(file, "/", "parameters", provenance.parameters);
  h5::write_string_attribute(file, "/", "inputs", inputs_json(provenance.inputs));
  if (provenance.wall_time_s) {
    h5::write_double_attribute(file, "/", "wall_time_s", *provenance.wall_time_s);
  }
  if (provenance.created_utc) {
    h5::write_string_attribute(file, "/", "created_utc", *provenance.created_utc);
  }
}

Provenance read_provenance(const h5::File& file) {
  Provenance provenance;
  provenance.stage = h5::read_string_attribute(file, "/", "stage");
  provenance.project_version = h5::read_string_attribute(file, "/", "project_version");
  provenance.parameters = h5::read_string_attribute(file, "/", "parameters");
  if (!Json::accept(provenance.parameters)) {
    throw Error::bad_dataset(file.name(), "/@parameters",
                             "expected JSON text, found " + provenance.parameters);
  }
  provenance.inputs = parse_inputs(h5::read_string_attribute(file, "/", "inputs"), file);
  if (h5::has_attribute(file, "/", "wall_time_s")) {
    provenance.wall_time_s = h5::read_double_attribute(file, "/", "wall_time_s");
  }
  if (h5::has_attribute(file, "/", "created_utc")) {
    provenance.created_utc = h5::read_string_attribute(file, "/", "created_utc");
  }
  return provenance;
}

std::string format_provenance(const Provenance& provenance) {
  std::string text;
  text += fmt::format("  stage            {}\n", provenance.stage);
  text += fmt::format("  project_version  {}\n", provenance.project_version);
  text += fmt::format("  created_utc      {}\n",
                      provenance.created_utc.value_or("(left out: reproducible run)"));
  text += provenance.wall_time_s
              ? fmt::format("  wall_time_s      {:.3f}\n", *provenance.wall_time_s)
              : std::string("  wall_time_s      (left out: reproducible run)\n");
  text += "  inputs\n";
  for (const ProvenanceInput& input : provenance.inputs) {
    text += fmt::format("    {:<12} {}  sha256 {}\n", input.role, input.path, input.sha256);
  }
  text += "  parameters\n";
  const Json parameters = Json::parse(provenance.parameters, nullptr, false);
  const std::string pretty = parameters.is_discarded() ? provenance.parameters : parameters.dump(2);
  size_t begin = 0;
  while (begin < pretty.size()) {
    size_t end = pretty.find('\n', begin);
    if (end == std::string::npos) end = pretty.size();
    text += "    " + pretty.substr(begin, end - begin) + "\n";
    begin = end + 1;
  }
  return text;
}

}  // namespace hair
