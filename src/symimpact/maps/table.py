"""The table of a map: rows (one per run, in point order) as a tidy pandas DataFrame with
nullable columns for the figures that can be undefined, and back."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from .runs import OUTPUTS


def table_rows(table) -> list[dict[str, Any]]:
    """A map table (or any DataFrame) as a list of row dicts, missing values as None."""
    import pandas as pd

    return table.astype(object).where(pd.notna(table), None).to_dict("records")


def tidy_table(rows: list[dict[str, Any]], names: Sequence[str]):
    """Rows as a DataFrame with fixed column order and dtypes (missing values as ``<NA>``)."""
    import pandas as pd

    columns = ["run", *names, *OUTPUTS]
    df = pd.DataFrame.from_records(rows, columns=columns)
    df["run"] = df["run"].astype("int64")
    for n in names:
        df[n] = df[n].astype("float64")
    for c in ("n_impacts", "n_effective"):
        df[c] = df[c].astype("int64")
    for c in OUTPUTS[2:-1]:
        df[c] = pd.array(
            [None if v is None or (isinstance(v, float) and math.isnan(v)) else v for v in df[c]],
            dtype="Float64",
        )
    df["class"] = df["class"].astype("string")
    return df.sort_values("run", kind="stable").reset_index(drop=True)
