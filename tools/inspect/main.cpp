// hair-inspect: prints an HDF5 file's tree with dtypes, shapes and value ranges, its
// provenance, and whether it conforms to its schema; or lists and prints the schemas.
#include <CLI/CLI.hpp>
#include <iostream>
#include <optional>
#include <string>

#include "hair/error.h"
#include "hair/h5/attribute.h"
#include "hair/h5/file.h"
#include "hair/h5/schema.h"
#include "hair/h5/schema_text.h"
#include "hair/h5/schema_validation.h"
#include "hair/h5/tree.h"
#include "hair/h5/tree_text.h"
#include "hair/provenance.h"

namespace {

/// Exit status 0 if the file conforms (or is not validated), 2 if it does not.
int inspect(const std::string& path, bool validate, const std::string& schema_name) {
  const hair::h5::File file = hair::h5::File::open_read_only(path);
  std::cout << hair::h5::format_tree(hair::h5::list_tree(file, true));
  if (hair::h5::has_attribute(file, "/", "stage")) {
    std::cout << "\nprovenance\n";
    try {
      std::cout << hair::format_provenance(hair::read_provenance(file));
    } catch (const hair::Error& error) {
      std::cout << "  unreadable: " << error.what() << "\n";
    }
  }
  if (!validate) return 0;
  const std::optional<std::string> violation = hair::h5::validate_file(file, schema_name);
  if (violation) {
    std::cout << "\ninvalid: " << *violation << "\n";
    return 2;
  }
  const hair::h5::Schema& schema = hair::h5::Schema::find(
      schema_name.empty() ? hair::h5::read_string_attribute(file, "/", "schema") : schema_name);
  std::cout << "\nvalid: " << schema.name << " v" << schema.version << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Inspect a hairstyle HDF5 file: tree, value ranges, provenance, schema check.",
               "hair-inspect");
  std::string path;
  bool no_validate = false;
  std::string schema_name;
  bool list_schemas = false;
  std::string print_schema;
  app.add_option("file", path, "HDF5 file to inspect");
  app.add_flag("--no-validate", no_validate, "Do not check the file against its schema");
  app.add_option("--schema", schema_name, "Check against this schema (the file must name it)");
  app.add_flag("--list-schemas", list_schemas, "List the schemas this build knows and exit");
  app.add_option("--print-schema", print_schema, "Print the schema NAME as text and exit");
  try {
    app.parse(argc, argv);
    if (list_schemas) {
      for (const hair::h5::Schema& schema : hair::h5::Schema::all()) {
        std::cout << schema.name << " v" << schema.version << "\n";
      }
      return 0;
    }
    if (!print_schema.empty()) {
      std::cout << hair::h5::format_schema(hair::h5::Schema::find(print_schema));
      return 0;
    }
    if (path.empty()) throw hair::Error::usage("no file given (see --help)");
    return inspect(path, !no_validate, schema_name);
  } catch (const CLI::ParseError& error) {
    const int status = app.exit(error);
    return status == 0 ? 0 : 2;
  } catch (const hair::Error& error) {
    std::cerr << "hair-inspect: error: " << error.what() << "\n";
    return error.exit_code();
  }
}
