// The training corpus of synthetic hairstyles: presets varied within plausible bounds by a
// seed, and the plan of a corpus's models.
#include "hair/synth/synth_model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "hair/synth/synth_rng.h"

namespace hair::synth {

HairStyleSpec varied_spec(HairStyleSpec spec, uint32_t seed, bool artists_families) {
  Rng rng(seed ^ 0x9e3779b9u);
  for (ComponentSpec& component : spec.components) {
    int preset_stream_count = component.stream_count;
    if (component.kind != ComponentSpec::Kind::braid)
      component.stream_count = std::max(
          3, static_cast<int>(std::lround(component.stream_count * rng.uniform(0.75, 1.25))));
    double scale = rng.uniform(0.85, 1.15);
    component.length_min_m *= scale;
    component.length_max_m *= scale;
    component.strip_width_m *= rng.uniform(0.85, 1.15);
    // A short cap's grids share the scalp: fewer grids, wider ones.
    if (component.kind == ComponentSpec::Kind::short_cap)
      component.strip_width_m *= static_cast<double>(preset_stream_count) / component.stream_count;
    if (component.wave_amplitude_m > 0) component.wave_amplitude_m *= rng.uniform(0.7, 1.3);
    if (component.kind == ComponentSpec::Kind::braid)
      component.braid_period_m *= rng.uniform(0.85, 1.15);
  }
  DefectSpec& defects = spec.defects;
  defects.rails_min = rng.integer(2, 3);
  defects.rails_max = std::max(defects.rails_min, std::min(defects.rails_max, rng.integer(3, 4)));
  defects.gap_m = rng.uniform(0.002, 0.008);
  defects.overlap_share = rng.uniform(0.0, 0.4);
  defects.jitter_m = rng.uniform(0.0, 0.0015);
  defects.triangulate_share = rng.chance(0.5) ? 0.0 : rng.uniform(0.05, 0.4);
  defects.reversed_share = rng.uniform(0.0, 0.3);
  defects.shuffled_share = rng.uniform(0.0, 0.1);
  // A third of the short caps are layered cuts, each grid cut into a root and a tip
  // piece (drawn last: the other presets' knobs stay as they were).
  if (std::any_of(spec.components.begin(), spec.components.end(),
                  [](const ComponentSpec& c) { return c.kind == ComponentSpec::Kind::short_cap; }))
    defects.normal_pieces_max = rng.chance(1.0 / 3.0) ? 2 : 1;
  if (!artists_families) return spec;
  // Families of artists' meshes the presets alone miss (issue 26), drawn after all else so
  // the knobs above stay as they were: a third of the short caps are swept back, their
  // whorl moved to the top of the forehead so the grids run from the front over the head
  // (as short04); half the braids hang to the waist (as braid01's, 2-2.5 H).
  for (ComponentSpec& component : spec.components) {
    if (component.kind == ComponentSpec::Kind::short_cap && rng.chance(1.0 / 3.0)) {
      component.band_azimuth_deg = rng.uniform(-30.0, 30.0);
      component.band_polar_deg = rng.uniform(35.0, 50.0);
    }
    if (component.kind == ComponentSpec::Kind::braid && rng.chance(0.5)) {
      double long_braid = rng.uniform(1.5, 2.0);
      component.length_min_m *= long_braid;
      component.length_max_m *= long_braid;
    }
  }
  // Half the tails and braids gathered from the whole head are loose hair drawn back low
  // with volume (as braid01's cap): the band moved down to the nape, the cap's grids
  // falling from their roots over the ears before they sweep back to it, standing 1.5-4.5
  // cm off the head. Drawn after the families above so their draws stay as they were.
  for (ComponentSpec& component : spec.components) {
    bool gathered_from_whole_head =
        (component.kind == ComponentSpec::Kind::braid ||
         (component.kind == ComponentSpec::Kind::ponytail && component.bun_radius_m == 0)) &&
        component.polar_max_deg >= 100.0;
    if (!gathered_from_whole_head || !rng.chance(0.5)) continue;
    component.band_polar_deg = rng.uniform(95.0, 110.0);
    component.cap_volume_m = rng.uniform(0.015, 0.045);
    component.cap_drape = true;
  }
  // Braids as artists make them (as braid01's), drawn last so every draw above stays as it
  // was: where loose hair with volume gathers, the braid's top stands out by about that
  // volume and the braid leaves it backwards; half the braids narrow down to the tie; half
  // are woven from the cap's cards, 3-5 side by side in each lobe, cut into pieces of one or
  // two crossings (5-10 cm), the lobes swinging wide enough to hold their cards.
  bool woven_cards = false;
  for (ComponentSpec& component : spec.components) {
    if (component.kind != ComponentSpec::Kind::braid) continue;
    if (component.cap_volume_m > 0)
      component.braid_lift_m = component.cap_volume_m * rng.uniform(0.5, 1.0);
    if (rng.chance(0.5)) component.braid_tip_width_share = rng.uniform(0.4, 0.7);
    if (rng.chance(0.5)) {
      component.braid_cards_per_lobe = rng.integer(3, 5);
      double lobe_width_m = (component.braid_cards_per_lobe + 1) * 0.5 * component.strip_width_m;
      component.braid_width_m = std::max(component.braid_width_m, 0.4 * lobe_width_m);
      component.braid_depth_m = std::max(component.braid_depth_m, 0.2 * lobe_width_m);
      woven_cards = true;
    }
  }
  if (woven_cards) defects.braid_piece_length_m = rng.uniform(0.05, 0.1);
  return spec;
}

std::vector<CorpusEntry> corpus_plan(int count, uint32_t base_seed, bool with_painted) {
  std::vector<std::string> names = preset_names();
  if (with_painted)
    for (const std::string& name : painted_preset_names())
      if (in_training_corpus(name)) names.push_back(name);
  std::vector<CorpusEntry> plan;
  for (int i = 0; i < count; ++i) {
    CorpusEntry entry;
    entry.preset = names[static_cast<size_t>(i) % names.size()];
    entry.seed = base_seed * 1000u + static_cast<uint32_t>(i);
    entry.spec = varied_spec(preset(entry.preset), entry.seed, with_painted);
    char index[16];
    std::snprintf(index, sizeof index, "%03d", i);
    entry.name = entry.preset + "_" + index;
    plan.push_back(std::move(entry));
  }
  return plan;
}

}  // namespace hair::synth
