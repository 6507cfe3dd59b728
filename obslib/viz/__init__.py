"""Every matplotlib drawing of the library; nothing else in it imports matplotlib.

One module per chapter of the book, named after its notebook without the number
(``model_and_bound``, ``pair_closed_form``, ``greedy_unique_pairs``, ``two_sensors_tracking``, ...),
each ``plot_*`` function drawing one figure of the chapter and returning it; and what the chapters
share: the looks and labels of :mod:`~obslib.viz.style`, and the runs and published runs of
:mod:`~obslib.viz.tracking`.
"""
