"""The structure of a result folder as line segments, for deploydyn_animate.py and
deploydyn_plot.py: which nodes each member joins (from the model file), where the nodes are at
each output row (history.csv; a node without columns — output.select, or a large model's fixed
nodes — stays at its model-file position), the members' forces (NaN without a column: drawn
grey), a deformation scale, and a view that projects 3D onto the page.

Everything is arrays, so that 10⁴ members are one LineCollection and a frame costs one numpy
expression, not a Python loop over members.
"""
import pathlib

import numpy as np
import yaml
from matplotlib import colors
from matplotlib.collections import LineCollection

# Views: (azimuth, elevation) in degrees, as matplotlib's 3D axes name them; "xy" looks down
# the z axis, "xz" along −y, "yz" along x, "iso" from (1, −1, 1).
VIEWS = {"xy": (-90.0, 90.0), "xz": (-90.0, 0.0), "yz": (0.0, 0.0), "iso": (-45.0, 35.264)}
MAX_LABELLED_NODES = 30   # node names are drawn up to this many nodes
MAX_MARKED_NODES = 300    # node dots up to this many


class Structure:
    """Members (index pairs), node names, their model-file positions (n × 3) and supports."""

    def __init__(self, model_file):
        # LibYAML's parser where python3-yaml has it: the pure-Python one reads ~0.1 MB/s.
        loader = getattr(yaml, "CBaseLoader", yaml.BaseLoader)
        spec = yaml.load(pathlib.Path(model_file).read_text(encoding="utf-8"), Loader=loader)
        if not isinstance(spec, dict) or not isinstance(spec.get("nodes"), dict) \
                or not isinstance(spec.get("elements"), dict):
            raise SystemExit(f"{model_file}: not a model file (no 'nodes' and 'elements' mappings)")
        self.node_names = [str(n) for n in spec["nodes"]]
        index = {n: i for i, n in enumerate(self.node_names)}
        self.initial = np.zeros((len(self.node_names), 3))
        for i, node in enumerate(spec["nodes"].values()):
            at = node.get("at") if isinstance(node, dict) else node
            for axis, value in enumerate(at[:3]):
                self.initial[i, axis] = float(value)
        self.dimension = 3 if any(len((n.get("at") if isinstance(n, dict) else n)) == 3
                                  for n in spec["nodes"].values()) else 2
        self.member_names, pairs = [], []
        for name, element in spec["elements"].items():
            nodes = element.get("nodes") if isinstance(element, dict) else None
            if isinstance(nodes, list) and len(nodes) == 2:   # bars, cables, beams; not hinges
                self.member_names.append(str(name))
                pairs.append((index[str(nodes[0])], index[str(nodes[1])]))
        self.members = np.array(pairs, dtype=int).reshape(-1, 2)
        self.supports = sorted({index[str(s["node"])] for s in spec.get("supports") or []
                                if isinstance(s, dict) and str(s.get("node")) in index})

    def positions(self, data):
        """Node positions at every row of a history {column: array}: rows × nodes × 3."""
        n_rows = len(data["t"])
        out = np.broadcast_to(self.initial, (n_rows, *self.initial.shape)).copy()
        for i, name in enumerate(self.node_names):
            for axis, letter in enumerate("xyz"):
                column = data.get(f"{letter}.{name}")
                if column is not None:
                    out[:, i, axis] = column
        return out

    def forces(self, data):
        """Axial force of every member at every row (rows × members); NaN without a column."""
        n_rows = len(data["t"])
        return np.column_stack([data.get(f"force.{m}", np.full(n_rows, np.nan))
                                for m in self.member_names]) if self.member_names else np.zeros((n_rows, 0))

    def deformed(self, positions, scale):
        """Model-file position + scale × displacement: scale 1 is the true shape; a larger one
        makes millimetre deflections visible."""
        return self.initial + scale * (positions - self.initial)


def add_view_arguments(parser, what=""):
    """--view, --azim, --elev and --scale, as both scripts take them; `what` names what they
    apply to in the help ("structure: ")."""
    parser.add_argument("--view", choices=sorted(VIEWS),
                        help=f"{what}projection xy (default in 2D), xz, yz or iso (default in 3D)")
    parser.add_argument("--azim", type=float, help=f"{what}view azimuth (degrees), as matplotlib's 3D axes")
    parser.add_argument("--elev", type=float, help=f"{what}view elevation (degrees)")
    parser.add_argument("--scale", type=float, default=1.0,
                        help=f"{what}model-file shape + SCALE × displacement (default 1)")


def view_angles(view=None, azim=None, elev=None, dimension=3):
    """(azimuth, elevation) in degrees from a view name or explicit angles."""
    if azim is not None or elev is not None:
        base = VIEWS.get(view or "iso")
        return (azim if azim is not None else base[0], elev if elev is not None else base[1])
    return VIEWS[view or ("xy" if dimension == 2 else "iso")]


def project(points, azim, elev):
    """Orthographic projection of points (… × 3) onto the page: (… × 2) in metres, the
    camera at azimuth `azim` and elevation `elev` (degrees) as in matplotlib's 3D axes. z points
    up on the page for elev = 0; "xy" (elev 90) shows x to the right and y up."""
    a, e = np.radians(azim), np.radians(elev)
    right = np.array([-np.sin(a), np.cos(a), 0.0])
    up = np.array([-np.cos(a) * np.sin(e), -np.sin(a) * np.sin(e), np.cos(e)])
    return np.stack([points @ right, points @ up], axis=-1)


def axis_labels(azim, elev):
    """The page's axes in words, e.g. ("x (m)", "y (m)") for the xy view."""
    for name, angles in VIEWS.items():
        if np.allclose(angles, (azim, elev)) and name != "iso":
            return f"{name[0]} (m)", f"{name[1]} (m)"
    return f"across the view azim {azim:g}°, elev {elev:g}° (m)", "up the view (m)"


def segments(structure, points2):
    """members × 2 ends × 2 page coordinates, from node points (nodes × 2)."""
    return points2[structure.members]


def force_norm(forces, force_range=None):
    """Colour scale symmetric about zero: ±force_range, else ± the largest finite |force|."""
    finite = np.abs(forces[np.isfinite(forces)])
    limit = force_range or (float(finite.max()) if finite.size else 0.0) or 1.0
    return colors.Normalize(-limit, limit)


def line_collection(structure, norm):
    """One LineCollection for every member: width thinner as members grow many; grey for NaN."""
    n = len(structure.member_names)
    width = 5.0 if n <= 50 else 2.0 if n <= 1000 else 0.6
    lines = LineCollection(np.zeros((n, 2, 2)), cmap="coolwarm", norm=norm, linewidths=width,
                           capstyle="round", zorder=2)
    lines.cmap.set_bad("lightgrey")
    return lines
