"""Grid convergence of an answer computed at successively finer spacings (verification practice
of CFD and finite elements: Roache 1994, 1998; Celik et al. 2008, the ASME procedure).

For an answer f(d) whose error falls as C d^p, three spacings d_3 > d_2 > d_1 with the constant
ratio r = d_3/d_2 = d_2/d_1 give

    the observed order       p   = ln((f_3 - f_2) / (f_2 - f_1)) / ln r,
    Richardson's extrapolate f_0 = f_1 + (f_1 - f_2) / (r^p - 1),
    the grid-convergence index of the finest answer
                             GCI = F_s |(f_1 - f_2) / f_1| / (r^p - 1),   F_s = 1.25,

a band that holds the converged answer with about 95% confidence when the three answers lie in
the asymptotic range (the observed order near the scheme's). Successive differences of opposite
signs (an oscillating sequence) or a zero one have no observed order: None, and no extrapolate.
Of two successive differences alone (no answer, only how far the runs lie apart, as the bars'
surfaces) the order is log_r(e_1 / e_2).
"""
import math

SAFETY = 1.25    # Roache's factor of safety for three or more spacings


def order_of_differences(coarse_difference, fine_difference, ratio=2.0):
    """log_r(e_coarse / e_fine) of two successive differences of a sequence, None if either is
    zero or their signs differ."""
    if coarse_difference == 0.0 or fine_difference == 0.0:
        return None
    quotient = coarse_difference / fine_difference
    if quotient <= 0.0:
        return None
    return math.log(quotient) / math.log(ratio)


def observed_order(coarse, medium, fine, ratio=2.0):
    """The observed order p of three answers at spacings r^2 d, r d and d (None: oscillating or
    flat)."""
    return order_of_differences(coarse - medium, medium - fine, ratio)


def richardson(medium, fine, order, ratio=2.0):
    """Richardson's extrapolate of the two finest answers for an error of order `order`."""
    if order is None or order <= 0.0:
        return None
    return fine + (fine - medium) / (ratio ** order - 1.0)


def grid_convergence_index(medium, fine, order, ratio=2.0, safety=SAFETY):
    """Roache's GCI of the finest answer, a fraction of it (None without an order or for a zero
    answer)."""
    if order is None or order <= 0.0 or fine == 0.0:
        return None
    return safety * abs((fine - medium) / fine) / (ratio ** order - 1.0)


def constant_ratio(spacings):
    """The ratio of successive spacings, coarsest first (a ValueError unless there are at least
    two and the ratio is constant)."""
    ratios = [a / b for a, b in zip(spacings, spacings[1:])]
    if not ratios or any(not math.isclose(r, ratios[0], rel_tol=1e-6) for r in ratios):
        raise ValueError(f"spacings {tuple(spacings)}: need at least two, coarsest first, of a constant ratio")
    return ratios[0]


def sequence(spacings, answers):
    """Each consecutive triple of a sequence of answers, coarsest first, at spacings of a constant
    ratio: a dict per triple with its spacings, observed order, extrapolate and GCI."""
    if len(spacings) != len(answers):
        raise ValueError(f"{len(spacings)} spacings against {len(answers)} answers")
    ratio = constant_ratio(spacings)
    rows = []
    for k in range(len(answers) - 2):
        d3, d2, d1 = spacings[k:k + 3]
        f3, f2, f1 = answers[k:k + 3]
        p = observed_order(f3, f2, f1, ratio)
        rows.append(dict(spacings=[d3, d2, d1], ratio=ratio, observed_order=p,
                         extrapolated=richardson(f2, f1, p, ratio),
                         gci=grid_convergence_index(f2, f1, p, ratio)))
    return rows
