// hair-inspect: prints an HDF5 file's tree with dtypes, shapes and value ranges, its
// provenance, and whether it conforms to its schema; or lists and prints the schemas.
#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include "hair/core/error.h"
#include "hair/h5/file.h"
#include "hair/h5/inspect_report.h"
#include "hair/h5/schema.h"
#include "hair/h5/schema_text.h"

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
    const hair::h5::InspectReport report =
        hair::h5::inspect_report(hair::h5::File::open_read_only(path), !no_validate, schema_name);
    std::cout << report.text;
    return report.violation ? 2 : 0;
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : 2;
  } catch (const hair::Error& error) {
    std::cerr << "hair-inspect: error: " << error.what() << "\n";
    return error.exit_code();
  }
}
