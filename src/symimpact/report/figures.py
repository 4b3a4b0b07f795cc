"""Shared figure helpers for the report stages (matplotlib, Agg backend, atomic PNG writes)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..io import atomic_savefig
from .plots import _pyplot


def pyplot() -> Any:
    """matplotlib.pyplot on the Agg backend."""
    return _pyplot()


def save(fig: Any, folder: Path, name: str, tight: bool = True) -> None:
    """Write ``fig`` as ``folder/name.png`` atomically and close it (``tight=False`` for figures
    with a shared colour bar, which tight_layout cannot place)."""
    plt = _pyplot()
    if tight:
        fig.tight_layout()
    atomic_savefig(fig, folder / f"{name}.png", what=f"figure {name}")
    plt.close(fig)


def covered_by_legend(fig: Any) -> list[str]:
    """Labels of the plotted data a legend of ``fig`` covers: a line whose drawn path, or a
    marker or scatter point whose centre, lies inside a legend's box (display coordinates,
    after a draw). Empty when every legend sits on blank space or outside the axes."""
    import numpy as np
    from matplotlib.path import Path as MplPath

    fig.canvas.draw()
    legends = [*fig.legends, *(ax.get_legend() for ax in fig.axes)]
    boxes = [leg.get_window_extent() for leg in legends if leg is not None]
    covered = []
    for ax in fig.axes:
        for line in ax.lines:
            xy = line.get_transform().transform(np.asarray(line.get_xydata(), dtype=float))
            xy = xy[np.all(np.isfinite(xy), axis=1)]
            drawn = line.get_linestyle() not in ("None", "", " ") and len(xy) > 1
            marked = line.get_marker() not in ("None", "", " ", None)
            for box in boxes:
                if (drawn and MplPath(xy).intersects_bbox(box, filled=False)) or (
                    marked and _inside(xy, box).any()
                ):
                    covered.append(line.get_label())
                    break
        for coll in ax.collections:
            offsets = np.asarray(coll.get_offsets(), dtype=float)
            if offsets.size == 0 or not hasattr(coll, "get_sizes") or not len(coll.get_sizes()):
                continue
            xy = coll.get_offset_transform().transform(offsets)
            if any(_inside(xy, box).any() for box in boxes):
                covered.append(coll.get_label())
    return covered


def _inside(xy: Any, box: Any) -> Any:
    """Which of the display points ``xy`` (n × 2) lie in the box."""
    return (xy[:, 0] >= box.x0) & (xy[:, 0] <= box.x1) & (xy[:, 1] >= box.y0) & (xy[:, 1] <= box.y1)
