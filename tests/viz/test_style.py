"""The book's palette (obslib.viz.style): every name the book draws has one look, and no two
looks can be mistaken for each other."""

import pytest
from matplotlib.colors import to_rgb

from obslib import measures, tracking
from obslib.viz import style


def test_every_strategy_and_measure_has_a_look():
    names = [*tracking.STRATEGIES, *tracking.CRITERIA, *measures.MEASURES]
    for name in names:
        assert isinstance(style.look(name), style.Look), name


def test_no_two_names_share_colour_and_marker():
    # one exception, by design: the bound's best pair is the greedy's choice for one target
    seen = {}
    for name, look in style.LOOKS.items():
        if look.color is None or name == "best-pair":
            continue
        key = (to_rgb(look.color), look.marker, look.linestyle if not look.marker else "")
        assert key not in seen, f"{name} looks like {seen.get(key)}"
        seen[key] = name


def test_strategies_drawn_together_have_different_colours():
    # the criteria study draws all eight strategies in one panel
    colours = [to_rgb(style.look(s).color) for s in (*tracking.STRATEGIES, *tracking.CRITERIA)]
    assert len(set(colours)) == len(colours)
    algorithms = [to_rgb(style.look(s).color)
                  for s in ("greedy", "literal", "relaxed", "optimal", "one-pass")]
    assert len(set(algorithms)) == len(algorithms)


def test_colours_come_from_the_colour_blind_safe_palette():
    allowed = {to_rgb(c) for c in style.OKABE_ITO.values()}
    for name, look in style.LOOKS.items():
        if look.color is not None:
            rgb = to_rgb(look.color)
            assert rgb in allowed or len(set(rgb)) == 1, name  # Okabe-Ito, or a grey
    assert to_rgb(style.OKABE_ITO["yellow"]) not in {
        to_rgb(look.color) for look in style.LOOKS.values() if look.color}  # too pale on white


def test_unknown_names_are_refused_with_the_known_ones():
    with pytest.raises(ValueError, match="best-pair"):
        style.look("best pair")
    with pytest.raises(ValueError, match="no look"):
        style.look(None)
