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
