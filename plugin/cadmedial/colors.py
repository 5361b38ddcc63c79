"""Colours for medial sheets: a perceptual colour map for the medial radius
and a palette of distinct colours for sheets."""

import numpy as np

# Viridis, 9 stops (matplotlib's, sampled evenly); linear in between.
_VIRIDIS = np.array(
    [
        [0.267, 0.005, 0.329],
        [0.283, 0.141, 0.458],
        [0.254, 0.265, 0.530],
        [0.207, 0.372, 0.553],
        [0.164, 0.471, 0.558],
        [0.128, 0.567, 0.551],
        [0.135, 0.659, 0.518],
        [0.267, 0.749, 0.441],
        [0.478, 0.821, 0.318],
        [0.741, 0.873, 0.150],
        [0.993, 0.906, 0.144],
    ]
)

# Tableau 10 and its lighter companions: distinct, readable on grey and white.
SHEET_PALETTE = np.array(
    [
        [0.122, 0.467, 0.706],
        [1.000, 0.498, 0.055],
        [0.173, 0.627, 0.173],
        [0.839, 0.153, 0.157],
        [0.580, 0.404, 0.741],
        [0.549, 0.337, 0.294],
        [0.890, 0.467, 0.761],
        [0.737, 0.741, 0.133],
        [0.090, 0.745, 0.812],
        [0.682, 0.780, 0.910],
        [1.000, 0.733, 0.471],
        [0.596, 0.875, 0.541],
        [1.000, 0.596, 0.588],
        [0.773, 0.690, 0.835],
        [0.769, 0.612, 0.580],
        [0.969, 0.714, 0.824],
        [0.859, 0.859, 0.553],
        [0.620, 0.855, 0.898],
    ]
)
OTHER_SHEETS_COLOR = (0.62, 0.62, 0.62)


def radius_colors(values, vmax):
    """RGB rows (K x 3, floats in [0, 1]) for values in [0, vmax]."""
    values = np.asarray(values, dtype=np.float64)
    t = np.zeros_like(values) if vmax <= 0 else np.clip(values / vmax, 0.0, 1.0)
    x = t * (len(_VIRIDIS) - 1)
    i = np.minimum(np.floor(x).astype(np.int64), len(_VIRIDIS) - 2)
    f = (x - i)[:, None]
    return _VIRIDIS[i] * (1.0 - f) + _VIRIDIS[i + 1] * f


def sheet_color(rank):
    """Colour of the sheet of size rank `rank` (0 = largest)."""
    return tuple(float(c) for c in SHEET_PALETTE[int(rank) % len(SHEET_PALETTE)])


def as_color_list(rgb):
    """A list of (r, g, b) float tuples, as App::PropertyColorList wants them."""
    return [(float(r), float(g), float(b)) for r, g, b in np.asarray(rgb, dtype=np.float64).tolist()]
