#include "hair/h5/inspect_report.h"

#include "hair/core/error.h"
#include "hair/h5/attribute.h"
#include "hair/h5/provenance.h"
#include "hair/h5/schema.h"
#include "hair/h5/schema_validation.h"
#include "hair/h5/tree.h"
#include "hair/h5/tree_text.h"

namespace hair::h5 {

InspectReport inspect_report(const File& file, bool validate, std::string_view schema_name) {
  InspectReport report;
  report.text = format_tree(list_tree(file, true));
  if (has_attribute(file, "/", "stage")) {
    report.text += "\nprovenance\n";
    try {
      report.text += format_provenance(read_provenance(file));
    } catch (const Error& error) {
      report.text += std::string("  unreadable: ") + error.what() + "\n";
    }
  }
  if (!validate) return report;
  report.violation = validate_file(file, schema_name);
  if (report.violation) {
    report.text += "\ninvalid: " + *report.violation + "\n";
    return report;
  }
  const Schema& schema = Schema::find(
      schema_name.empty() ? read_string_attribute(file, "/", "schema") : std::string(schema_name));
  report.text += "\nvalid: " + schema.name + " v" + std::to_string(schema.version) + "\n";
  return report;
}

}  // namespace hair::h5
