"""Figures of a continuation result folder (analysis.type: continuation), for deploydyn_plot.py:

    path.{png,svg}  the equilibrium path: load factor μ against the displacement's norm (and
                    against the first three node coordinates that move along it), and the
                    lowest eigenvalues of the constrained stiffness
                    against μ (< 0: unstable), with the summary's events (limit points,
                    bifurcations, thresholds) marked where they were located

The table is path.csv (runs/path_to_folder.hpp): mu, load_N, displacement_norm_m,
eigenvalue_<k>_N_m, n_negative, event, then history.csv's columns at each point (x.<node>,
force.<element>, ...; output.select applies).
"""
import numpy as np

from plot_legend import legend_beside

EVENT_COLOURS = {"limit_point": "tab:red", "bifurcation": "tab:purple"}


def event_marks(summary):
    """(μ, label, colour) of the events summary.json lists."""
    marks = []
    for event in (summary or {}).get("events") or []:
        if isinstance(event, dict) and isinstance(event.get("mu"), (int, float)):
            kind = str(event.get("kind", "event"))
            marks.append((float(event["mu"]), f"{kind.replace('_', ' ')} μ = {event['mu']:.6g}",
                          EVENT_COLOURS.get(kind, "tab:orange")))
    return marks


def mark_events(ax, marks, horizontal):
    """Events as dotted lines across the panel: at their μ on the μ axis."""
    for mu, label, colour in marks:
        line = ax.axhline if horizontal else ax.axvline
        line(mu, color=colour, linestyle=":", linewidth=1.2, label=label)


def plot_path(fig, runs):
    """runs: [(label, path.csv as {column: array}, summary or None)]. Returns False when no run
    has a path."""
    runs = [r for r in runs if r[1] is not None and "mu" in r[1] and len(r[1]["mu"])]
    if not runs:
        return False
    # path.csv carries the positions of every node history.csv would (output.select): panels
    # for the first three coordinates that move along the path, not the supports'.
    coordinates = [c for c in runs[0][1] if c[:2] in ("x.", "y.", "z.")
                   and np.ptp(np.asarray(runs[0][1][c], dtype=float)) > 0]
    panels = 1 + len(coordinates[:3]) + 1
    axes = fig.subplots(panels, 1, squeeze=False)[:, 0]
    several = len(runs) > 1
    for i, (label, table, summary) in enumerate(runs):
        colour = f"C{i % 10}"
        name = label if several else "path"
        axes[0].plot(table["displacement_norm_m"], table["mu"], color=colour, linewidth=1.6, label=name)
        for ax, column in zip(axes[1:-1], coordinates):
            if column in table:
                ax.plot(table[column], table["mu"], color=colour, linewidth=1.6, label=name)
                ax.set_xlabel(f"{column} (m)")
        eigenvalues = sorted(c for c in table if c.startswith("eigenvalue_"))
        for k, column in enumerate(eigenvalues):
            axes[-1].plot(table["mu"], table[column], color=colour if several else f"C{k}",
                          linestyle=("-", "--", ":", "-.")[k % 4] if several else "-", linewidth=1.4,
                          label=f"{label}: λ{k + 1}" if several else f"λ{k + 1}")
        marks = [] if several else event_marks(summary)
        for ax in axes[:-1]:
            mark_events(ax, marks, horizontal=True)
        mark_events(axes[-1], marks, horizontal=False)
    axes[0].set_xlabel("displacement norm ‖q − q₀‖ (m)")
    for ax in axes[:-1]:
        ax.set_ylabel("load factor μ (1)")
    eigen_axis = axes[-1]
    eigen_axis.axhline(0.0, color="grey", linewidth=0.8)
    eigen_axis.set_yscale("symlog", linthresh=_linear_range(runs))
    eigen_axis.set_xlabel("load factor μ (1)")
    eigen_axis.set_ylabel("lowest eigenvalues (N/m); < 0: unstable")
    for ax in axes:
        ax.grid(True, alpha=0.3)
        legend_beside(ax)
    return True


def _linear_range(runs):
    """The symlog axis's linear range: a thousandth of the largest |eigenvalue| shown, so that
    the sign change at an instability stays visible beside values decades larger."""
    largest = max((np.nanmax(np.abs(table[c])) for _, table, _ in runs for c in table
                   if c.startswith("eigenvalue_") and np.isfinite(table[c]).any()), default=1.0)
    return max(largest * 1e-3, 1e-12)
