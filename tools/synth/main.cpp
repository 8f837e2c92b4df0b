// hair-synth: synthetic hair meshes with ground truth (issue 3), for measuring every
// stage. One model, a corpus with a manifest, or a gallery picture of the presets.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <opencv2/core.hpp>

#include "hair/core/atomic_file.h"
#include "hair/core/error.h"
#include "hair/h5/provenance.h"
#include "hair/h5/schema_validation.h"
#include "hair/mesh/mesh_io.h"
#include "hair/render/strand_render.h"
#include "hair/render/synth_gallery.h"
#include "hair/synth/synth_io.h"

namespace {

namespace fs = std::filesystem;
using hair::synth::SynthModel;

struct Common {
  std::string body_path = "data/samples/body.obj";
  double unit_scale = 0.1;
  int strands_per_stream = 24;
  bool reproducible = false;
};

hair::PolyMesh body_in_metres(const Common& common) {
  hair::PolyMesh body = hair::read_mesh(common.body_path);
  body.vertices *= static_cast<float>(common.unit_scale);
  return body;
}

void write_text_atomically(const fs::path& path, const std::string& text) {
  hair::AtomicFile output(path);
  {
    std::ofstream stream(output.temporary_path(), std::ios::binary);
    stream << text;
    if (!stream.flush()) throw hair::Error::runtime(path.string(), "cannot write");
  }
  output.commit();
}

/// Writes DIR/<name>.obj and DIR/<name>.truth.h5; for a painted model also DIR/<name>.mtl
/// and DIR/textures/<name>.png, as artists ship hair meshes.
void write_model(const SynthModel& model, const std::string& name, const fs::path& directory,
                 const Common& common, double wall_time_s) {
  fs::path obj_path = directory / (name + ".obj");
  fs::path truth_path = directory / (name + ".truth.h5");
  std::string mtl_name;
  if (model.mesh.has_materials()) {
    const std::string image_name = "textures/" + name + ".png";
    fs::create_directories(directory / "textures");
    const std::vector<uint8_t>& png = model.mesh.materials.front().diffuse.encoded;
    write_text_atomically(directory / image_name, std::string(png.begin(), png.end()));
    mtl_name = name + ".mtl";
    write_text_atomically(directory / mtl_name, hair::synth::mtl_text(model, image_name));
  }
  write_text_atomically(obj_path, hair::synth::obj_text(model, common.unit_scale, mtl_name));
  hair::AtomicFile output(truth_path);
  auto file = hair::h5::File::create(output.temporary_path(), truth_path.string());
  hair::synth::write_truth_file(file, model, common.unit_scale, obj_path.filename().string());
  hair::write_provenance(
      file,
      hair::stage_provenance("hair-synth", hair::synth::spec_json(model.spec).dump(),
                             {{"body_mesh", common.body_path}}, wall_time_s, common.reproducible));
  hair::h5::require_valid_output(file, hair::synth::kSynthTruthSchema);
  file.close();
  output.commit();
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The models of corpus_plan() and DIR/manifest.tsv: one line per model with its
/// streams per style.
void write_corpus(int count, uint32_t base_seed, bool with_painted, const fs::path& directory,
                  const Common& common) {
  hair::PolyMesh body = body_in_metres(common);
  std::string manifest =
      "name\tpreset\tseed\tmixed\tpatches\tvertices\tstreams\tnormal\tfixed\tshort\tbraided\n";
  std::array<int, 4> totals{};
  int mixed_models = 0;
  for (const hair::synth::CorpusEntry& entry :
       hair::synth::corpus_plan(count, base_seed, with_painted)) {
    auto start = std::chrono::steady_clock::now();
    SynthModel model =
        hair::synth::generate_model(entry.spec, body, entry.seed, common.strands_per_stream);
    write_model(model, entry.name, directory, common, seconds_since(start));
    auto by_style = hair::synth::streams_by_style(model);
    bool mixed = entry.spec.components.size() > 1;
    mixed_models += mixed ? 1 : 0;
    for (size_t s = 0; s < 4; ++s) totals[s] += by_style[s];
    manifest +=
        fmt::format("{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\n", entry.name, entry.preset,
                    entry.seed, mixed ? 1 : 0, model.patches.size(), model.mesh.vertex_count(),
                    model.stream_style.size(), by_style[0], by_style[1], by_style[2], by_style[3]);
    std::cerr << "hair-synth: " << entry.name << ": " << model.patches.size() << " patches\n";
  }
  write_text_atomically(directory / "manifest.tsv", manifest);
  std::cout << fmt::format(
      "{} models ({} mixed); streams: normal {}, fixed {}, short {}, braided {}\n", count,
      mixed_models, totals[0], totals[1], totals[2], totals[3]);
}

/// A picture of every preset (seed 1), see synth_gallery().
void write_gallery(const fs::path& png_path, int view_size_px, const Common& common) {
  hair::PolyMesh body = body_in_metres(common);
  std::vector<SynthModel> models;
  for (const std::string& preset : hair::synth::preset_names())
    models.push_back(hair::synth::generate_model(hair::synth::preset(preset), body, 1,
                                                 common.strands_per_stream));
  hair::write_png(hair::synth_gallery(models, body, view_size_px), png_path.string());
}

/// A specification from a JSON file (spec_from_json); bad JSON is a usage error naming it.
hair::synth::HairStyleSpec read_spec(const std::string& path) {
  std::ifstream stream(path);
  if (!stream) throw hair::Error::bad_input(path, "cannot read the specification");
  nlohmann::json json = nlohmann::json::parse(stream, nullptr, false);
  if (json.is_discarded()) throw hair::Error::bad_input(path, "not valid JSON");
  try {
    return hair::synth::spec_from_json(json);
  } catch (const hair::Error& e) {
    throw hair::Error(hair::ErrorKind::usage, path, "", e.reason());
  }
}

void add_common(CLI::App& app, Common& common) {
  app.add_option("--body", common.body_path, "body mesh the hair is fitted on")
      ->capture_default_str();
  app.add_option("--unit-scale", common.unit_scale,
                 "metres per unit of the body and of the written meshes (0.1: decimetres)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--strands-per-stream", common.strands_per_stream, "dense true strands per stream")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  app.add_flag("--reproducible", common.reproducible,
               "leave the date and wall time out of provenance (byte-identical reruns)");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Synthetic hair meshes with ground truth: hair-synth --preset NAME --seed N -o DIR",
               "hair-synth");
  Common common;
  std::string preset, name, output;
  uint32_t seed = 1;
  bool list_presets = false, vary = false;
  std::string spec_path;
  bool print_spec = false;
  app.add_option("--preset", preset, "hairstyle preset (--list-presets)");
  app.add_option("--spec", spec_path,
                 "hairstyle specification as JSON (the form --print-spec prints), instead of "
                 "--preset: every component and defect knob");
  app.add_flag("--print-spec", print_spec,
               "print the specification of --preset (after --vary) as JSON and exit");
  app.add_option("--seed", seed, "random seed")->capture_default_str();
  app.add_option("--name", name, "file stem of the outputs (default: the preset)");
  app.add_flag("--vary", vary, "vary the preset's knobs by the seed, as the corpus does");
  app.add_option("-o,--output", output, "output folder");
  app.add_flag("--list-presets", list_presets, "print the presets and exit");
  add_common(app, common);

  CLI::App* corpus =
      app.add_subcommand("corpus", "write COUNT models across the presets and a manifest");
  int count = 60;
  uint32_t corpus_seed = 1;
  std::string corpus_output;
  corpus->add_option("--count", count, "models")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  corpus->add_option("--seed", corpus_seed, "base seed: model i gets seed*1000+i")
      ->capture_default_str();
  corpus->add_option("-o,--output", corpus_output, "output folder")->required();
  bool corpus_painted = false;
  corpus->add_flag("--painted", corpus_painted,
                   "cycle through the painted presets too (the kinds of community meshes, with "
                   "their textures): the corpus the style classifiers train on");
  add_common(*corpus, common);

  CLI::App* gallery = app.add_subcommand("gallery", "render the presets into one PNG");
  std::string gallery_output;
  int view_size_px = 220;
  gallery->add_option("-o,--output", gallery_output, "PNG to write")->required();
  gallery->add_option("--size", view_size_px, "pixels per view")->check(CLI::Range(64, 2048));
  add_common(*gallery, common);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "hair-synth: error: " << e.what() << "\n";
    return 2;
  }
  try {
    if (list_presets) {
      for (const std::string& p : hair::synth::preset_names()) std::cout << p << "\n";
      for (const std::string& p : hair::synth::painted_preset_names())
        std::cout << p
                  << (hair::synth::in_training_corpus(p)
                          ? " (painted; in the corpus with corpus --painted)\n"
                          : " (painted; not in the corpus)\n");
      return 0;
    }
    if (*corpus) {
      fs::create_directories(corpus_output);
      write_corpus(count, corpus_seed, corpus_painted, corpus_output, common);
      return 0;
    }
    if (*gallery) {
      write_gallery(gallery_output, view_size_px, common);
      return 0;
    }
    if (preset.empty() == spec_path.empty())
      throw hair::Error::usage(
          "give one of --preset and --spec (or a subcommand: corpus, gallery)");
    auto start = std::chrono::steady_clock::now();
    hair::synth::HairStyleSpec spec =
        spec_path.empty() ? hair::synth::preset(preset) : read_spec(spec_path);
    if (vary) spec = hair::synth::varied_spec(spec, seed);
    if (print_spec) {
      std::cout << hair::synth::spec_json(spec).dump(2) << "\n";
      return 0;
    }
    if (output.empty()) throw hair::Error::usage("-o is required");
    if (name.empty()) name = spec.name.empty() ? "custom" : spec.name;
    fs::create_directories(output);
    SynthModel model =
        hair::synth::generate_model(spec, body_in_metres(common), seed, common.strands_per_stream);
    write_model(model, name, output, common, seconds_since(start));
  } catch (const hair::Error& e) {
    std::cerr << "hair-synth: error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "hair-synth: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
