"""The refinement options of the studies of a failure (vertical_cut, strength_reduction,
bearing_capacity): the command line's --refine, --stepping, --criterion, --threshold, --every,
--balance, --buffer, --ease and --split, the input variables they set (examples/vertical_cut,
examples/slope and examples/bearing_capacity read the same names: refine, stepping, criterion,
threshold, check, balance, buffer, ease, separation, smoothing), a directory tag and a title per
configuration, and the fields that describe it in a JSON summary."""


def add_arguments(p, every):
    """The options; `every` is the input's own default check interval."""
    p.add_argument('--refine', type=int, nargs='?', const=1, default=0,
                   help='dynamic refinement (-var refine N, N levels deep; 1 without a value): the '
                        'particles that shear split')
    p.add_argument('--stepping', choices=('global', 'level'), default='global',
                   help='with --refine: one time step for all, or a time step per level')
    p.add_argument('--criterion', choices=('strain', 'shear_strain_rate'), default='strain',
                   help='with --refine: what splits (the input\'s -var criterion)')
    p.add_argument('--every', type=int, default=every,
                   help='with --refine: check every N steps (the input rounds it up to a multiple of 2^N '
                        'with --stepping level)')
    p.add_argument('--balance', action='store_true',
                   help='with --refine: balance the ranks\' work (fix balance weighted by step_period)')
    p.add_argument('--threshold', type=float, default=None,
                   help='with --refine: the criterion\'s threshold (the input\'s default without it)')
    p.add_argument('--buffer', type=float, default=None,
                   help='with --refine: also split the particles whose kernel reaches, within this many '
                        'of its supports (0 to 1), one the criterion wants (the input\'s default without it)')
    p.add_argument('--ease', type=float, default=None,
                   help='with --refine: daughters born with the smoothing ratio the soil least feels, eased to '
                        'the level\'s h over this time (s)')
    p.add_argument('--split', type=float, nargs=2, default=None, metavar=('EPS', 'ALPHA'),
                   help='with --refine: the daughters\' separation and smoothing ratio (the input\'s '
                        'default without it)')
    p.set_defaults(default_every=every)


def variables(args):
    """The input's refinement variables (refine 0 without --refine)."""
    if not args.refine:
        return [('refine', '0')]
    return [('refine', str(args.refine)), ('stepping', args.stepping), ('criterion', args.criterion),
            ('check', str(args.every)), ('balance', '1' if args.balance else '0')] + \
        ([('threshold', f'{args.threshold:g}')] if args.threshold is not None else []) + \
        ([('buffer', f'{args.buffer:g}')] if args.buffer is not None else []) + \
        ([('ease', f'{args.ease:g}')] if args.ease is not None else []) + \
        ([('separation', f'{args.split[0]:g}'), ('smoothing', f'{args.split[1]:g}')] if args.split else [])


def tag(args):
    """The directory tag of a configuration's refinement ('' without --refine)."""
    if not args.refine:
        return ''
    t = '_refined' + (f'{args.refine}' if args.refine > 1 else '')
    if args.stepping != 'global':
        t += f'_{args.stepping}'
    if args.criterion != 'strain' or args.threshold is not None:
        t += f'_{args.criterion}' + (f'{args.threshold:g}' if args.threshold is not None else '')
    if args.every != args.default_every:
        t += f'_N{args.every}'
    if args.balance:
        t += '_balanced'
    if args.buffer is not None:
        t += f'_buffer{args.buffer:g}'
    if args.ease is not None:
        t += f'_ease{args.ease:g}'
    if args.split:
        t += f'_split{args.split[0]:g}_{args.split[1]:g}'
    return t


def title(args):
    """', refined 2 levels, a step per level' (empty without --refine)."""
    if not args.refine:
        return ''
    return (f', refined {"once" if args.refine == 1 else f"{args.refine} levels"}'
            f'{", a step per level" if args.stepping == "level" else ""}'
            f'{f", buffer {args.buffer:g}" if args.buffer is not None else ""}'
            f'{f", eased over {args.ease:g} s" if args.ease is not None else ""}'
            f'{f", split {args.split[0]:g} / {args.split[1]:g}" if args.split else ""}')


def summary(args, spacing):
    """A configuration's fields in a study's JSON: its spacing, the finest spacing it reaches
    (spacing / 2^refine: a split halves the spacing) and its refinement settings."""
    return {'spacing_m': spacing, 'finest_spacing_m': spacing / 2 ** args.refine, 'refined': args.refine,
            'stepping': args.stepping if args.refine else None,
            'criterion': args.criterion if args.refine else None, 'threshold': args.threshold,
            'every': args.every if args.refine else None, 'balanced': bool(args.refine and args.balance),
            'buffer': args.buffer if args.refine else None, 'ease': args.ease if args.refine else None,
            'split': args.split if args.refine else None}
