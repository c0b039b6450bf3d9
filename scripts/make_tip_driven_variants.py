#!/usr/bin/python3
"""Write the paper's linkages with a prescribed-tip-position driver instead of a direction-only one.

examples/paper/{parallel,general}.yaml turn the driven bar with a `bar_angle` driver, which fixes
the bar's direction only: the bar stays free to stretch, so a heated driven bar is not stressed.
The variants written here into examples/paper/variants/<linkage>_tip.yaml prescribe instead
both coordinates of the driven bar's tip (C for the parallel linkage, B for the general one) on
the rigid rotation of its initial position about the pivot, θ(t) = θ0 + ∫ω dt (Eq. 23 read as
an angular velocity), by two `coordinate` drivers with `reading: displacement` and `table`
profiles. The ground pin at the pivot stays. The driven bar then keeps its reference length and
carries S = −EA·α·ΔT.

The tables are sampled at every time step of the base example (1 ms: 5001 points), so that at
each step time the tip lies exactly on the circle; linear interpolation between coarser points
would cut the chord and strain the driven bar by about Δθ²/8 (Δθ the turn between points).
Run the variants with the example's step; regenerate them after changing it.

    /usr/bin/python3 scripts/make_tip_driven_variants.py
"""
import numpy as np

from linkage_models import ROOT, TABLE1, base_step, check_base, driver_rotation, \
    function_text, linkage, node_positions, write


def tip_displacements(pivot, tip, times):
    """x and y displacements of `tip` turned rigidly about `pivot` by driver_rotation(times)."""
    rx, ry = np.asarray(tip, float) - np.asarray(pivot, float)
    turn = driver_rotation(times)
    cos_minus_1 = -2.0 * np.sin(turn / 2) ** 2          # cos − 1 without cancellation
    return cos_minus_1 * rx - np.sin(turn) * ry, np.sin(turn) * rx + cos_minus_1 * ry


def tip_driven_model(kind):
    """Model text of linkage `kind` with its driven bar's tip prescribed in x and y."""
    nodes = node_positions(kind)
    step = base_step(kind)
    element, pivot, tip = TABLE1[kind]["driven"]
    times = np.round(np.arange(0.0, 5.0 + step / 2, step), 12)
    dx, dy = tip_displacements(nodes[pivot], nodes[tip], times)
    drivers = {
        f"tip_{axis}": f"{{type: coordinate, node: {tip}, direction: {axis}, reading: displacement, "
                       f"profile: {function_text(np.column_stack([times, disp]))}}}"
        for axis, disp in (("x", dx), ("y", dy))}
    header = (f"{kind} four-bar linkage of Cai et al. (2017), DRIVEN BY ITS TIP POSITION: node {tip} of\n"
              f"bar {element} is prescribed in x and y on the rigid rotation about {pivot},\n"
              "θ(t) = θ0 + ∫ω dt with ω of Eq. (23), sampled every "
              f"{step:g} s (the time step; keep them equal).\n"
              f"Bar {element} thus keeps its reference length: heated, it carries S = −EA·α·ΔT.\n"
              "Written by scripts/make_tip_driven_variants.py; do not edit by hand.\n"
              "Temperature case: --set thermal.dT=130 (hot), 0 (normal), -170 (cold).")
    return linkage(kind, nodes=nodes, drivers=drivers, header=header)


def main():
    """Write examples/paper/variants/{parallel,general}_tip.yaml."""
    check_base()
    for kind in TABLE1:
        write(ROOT / "examples" / "paper" / "variants" / f"{kind}_tip.yaml", tip_driven_model(kind))


if __name__ == "__main__":
    main()
