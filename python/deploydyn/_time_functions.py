"""Functions of time (driver profiles, ΔT, load factors): the dicts the model file's mappings
hold (docs/model-format.md, "Functions of time"), with their arguments checked."""
from deploydyn import _arguments as checked


def constant(value):
    """A function of time that is `value` at every t: {"type": "constant", "value": value}."""
    return {"type": "constant", "value": checked.number("constant", "value", value)}


def smooth_step(t0, v0, t1, v1):
    """v0 until t0, v1 from t1, ADAMS' cubic STEP in between."""
    return {"type": "smooth_step", **{name: checked.number("smooth_step", name, value) for name, value in
                                      (("t0", t0), ("v0", v0), ("t1", t1), ("v1", v1))}}


def pair_of_times(where, name, value):
    values = checked.numbers(where, name, value)
    if len(values) != 2:
        raise ValueError(f"{where}: {name} must be two numbers (t_start, t_end), got {len(values)}")
    return values


def smooth_trapezoid(amplitude, rise, fall):
    """0 → amplitude over rise = (t0, t1), held, back to 0 over fall = (t2, t3)."""
    return {"type": "smooth_trapezoid",
            "amplitude": checked.number("smooth_trapezoid", "amplitude", amplitude),
            "rise": pair_of_times("smooth_trapezoid", "rise", rise),
            "fall": pair_of_times("smooth_trapezoid", "fall", fall)}


def paper_eq23(**changes):
    """The paper's Eq. (23) (amplitude 0.365, rise [0, 1], fall [4, 5]); keywords change parts."""
    spec = {"type": "paper_eq23"}
    for key, value in changes.items():
        if key == "amplitude":
            spec[key] = checked.number("paper_eq23", key, value)
        elif key in ("rise", "fall"):
            spec[key] = pair_of_times("paper_eq23", key, value)
        else:
            spec[key] = value  # the loader names what it does not know
    return spec


def table(points):
    """Linear between (t, value) points, held constant outside."""
    if isinstance(points, (str, bytes)) or not hasattr(points, "__iter__"):
        raise TypeError("table: points must be a sequence of (t, value) pairs, "
                        f"not {checked.shown(points)}")
    rows = []
    for i, point in enumerate(points):
        values = checked.numbers("table", f"points[{i}]", point)
        if len(values) != 2:
            raise ValueError(f"table: points[{i}] must be a (t, value) pair, "
                             f"got {len(values)} numbers")
        rows.append([float(v) for v in values])
    return {"type": "table", "points": rows}


def ramp(kind, t0, v0, t1, v1):
    return {"type": kind, **{name: checked.number(kind, name, value) for name, value in
                             (("t0", t0), ("v0", v0), ("t1", t1), ("v1", v1))}}


def cosine_ramp(t0, v0, t1, v1):
    """v0 until t0, v1 from t1, a half cosine in between: v0 + (v1 - v0)(1 - cos(pi s))/2,
    s = (t - t0)/(t1 - t0). Starts and stops at rest; its acceleration jumps at t0 and t1."""
    return ramp("cosine_ramp", t0, v0, t1, v1)


def cycloidal(t0, v0, t1, v1):
    """v0 until t0, v1 from t1, a cycloid in between: v0 + (v1 - v0)(s - sin(2 pi s)/(2 pi)),
    s = (t - t0)/(t1 - t0). Starts and stops at rest with zero acceleration (jerk-limited): a
    drive that does not set the structure ringing as smooth_step does."""
    return ramp("cycloidal", t0, v0, t1, v1)


def polynomial(coefficients, interval=None):
    """c[0] + c[1] tau + c[2] tau**2 + ... (1 to 16 coefficients). Without `interval`, tau = t
    at every t; with interval = (t0, t1), tau = t - t0 on it and the function is held at its
    end values outside."""
    spec = {"type": "polynomial",
            "coefficients": [float(c) for c in checked.numbers("polynomial", "coefficients", coefficients)]}
    if interval is not None:
        spec["interval"] = pair_of_times("polynomial", "interval", interval)
    return spec


def harmonic(amplitude, frequency, phase=0.0, offset=0.0):
    """offset + amplitude * sin(2 pi frequency t + phase); frequency in Hz (> 0), phase in rad."""
    return {"type": "harmonic", "amplitude": checked.number("harmonic", "amplitude", amplitude),
            "frequency": checked.number("harmonic", "frequency", frequency),
            "phase": checked.number("harmonic", "phase", phase),
            "offset": checked.number("harmonic", "offset", offset)}


def piecewise(pieces):
    """Each piece (t_from, t_to, function) on [t_from, t_to), the pieces in order, each starting
    where the one before ends, their values joining; held at the first value before and the last
    after. A function is a number, a function's name or any of these functions, in the absolute
    time t."""
    if isinstance(pieces, (str, bytes, dict)) or not hasattr(pieces, "__iter__"):
        raise TypeError(f"piecewise: pieces must be a sequence of (t_from, t_to, function), "
                        f"not {checked.shown(pieces)}")
    rows = []
    for i, piece in enumerate(pieces):
        if isinstance(piece, (str, bytes, dict)) or not hasattr(piece, "__len__") or len(piece) != 3:
            raise TypeError(f"piecewise: pieces[{i}] must be a (t_from, t_to, function) triple, "
                            f"not {checked.shown(piece)}")
        t_from, t_to, function = piece
        rows.append({"from": checked.number("piecewise", f"pieces[{i}] t_from", t_from),
                     "to": checked.number("piecewise", f"pieces[{i}] t_to", t_to),
                     "function": checked.time_function("piecewise", f"pieces[{i}] function", function)})
    return {"type": "piecewise", "pieces": rows}


def sum_of(*terms):
    """The sum of the given functions of time (numbers, names or any of these functions)."""
    return {"type": "sum",
            "terms": [checked.time_function("sum_of", f"terms[{i}]", term) for i, term in enumerate(terms)]}
