"""The studies' report values: tables as Table (a dict of columns), figures
as Figure (an image array and its caption). Every function runs the C++
study with the GIL released; stochtex.dask runs the embarrassingly parallel
ones on a Dask cluster with exactly the same result."""
from __future__ import annotations

from typing import Any, Dict, List, NamedTuple, Sequence, Union

import numpy as np

from . import _stochtex
from ._stochtex import Table1Sampler  # noqa: F401 (re-exported)

__all__ = ["Figure", "Table", "Table1Sampler", "table1", "table1_from_terms", "TABLE1_FOOTPRINTS"]

TABLE1_FOOTPRINTS = (2, 4, 8, 16, 32, 64, 128)

Column = Union[np.ndarray, List[str]]


class Table(Dict[str, Column]):
    """A study's table: column key (the CSV header) → values, a float64 array
    where every cell is a number (NaN where a cell does not apply), else a
    list of the cells' text. `headers` and `units` are the page's."""

    def __init__(self, title: str, note: str, columns: Sequence[tuple]):
        super().__init__((key, values) for key, _, _, values in columns)
        self.title = title
        self.note = note
        self.headers = {key: header for key, header, _, _ in columns}
        self.units = {key: unit for key, _, unit, _ in columns}

    def rows(self) -> int:
        return len(next(iter(self.values()))) if self else 0

    def __repr__(self) -> str:
        return f"<stochtex Table {self.title!r}: {self.rows()} rows, columns {list(self)}>"


class Figure(NamedTuple):
    file: str  # the name the report writes it under
    caption: str
    image: np.ndarray  # float32 (height, width, channels), as the report writes it


def _result(raw: Dict[str, Any]) -> Dict[str, Any]:
    return {
        "data": Table(*raw["data"]),
        "tables": [Table(*t) for t in raw["tables"]],
        "figures": [Figure(*f) for f in raw["figures"]],
    }


def table1(
    *,
    count: int = 1000,
    footprints: Sequence[int] = TABLE1_FOOTPRINTS,
    seed: int = 1,
    noise_seed: int = 1,
    max_samples: int = 512,
) -> Dict[str, Any]:
    """Paper Table 1 (`stochtex reproduce table1`): the estimators' mean errors
    over `count` random square footprints of each size (texels), against the
    exact statistics. "data" has one row per noise × footprint × estimator
    (table1.csv); "tables" the paper's layout; "figures" the plots."""
    return _result(
        _stochtex.table1(count=count, footprints=list(footprints), seed=seed, noise_seed=noise_seed, max_samples=max_samples)
    )


def table1_from_terms(terms: Sequence[Sequence[np.ndarray]], **options: Any) -> Dict[str, Any]:
    """Table 1 from its per-footprint terms (Table1Sampler.terms of every
    footprint, terms[noise][k] for footprints[k] in index order, each
    (count, terms_per_footprint)), with table1()'s keywords: exactly
    table1() with the same options."""
    if "footprints" in options:
        options["footprints"] = list(options["footprints"])
    return _result(_stochtex.table1_from_terms([list(t) for t in terms], **options))
