"""The studies' report values: tables as Table (a dict of columns), figures
as Figure (an image array and its caption). Every function runs the C++
study with the GIL released; stochtex.dask runs the embarrassingly parallel
ones on a Dask cluster with exactly the same result."""
from __future__ import annotations

import base64
import html
from typing import Any, Dict, List, NamedTuple, Sequence, Union

import numpy as np

from . import _stochtex
from ._stochtex import InstanceStatistics, StabilitySampler, Table1Sampler, TextureSource  # noqa: F401 (re-exported)

__all__ = [
    "Figure",
    "Report",
    "Section",
    "Table",
    "Table1Sampler",
    "TABLE1_FOOTPRINTS",
    "estimator_renders",
    "analyze",
    "contrast",
    "correlation",
    "figure4",
    "figure10",
    "figure11",
    "figure12",
    "figure14",
    "figures7to9",
    "flicker_from_pairs",
    "flicker_pairs",
    "fractalize",
    "frame_analysis",
    "instance_chunk",
    "instance_chunk_count",
    "instance_report",
    "instance_statistics",
    "marble",
    "stability",
    "stability_from_frames",
    "stimuli",
    "stimulus",
    "StabilitySampler",
    "table1",
    "table1_from_terms",
]

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

    def to_pandas(self):
        """The table as a pandas DataFrame, a column per key (numbers as
        float64, NaN where a cell does not apply; text as object), the title,
        headers and units in its `attrs`. pandas is optional (Debian's
        python3-pandas; scripts/install-deps.sh installs it)."""
        import pandas

        frame = pandas.DataFrame({key: values for key, values in self.items()})
        frame.attrs.update(title=self.title, note=self.note, headers=dict(self.headers), units=dict(self.units))
        return frame

    def __repr__(self) -> str:
        return f"<stochtex Table {self.title!r}: {self.rows()} rows, columns {list(self)}>"

    def _repr_html_(self) -> str:
        """The table as a notebook shows it: headers with units, numbers with
        6 significant digits (as the CSV), — where a cell does not apply."""

        def cell(v: Any) -> str:
            if isinstance(v, (float, np.floating)):
                return "—" if np.isnan(v) else f"{v:.6g}"
            return html.escape(str(v))

        head = "".join(
            f"<th>{html.escape(self.headers[k])}{' (' + html.escape(self.units[k]) + ')' if self.units[k] else ''}</th>"
            for k in self
        )
        body = "".join(
            "<tr>" + "".join(f"<td>{cell(self[k][i])}</td>" for k in self) + "</tr>" for i in range(self.rows())
        )
        title = f"<caption>{html.escape(self.title)}</caption>" if self.title else ""
        return f"<table>{title}<thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


class Figure(NamedTuple):
    file: str  # the name the report writes it under
    caption: str
    image: np.ndarray  # float32 (height, width, channels): display codes in [0, 1], as the report writes them

    def _repr_png_(self) -> bytes:
        """The figure's PNG, as the report writes it (a notebook shows it)."""
        return _stochtex.encode_image(self.image, display=True)

    def _repr_html_(self) -> str:
        png = base64.b64encode(self._repr_png_()).decode("ascii")
        caption = f"<figcaption>{html.escape(self.caption)}</figcaption>" if self.caption else ""
        return f'<figure><img src="data:image/png;base64,{png}" alt="{html.escape(self.file)}">{caption}</figure>'


class Section(NamedTuple):
    heading: str
    html: str  # the page's text under the heading
    tables: Dict[str, Table]  # by the CSV file the report writes (else the table's title)
    figures: List[Figure]
    files: Dict[str, str]  # other text files the report writes (a page, a Markdown table), by name
    folder: str = ""  # where the CLI writes the section's files, under its output folder ("" : there)

    def path(self, name: str) -> str:
        """A file of the section by its path under the report's folder."""
        return f"{self.folder}/{name}" if self.folder else name


class Report(NamedTuple):
    """A study's report as `stochtex reproduce` writes it, as values."""

    title: str
    sections: List[Section]

    # The sections' tables, figures and files by their paths under the
    # report's folder, as the CLI writes them (a section's folder first:
    # "marble/correlation.csv" beside "correlation/correlation.csv").
    @property
    def tables(self) -> Dict[str, Table]:
        return {s.path(name): t for s in self.sections for name, t in s.tables.items()}

    @property
    def figures(self) -> List[Figure]:
        return [f._replace(file=s.path(f.file)) for s in self.sections for f in s.figures]

    @property
    def files(self) -> Dict[str, str]:
        return {s.path(name): text for s in self.sections for name, text in s.files.items()}

    def _repr_html_(self) -> str:
        """The report as a notebook shows it: each section's heading, text,
        tables and figures (embedded PNGs), as `stochtex reproduce` lays out
        its page."""
        parts = [f"<h2>{html.escape(self.title)}</h2>"]
        for section in self.sections:
            if section.heading:
                parts.append(f"<h3>{html.escape(section.heading)}</h3>")
            parts.append(section.html)
            parts += [t._repr_html_() for t in section.tables.values()]
            parts += [f._repr_html_() for f in section.figures if f.caption]
        return "\n".join(parts)


def _report(raw: Dict[str, Any]) -> Report:
    sections = []
    for s in raw["sections"]:
        tables = {}
        for file, t in s["tables"]:
            table = Table(*t)
            tables[file or table.title] = table
        figures = [Figure(*f) for f in s["figures"]]
        sections.append(Section(s["heading"], s["html"], tables, figures, dict(s["files"]), s["folder"]))
    return Report(raw["title"], sections)


def figure4(
    pattern: Any = "camouflage",
    *,
    footprints: Sequence[int] = (1, 2, 4, 8, 16, 32, 64, 128),
    prefilter: str = "smooth",
    reference_tolerance: float = 5e-4,
    **numbers: Any,
) -> Report:
    """Paper Figure 4 (`stochtex reproduce figure4`) for any pattern (a
    Pattern, preset name, path or dict): per footprint the reference S̄, Ŝ
    from the exact statistics and from the estimators, and their mean errors
    (the table "figure4.csv"). numbers: the study's option table, size (image
    side per footprint) and reference_samples (the reference's cap per axis)."""
    from . import pattern as _pattern

    return _report(
        _stochtex.figure4(
            _pattern(pattern), footprints=list(footprints), prefilter=prefilter,
            reference_tolerance=reference_tolerance, **numbers
        )
    )


def figure10(**numbers: Any) -> Report:
    """Paper Figure 10 (`stochtex reproduce figure10`): the phasor variants'
    sheet, and procedural phasor noise beside ours with their spectra.
    numbers: size, comparison_size."""
    return _report(_stochtex.figure10(**numbers))


def figure12(pattern: Any = "lean-ridges", **options: Any) -> Report:
    """Paper Figure 12 (`stochtex reproduce figure12`): a LEAN-mapped
    procedural normal map on a plane, four variants against the reference.
    Options: size (the view's width; height 5/8 of it), tilt_deg, aniso,
    reference_samples, progress."""
    from . import pattern as _pattern

    return _report(_stochtex.figure12(_pattern(pattern), **options))


def figure14(pattern: Any = "figure14", *, footprints: Sequence[int] = (1, 2, 4, 8, 16, 32, 64), **options: Any) -> Report:
    """Paper Figure 14 (`stochtex reproduce figure14`): a texture graph
    filtered per footprint against its reference. Options: prefilter, size,
    reference_samples, progress."""
    from . import pattern as _pattern

    return _report(_stochtex.figure14(_pattern(pattern), footprints=list(footprints), **options))


def estimator_renders(**options: Any) -> Report:
    """The estimators' rendered error (`stochtex reproduce estimators`):
    presets (names), scales (texels per pixel), plane (bool), prefilter,
    and the numbers size, reference_samples, aniso, tilt_deg, plane_scale."""
    for key in ("presets", "scales"):
        if key in options:
            options[key] = list(options[key])
    return _report(_stochtex.estimator_renders(**options))


def frame_analysis(source: TextureSource, analyses: Sequence[str] = ("spectrum",), **options: Any) -> Report:
    """Frame studies of a source's window on one page, as `stochtex
    shadertoy PROG --analyse ...` writes it: "spectrum" (the first frame's
    power spectrum), "flow" (optical flow between consecutive frames),
    "coherence", "flicker" (what the flow does not explain), "statistics"
    (over instances). A source: ZoomTexture, Shadertoy, Renderer.source().
    Options: size (N or (width, height)), origin, time and time_step (the
    source's start and frame step by default), frames, instances, point_x,
    point_y, progress."""
    return _report(_stochtex.frame_analysis(source, analyses=list(analyses), **options))


def stability(pattern: Any = "marble", **options: Any) -> Report:
    """Temporal stability under a zoom (`stochtex stability`): per filter,
    the error flicker (the change of frame − S̄ between consecutive frames,
    the zoom undone), the accuracy and the image change of a zoom-out
    sequence. Options: filters (names), estimators (each filter over the
    estimators once per name), aniso, reference_max_samples, progress, and
    the numbers frames, size, from, to, truth_samples. stochtex.dask.stability
    measures the frames on a cluster with exactly this result."""
    from . import pattern as _pattern

    return _report(_stochtex.stability(_pattern(pattern), **_lists(options)))


def stability_from_frames(parts: Sequence[tuple], pattern: Any = "marble", **options: Any) -> Report:
    """The stability study from StabilitySampler.frames' parts that cover
    every frame in order, with stability()'s options: exactly its result."""
    from . import pattern as _pattern

    return _report(_stochtex.stability_from_frames(list(parts), _pattern(pattern), **_lists(options)))


def _lists(options: Dict[str, Any]) -> Dict[str, Any]:
    return {k: list(v) if k in ("filters", "estimators") else v for k, v in options.items()}


def correlation(zoom: Any = None, **options: Any) -> Report:
    """The thesis's correlation study (`stochtex correlation`, Figures
    2.8–2.10): per zoom variant ("sliding", "fixed", "simple", "random")
    and layer count, the correlation over instances of the zoom texture
    measured beside its closed form. zoom: a ZoomTexture giving the numbers
    and the base (default: ZoomTexture()). Options: variants, layers,
    instances, plot_size, progress."""
    from . import ZoomTexture

    for key in ("variants", "layers"):
        if key in options:
            options[key] = list(options[key])
    return _report(_stochtex.correlation(zoom if zoom is not None else ZoomTexture(), **options))


def contrast(zoom: Any = None, **numbers: Any) -> Report:
    """The thesis's contrast corrections (`stochtex contrast`, §2.4):
    linear, polynomial and sigmoid correction of the zoom texture (default
    ZoomTexture(layers=16), Figure 2.6's) at its time, with histograms,
    curves and clamped-pixel percentages ("contrast.csv"). numbers: size."""
    from . import ZoomTexture

    return _report(_stochtex.contrast(zoom if zoom is not None else ZoomTexture(layers=16), **numbers))


def fractalize(images: Any, **options: Any) -> Report:
    """Image textures as the zoom texture's base (`stochtex fractalize`,
    thesis Figures 2.15–2.17): each image's correlation around a point and
    the zoom texture's over it, without and with hashed offsets
    ("fractalize.csv", figure2_15.png, figure2_17.png). images: a dict
    {name: pixels or path} (pixels as read_image gives them) or a sequence
    of paths. Options: layers (8), max_scale, size, instances, reference_x,
    reference_y, echo_radius, progress."""
    return _report(_stochtex.fractalize(images if isinstance(images, dict) else list(images), **options))


def analyze(zoom: Any = None, **options: Any) -> Report:
    """The report page on the zoom texture's artifacts (`stochtex analyze`):
    sliding, contrast and its corrections, correlation, spectrum, optical
    flow, temporal coherence over the layer counts, image bases, the marble
    texture and the perception stimuli, one section each (the marble's
    sliding videos are the CLI's). zoom: a ZoomTexture giving the numbers
    and the base (default: ZoomTexture()). Options: images (as fractalize
    takes them), layers, coherence_layers, instances, plot_size, size,
    frame_size, spectrum_instances, coherence_frames, progress."""
    from . import ZoomTexture

    for key in ("layers", "coherence_layers"):
        if key in options:
            options[key] = list(options[key])
    if options.get("images") is not None and not isinstance(options["images"], dict):
        options["images"] = list(options["images"])
    return _report(_stochtex.analyze(zoom if zoom is not None else ZoomTexture(), **options))


def figure11(**options: Any) -> Report:
    """Paper Figure 11 (`stochtex reproduce figure11`): Figure 4's
    comparison for the phasor sine pattern (phasor-stripes), fading to the
    profile's mean colour. Options: footprints, reference_tolerance, size,
    reference_samples, progress."""
    if "footprints" in options:
        options["footprints"] = list(options["footprints"])
    return _report(_stochtex.figure11(**options))


def figures7to9(**options: Any) -> Report:
    """Paper Figures 7–9 (`stochtex reproduce figures7-9`): sheets of four
    presets each, `size` pixels per pattern; progress."""
    return _report(_stochtex.figures7to9(**options))


def marble(**options: Any) -> Report:
    """The thesis's marble study (`stochtex marble`, §2.7.2–2.8):
    stretching, correlation ("correlation.csv"), spectra and sliding of the
    marble texture, continuous scaling against the blended fix. Options:
    scalings, point, method (the flow's), seed, progress, the texture's
    numbers (band_period, band_angle, distortion, level, level_amplitude,
    level_period, level_rate) and the study's (size, correlation_size,
    instances, spectrum_instances, slide_rate, frames, time_step,
    flow_step)."""
    if "scalings" in options:
        options["scalings"] = list(options["scalings"])
    return _report(_stochtex.marble(**options))


def stimulus(**options: Any) -> np.ndarray:
    """One perception stimulus (thesis §2.6.2): float32 (size, size) display
    values of tiled white noise whose pixels one tile apart correlate as
    asked. Options: size, tile, correlation, seed, mean, contrast."""
    return _stochtex.stimulus(**options)


def stimuli(**options: Any) -> Report:
    """The perception experiment's stimulus set (`stochtex stimuli`): the
    table "stimuli.csv" (one row per trial, in presentation order), the
    stimuli as figures and the experiment page (report.files
    ["experiment.html"], self-contained). Options: tiles, correlations,
    seed, mean, contrast, size, repeats, duration_ms, reset_ms, progress."""
    for key in ("tiles", "correlations"):
        if key in options:
            options[key] = list(options[key])
    return _report(_stochtex.stimuli(**options))


def flicker_pairs(source: TextureSource, first: int, count: int, **options: Any) -> tuple:
    """The flicker of pairs [first, first + count) (pair k: frame k → k + 1)
    of frame_analysis(source, ["flicker"], **options)'s run, its frames
    rendered here: (first, residual, contrast, relative, worst_map)."""
    return _stochtex.flicker_pairs(source, first, count, **options)


def flicker_from_pairs(source: TextureSource, parts: Sequence[tuple], **options: Any) -> Report:
    """frame_analysis(source, ["flicker"], **options) from flicker_pairs'
    parts that cover every pair in order: exactly its report."""
    return _report(_stochtex.flicker_from_pairs(source, list(parts), **options))


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


def instance_statistics(source: TextureSource, **options: Any) -> InstanceStatistics:
    """The statistical accumulator (thesis §3.3) over instances 0…N−1 of a
    source (ZoomTexture, Shadertoy) at one time: per-pixel mean and variance
    of the gray frames, the correlation of every pixel with a point (eq. 3.1),
    with a row, and between the pixels of the probe row. Options: size (N or
    (width, height), 4…1024), origin ((x0, y0); default: centred), time,
    instances, chunk, point_x, point_y, reference_row, probe_row, progress
    (a callable(fraction, step)). stochtex.dask.instance_statistics splits
    the same run over a cluster with exactly this result."""
    return _stochtex.instance_statistics(source, **options)


def instance_chunk(source: TextureSource, index: int, **options: Any) -> InstanceStatistics:
    """The sums of chunk `index` (instances [index·chunk, (index+1)·chunk))
    of instance_statistics with the same options. Merged in index order into
    InstanceStatistics(**options), the chunks give its result exactly."""
    return _stochtex.instance_chunk(source, index, **options)


def instance_chunk_count(**options: Any) -> int:
    """The number of chunks of instance_statistics with these options."""
    return _stochtex.instance_chunk_count(**options)


def instance_report(statistics: InstanceStatistics) -> Report:
    """What `stochtex shadertoy --analyse statistics` reports: the summary
    table "statistics.csv" (instances, mean of the mean and its spread, mean
    variance, the correlation's Corr ≥ ½ area, elongation, anti-correlation)
    and maps of the mean, the variance and the correlation."""
    return _report(_stochtex.instance_report(statistics))
