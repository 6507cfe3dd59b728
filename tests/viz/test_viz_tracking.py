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
