"""Bisection of a bracket over LAMMPS runs: the critical value between one at which the problem
stands and one at which it fails (vertical_cut, strength_reduction)."""


def bisect(run, low, high, steps, tool):
    """run(value) -> a dict with 'fails'; runs both ends (the bracket must stand at `low` and fail
    at `high`), then `steps` bisections. Returns every run (in the order run) and the final
    bracket (low, high)."""
    runs = [run(low), run(high)]
    if runs[0]['fails'] or not runs[1]['fails']:
        raise SystemExit(f'{tool}: [{low}, {high}] is not a bracket (it must stand at {low} and fail '
                         f'at {high}): fails {runs[0]["fails"]} and {runs[1]["fails"]}')
    for _ in range(steps):
        middle = 0.5 * (low + high)
        r = run(middle)
        runs.append(r)
        if r['fails']:
            high = middle
        else:
            low = middle
    return runs, low, high


def summary(runs, low, high, quantity):
    """The result of bisect() in a study's JSON (the same keys for every study, which
    python3 -m sph_soil showcase reads): the critical value of `quantity` as the final bracket's
    middle +- its half width, the wall time of all runs, and every run without its time series."""
    return {'quantity': quantity, 'stands_up_to': low, 'fails_from': high, 'critical': 0.5 * (low + high),
            'half_width': 0.5 * (high - low),
            'wall_seconds_all_runs': round(sum(r['wall_seconds'] or 0.0 for r in runs), 1),
            'runs': [{k: v for k, v in r.items() if k not in ('time', 'moved')}
                     for r in sorted(runs, key=lambda r: r[quantity])]}
