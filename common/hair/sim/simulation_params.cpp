#include "hair/sim/simulation_params.h"

namespace hair {

void declare_simulation_params(ParamSet& params, SimulateStageParams& values) {
  SimulationParams& p = values.simulation;
  StrandMaterial& m = p.material;
  params.add("motion", values.motion,
             "head motion preset (the keyframes of --keyframes replace it)",
             HeadMotion::preset_names());
  params.add("fps", p.fps, "frames per second", ParamRange::closed(1, 1000));
  params.add("duration_s", p.duration_s, "seconds to simulate; 0: one cycle of the motion",
             ParamRange::closed(0, 3600));
  params.add("substeps", p.substeps, "time steps per frame", ParamRange::closed(1, 1000));
  params.add("guide_count", p.guide_count,
             "guide strands over the normal and short clusters (paper: 169)",
             ParamRange::closed(0, 1000000));
  params.add("segment_length_h", p.segment_length_h,
             "guide particle spacing along normal hair, in H", ParamRange::closed(0.005, 1));
  params.add("short_segment_factor", p.short_segment_factor,
             "short hair: segments this many times longer (fewer particles, stiffer)",
             ParamRange::closed(1, 10));
  params.add("wisp_segment_factor", p.wisp_segment_factor,
             "a braid's wisp centre strand: segments this many times longer",
             ParamRange::closed(0.25, 10));
  params.add("wisp_gather_radius_h", p.wisp_gather_radius_h,
             "a braid's strands form its wisp where their mean distance from their mean point "
             "is within this, in H",
             ParamRange::above(0));
  params.add("youngs_modulus_pa", m.fibre.youngs_modulus_pa,
             "a hair's Young's modulus, Pa (Robbins 2012: 3.89 GPa)", ParamRange::above(0));
  params.add("shear_modulus_pa", m.fibre.shear_modulus_pa,
             "a hair's shear (torsional) modulus, Pa (Robbins 2012: 0.89 GPa)",
             ParamRange::above(0));
  params.add("hair_radius_m", m.fibre.radius_m, "a hair's radius, m (35 um: 70 um across)",
             ParamRange::closed(1e-6, 1e-3));
  params.add("hair_density_kg_m3", m.fibre.density_kg_m3,
             "a hair's density, kg/m^3 (Robbins 2012: 1320)", ParamRange::closed(100, 10000));
  params.add("fibres_per_guide", m.fibres_per_strand,
             "hairs a guide strand stands for (its mass and rigidities scale with it)",
             ParamRange::closed(1, 1e7));
  params.add("lock_cohesion", m.lock_cohesion,
             "how a lock's hairs hold together in bending: 0 free to slide (N E I), 1 bonded "
             "(N^2 E I)",
             ParamRange::closed(0, 1));
  params.add("stretch_frequency_hz", m.stretch_frequency_hz,
             "the hair segments' springs vibrate at this (numerical: the strain limit keeps "
             "the hair's length)",
             ParamRange::closed(1, 1e6));
  params.add("stiffness_scale", m.stiffness_scale,
             "expert override: every spring constant times this (1: the hair's own)",
             ParamRange::closed(1e-6, 1e6));
  params.add("sag_free", p.sag_free,
             "make the groom the rest under gravity (tension along the hair, a support fixed "
             "in the head's frame for the rest; --sag_free=false: the groom sags)");
  params.add("anchor_stiffness_per_kg", m.anchor_stiffness_per_kg,
             "springs from a braid's wisp to the strand ends it hangs from, per kg (1/s^2)",
             ParamRange::at_least(0));
  params.add("damping_ratio", m.damping_ratio, "spring damping, a fraction of critical",
             ParamRange::closed(0, 10));
  params.add("drag_per_s", m.drag_per_s, "air drag: velocity lost per second",
             ParamRange::closed(0, 1000));
  params.add("max_stretch", m.max_stretch, "hair segments are kept within this strain",
             ParamRange::closed(0, 1));
  params.add("bundle_cohesion_per_s2", p.bundle_cohesion_per_s2,
             "tails hold together: a guide hanging from a band is drawn back towards its "
             "bundle's centre line beyond its rest distance, per kg (1/s^2; 0: off)",
             ParamRange::closed(0, 1e6));
  params.add("bundle_damping_ratio", p.bundle_damping_ratio,
             "tails hold together: a guide's hair straying beyond its rest distance from its "
             "bundle's centre line is damped in its outward speed, a fraction of the "
             "cohesion's critical damping (held to 1/dt; 0: undamped)",
             ParamRange::closed(0, 10));
  params.add("gravity_m_s2", p.gravity_m_s2, "gravity along -Y, m/s^2",
             ParamRange::closed(0, 1000));
  params.add("body_clearance_h", p.body_clearance_h,
             "hair particles are kept this far outside the body, in H", ParamRange::closed(0, 0.2));
  params.add("body_voxel_h", p.body_voxel_h, "spacing of the body's signed distance field, in H",
             ParamRange::closed(0.002, 0.2));
  params.add("body_band_h", p.body_band_h,
             "the field holds exact distances this far from the body, in H",
             ParamRange::closed(0.004, 1));
  params.add("friction", p.friction, "Coulomb friction of hair on the body",
             ParamRange::closed(0, 10));
  params.add("body_collisions", p.body_collisions,
             "collide hair with the body (--body_collisions=false: pass through it)");
  params.add("repulsion_m_s2", p.repulsion_m_s2,
             "hair-hair repulsion down the density gradient, m/s^2 (0: none)",
             ParamRange::closed(0, 1000));
  params.add("density_cell_h", p.density_cell_h, "cell of the hair density grid, in H",
             ParamRange::closed(0.005, 1));
  params.add("repulsion_interval_frames", p.repulsion_interval_frames,
             "the repulsion is worked out every this many frames and held in between (1: "
             "every frame)",
             ParamRange::closed(1, 100));
  params.add("settle_speed_h_s", p.settle_speed_h_s,
             "a still head: integration stops when no particle is faster than this (H/s) ...",
             ParamRange::closed(0, 100));
  params.add("settle_frames", p.settle_frames, "... for this many frames in a row",
             ParamRange::closed(1, 100000));
  params.add("by_style", p.by_style,
             "simulate each cluster by its style (--by_style=false: all as normal hair, the "
             "style rules off; for benchmarks)");
  params.add("profile_phases", p.profile_phases,
             "time every phase of every strand step and log where the frames' time went "
             "(springs, solve, limits, collisions, hair-hair, bundles, frames); costs about "
             "0.5 microseconds a strand step");
}

}  // namespace hair
