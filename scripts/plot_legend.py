"""Legends beside the axes they explain, never over the data (every figure the scripts draw).

A legend inside the axes hides whatever curve runs under it, and which one that is depends on the
run: matplotlib's loc="best" only avoids the data it has seen. So every script places its
legends through `legend_beside`, and the tests check with `legends_over_axes` that none covers
any axes of its figure (python/tests/test_plot_legends.py)."""


def legend_beside(ax, **options):
    """The legend of `ax`, to the right of it with its top at the axes' top; None when nothing is
    labelled. `options` go to Axes.legend (fontsize, ncol, title, ...)."""
    if not ax.get_legend_handles_labels()[0]:
        return None
    options.setdefault("fontsize", 8)
    return ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, **options)


def legend_below(ax, **options):
    """The legend of `ax` under it, below the axis label, in `ncol` columns (default 2): for a
    figure of one wide axes. None when nothing is labelled."""
    if not ax.get_legend_handles_labels()[0]:
        return None
    options.setdefault("fontsize", 8)
    options.setdefault("ncol", 2)
    return ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.12), **options)


def legends_over_axes(figure, tolerance_px=1.0):
    """(legend's axes index, covered axes index) for every legend that overlaps the data region of
    any axes of `figure` (its own included), after drawing it; empty when every legend is clear."""
    figure.canvas.draw()
    boxes = [ax.get_window_extent() for ax in figure.axes]
    found = []
    for i, ax in enumerate(figure.axes):
        legend = ax.get_legend()
        if legend is None or not legend.get_visible():
            continue
        box = legend.get_window_extent()
        for j, other in enumerate(boxes):
            overlap_x = min(box.x1, other.x1) - max(box.x0, other.x0)
            overlap_y = min(box.y1, other.y1) - max(box.y0, other.y0)
            if overlap_x > tolerance_px and overlap_y > tolerance_px:
                found.append((i, j))
    return found
