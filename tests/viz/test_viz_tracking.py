"""Drawings of tracking runs (obslib.viz.tracking)."""

from __future__ import annotations

import numpy as np
import pytest

from obslib import tracking as tr
from obslib.viz import tracking as viz

CIRCLE = tr.PAPER_CIRCLE
ADV = tr.PAPER_ADVERSARIAL


def test_cov_ellipse_is_the_99_73_percent_contour():
    cov = np.array([[0.3, 0.1], [0.1, 0.2]])
    pts = viz.cov_ellipse([1.0, 2.0], cov)
    d = pts - [1.0, 2.0]
    q = np.einsum("ni,ij,nj->n", d, np.linalg.inv(cov), d)
    np.testing.assert_allclose(q, 11.82, rtol=1e-10)


def test_animation_has_every_frame():
    import matplotlib

    matplotlib.use("Agg")
    r = tr.simulate_batch(CIRCLE.replace(steps=20), "best-pair", seeds=[0]).run(0)
    anim = viz.animate(r, every=6, dpi=30)
    assert anim.frames == [1, 7, 13, 19, 20]
    html = viz.animation_html(anim, uid="t")
    assert html.count("data:image/png;base64") == 5
    assert 'id="_anim_imgt"' in html and "cdnjs" not in html
    assert viz.animation_html(viz.animate(r, every=6, dpi=30), uid="t") == html  # deterministic
    with pytest.raises(ValueError, match="every"):
        viz.animate(r, every=0)


def _ax():
    from matplotlib.figure import Figure

    return Figure().add_subplot()


def test_overlay_draws_the_published_series_under_the_replay():
    from obslib.published_runs import published_run

    pub = published_run("best-pair")
    k = np.arange(1, pub.steps + 1)
    ax = viz.draw_published_overlay(ax=_ax(), published=pub.bound, replay=pub.bound[:10], x=k,
                                    color="tab:red", label="bound")
    wide, thin = ax.get_lines()
    np.testing.assert_array_equal(wide.get_xydata(), np.column_stack([k, pub.bound]))
    np.testing.assert_array_equal(thin.get_xydata(), np.column_stack([k[:10], pub.bound[:10]]))
    assert wide.get_linewidth() > thin.get_linewidth() and wide.get_alpha() < 1
    assert wide.get_color() == thin.get_color() == "tab:red"
    # a path: its x and y columns
    ax = viz.draw_published_overlay(_ax(), pub.truth, pub.estimate)
    np.testing.assert_array_equal(ax.get_lines()[1].get_xydata(), pub.estimate)
    assert ax.get_lines()[0].get_label().startswith("_")  # no label given: not in a legend


def test_overlay_rejects_bad_input():
    with pytest.raises(ValueError, match="needs x"):
        viz.draw_published_overlay(_ax(), [1.0, 2.0])
    with pytest.raises(ValueError, match="does not match"):
        viz.draw_published_overlay(_ax(), np.zeros((3, 2)), np.zeros((3, 3)))
    with pytest.raises(ValueError, match="fewer"):
        viz.draw_published_overlay(_ax(), [1.0, 2.0], x=[1])
    with pytest.raises(ValueError, match="published must be numeric"):
        viz.draw_published_overlay(_ax(), ["a"], x=[1])
    with pytest.raises(ValueError, match="steps"):
        viz.draw_pair_overlay(_ax(), [1, 2, 3], [1, 2])
    with pytest.raises(ValueError, match="bool"):
        viz.draw_switch_overlay(_ax(), [0, 1])
    with pytest.raises(ValueError, match="y must"):
        viz.draw_switch_overlay(_ax(), [True], y="low")


def test_switch_ticks_sit_where_the_logged_pair_changes():
    from obslib.published_runs import published_run

    pub = published_run("adversarial")
    changed = np.array([tuple(a) != tuple(b) for a, b in zip(pub.pairs[:-1], pub.pairs[1:])])
    ax = viz.draw_switch_overlay(_ax(), changed, changed, y=-0.03)
    wide, thin = ax.get_lines()
    # the first step k with a pair other than step k - 1's (pairs[k - 1] is step k's)
    steps = [k for k in range(2, pub.steps + 1)
             if tuple(pub.pairs[k - 1]) != tuple(pub.pairs[k - 2])]
    assert wide.get_xdata().tolist() == thin.get_xdata().tolist() == steps
    assert len(steps) == pub.switches
    assert set(wide.get_ydata().tolist()) == {-0.03}


def _player():
    """A closed figure's FuncAnimation redrawing mathtext, contour labels and a legend."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.animation import FuncAnimation

    a, t = np.meshgrid(np.linspace(0, 3, 30), np.linspace(-3, 3, 40))
    fig, ax = plt.subplots(figsize=(3, 2), dpi=40)

    def frame(k):
        ax.clear()
        ax.clabel(ax.contour(a, t, np.sin(a * (k + 1)) * np.cos(t)), fontsize=8)
        ax.plot([1], [1], "r*", label=r"$\alpha^*$")
        ax.set_title(f"$q = {k}$")
        ax.legend(loc="upper right")

    player = FuncAnimation(fig, frame, frames=3, interval=100)
    plt.close(fig)
    return fig, player


def test_animation_html_of_a_closed_figure_is_matplotlibs_player():
    import re

    fig, player = _player()
    canvas = fig.canvas
    html = viz.animation_html(player, uid="t")
    assert fig.canvas is canvas  # the closed figure's canvas is given back
    # matplotlib's own to_jshtml on the bare canvas of the closed figure, id replaced
    ref = _player()[1].to_jshtml()
    ref = ref.replace(re.search(r'id="_anim_img([0-9a-f]+)"', ref).group(1), "t")
    ref = re.sub(r'<link[^>]*href="(?:https?:)?//[^"]*"[^>]*>\s*', "", ref)
    assert html.count("data:image/png;base64") == 3
    assert html == ref
