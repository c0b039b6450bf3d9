"""The paper's two four-bar linkages as data, and a writer of deploydyn model files for them.

Shared by scripts/make_tip_driven_variants.py and scripts/make_geometry_variants.py, which write
variants of examples/paper/{parallel,general}.yaml: same bars (Cai et al. 2017, Table 1), same
driver profile (Eq. 23), same integrator, with one assumption changed. The base examples are
reproduced exactly by `linkage(...)` with the default arguments (checked by `check_base`).
"""
import math
import pathlib
import sys

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parent.parent
ALPHA = 2.0e-5          # 1/°C, paper §3
OMEGA = 0.365           # rad/s, paper Eq. (23)

# Table 1: per linkage, material name -> E (Pa); element -> (nodes, area m², material, mass kg, L0 m)
TABLE1 = {
    "parallel": {
        "materials": {"steel": 1.5e11},
        "elements": {"1": (("A", "B"), 4.64e-5, "steel", 0.288, 0.288),
                     "2": (("B", "C"), 4.64e-5, "steel", 0.357, 0.357),
                     "3": (("C", "D"), 4.64e-5, "steel", 0.288, 0.288)},
        "driven": ("3", "D", "C"),      # element, pivot, tip
    },
    "general": {
        "materials": {"crank": 1.0e9, "coupler": 5.0e6, "rocker": 5.0e8},
        "elements": {"1": (("A", "B"), 1.26e-3, "crank", 0.6811, 0.2),
                     "2": (("B", "C"), 1.96e-3, "coupler", 2.474, 0.9),
                     "3": (("C", "D"), 7.07e-4, "rocker", 1.47, 0.5197)},
        "driven": ("1", "A", "B"),
    },
}


def driver_rotation(t):
    """Rotation (rad) of the driven bar at time(s) t: the integral of the paper's Eq. (23) ω(t).

    ω rises smoothly 0 → 0.365 rad/s over [0, 1] s, is held to 4 s and falls back to 0 at 5 s,
    so the rotation is 0.1825 rad at 1 s, 1.2775 rad at 4 s and 1.46 rad from 5 s on.
    """
    t = np.asarray(t, dtype=float)
    rise = np.clip(t, 0.0, 1.0)
    held = np.clip(t - 1.0, 0.0, 3.0)
    fall = np.clip(t - 4.0, 0.0, 1.0)
    return OMEGA * ((rise ** 3 - rise ** 4 / 2) + held + (fall - fall ** 3 + fall ** 4 / 2))


def circle_intersection(p, r_p, q, r_q):
    """The intersection of circles (p, r_p) and (q, r_q) with the larger y (above the ground)."""
    p, q = np.asarray(p, float), np.asarray(q, float)
    d = np.linalg.norm(q - p)
    if not abs(r_p - r_q) < d < r_p + r_q:
        raise ValueError(f"circles ({p}, {r_p}) and ({q}, {r_q}) do not intersect: cannot assemble")
    a = (r_p ** 2 - r_q ** 2 + d ** 2) / (2 * d)
    h = math.sqrt(r_p ** 2 - a ** 2)
    mid = p + a * (q - p) / d
    normal = np.array([-(q - p)[1], (q - p)[0]]) / d
    return max(mid + h * normal, mid - h * normal, key=lambda c: c[1])


def node_positions(kind, ground=None, angle_deg=None):
    """Initial node positions {name: (x, y)} of a linkage whose bars have their Table-1 lengths.

    parallel: A = (0, 0), D = (ground, 0) (default 0.357 m), posts at angle_deg (default 5°)
    above the ground line, B = A + 0.288 (cos γ, sin γ), C the assembly above the ground.
    general: A = (0, 0), D = (ground, 0) (default 0.8 m), crank A–B at angle_deg (default 60°),
    C found by circle intersection (|BC| = 0.9, |CD| = 0.5197) above the ground line.
    """
    lengths = {e: spec[4] for e, spec in TABLE1[kind]["elements"].items()}
    if kind == "parallel":
        ground = 0.357 if ground is None else ground
        angle = math.radians(5.0 if angle_deg is None else angle_deg)
    else:
        ground = 0.8 if ground is None else ground
        angle = math.radians(60.0 if angle_deg is None else angle_deg)
    a, d = np.array([0.0, 0.0]), np.array([ground, 0.0])
    b = a + lengths["1"] * np.array([math.cos(angle), math.sin(angle)])
    c = circle_intersection(b, lengths["2"], d, lengths["3"])
    return {"A": tuple(a), "B": tuple(b), "C": tuple(c), "D": tuple(d)}


def number(x):
    """Shortest text that reads back to the same double (repr), with integers kept short."""
    x = float(x)
    return repr(int(x)) if x.is_integer() and abs(x) < 1e15 else repr(x)


def function_text(points):
    """An inline `table` time function from an (n, 2) array of (t, value) rows."""
    rows = ", ".join(f"[{number(t)}, {number(v)}]" for t, v in points)
    return f"{{type: table, points: [{rows}]}}"


def linkage(kind, nodes=None, dT=0.0, drivers=None, header="", explicit_lengths=False,
            functions=None):
    """The text of a deploydyn model file for a Table-1 linkage.

    nodes: initial positions (default `node_positions(kind)`); dT: thermal.dT (a number or a
    function name); drivers: {name: inline-mapping text} (default the base example's bar_angle
    driver, Eq. 23 read as ω); explicit_lengths: write each bar's Table-1 length as its
    reference length L0 instead of letting it default to the distance of its nodes;
    functions: {name: inline-mapping text}; header: comment lines put on top. The analysis
    section is the base example's.
    """
    spec = TABLE1[kind]
    nodes = nodes or node_positions(kind)
    element, pivot, _ = spec["driven"]
    if drivers is None:
        drivers = {"motor": f"{{type: bar_angle, element: {element}, pivot: {pivot}, "
                            "profile: paper_eq23, reading: angular_velocity}"}
    lines = [f"# {line}" if line else "#" for line in header.strip().splitlines()]
    lines += [f"name: {kind} four-bar linkage (variant)", "", "nodes:                      # m"]
    lines += [f"  {n}: [{number(x)}, {number(y)}]" for n, (x, y) in nodes.items()]
    lines += ["", "materials:                  # Pa, 1/°C"]
    lines += [f"  {m}: {{E: {number(e)}, alpha: {number(ALPHA)}}}" for m, e in spec["materials"].items()]
    lines += ["", "elements:                   # area m², mass kg, length m"]
    for name, (ends, area, material, mass, length) in spec["elements"].items():
        extra = f", length: {number(length)}" if explicit_lengths else ""
        lines.append(f"  {name}: {{nodes: [{ends[0]}, {ends[1]}], area: {number(area)}, "
                     f"material: {material}, mass: {number(mass)}{extra}}}")
    if functions:
        lines += ["", "functions:"] + [f"  {n}: {text}" for n, text in functions.items()]
    dT_text = number(dT) if isinstance(dT, (int, float)) else dT
    lines += ["", "thermal:", f"  dT: {dT_text}                     # °C on every bar",
              "", "supports:", "  - {node: A}", "  - {node: D}", "", "drivers:"]
    lines += [f"  {n}: {text}" for n, text in drivers.items()]
    lines += ["", base_analysis_block(kind)]
    return "\n".join(lines)


def base_analysis_block(kind):
    """The `analysis:` section of examples/paper/<kind>.yaml, verbatim (step, integrator, ...),
    so that every variant is integrated exactly as the example it varies."""
    text = (ROOT / "examples" / "paper" / f"{kind}.yaml").read_text()
    block = text[text.index("\nanalysis:") + 1:]
    end = next((i for i, line in enumerate(block.splitlines()[1:], 1)
                if line and not line[0].isspace() and not line.startswith("#")), None)
    return "\n".join(block.splitlines()[:end]).rstrip() + "\n"


def base_step(kind):
    """The time step (s) of examples/paper/<kind>.yaml."""
    for line in base_analysis_block(kind).splitlines():
        if line.strip().startswith("step:"):
            return float(line.split(":")[1].split("#")[0])
    raise SystemExit(f"examples/paper/{kind}.yaml gives no analysis.step")


def check_base():
    """Fail unless the default geometry equals the node positions of examples/paper/*.yaml."""
    for kind in TABLE1:
        text = (ROOT / "examples" / "paper" / f"{kind}.yaml").read_text()
        for name, (x, y) in node_positions(kind).items():
            line = next(l for l in text.splitlines() if l.strip().startswith(f"{name}:"))
            xs, ys = line.split("[")[1].split("]")[0].split(",")
            if abs(float(xs) - x) > 1e-12 or abs(float(ys) - y) > 1e-12:
                raise SystemExit(f"{kind}: node {name} at ({x}, {y}), example has {line.strip()}")


def write(path, text):
    """Write a model file, creating its folder, and say so."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    print(f"wrote {path.relative_to(ROOT)}", file=sys.stderr)
