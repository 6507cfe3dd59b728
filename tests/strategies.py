"""Hypothesis strategies for scenes: distinct sensors, none on the target, any length scale."""

import numpy as np
from hypothesis import assume
from hypothesis import strategies as st

unit = st.floats(-1.0, 1.0, allow_nan=False, allow_infinity=False)
scales = st.sampled_from([1e-3, 1e-1, 1.0, 10.0, 1e3, 1e4])


@st.composite
def scenes(draw, min_sensors=2, max_sensors=6):
    """(sensors (N, 2), target (2,), u_max) at a random scale, sensors apart from each other and the
    target."""
    scale = draw(scales)
    n = draw(st.integers(min_sensors, max_sensors))
    pts = np.array(draw(st.lists(st.tuples(unit, unit), min_size=n + 1, max_size=n + 1)))
    # keep every point at least 1e-3 (relative) from every other, so the scene is legal
    d = np.linalg.norm(pts[:, None] - pts[None], axis=-1) + np.eye(n + 1)
    assume(d.min() > 1e-3)
    u_max = draw(st.one_of(st.just(0.0), st.floats(1e-3, 3.0))) * scale
    return scale * pts[1:], scale * pts[0], u_max
