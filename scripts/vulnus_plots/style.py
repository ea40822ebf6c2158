"""Shared look of the vulnus pictures: the Agg backend, failure-flag colours and labels."""
import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

# Failure flags of the particle files: 0 intact, 1 matrix, 2 fiber, 3 total.
FLAG_LABELS = {0: "intact", 1: "matrix failure", 2: "fiber failure", 3: "total failure"}
FLAG_COLOURS = {0: "#d0d0d0", 1: "#1f77b4", 2: "#ff9f1c", 3: "#d62728"}
BULLET_COLOUR = "#404040"


def figure(n_rows, n_columns, width=5.0, height=4.0, **kwargs):
    return plt.subplots(n_rows, n_columns, figsize=(width * n_columns, height * n_rows),
                        squeeze=False, **kwargs)


def save(fig, path):
    fig.savefig(path, dpi=120, bbox_inches="tight")
    plt.close(fig)
    print("wrote %s" % path)


def scatter_flags(axis, u, v, flags, size=2.0, show_intact=True):
    """Points (u, v) coloured by failure flag, intact first so failure draws on top."""
    for flag in (0, 1, 2, 3):
        if flag == 0 and not show_intact:
            continue
        chosen = flags == flag
        if chosen.any():
            axis.scatter(u[chosen], v[chosen], s=size, c=FLAG_COLOURS[flag], linewidths=0,
                         label="%s (%d)" % (FLAG_LABELS[flag], chosen.sum()), rasterized=True)
