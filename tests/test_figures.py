"""The text of the book's figures: no two texts overlap, none is cut off, none is shown below
10 pt in the book's column (obsbook.figures).

Each figure of a notebook set up with ``obsbook.setup()`` is stored with the extents and sizes
of its texts as drawn (the PNG output's metadata); the notebook tests below read them from the
committed notebooks. Notebooks not yet set up that way store none, and their test is skipped
with the reason. The checks themselves are tested first, on figures drawn here: against the
pixels of the PNG, and on figures made to have each defect.
"""

from __future__ import annotations

import json
import struct
from io import BytesIO

import matplotlib

matplotlib.use("agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from obsbook import figures  # noqa: E402
from obslib.tools.run import notebooks  # noqa: E402


def _describe(fig) -> dict:
    """What the formatter stores of ``fig``, as the notebook tests read it."""
    return figures.unpack(figures.pack(figures.render(fig)[1]))


def _texts(d: dict) -> list[str]:
    return [t["text"] for t in d["texts"]]


# ------------------------------------------------------------------- what is recorded is true

@pytest.mark.parametrize("density", [1, 2])
def test_recorded_extent_holds_the_pixels_of_the_text(density):
    # one dark text on white: every inked pixel lies in its recorded box, which it fills; the
    # box is in pixels shown, the image has density times as many
    fig = Figure(figsize=(3, 2), dpi=100)
    fig.text(0.3, 0.4, "Hxg", fontsize=20)
    png, d = figures.render(fig, density=density)
    from PIL import Image

    img = np.asarray(Image.open(BytesIO(png)).convert("L"))
    assert [img.shape[1], img.shape[0]] == [300 * density, 200 * density]
    assert d["size"] == [300, 200] and d["density"] == density
    ys, xs = np.nonzero(img < 128)
    xs, ys = xs / density, ys / density
    (t,) = d["texts"]
    x0, y0, x1, y1 = t["box"]
    assert x0 - 1 <= xs.min() and xs.max() <= x1 + 1 and y0 - 1 <= ys.min() and ys.max() <= y1 + 1
    # the box is the text's line (ascent to descent), so the ink fills most of it
    assert xs.max() - xs.min() > 0.8 * (x1 - x0) and ys.max() - ys.min() > 0.8 * (y1 - y0)
    assert t["pt"] == 20.0 and t["text"] == "Hxg"


def test_the_png_has_twice_the_pixels_of_the_size_it_is_shown_at():
    fig = Figure(figsize=(4.1, 2.3), dpi=100)
    fig.add_subplot().plot([0, 1])
    data, meta = figures.png_with_texts(fig)
    import base64

    from PIL import Image

    png = base64.b64decode(data)
    width, height = struct.unpack(">II", png[16:24])  # the IHDR chunk
    assert [width, height] == [820, 460]
    assert meta[figures.METADATA_KEY]["size"] == [410, 230] and meta["width"] == 410
    # the PNG says 200 pixels per inch, so print and LaTeX give it its 4.1 in
    assert Image.open(BytesIO(png)).info["dpi"] == pytest.approx((200, 200), abs=0.01)
    assert fig.dpi == 100  # the figure keeps its own dpi


def test_the_text_record_does_not_depend_on_the_density():
    # the same figure drawn with 1 and 2 image pixels per pixel shown: the same texts, centred
    # at the same places in pixels shown to a pixel, and as large to 5 % (glyphs are fitted to
    # the pixel grid at each size: a 12 pt title is 3 px wider at 1 than at 2)
    fig = _two_panels()
    one, two = (figures.render(fig, density=k)[1] for k in (1, 2))
    assert one["size"] == two["size"] and _texts(one) == _texts(two)
    for a, b in zip(one["texts"], two["texts"]):
        a, b = np.array(a["box"]), np.array(b["box"])
        assert np.allclose((a[:2] + a[2:]) / 2, (b[:2] + b[2:]) / 2, atol=1.0), (a, b)
        assert np.allclose(a[2:] - a[:2], b[2:] - b[:2], rtol=0.05, atol=0.5), (a, b)


@pytest.mark.parametrize("density", [0, -1, "2", True, float("nan")])
def test_a_bad_density_is_refused(density):
    with pytest.raises(ValueError, match="density"):
        figures.render(Figure(), density=density)


def test_only_drawn_tick_labels_are_recorded():
    # the locator places ticks beyond the view too; matplotlib keeps but does not draw them
    fig = Figure(figsize=(4, 3), dpi=100)
    ax = fig.add_subplot()
    ax.set_yticks([])
    ax.set_xticks(np.linspace(-0.2, 1.2, 8), [f"t{k}" for k in range(8)])
    ax.set_xlim(0.05, 0.95)  # t2..t5 in view (set_xticks widens the view to hold them all)
    assert sorted(_texts(_describe(fig))) == ["t2", "t3", "t4", "t5"]


def _two_panels() -> Figure:
    fig = Figure(figsize=(5, 3), dpi=100, layout="constrained")
    ax0, ax1 = fig.subplots(1, 2)
    ax0.plot([1, 10, 100], [3, 1, 2], label="a line")
    ax0.set_xscale("log")
    ax0.set_xlabel("distance (m)")
    ax0.legend()
    ax1.imshow(np.arange(12.0).reshape(3, 4))
    ax1.set_title("an image")
    fig.suptitle("two panels")
    return fig


def test_a_laid_out_figure_is_drawn_once_into_the_image_savefig_makes(monkeypatch):
    # savefig first draws a figure with drawing switched off to run its layout engine, then
    # again for the image; render lays it out inside its one draw: the same bytes
    buf = BytesIO()
    _two_panels().savefig(buf, format="png", dpi=2 * 100)
    fig = _two_panels()
    draws = []
    original = Figure.draw

    def counted(self, renderer):
        draws.append(renderer)
        return original(self, renderer)

    monkeypatch.setattr(Figure, "draw", counted)
    png, _ = figures.render(fig)
    monkeypatch.undo()
    assert len(draws) == 1
    assert png == buf.getvalue()
    assert fig.get_layout_engine() is not None  # the figure keeps its layout engine


def test_the_formatter_output_reaches_ipython_as_metadata():
    from IPython.core.formatters import DisplayFormatter

    formatter = DisplayFormatter()
    formatter.formatters["image/png"].for_type(Figure, figures.png_with_texts)
    fig = Figure(figsize=(2, 2), dpi=100)
    fig.add_subplot().set_title("t")
    data, meta = formatter.format(fig)
    assert data["image/png"] and "t" in _texts(
        figures.unpack(meta["image/png"][figures.METADATA_KEY])
    )
    # the width it is shown at, and no height: a page that narrows it keeps its proportions
    assert set(meta["image/png"]) == {figures.METADATA_KEY, "width"}
    assert meta["image/png"]["width"] == 200


def test_turned_text_gets_its_turned_box():
    fig = Figure(figsize=(3, 3), dpi=100)
    fig.text(0.5, 0.5, "a long turned label", rotation=30, ha="center", va="center")
    (t,) = _describe(fig)["texts"]
    q = np.array(t["quad"])
    sides = np.linalg.norm(np.roll(q, -1, axis=0) - q, axis=1)
    angle = np.degrees(np.arctan2(-(q[1, 1] - q[0, 1]), q[1, 0] - q[0, 0]))  # y points down
    assert abs(angle - 30) < 0.5 and sides[0] > 3 * sides[1]
    x0, y0, x1, y1 = t["box"]
    assert np.allclose([q[:, 0].min(), q[:, 1].min(), q[:, 0].max(), q[:, 1].max()],
                       [x0, y0, x1, y1], atol=1.0)  # the upright box is the one around it


# ------------------------------------------------------------------------ the checks, tried

def _clean_figure():
    fig = Figure(figsize=(7.5, 3), dpi=100, layout="constrained")
    ax = fig.add_subplot()
    ax.plot([0, 1], [0, 1], label="a line")
    ax.set_xlabel("x label")
    ax.set_ylabel("y label")
    ax.set_title("a title")
    ax.legend()
    return fig


def test_a_clean_figure_passes():
    d = _describe(_clean_figure())
    assert len(d["texts"]) > 10 and figures.problems(d) == []


def test_overlapping_texts_fail():
    fig = _clean_figure()
    ax = fig.axes[0]
    ax.text(0.5, 0.5, "first", transform=ax.transAxes)
    ax.text(0.52, 0.51, "second", transform=ax.transAxes)
    assert figures.overlaps(_describe(fig)) == [("first", "second")]


def test_a_label_on_a_tick_label_fails():
    fig = _clean_figure()
    fig.axes[0].set_xticks([0, 0.5, 1])
    fig.axes[0].set_xlabel("x label", labelpad=-12)  # pulled up onto the tick label 0.5
    found = figures.overlaps(_describe(fig))
    assert found and all("x label" in pair for pair in found)


def test_texts_that_only_touch_pass():
    d = {"size": [100, 100], "texts": [
        {"text": "a", "pt": 10, "angle": 0, "box": [10, 10, 30, 20]},
        {"text": "b", "pt": 10, "angle": 0, "box": [30, 10, 50, 20]},
        {"text": "c", "pt": 10, "angle": 0, "box": [10, 20, 30, 30]}]}
    assert figures.problems(d) == []


def test_turned_texts_whose_upright_boxes_overlap_pass_unless_they_overlap():
    # two parallel labels turned by 45 degrees: their upright boxes overlap, they do not
    fig = Figure(figsize=(4, 4), dpi=100)
    for x in (0.40, 0.52):
        fig.text(x, 0.5, "a label turned", rotation=45, ha="center", va="center")
    d = _describe(fig)
    (a, b) = d["texts"]
    assert min(a["box"][2], b["box"][2]) > max(a["box"][0], b["box"][0])  # upright: overlap
    assert figures.overlaps(d) == []
    fig.texts[1].set_x(0.43)  # at 0.43 the turned boxes overlap too
    assert len(figures.overlaps(_describe(fig))) == 1


def test_3d_axes_labels_are_checked_where_they_are_drawn():
    fig = Figure(figsize=(7.5, 3.5), dpi=100, layout="constrained")
    grid = fig.add_gridspec(1, 2)
    ax3 = fig.add_subplot(grid[0, 0], projection="3d")
    ax3.set_zlabel("a z label of some length")
    ax2 = fig.add_subplot(grid[0, 1])
    ax2.set_ylabel("a y label of some length")
    d = _describe(fig)
    assert "a z label of some length" in _texts(d)
    # constrained layout does not make room for a 3-D z label: it runs into the neighbour's
    assert ("a z label of some length", "a y label of some length") in figures.overlaps(d)


def test_small_text_and_wide_figures_fail():
    fig = _clean_figure()
    fig.axes[0].tick_params(labelsize=9)
    small = figures.small_texts(_describe(fig))
    assert small and {pt for _, pt in small} == {9.0}
    # 10 pt text in an 8.9 in figure is shown at 756 / 890 of its size
    fig = _clean_figure()
    fig.axes[0].set_xlabel("x label", fontsize=11)
    fig.set_size_inches(8.9, 3)
    shown = dict(figures.small_texts(_describe(fig)))
    assert shown["x label"] == pytest.approx(11 * 756 / 890, abs=0.01)  # 9.34 pt
    fig.axes[0].set_xlabel("x label", fontsize=12)  # 12 * 756 / 890 = 10.2 pt: large enough
    assert "x label" not in dict(figures.small_texts(_describe(fig)))


def test_text_cut_off_at_the_edge_fails():
    fig = Figure(figsize=(3, 2), dpi=100)
    fig.text(0.9, 0.5, "beyond the edge")
    assert figures.problems(_describe(fig)) == [
        "'beyond the edge' is cut off at the edge of the image"
    ]


# ---------------------------------------------------------------------- the book's notebooks

def _figures(path):
    """(cell index, metadata or None) of every PNG stored in the notebook ``path``."""
    out = []
    for i, cell in enumerate(json.loads(path.read_text())["cells"]):
        for o in cell.get("outputs", []):
            if any(k.endswith("image/png") for k in o.get("data", {})):
                meta = o.get("metadata", {}).get("image/png", {}).get(figures.METADATA_KEY)
                out.append((i, meta))
    return out


@pytest.mark.parametrize("path", notebooks(), ids=lambda p: p.stem)
def test_no_text_of_a_figure_overlaps_is_cut_off_or_is_too_small(path):
    stored = _figures(path)
    described = [(i, m) for i, m in stored if m is not None]
    if stored and not described:
        n = len(stored)
        pytest.skip(f"{path.stem}: its {n} figure{'s' * (n > 1)} drawn without obsbook.setup() "
                    "carry no description of their text")
    assert len(described) == len(stored), (
        f"{path.stem}: cells {[i for i, m in stored if m is None]} store figures without the "
        "description obsbook.setup() gives")
    found = [f"cell {i}: {p}" for i, m in described for p in figures.problems(figures.unpack(m))]
    assert not found, f"{path.stem}:\n" + "\n".join(found)


# ----------------------------------------------------------------------- the front page's picture

def test_the_front_page_picture_passes_the_checks():
    """The front page's picture (written by ``make book``, never committed) obeys the rules of
    every figure: at most the column's width, no text overlapping, cut off or below 10 pt."""
    from obsbook import front

    png, d = front.front_figure()
    assert png[:4] == b"\x89PNG"
    assert d["size"][0] <= figures.COLUMN_PX, d["size"]
    assert figures.problems(d) == []
    texts = _texts(d)
    assert "angle between the sensors (degrees)" in texts and "x (m)" in texts
    assert min(t["pt"] for t in d["texts"]) * figures.displayed_scale(d) >= figures.MIN_PT


def test_the_front_page_picture_is_written_whole_and_only_when_it_changes(tmp_path):
    from obsbook import front

    path = tmp_path / "front.png"
    assert front.write_figure(path) is True
    assert path.read_bytes() == front.front_figure()[0]
    before = path.stat().st_mtime_ns
    assert front.write_figure(path) is False  # the same picture: the file is left alone
    assert path.stat().st_mtime_ns == before
    assert [p.name for p in tmp_path.iterdir()] == ["front.png"]  # no temporary file left


def test_a_failed_write_of_the_front_page_picture_keeps_the_old_one(tmp_path, monkeypatch):
    import os

    from obsbook import front

    path = tmp_path / "front.png"
    path.write_bytes(b"old picture")

    def full_disk(*args, **kwargs):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", full_disk)
    with pytest.raises(OSError):
        front.write_figure(path)
    assert path.read_bytes() == b"old picture"
    assert [p.name for p in tmp_path.iterdir()] == ["front.png"]


def test_the_front_page_picture_command_refuses_an_impossible_path(tmp_path, capsys):
    from obsbook import front

    with pytest.raises(SystemExit) as exc:
        front.main(["--figure", str(tmp_path / "no-such-folder" / "front.png")])
    assert exc.value.code == 2
    assert "does not exist" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []
