"""Numbers the paper publishes (figure data of its runs), in one place, for comparison.

Plain constants; each names the figure it comes from.
"""

#: The published Figs. 4-6 run: pair changes over 314 transitions and run means, per strategy.
PUBLISHED_CIRCLE = {
    "best-pair": {"switches": 148, "mean_bound": 0.73, "mean_error": 0.16, "mean_trace": 0.073},
    "best-partner": {"switches": 102, "mean_bound": 0.49, "mean_error": 0.19, "mean_trace": 0.140},
    "fixed-pair": {"switches": 0, "mean_bound": 0.27, "mean_error": 0.22, "mean_trace": 0.217},
}

#: The published Fig. 7 run: mean bound and pair changes over 314 transitions.
PUBLISHED_ADVERSARIAL = {"mean_bound": 0.79, "switches": 306, "transitions": 314}
