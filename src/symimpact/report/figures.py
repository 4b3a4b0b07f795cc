"""Shared figure helpers for the report stages (matplotlib, Agg backend, atomic PNG writes)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..io import atomic_savefig
from ..plots import _pyplot


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
