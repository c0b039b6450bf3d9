"""Legends never cover data (issue 31, item 1): every script places its legends through
scripts/plot_legend.py, and `legends_over_axes` finds any legend that overlaps an axes."""
import re
import sys

import matplotlib
import pytest

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from conftest import SOURCE_DIR  # noqa: E402

sys.path.insert(0, str(SOURCE_DIR / "scripts"))
from plot_legend import legend_below, legend_beside, legends_over_axes  # noqa: E402


def test_every_legend_is_placed_through_plot_legend():
    """A bare Axes.legend(...) or Figure.legend(...) call would let matplotlib put the legend over
    the data (loc='best' only avoids what is drawn so far)."""
    calls = []
    for folder in ("scripts", "python/deploydyn"):
        for path in sorted((SOURCE_DIR / folder).glob("*.py")):
            if path.name == "plot_legend.py":
                continue
            for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
                if re.search(r"\.legend\(|figlegend\(", line):
                    calls.append(f"{path.relative_to(SOURCE_DIR)}:{number}: {line.strip()}")
    assert calls == [], "place legends with plot_legend.legend_beside or legend_below:\n" + "\n".join(calls)


def labelled_grid():
    figure, axes = plt.subplots(2, 2, figsize=(12, 8))
    for ax in axes.flat:
        for k in range(3):
            ax.plot([0, 1], [k, k + 1], label=f"curve {k} with a long label")
    return figure, axes


def test_a_legend_inside_the_axes_is_found():
    figure, axes = labelled_grid()
    axes[0, 0].legend(loc="upper right")
    assert (0, 0) in legends_over_axes(figure)
    plt.close(figure)


def test_legends_beside_and_below_cover_no_axes_after_layout():
    figure, axes = labelled_grid()
    for ax in axes.flat:
        legend_beside(ax, fontsize="x-small")
    figure.tight_layout()
    assert legends_over_axes(figure) == []
    plt.close(figure)
    figure, ax = plt.subplots(figsize=(8, 5))
    ax.plot([0, 1], [0, 1], label="a")
    ax.plot([0, 1], [1, 0], label="b")
    legend_below(ax)
    assert legends_over_axes(figure) == []
    plt.close(figure)


def test_nothing_labelled_draws_no_legend():
    figure, ax = plt.subplots()
    ax.plot([0, 1], [0, 1])
    assert legend_beside(ax) is None and legend_below(ax) is None and ax.get_legend() is None
    plt.close(figure)


@pytest.mark.parametrize("beside", [True, False])
def test_the_checker_sees_a_legend_over_a_neighbouring_axes(beside):
    """A legend beside the left axes of a tight row, with no room made for it, lands on the right
    axes: the checker must say so (and not when the row leaves room)."""
    figure, axes = plt.subplots(1, 2, figsize=(8, 4), gridspec_kw={"wspace": 0.05 if beside else 4.0})
    for ax in axes:
        ax.plot([0, 1], [0, 1], label="a label long enough to reach the next axes")
    legend_beside(axes[0])
    found = legends_over_axes(figure)
    assert ((0, 1) in found) == beside
    plt.close(figure)
