#!/usr/bin/python3
"""Write variants of the paper's linkages, each changing one assumption the paper leaves open.

Into examples/paper/variants/:

- general_ground_<g>.yaml, g = 0.7, 0.8, 0.9 m: the general linkage's ground length (the project
  uses 0.8 m). C is recomputed by circle intersection so the bars keep their Table-1 lengths.
- general_crank_<a>.yaml, a = 30, 60, 90°: the general linkage's initial crank angle (project: 60°).
- <linkage>_ground_expands_<case>.yaml, case hot/cold: the ground expands like the bars. Every
  node is moved to (1 + αΔT)·its position about A (a uniform thermal expansion of the whole
  frame, ground included), the bars keep their Table-1 reference lengths (written explicitly),
  and ΔT is in the file. The project's default is a ground that does not expand.
- <linkage>_heated_at_start.yaml: another initial state. The linkage is assembled stress-free
  at ΔT = 0 and ΔT is applied during the first 10 ms of the run (function `heat`, a smooth step
  0 → ΔT over [0, 0.01] s; choose ΔT with --set functions.heat.v1=130), instead of starting
  from rest in thermal equilibrium.

The ω reading (Eq. 23 as an angle rather than an angular velocity) needs no file:
--set drivers.motor.reading=angle on the base examples.

    /usr/bin/python3 scripts/make_assumption_variants.py
"""
from linkage_models import ALPHA, ROOT, TABLE1, check_base, linkage, node_positions, write

VARIANTS = ROOT / "examples" / "paper" / "variants"
GROUND_LENGTHS = (0.7, 0.8, 0.9)        # m, general linkage
CRANK_ANGLES = (30, 60, 90)             # degrees, general linkage
EXPANSION_CASES = (("hot", 130.0), ("cold", -170.0))
HEATING_TIME = 0.01                     # s, heated_at_start


def general_geometry_variant(ground=0.8, crank_deg=60):
    """The general linkage with ground length `ground` (m) and initial crank angle `crank_deg`."""
    nodes = node_positions("general", ground=ground, angle_deg=crank_deg)
    header = (f"General four-bar linkage of Cai et al. (2017) with ground A–D = {ground:g} m and the\n"
              f"crank at {crank_deg:g}° (the paper gives neither; the project uses 0.8 m, 60°).\n"
              f"C = ({nodes['C'][0]:.6f}, {nodes['C'][1]:.6f}) by circle intersection: the bars keep their\n"
              "Table-1 lengths. Written by scripts/make_assumption_variants.py; do not edit by hand.\n"
              "Temperature case: --set thermal.dT=130 (hot), 0 (normal), -170 (cold).")
    return linkage("general", nodes=nodes, header=header)


def ground_expands_variant(kind, case, delta_t):
    """Linkage `kind` at ΔT = delta_t with the frame (ground included) expanded by 1 + αΔT."""
    scale = 1.0 + ALPHA * delta_t
    nodes = {n: (scale * x, scale * y) for n, (x, y) in node_positions(kind).items()}
    header = (f"{kind} four-bar linkage of Cai et al. (2017), case {case} (ΔT = {delta_t:+g} °C), with a\n"
              f"GROUND THAT EXPANDS like the bars: nodes at (1 + αΔT) = {scale:.6f} times their\n"
              "positions about A; the bars keep their Table-1 reference lengths (given explicitly).\n"
              "Written by scripts/make_assumption_variants.py; do not edit by hand.")
    return linkage(kind, nodes=nodes, dT=delta_t, explicit_lengths=True, header=header)


def heated_at_start_variant(kind):
    """Linkage `kind` assembled stress-free at ΔT = 0, heated to ΔT in the run's first 10 ms."""
    header = (f"{kind} four-bar linkage of Cai et al. (2017), HEATED AT THE START: the run starts from\n"
              f"rest, stress-free at ΔT = 0, and ΔT rises to its value over [0, {HEATING_TIME:g}] s\n"
              "(function heat) while the deployment begins. Choose the case with\n"
              "--set functions.heat.v1=130 (hot) or -170 (cold).\n"
              "Written by scripts/make_assumption_variants.py; do not edit by hand.")
    functions = {"heat": f"{{type: smooth_step, t0: 0, v0: 0, t1: {HEATING_TIME!r}, v1: 0}}"}
    return linkage(kind, dT="heat", functions=functions, header=header)


def main():
    """Write every variant listed in this module's docstring."""
    check_base()
    for ground in GROUND_LENGTHS:
        write(VARIANTS / f"general_ground_{ground:g}.yaml", general_geometry_variant(ground=ground))
    for angle in CRANK_ANGLES:
        write(VARIANTS / f"general_crank_{angle:g}.yaml", general_geometry_variant(crank_deg=angle))
    for kind in TABLE1:
        for case, delta_t in EXPANSION_CASES:
            write(VARIANTS / f"{kind}_ground_expands_{case}.yaml",
                  ground_expands_variant(kind, case, delta_t))
        write(VARIANTS / f"{kind}_heated_at_start.yaml", heated_at_start_variant(kind))


if __name__ == "__main__":
    main()
