#!/usr/bin/python3
"""Per-run figures of a guides.h5 for bench/stability.sh, on one line.

    bench/stability_stats.py GUIDES_H5 [MAX_STRETCH_BOUND] [INSIDE_BOUND]

Prints, space-separated: frames, whether every guide point is finite (1/0), the largest
stretch, the deepest penetration before a push (mm), the largest share of hair particles
left inside the body at a frame's end, the fastest particle (m/s), the energies (total =
kinetic + elastic + gravity, J) of the first frame, the last frame, their largest, and the
kinetic energy's largest over the middle and the last third of the frames, the growth
(the last third's largest kinetic energy over the middle third's), the springs' deformation
(mm: sqrt(2 E / (k M)) for the largest elastic energy E, the edge stiffness per kg k and
the simulated hair's mass M, wisps by the strands they carry; a root mean square of how
far the springs are from their rest lengths, whatever their stiffness), and the verdict:
"stable" when every point is finite, the stretch is within MAX_STRETCH_BOUND (default
0.011), the share left inside within INSIDE_BOUND (default 0.05), the deformation within
0.05 H and the growth at most 2 (or the kinetic energy under 1 uJ); otherwise the first
criterion that failed.
"""
import json
import sys

import h5py
import numpy as np


def main():
    path = sys.argv[1]
    stretch_bound = float(sys.argv[2]) if len(sys.argv) > 2 else 0.011
    inside_bound = float(sys.argv[3]) if len(sys.argv) > 3 else 0.05
    with h5py.File(path, "r") as f:
        frames = f["frames"]
        kinetic = frames["kinetic_energy_j"][()]
        elastic = frames["elastic_energy_j"][()]
        gravity = frames["gravity_energy_j"][()]
        stretch = frames["max_stretch"][()]
        depth = frames["max_penetration_m"][()]
        inside = frames["inside_fraction"][()]
        speed = frames["max_speed_m_s"][()]
        # Frame by frame, so that a 10,000-frame run is not read at once.
        points = frames["guide_points"]
        finite = True
        chunk = 512
        for start in range(0, points.shape[0], chunk):
            if not np.isfinite(points[start:start + chunk]).all():
                finite = False
                break
        # The simulated hair's mass M (wisps by the strands they carry).
        rest = f["guides"]["rest_points"][()].astype(np.float64)
        offsets = f["guides"]["offsets"][()]
        mass_scale = f["guides"]["mass_scale"][()]
        parameters = json.loads(f.attrs["parameters"])
        head_height = float(f.attrs["head_height_m"])
    length = 0.0
    for g in range(len(offsets) - 1):
        points = rest[offsets[g]:offsets[g + 1]]
        length += mass_scale[g] * np.linalg.norm(np.diff(points, axis=0), axis=1).sum()
    fibre_mass_per_length = parameters["hair_density_kg_m3"] * np.pi * parameters["hair_radius_m"] ** 2
    mass = length * parameters["fibres_per_guide"] * fibre_mass_per_length
    # The springs' deformation as a length, whatever their stiffness: sqrt(2 E / (k M)),
    # k the hair segments' stiffness per kilogram, (2 pi f)^2 times the stiffness scale.
    per_kg = (2 * np.pi * parameters["stretch_frequency_hz"]) ** 2 * parameters["stiffness_scale"]
    deformation = np.sqrt(2 * float(elastic.max()) / (per_kg * mass))
    deformation_h = deformation / head_height
    total = kinetic + elastic + gravity
    finite = finite and bool(np.isfinite(total).all())
    # The first third holds the ramp and the swing building up (a braid's wisp, heavy
    # and long, takes seconds): the growth compares the last third with the middle one.
    n = len(total)
    third = max(1, n // 3)
    first_half = float(np.max(kinetic[third:2 * third])) if n > third else float(kinetic.max())
    second_half = float(np.max(kinetic[2 * third:])) if n > 2 * third else first_half
    growth = second_half / first_half if first_half > 0 else (0.0 if second_half == 0 else np.inf)
    if not finite:
        verdict = "non-finite"
    elif stretch.max() > stretch_bound:
        verdict = "stretch"
    elif inside.max() > inside_bound:
        verdict = "inside"
    elif deformation_h > 0.05:
        verdict = "deformation"
    elif growth > 2 and second_half > 1e-6:
        verdict = "energy-growth"
    else:
        verdict = "stable"
    print(n, int(finite), f"{stretch.max():.4f}", f"{depth.max() * 1e3:.1f}",
          f"{inside.max() * 100:.2f}", f"{speed.max():.2f}", f"{total[0]:.3e}",
          f"{total[-1]:.3e}", f"{total.max():.3e}", f"{first_half:.3e}", f"{second_half:.3e}",
          f"{growth:.2f}", f"{deformation * 1e3:.2f}", verdict)


if __name__ == "__main__":
    main()
