"""Shared figure helpers for the report stages (matplotlib, Agg backend, atomic PNG writes)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..io import atomic_savefig
from ..plots import _pyplot


def pyplot() -> Any:
    """matplotlib.pyplot on the Agg backend."""
    return _pyplot()


def save(fig: Any, folder: Path, name: str) -> None:
    """Write ``fig`` as ``folder/name.png`` atomically and close it."""
    plt = _pyplot()
    fig.tight_layout()
    atomic_savefig(fig, folder / f"{name}.png", what=f"figure {name}")
    plt.close(fig)
