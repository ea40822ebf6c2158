"""Generalized Richardson extrapolation of a figure from runs at several cell sizes: the
observed order and the h -> 0 value through the three finest."""


def extrapolate(cells, values):
    """(order, h -> 0 value) through the three finest (h, f); (None, None) when they are not
    monotone or converge slower than order 0.5. f = f0 + C h^p: the ratio of the two
    differences fixes p (bisection)."""
    pairs = [(h, f) for h, f in zip(cells, values) if f is not None]
    if len(pairs) < 3:
        return None, None
    (h1, f1), (h2, f2), (h3, f3) = sorted(pairs, reverse=True)[-3:]
    if f2 == f3 and f1 == f2:
        return None, f3
    if f2 == f3 or (f1 - f2) * (f2 - f3) <= 0:
        return None, None
    ratio = (f1 - f2) / (f2 - f3)

    def model_ratio(p):
        return (h1 ** p - h2 ** p) / (h2 ** p - h3 ** p)

    low, high = 0.5, 3.0  # model_ratio grows with p
    if ratio < model_ratio(low):
        return None, None
    if ratio >= model_ratio(high):
        order = high
    else:
        for _ in range(60):
            middle = 0.5 * (low + high)
            if model_ratio(middle) < ratio:
                low = middle
            else:
                high = middle
        order = 0.5 * (low + high)
    constant = (f2 - f3) / (h2 ** order - h3 ** order)
    return order, f3 - constant * h3 ** order
